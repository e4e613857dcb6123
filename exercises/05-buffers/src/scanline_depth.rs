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
    // Unused until you write the body:
    let _ = (&triangle, &ys);
    todo!(
        "scanline_depth: pick vertex 1 and the edges 1–2, 1–3 crossing ys, then apply the z_a, z_b (and x_a, x_b) formulas"
    )
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
    // Unused until you write the body:
    let _ = (&span, &x_p);
    todo!("scanline_depth: apply the z_p formula; return z_a for a span of zero width")
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
        // Unused until you write the body:
        let _ = &triangle;
        todo!(
            "scanline_depth: the normal is the cross product of two edges, D = −normal · V0; reject C = 0"
        )
    }

    /// `z(x, y) = (−A·x − B·y − D) / C`.
    #[must_use]
    #[transcript::task]
    pub fn depth_at(&self, p: DVec2) -> f64 {
        // Unused until you write the body:
        let _ = &p;
        todo!("scanline_depth: solve the plane equation for z")
    }

    /// The constant `A/C` that one step to the right subtracts:
    /// `z(x + 1, y) = z(x, y) − A/C`.
    #[must_use]
    #[transcript::task]
    pub fn step_x(&self) -> f64 {
        todo!("scanline_depth: the x step of the plane equation")
    }

    /// The constant `B/C` that one step up subtracts:
    /// `z(x, y + 1) = z(x, y) − B/C`.
    #[must_use]
    #[transcript::task]
    pub fn step_y(&self) -> f64 {
        todo!("scanline_depth: the y step of the plane equation")
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
    // Unused until you write the body:
    let _ = (&plane, &y, &first_x, &count);
    todo!("scanline_depth: evaluate the plane once at the first pixel, then subtract A/C per step")
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
    // Unused until you write the body:
    let _ = (&plane, &first_y, &first_xs);
    todo!(
        "scanline_depth: evaluate the plane once at the first row's start, then per row subtract A/C times the columns moved and B/C"
    )
}
