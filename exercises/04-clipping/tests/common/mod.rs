//! What the tests compare with: the clip volume, areas and visible parts
//! of segments by their definitions, in `f64`, written differently from
//! the algorithms you write.
#![allow(dead_code)] // each test file uses a different part

use canvas::{Rgba, Vec2, Vec4};
use clipping::{ClipPlane, ClipVertex, ClipWindow, Segment};
use proptest::prelude::*;

/// The six planes of the clip volume `−w ≤ x, y, z ≤ w`, written out
/// (`testkit::definitions::CLIP_VOLUME_PLANES`, not taken from
/// `clip_planes()`): right, left, top, bottom, far, near.
pub const VOLUME_PLANES: [ClipPlane; 6] = {
    let p = testkit::definitions::CLIP_VOLUME_PLANES;
    [
        ClipPlane::new(p[0]),
        ClipPlane::new(p[1]),
        ClipPlane::new(p[2]),
        ClipPlane::new(p[3]),
        ClipPlane::new(p[4]),
        ClipPlane::new(p[5]),
    ]
};

/// A clip-space vertex.
pub fn cv(x: f32, y: f32, z: f32, w: f32, colour: Rgba) -> ClipVertex {
    ClipVertex {
        position: Vec4::new(x, y, z, w),
        colour,
    }
}

/// A vertex of the plane `z = 0, w = 1`: 2D clipping against the square
/// `[−1, 1]²`.
pub fn flat(x: f32, y: f32, colour: Rgba) -> ClipVertex {
    cv(x, y, 0.0, 1.0, colour)
}

/// A vertex in one line: `(x, y, z, w) rgba(r, g, b, a)`.
pub fn vertex_text(v: ClipVertex) -> String {
    let ([x, y, z, w], c) = (v.position.to_array(), v.colour);
    format!(
        "({x}, {y}, {z}, {w}) rgba({}, {}, {}, {})",
        c.r, c.g, c.b, c.a
    )
}

/// A polygon for a message: one numbered vertex a line (see
/// [`vertex_text`]), or `no vertices`.
pub fn polygon_text(polygon: &[ClipVertex]) -> String {
    if polygon.is_empty() {
        return "  no vertices".to_string();
    }
    polygon
        .iter()
        .enumerate()
        .map(|(i, &v)| format!("  {i}: {}", vertex_text(v)))
        .collect::<Vec<_>>()
        .join("\n")
}

/// Asserts that `yours` is `expected`, vertex for vertex and exactly. On
/// failure it names `what`, the first vertex that differs (or both vertex
/// counts) and lists both polygons one vertex a line, rather than dumping
/// two vectors of structs.
#[track_caller]
pub fn assert_same_polygon(yours: &[ClipVertex], expected: &[ClipVertex], what: &str) {
    if yours == expected {
        return;
    }
    let first = match yours.iter().zip(expected).position(|(y, e)| y != e) {
        Some(i) => format!("vertex {i} differs"),
        None => format!(
            "yours has {} vertices, expected {}",
            yours.len(),
            expected.len()
        ),
    };
    panic!(
        "{what}: {first}\nexpected:\n{}\nyours:\n{}",
        polygon_text(expected),
        polygon_text(yours)
    );
}

/// How far outside the volume `v` lies: the largest of `|x| − w`,
/// `|y| − w`, `|z| − w`, in `f64` (≤ 0 inside).
pub fn excess(v: Vec4) -> f64 {
    let [x, y, z, w] = v.to_array().map(f64::from);
    (x.abs() - w).max(y.abs() - w).max(z.abs() - w)
}

/// `Σ (x_i y_{i+1} − x_{i+1} y_i) / 2` of the xy projection: the signed
/// area (counter-clockwise positive); overlapping back-and-forth edges
/// cancel.
pub fn shoelace(vertices: &[ClipVertex]) -> f64 {
    let n = vertices.len();
    (0..n)
        .map(|i| {
            let (a, b) = (vertices[i].position, vertices[(i + 1) % n].position);
            f64::from(a.x) * f64::from(b.y) - f64::from(b.x) * f64::from(a.y)
        })
        .sum::<f64>()
        / 2.0
}

/// The area of a convex polygon (xy, `z = 0`, `w = 1`) inside the square
/// `[−1, 1]²`, found without clipping: the intersection of two convex sets
/// is the convex hull of the vertices of each inside the other and of the
/// crossings of their edges.
pub fn convex_area_in_square(polygon: &[Vec2]) -> f64 {
    let p: Vec<[f64; 2]> = polygon
        .iter()
        .map(|v| [f64::from(v.x), f64::from(v.y)])
        .collect();
    let square = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
    let mut points: Vec<[f64; 2]> = Vec::new();
    points.extend(p.iter().filter(|v| v[0].abs() <= 1.0 && v[1].abs() <= 1.0));
    points.extend(square.iter().filter(|&&c| in_convex(&p, c)));
    for i in 0..p.len() {
        for j in 0..4 {
            if let Some(x) =
                segment_crossing(p[i], p[(i + 1) % p.len()], square[j], square[(j + 1) % 4])
            {
                points.push(x);
            }
        }
    }
    hull_area(points)
}

