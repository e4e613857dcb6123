//! Depth along a scanline, two ways (seed 002, §6.2 "Z-Wert-Bestimmung"
//! and "Z-Wert-Bestimmung: Beschleunigung"): by interpolation between the
//! scanline's intersections with two edges, and incrementally from the
//! plane equation.
//!
//! Convention (see `canvas`): pixel centres at integers, y up; scanline
//! `y` runs through the centres of row `y`. Everything is in `f64`
//! (`DVec3` = `(x, y, z)`), so that the two ways agree to ~1e-12.
//!
//! ```text
//!   ys ≥ y_mid: vertex 1 is hi           ys < y_mid: vertex 1 is lo
//!   (y up: the top of the drawing is the largest y)
//!
//!          1 = hi                               3 = hi
//!         / \                                  / \
//!      a /-p-\ b   ← ys                       /   \
//!       /     \                              /     \
//!      2 .     \                            2 .     \
//!   = mid  .    \                        = mid  . a-p-\ b   ← ys
//!             .  3 = lo                            .  1 = lo
//!
//!   a on the short edge 1–2, b on the long edge 1–3, p between them;
//!   the dotted edge is the one the scanline does not cross.
//! ```

use glam::{DVec2, DVec3};

/// Why a triangle has no depth plane.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum ScanlineError {
    /// A coordinate is NaN or infinite.
    #[error("a vertex coordinate is not finite")]
    NotFinite,
    /// The triangle's projection has zero area (`C = 0`: it is seen edge
    /// on, and `z(x, y)` is not a function).
    #[error("the triangle is degenerate in x and y (C = 0)")]
    Degenerate,
}

/// The two ends of the span where a scanline crosses a triangle: the
/// points `a` (on the short edge 1–2) and `b` (on the long edge 1–3), with
/// the seed's names, each with its depth. (The pixels between them are a
/// [`canvas::Span`]; this is the continuous crossing they come from.)
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpanEnds {
    /// The scanline's `y`.
    pub y: f64,
    /// `(x_a, z_a)`: the crossing with edge 1–2.
    pub a: DVec2,
    /// `(x_b, z_b)`: the crossing with edge 1–3.
    pub b: DVec2,
}

/// The span of `triangle` on the scanline `ys`, by the seed's formulas
///
/// ```text
///   z_a = z1 − (z1 − z2) · (y1 − ys) / (y1 − y2)      x_a likewise with x
///   z_b = z1 − (z1 − z3) · (y1 − ys) / (y1 − y3)      x_b likewise with x
/// ```
///
/// **Which vertex is 1.** Sort the vertices by `y` into `lo ≤ mid ≤ hi`.
/// The long edge `lo–hi` crosses every scanline of the triangle; the short
/// edge is `lo–mid` below `mid` and `mid–hi` from `mid` up. Vertex 1 is the
/// end the two crossed edges share: for `ys < mid.y` it is `lo` (2 = `mid`,
/// 3 = `hi`); for `ys ≥ mid.y` it is `hi` (2 = `mid`, 3 = `lo`). When
/// `lo.y = mid.y` (a flat bottom) the second case covers every scanline,
/// so `y1 − y2` is never 0; the seed leaves this choice open. A flat top
/// (`mid.y = hi.y`) at its own scanline `ys = hi.y` has the horizontal
/// edge 1–2 itself as the crossing: `a` is then vertex 2 (`mid`).
///
/// `None` when `ys` lies outside `[lo.y, hi.y]`, when the triangle has no
/// height (`lo.y = hi.y`) or when any input is not finite.
#[must_use]
#[transcript::task]
pub fn span_at(triangle: [DVec3; 3], ys: f64) -> Option<SpanEnds> {
    // BEGIN SOLUTION scanline_depth: pick vertex 1 and the edges 1–2, 1–3 crossing ys, then apply the z_a, z_b (and x_a, x_b) formulas
    if !ys.is_finite() || !triangle.iter().all(|v| v.is_finite()) {
        return None;
    }
    let mut v = triangle;
    v.sort_by(|p, q| p.y.total_cmp(&q.y));
    let [lo, mid, hi] = v;
    if lo.y == hi.y || ys < lo.y || ys > hi.y {
        return None;
    }
    let (v1, v2, v3) = if ys < mid.y {
        (lo, mid, hi)
    } else {
        (hi, mid, lo)
    };
    // The seed's formula for both coordinates at once: the point at
    // parameter (y1 − ys)/(y1 − yk) on the edge from vertex 1 to vertex k.
    // A horizontal edge 1–k (a flat top at its own scanline) is crossed
    // along its whole length: take its far end, vertex k.
    let cross = |vk: DVec3| {
        let s = if v1.y == vk.y {
            1.0
        } else {
            (v1.y - ys) / (v1.y - vk.y)
        };
        DVec2::new(v1.x - (v1.x - vk.x) * s, v1.z - (v1.z - vk.z) * s)
    };
    Some(SpanEnds {
        y: ys,
        a: cross(v2),
        b: cross(v3),
    })
    // END SOLUTION
}

