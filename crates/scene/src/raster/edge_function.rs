//! Triangle fill with edge functions and barycentric interpolation: sheet,
//! sections 6.2 and 6.3.
//!
//! Convention: pixel centres at integers; a centre exactly on an edge is
//! inside (the sheet's `O_i ≤ 0`), so pixels on an edge shared by two
//! triangles are drawn by both and the depth test keeps the first.

use canvas::{Canvas, Fragment, Pixel, Vertex};
use glam::DVec2;

use super::{depth_test, drawable};

/// The line `O(x, y) = A·x + B·y + C` through `from` in the direction
/// `to − from`: `(A, B) = (−e_y, e_x)` is the edge's normal (sheet,
/// equations (9) to (11)).
#[derive(Clone, Copy, Debug)]
struct EdgeFunction {
    a: f64,
    b: f64,
    c: f64,
}

impl EdgeFunction {
    fn through(from: DVec2, to: DVec2) -> Self {
        let e = to - from;
        let (a, b) = (-e.y, e.x);
        Self {
            a,
            b,
            c: -(a * from.x + b * from.y),
        }
    }

    fn at(self, p: DVec2) -> f64 {
        self.a * p.x + self.b * p.y + self.c
    }
}

/// Fills the triangle `v1 v2 v3` with colour and depth interpolated by
/// barycentric coordinates, depth-tested.
///
/// For each pixel centre `P` in the triangle's bounding box (clamped to the
/// canvas) it evaluates the three edge functions `O_1` (edge `V2 → V3`),
/// `O_2` (`V3 → V1`), `O_3` (`V1 → V2`) and the barycentric coordinates
/// `α = O_1(P) / O_1(V1)`, `β = O_2(P) / O_2(V2)`, `γ = O_3(P) / O_3(V3)`
/// (equation (12)); `P` is inside when all three are `≥ 0`. Colour and depth
/// are `α·c1 + β·c2 + γ·c3`, linear in screen space (no perspective
/// correction, as in the sheet).
///
/// Both windings are filled. A degenerate triangle (zero area) and one with
/// a vertex that is not finite or lies beyond ±[`canvas::MAX_COORD`] draw
/// nothing. Edge functions are evaluated in `f64`, so that coordinates up to
/// `MAX_COORD` keep their precision.
pub fn fill_triangle(canvas: &mut Canvas, [v1, v2, v3]: [Vertex; 3]) {
    if !(drawable(&v1) && drawable(&v2) && drawable(&v3)) {
        return;
    }
    let [p1, p2, p3] = [v1, v2, v3].map(|v| v.position.as_dvec2());
    let o1 = EdgeFunction::through(p2, p3);
    let o2 = EdgeFunction::through(p3, p1);
    let o3 = EdgeFunction::through(p1, p2);
    // The sheet's test `O_i(P) ≤ 0` holds inside for one winding only;
    // dividing by `O_i(V_i)`, which has the winding's sign, accepts both.
    let (f1, f2, f3) = (o1.at(p1), o2.at(p2), o3.at(p3));
    if f1 == 0.0 || f2 == 0.0 || f3 == 0.0 {
        return;
    }
    let lo = p1.min(p2).min(p3).ceil().max(DVec2::ZERO);
    let hi = p1
        .max(p2)
        .max(p3)
        .floor()
        .min(DVec2::new(f64::from(canvas.width()), f64::from(canvas.height())) - 1.0);
    if lo.x > hi.x || lo.y > hi.y {
        return;
    }
    for y in lo.y as i32..=hi.y as i32 {
        for x in lo.x as i32..=hi.x as i32 {
            let p = DVec2::new(f64::from(x), f64::from(y));
            let (alpha, beta, gamma) = (o1.at(p) / f1, o2.at(p) / f2, o3.at(p) / f3);
            if alpha < 0.0 || beta < 0.0 || gamma < 0.0 {
                continue;
            }
            let (alpha, beta, gamma) = (alpha as f32, beta as f32, gamma as f32);
            depth_test(
                canvas,
                Fragment {
                    pixel: Pixel::new(x, y),
                    depth: v1.depth * alpha + v2.depth * beta + v3.depth * gamma,
                    colour: v1.colour * alpha + v2.colour * beta + v3.colour * gamma,
                },
            );
        }
    }
}
