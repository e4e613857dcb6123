//! What the tests compare with: coverage by its definition, decided pixel
//! by pixel in exact integer arithmetic, not by the algorithms you write.
#![allow(dead_code, unused_imports)] // each test file uses a different part

use canvas::{Canvas, Pixel, Rgba, Vec2, Viewport};

pub mod triangles;

/// The colour used for test drawings.
pub const INK: Rgba = Rgba::WHITE;

pub use testkit::definitions::{
    SUBPIXEL_BITS, snap, triangle_covers, triangle_pixels, viewport_pixels,
};
pub use testkit::pixels::{collect, collect_fragments, counts, first_duplicate, grid_pixels};

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