/// The depth at `x_p` on a span, by the seed's formula
///
/// ```text
///   z_p = z_b − (z_b − z_a) · (x_b − x_p) / (x_b − x_a)
/// ```
///
/// `x_p = x_b` gives `z_b` and `x_p = x_a` gives `z_a`. When the span has
/// no width (`x_a = x_b`, at a vertex) the formula divides by zero — a
/// case the seed does not mention — and `z_a` is returned.
#[must_use]
#[transcript::task]
pub fn depth_in_span(span: &SpanEnds, x_p: f64) -> f64 {
    // BEGIN SOLUTION scanline_depth: apply the z_p formula; return z_a for a span of zero width
    let (a, b) = (span.a, span.b);
    if a.x == b.x {
        return a.y;
    }
    b.y - (b.y - a.y) * (b.x - x_p) / (b.x - a.x)
    // END SOLUTION
}

/// The plane `A·x + B·y + C·z + D = 0` through a triangle, solved for
/// `z(x, y) = (−A·x − B·y − D) / C` (seed: "Ebenengleichung").
///
/// `(A, B, C)` is a normal of the plane (the cross product of two edges),
/// `D = −(A, B, C) · V0`. Only the ratios `A/C`, `B/C`, `D/C` matter. (The
/// seed calls `D` "Abstand vom Ursprung": that holds only for a normal of
/// length 1; here the normal is not normalized, and need not be.)
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DepthPlane {
    /// The normal `(A, B, C)`; `C ≠ 0`.
    pub normal: DVec3,
    /// The offset `D`.
    pub d: f64,
}

impl DepthPlane {
    /// The plane through the three vertices: `(A, B, C) = (V1 − V0) × (V2 −
    /// V0)` and `D = −(A, B, C) · V0`.
    ///
    /// An error when a coordinate is not finite or `C = 0` (the triangle's
    /// projection onto the screen has no area).
    #[transcript::task]
    pub fn try_from_triangle(triangle: [DVec3; 3]) -> Result<Self, ScanlineError> {
        // BEGIN SOLUTION scanline_depth: the normal is the cross product of two edges, D = −normal · V0; reject C = 0
        if !triangle.iter().all(|v| v.is_finite()) {
            return Err(ScanlineError::NotFinite);
        }
        let [v0, v1, v2] = triangle;
        let normal = (v1 - v0).cross(v2 - v0);
        if normal.z == 0.0 || !normal.is_finite() {
            return Err(ScanlineError::Degenerate);
        }
        Ok(Self {
            normal,
            d: -normal.dot(v0),
        })
        // END SOLUTION
    }