fn cross(o: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
}

/// Whether `c` lies in the convex polygon `p` (either winding, border in).
fn in_convex(p: &[[f64; 2]], c: [f64; 2]) -> bool {
    let n = p.len();
    let sides: Vec<f64> = (0..n).map(|i| cross(p[i], p[(i + 1) % n], c)).collect();
    sides.iter().all(|&s| s >= -1e-12) || sides.iter().all(|&s| s <= 1e-12)
}

fn segment_crossing(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> Option<[f64; 2]> {
    let r = [b[0] - a[0], b[1] - a[1]];
    let s = [d[0] - c[0], d[1] - c[1]];
    let denom = r[0] * s[1] - r[1] * s[0];
    if denom == 0.0 {
        return None;
    }
    let q = [c[0] - a[0], c[1] - a[1]];
    let t = (q[0] * s[1] - q[1] * s[0]) / denom;
    let u = (q[0] * r[1] - q[1] * r[0]) / denom;
    ((0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u))
        .then(|| [a[0] + t * r[0], a[1] + t * r[1]])
}

/// Andrew's monotone chain, then the shoelace formula.
fn hull_area(mut points: Vec<[f64; 2]>) -> f64 {
    points.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    points.dedup();
    if points.len() < 3 {
        return 0.0;
    }
    let mut hull: Vec<[f64; 2]> = Vec::new();
    for pass in 0..2 {
        let start = hull.len();
        let iter: Box<dyn Iterator<Item = &[f64; 2]>> = if pass == 0 {
            Box::new(points.iter())
        } else {
            Box::new(points.iter().rev())
        };
        for &pt in iter {
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], pt) <= 0.0
            {
                hull.pop();
            }
            hull.push(pt);
        }
        hull.pop();
    }
    let n = hull.len();
    (0..n)
        .map(|i| hull[i][0] * hull[(i + 1) % n][1] - hull[(i + 1) % n][0] * hull[i][1])
        .sum::<f64>()
        .abs()
        / 2.0
}

/// The largest distance from a vertex of one closed polygon to the
/// boundary (the edges, closing edge included) of the other, both ways, in
/// 4D: how far apart their outlines are, whatever their vertex counts.
pub fn outline_distance(a: &[ClipVertex], b: &[ClipVertex]) -> f32 {
    fn to_boundary(p: Vec4, polygon: &[ClipVertex]) -> f32 {
        let n = polygon.len();
        (0..n)
            .map(|i| {
                let (u, v) = (polygon[i].position, polygon[(i + 1) % n].position);
                let d = v - u;
                let t = if d == Vec4::ZERO {
                    0.0
                } else {
                    ((p - u).dot(d) / d.dot(d)).clamp(0.0, 1.0)
                };
                p.distance(u + t * d)
            })
            .fold(f32::INFINITY, f32::min)
    }
    let one_way = |a: &[ClipVertex], b: &[ClipVertex]| {
        a.iter()
            .map(|u| to_boundary(u.position, b))
            .fold(0.0, f32::max)
    };
    if a.is_empty() || b.is_empty() {
        return if a.len() == b.len() {
            0.0
        } else {
            f32::INFINITY
        };
    }
    one_way(a, b).max(one_way(b, a))
}

/// Whether `v` equals `a.lerp(b, t)` for one `t ∈ [0, 1]` in position
/// *and* colour, to `tolerance`: `t` is taken from the coordinate that
/// changes most along the edge.
pub fn is_on_edge(v: ClipVertex, a: ClipVertex, b: ClipVertex, tolerance: f32) -> bool {
    let d = b.position - a.position;
    let k = (0..4)
        .max_by(|&i, &j| d[i].abs().total_cmp(&d[j].abs()))
        .unwrap_or(0);
    if d[k] == 0.0 {
        return v.position.distance(a.position) <= tolerance
            && v.colour.approx_eq(a.colour, tolerance);
    }
    let t = (v.position[k] - a.position[k]) / d[k];
    (-tolerance..=1.0 + tolerance).contains(&t)
        && v.position.distance(a.position + t * d) <= tolerance
        && v.colour.approx_eq(a.colour.lerp(b.colour, t), tolerance)
}

// ---------------------------------------------------------------------------
// Segments.

