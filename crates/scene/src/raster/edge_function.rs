//! Triangle fill with edge functions and barycentric interpolation: sheet,
//! sections 6.2 and 6.3.
//!
//! Convention: pixel centres at integers; a centre exactly on an edge is
//! inside (the sheet's `O_i ≤ 0`), so pixels on an edge shared by two
//! triangles are drawn by both and the depth test keeps the first.
//!
//! [`cover`] finds a triangle's pixels and their barycentric weights; the
//! pipeline's [`fill_triangle`] and the surface topics' renderers
//! interpolate and write what they need with it.

use canvas::{Canvas, Fragment, Pixel, Vertex, Viewport};
use glam::DVec2;

use super::{depth_test, drawable};

/// The edge function of the edge `a → b` at `p`: twice the signed area of
/// the triangle `a, b, p`, positive when `p` lies to the left of the edge
/// (counter-clockwise, y up). It is the sheet's `O(x, y) = A·x + B·y + C`
/// with `(A, B) = (−e_y, e_x)`, the edge's normal, and `e = b − a`
/// (equations (9) to (11)), written as one cross product.
fn edge(a: DVec2, b: DVec2, p: DVec2) -> f64 {
    (b - a).perp_dot(p - a)
}

/// The pixels of the triangle `corners` inside `viewport` (inclusive
/// bounds), each with its barycentric weights: `visit(pixel, [α, β, γ])`
/// for every pixel centre `P` with `α, β, γ ≥ 0`, row by row from the
/// bottom, left to right. This is the one triangle rasterizer of the
/// course's given code; what is interpolated, and how a fragment is
/// tested and written, is the caller's.
///
/// For each pixel centre `P` in the triangle's bounding box (clamped to
/// the viewport) it evaluates the three edge functions `O_1` (edge
/// `V2 → V3`), `O_2` (`V3 → V1`), `O_3` (`V1 → V2`) and divides each by
/// twice the signed area `A = O_3(V3)`:
///
/// ```text
///   α = O_1(P) / A,   β = O_2(P) / A,   γ = O_3(P) / A,   α + β + γ = 1
/// ```
///
/// (equation (12)); `P` is inside when all three are `≥ 0`, so a centre
/// on an edge is inside for both triangles that share it (no fill rule:
/// a depth test keeps one). A value `v` interpolated at `P` is
/// `α·v1 + β·v2 + γ·v3`, linear in screen space (no perspective
/// correction, as in the sheet).
///
/// Both windings are covered (dividing by `A`, which has the winding's
/// sign, makes the weights positive inside either way). A triangle with a
/// zero or non-finite area, or with a coordinate beyond
/// ±[`canvas::MAX_COORD`], covers nothing; the work is bounded by the
/// viewport's size, however large the triangle.
pub fn cover(corners: [DVec2; 3], viewport: Viewport, mut visit: impl FnMut(Pixel, [f64; 3])) {
    let limit = f64::from(canvas::MAX_COORD);
    if viewport.is_empty() || !corners.iter().all(|p| p.abs().max_element() <= limit) {
        return;
    }
    let [p1, p2, p3] = corners;
    let area = edge(p1, p2, p3);
    if area == 0.0 || !area.is_finite() {
        return;
    }
    let lo = p1.min(p2).min(p3).ceil().max(DVec2::new(
        f64::from(viewport.x_min),
        f64::from(viewport.y_min),
    ));
    let hi = p1.max(p2).max(p3).floor().min(DVec2::new(
        f64::from(viewport.x_max),
        f64::from(viewport.y_max),
    ));
    if !(lo.x <= hi.x && lo.y <= hi.y) {
        return;
    }
    for y in lo.y as i32..=hi.y as i32 {
        for x in lo.x as i32..=hi.x as i32 {
            let p = DVec2::new(f64::from(x), f64::from(y));
            let weights = [
                edge(p2, p3, p) / area,
                edge(p3, p1, p) / area,
                edge(p1, p2, p) / area,
            ];
            if weights.iter().all(|&w| w >= 0.0) {
                visit(Pixel::new(x, y), weights);
            }
        }
    }
}

/// Fills the triangle `v1 v2 v3` with colour and depth interpolated by
/// barycentric coordinates, depth-tested: the pixels [`cover`] finds on
/// the canvas, each written by [`depth_test`].
///
/// Both windings are filled. A degenerate triangle (zero area) and one with
/// a vertex that is not finite or lies beyond ±[`canvas::MAX_COORD`] draw
/// nothing. Edge functions are evaluated in `f64`, so that coordinates up to
/// `MAX_COORD` keep their precision.
pub fn fill_triangle(canvas: &mut Canvas, [v1, v2, v3]: [Vertex; 3]) {
    if !(drawable(&v1) && drawable(&v2) && drawable(&v3)) {
        return;
    }
    let corners = [v1, v2, v3].map(|v| v.position.as_dvec2());
    let viewport = canvas.viewport();
    cover(corners, viewport, |pixel, weights| {
        let [alpha, beta, gamma] = weights.map(|w| w as f32);
        depth_test(
            canvas,
            Fragment {
                pixel,
                depth: v1.depth * alpha + v2.depth * beta + v3.depth * gamma,
                colour: v1.colour * alpha + v2.colour * beta + v3.colour * gamma,
            },
        );
    });
}