    /// `z(x, y) = (−A·x − B·y − D) / C`.
    #[must_use]
    #[transcript::task]
    pub fn depth_at(&self, p: DVec2) -> f64 {
        // BEGIN SOLUTION scanline_depth: solve the plane equation for z
        let n = self.normal;
        (-n.x * p.x - n.y * p.y - self.d) / n.z
        // END SOLUTION
    }

    /// The constant `A/C` that one step to the right subtracts:
    /// `z(x + 1, y) = z(x, y) − A/C`.
    #[must_use]
    #[transcript::task]
    pub fn step_x(&self) -> f64 {
        // BEGIN SOLUTION scanline_depth: the x step of the plane equation
        self.normal.x / self.normal.z
        // END SOLUTION
    }

    /// The constant `B/C` that one step up subtracts:
    /// `z(x, y + 1) = z(x, y) − B/C`.
    #[must_use]
    #[transcript::task]
    pub fn step_y(&self) -> f64 {
        // BEGIN SOLUTION scanline_depth: the y step of the plane equation
        self.normal.y / self.normal.z
        // END SOLUTION
    }
}

/// The depths of `count` pixels of row `y`, starting at column `first_x`,
/// computed incrementally: `z(first_x, y)` from the plane equation, then
/// `z(x + 1, y) = z(x, y) − A/C` — one subtraction per pixel.
///
/// Rounding errors add up along the row: after `n` steps the result may
/// differ from [`DepthPlane::depth_at`] by about `n` units in the last
/// place of the largest value involved. The caller chooses `count` (a
/// span of the canvas): the result holds `count` values.
#[must_use]
#[transcript::task]
pub fn incremental_depths(plane: &DepthPlane, y: i32, first_x: i32, count: usize) -> Vec<f64> {
    // BEGIN SOLUTION scanline_depth: evaluate the plane once at the first pixel, then subtract A/C per step
    let step = plane.step_x();
    let mut z = plane.depth_at(DVec2::new(f64::from(first_x), f64::from(y)));
    let mut depths = Vec::with_capacity(count);
    for _ in 0..count {
        depths.push(z);
        z -= step;
    }
    depths
    // END SOLUTION
}

/// The depth of the first pixel of each row of a triangle, each found
/// from the row below it (seed: "Gleiches gilt für die Berechnung des
/// ersten z-Wertes der darauffolgenden Scanline!"): row `k` is
/// `y = first_y + k` and starts at column `first_xs[k]` (where the left
/// edge crosses it, as the fill finds it), and
///
/// ```text
///   z_0     = z(first_xs[0], first_y)                (the plane equation, once)
///   z_{k+1} = z_k − A/C · (x_{k+1} − x_k) − B/C      (evaluated left to right)
/// ```
///
/// One step up subtracts `B/C`; the new row's start lies `x_{k+1} − x_k`
/// columns to the side, which subtracts `A/C` per column, as along a row.
/// Together with [`incremental_depths`] every depth of the triangle comes
/// from one evaluation of the plane. The result holds one depth per entry
/// of `first_xs` (none for an empty slice). Rounding adds up over the
/// rows as it does along a row.
#[must_use]
#[transcript::task]
pub fn row_start_depths(plane: &DepthPlane, first_y: i32, first_xs: &[i32]) -> Vec<f64> {
    // BEGIN SOLUTION scanline_depth: evaluate the plane once at the first row's start, then per row subtract A/C times the columns moved and B/C
    let Some((&x0, rest)) = first_xs.split_first() else {
        return Vec::new();
    };
    let (step_x, step_y) = (plane.step_x(), plane.step_y());
    let mut z = plane.depth_at(DVec2::new(f64::from(x0), f64::from(first_y)));
    let mut depths = Vec::with_capacity(first_xs.len());
    depths.push(z);
    let mut x = x0;
    for &next in rest {
        z = z - step_x * (f64::from(next) - f64::from(x)) - step_y;
        depths.push(z);
        x = next;
    }
    depths
    // END SOLUTION
}