/// The visible part of a segment by its definition: the parameters
/// `t ∈ [0, 1]` whose point lies in the closed window. Candidates are 0, 1
/// and where the segment's line meets the four border lines; between two
/// neighbouring candidates the segment is wholly in or wholly out, so its
/// midpoint decides. Returns the smallest and largest visible `t`.
pub fn visible_interval(segment: Segment, window: ClipWindow) -> Option<[f64; 2]> {
    let p0 = [f64::from(segment.from.x), f64::from(segment.from.y)];
    let p1 = [f64::from(segment.to.x), f64::from(segment.to.y)];
    let (min, max) = (window.min(), window.max());
    let lo = [f64::from(min.x), f64::from(min.y)];
    let hi = [f64::from(max.x), f64::from(max.y)];
    let point = |t: f64| [p0[0] + t * (p1[0] - p0[0]), p0[1] + t * (p1[1] - p0[1])];
    let inside = |q: [f64; 2]| (0..2).all(|k| lo[k] <= q[k] && q[k] <= hi[k]);
    let mut candidates = vec![0.0, 1.0];
    for k in 0..2 {
        let d = p1[k] - p0[k];
        if d != 0.0 {
            for border in [lo[k], hi[k]] {
                let t = (border - p0[k]) / d;
                if (0.0..=1.0).contains(&t) {
                    candidates.push(t);
                }
            }
        }
    }
    candidates.sort_by(f64::total_cmp);
    let mut visible: Vec<f64> = Vec::new();
    for pair in candidates.windows(2) {
        if inside(point((pair[0] + pair[1]) / 2.0)) {
            visible.extend(pair);
        }
    }
    // A border crossing can be the only visible point (a touched corner);
    // allow for the rounding of the crossing itself.
    let snap = |q: [f64; 2]| {
        let eps = 1e-9 * (1.0 + q[0].abs() + q[1].abs());
        (0..2).all(|k| lo[k] - eps <= q[k] && q[k] <= hi[k] + eps)
    };
    visible.extend(candidates.iter().filter(|&&t| snap(point(t))));
    let first = visible.iter().copied().reduce(f64::min)?;
    let last = visible.iter().copied().reduce(f64::max)?;
    Some([first, last])
}

/// The visible part of `segment` by [`visible_interval`], as a segment in
/// `f64` points.
pub fn visible_part(segment: Segment, window: ClipWindow) -> Option<[[f64; 2]; 2]> {
    let [a, b] = visible_interval(segment, window)?;
    let p = |t: f64| {
        [
            f64::from(segment.from.x) + t * (f64::from(segment.to.x) - f64::from(segment.from.x)),
            f64::from(segment.from.y) + t * (f64::from(segment.to.y) - f64::from(segment.from.y)),
        ]
    };
    Some([p(a), p(b)])
}

/// Distance between two `f64` points.
pub fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// As an `f64` point.
pub fn to_f64(p: Vec2) -> [f64; 2] {
    [f64::from(p.x), f64::from(p.y)]
}

/// Checks a clipped segment against [`visible_part`]: the same endpoints
/// to `tolerance`, or, where one side found nothing, the other found at
/// most a piece shorter than `tolerance` (a corner grazed within rounding).
pub fn matches_visible_part(
    got: Option<Segment>,
    segment: Segment,
    window: ClipWindow,
    tolerance: f64,
) -> Result<(), String> {
    let expected = visible_part(segment, window);
    match (got, expected) {
        (Some(g), Some([a, b])) => {
            let (ga, gb) = (to_f64(g.from), to_f64(g.to));
            if dist(ga, a) <= tolerance && dist(gb, b) <= tolerance {
                Ok(())
            } else {
                Err(format!("expected {a:?} → {b:?}, got {g:?}"))
            }
        }
        (None, None) => Ok(()),
        (None, Some([a, b])) if dist(a, b) <= tolerance => Ok(()),
        (Some(g), None) if dist(to_f64(g.from), to_f64(g.to)) <= tolerance => Ok(()),
        (g, e) => Err(format!("expected {e:?}, got {g:?}")),
    }
}

/// Windows with corners in `±12`, at least zero wide and high, sometimes
/// on the half-pixel lattice of a viewport.
pub fn window() -> impl Strategy<Value = ClipWindow> {
    prop_oneof![
        (-12.0f32..12.0, -12.0f32..12.0, 0.0f32..12.0, 0.0f32..12.0).prop_map(|(x, y, w, h)| {
            ClipWindow::try_new(Vec2::new(x, y), Vec2::new(x + w, y + h)).expect("valid window")
        }),
        (-12i32..12, -12i32..12, 0i32..12, 0i32..12).prop_map(|(x, y, w, h)| {
            ClipWindow::from_viewport(canvas::Viewport::new(x, y, x + w, y + h))
                .expect("valid viewport")
        }),
    ]
}

/// Segments with endpoints in `±30`, also on the half-pixel lattice,
/// horizontal, vertical and of length zero.
pub fn segment() -> impl Strategy<Value = Segment> {
    use testkit::strategies::{half_pixel_point, point};
    prop_oneof![
        (point(30.0), point(30.0)).prop_map(|(a, b)| Segment::new(a, b)),
        (half_pixel_point(20), half_pixel_point(20)).prop_map(|(a, b)| Segment::new(a, b)),
        (point(30.0), -30.0f32..30.0).prop_map(|(a, x)| Segment::new(a, Vec2::new(x, a.y))),
        (point(30.0), -30.0f32..30.0).prop_map(|(a, y)| Segment::new(a, Vec2::new(a.x, y))),
        point(30.0).prop_map(|a| Segment::new(a, a)),
    ]
}

pub mod lines;
