//! What the tests compare with: coverage by its definition, decided pixel
//! by pixel in exact integer arithmetic, not by the algorithms you write.
#![allow(dead_code, unused_imports)] // each test file uses a different part

use std::collections::{BTreeMap, BTreeSet};

use canvas::{Canvas, Fragment, MAX_COORD, Pixel, Rgba, Vec2, Viewport};

/// The colour used for test drawings.
pub const INK: Rgba = Rgba::WHITE;

pub use testkit::pixels::{collect, collect_fragments, counts, first_duplicate, grid_pixels};

/// Every pixel of a (small) viewport.
pub fn viewport_pixels(viewport: Viewport) -> impl Iterator<Item = Pixel> {
    (viewport.y_min..=viewport.y_max)
        .flat_map(move |y| (viewport.x_min..=viewport.x_max).map(move |x| Pixel::new(x, y)))
}

/// A canvas with the given pixels set to [`INK`].
pub fn canvas_with(width: u32, height: u32, pixels: &[Pixel]) -> Canvas {
    let mut canvas = Canvas::new(width, height);
    for &p in pixels {
        canvas.set(p, INK);
    }
    canvas
}

// ---------------------------------------------------------------------------
// Rectangles.

/// Whether the centre of `p` lies in the half-open box `[min, max)`,
/// compared exactly (every `i32` of a test and every `f32` fit in `f64`).
pub fn in_half_open_box(p: Pixel, min: Vec2, max: Vec2) -> bool {
    let (x, y) = (f64::from(p.x), f64::from(p.y));
    f64::from(min.x) <= x && x < f64::from(max.x) && f64::from(min.y) <= y && y < f64::from(max.y)
}

// ---------------------------------------------------------------------------
// Triangles.

/// Fixed-point fractional bits, as the sheet prescribes for `edge_function`.
pub const SUBPIXEL_BITS: u32 = 8;

/// `round(v · 2^SUBPIXEL_BITS)`, ties away from zero; `None` for NaN,
/// infinities and `|v| > MAX_COORD`.
pub fn snap(v: f32) -> Option<i64> {
    if !v.is_finite() || v.abs() > MAX_COORD as f32 {
        return None;
    }
    Some((f64::from(v) * f64::from(1_u32 << SUBPIXEL_BITS)).round() as i64)
}

/// Whether the triangle covers the centre of `p`, by a definition written
/// differently from the sheet's: the centre is moved by an infinitesimal
/// `(δ, −δ²)` (right, and a hair down), which never lies on an edge, and is
/// then inside when it lies strictly on the inner side of all three edges.
/// Moving right takes centres on left edges in and on right edges out;
/// moving down does the same for top and bottom edges: the top-left rule.
pub fn triangle_covers(positions: [Vec2; 3], p: Pixel) -> bool {
    let mut q = [[0_i64; 2]; 3];
    for (k, v) in positions.iter().enumerate() {
        match (snap(v.x), snap(v.y)) {
            (Some(x), Some(y)) => q[k] = [x, y],
            _ => return false,
        }
    }
    let one = 1_i64 << SUBPIXEL_BITS;
    let c = [i64::from(p.x) * one, i64::from(p.y) * one];
    let cross = |a: [i64; 2], b: [i64; 2], d: [i64; 2]| {
        i128::from(b[0] - a[0]) * i128::from(d[1] - a[1])
            - i128::from(b[1] - a[1]) * i128::from(d[0] - a[0])
    };
    let area = cross(q[0], q[1], q[2]);
    if area == 0 {
        return false;
    }
    (0..3).all(|i| {
        let (a, b) = (q[i], q[(i + 1) % 3]);
        let (ex, ey) = (b[0] - a[0], b[1] - a[1]);
        // cross(e, c + (δ, −δ²) − a) = O + δ·(−e.y) + δ²·(−e.x)
        let side = [cross(a, b, c), i128::from(-ey), i128::from(-ex)]
            .into_iter()
            .find(|&t| t != 0)
            .unwrap_or(0);
        side.signum() == area.signum()
    })
}

/// The pixels of `viewport` a triangle covers, by [`triangle_covers`].
pub fn triangle_pixels(positions: [Vec2; 3], viewport: Viewport) -> Vec<Pixel> {
    viewport_pixels(viewport)
        .filter(|&p| triangle_covers(positions, p))
        .collect()
}

// ---------------------------------------------------------------------------
// Polygons.

/// Where the edge `a–b` crosses row `y`, computed exactly as the sheet
/// prescribes (lower endpoint first, in `f64`, in this order).
pub fn crossing(a: Vec2, b: Vec2, y: i32) -> f64 {
    let (lo, hi) = if a.y < b.y { (a, b) } else { (b, a) };
    let (lo_x, lo_y) = (f64::from(lo.x), f64::from(lo.y));
    let (hi_x, hi_y) = (f64::from(hi.x), f64::from(hi.y));
    lo_x + ((f64::from(y) - lo_y) * (hi_x - lo_x)) / (hi_y - lo_y)
}

/// The even-odd rule at the centre of `p`: inside when an odd number of
/// edges cross row `p.y` (lower end counted, upper end not) at or left of
/// `p.x`. Polygons with fewer than three vertices or a non-finite
/// coordinate cover nothing.
pub fn even_odd_covers(vertices: &[Vec2], p: Pixel) -> bool {
    if vertices.len() < 3 || !vertices.iter().all(|v| v.is_finite()) {
        return false;
    }
    let y = f64::from(p.y);
    let n = vertices.len();
    let crossings = (0..n)
        .map(|i| (vertices[i], vertices[(i + 1) % n]))
        .filter(|(a, b)| (f64::from(a.y) <= y) != (f64::from(b.y) <= y))
        .filter(|&(a, b)| crossing(a, b, p.y) <= f64::from(p.x))
        .count();
    crossings % 2 == 1
}

/// The pixels of `viewport` inside the polygon, by [`even_odd_covers`].
pub fn even_odd_pixels(vertices: &[Vec2], viewport: Viewport) -> Vec<Pixel> {
    viewport_pixels(viewport)
        .filter(|&p| even_odd_covers(vertices, p))
        .collect()
}

/// The viewport polygon tests draw into.
pub const POLYGON_VIEWPORT: Viewport = Viewport::new(-24, -24, 24, 24);

/// Simple polygons: star-shaped around a centre, vertices at sorted
/// angles and random radii (convex and concave, both windings).
pub fn star_polygon() -> impl proptest::strategy::Strategy<Value = Vec<Vec2>> {
    use proptest::prelude::*;
    (
        testkit::strategies::point(6.0),
        prop::collection::vec((0.0f32..std::f32::consts::TAU, 1.0f32..16.0), 3..12),
        any::<bool>(),
    )
        .prop_map(|(centre, mut spokes, clockwise)| {
            spokes.sort_by(|a, b| a.0.total_cmp(&b.0));
            if clockwise {
                spokes.reverse();
            }
            spokes
                .into_iter()
                .map(|(angle, r)| centre + r * Vec2::new(angle.cos(), angle.sin()))
                .collect()
        })
}

/// Any polygon the even-odd rule defines: random vertices, often
/// self-intersecting, sometimes on the half-pixel lattice so that
/// vertices and edges meet pixel centres and rows exactly.
pub fn any_polygon() -> impl proptest::strategy::Strategy<Value = Vec<Vec2>> {
    use proptest::prelude::*;
    prop_oneof![
        star_polygon(),
        prop::collection::vec(testkit::strategies::point(20.0), 0..12),
        prop::collection::vec(testkit::strategies::half_pixel_point(20), 0..12),
    ]
}

/// Polygons with hostile coordinates mixed in.
pub fn hostile_polygon() -> impl proptest::strategy::Strategy<Value = Vec<Vec2>> {
    use proptest::prelude::*;
    prop::collection::vec(
        prop_oneof![
            testkit::strategies::hostile_point(),
            testkit::strategies::point(20.0)
        ],
        0..8,
    )
}
