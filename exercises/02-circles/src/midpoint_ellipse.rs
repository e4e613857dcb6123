//! The midpoint ellipse in two regions, in integer arithmetic: the lecture
//! slides name ellipses among the "weitere Bresenham-Algorithmen" (seed
//! 002); the two regions follow Van Aken (1984) and Foley et al.,
//! *Computer Graphics*, §3.4, with the change of region chosen so that
//! equal semi-axes give exactly the midpoint circle.
//!
//! Convention (see `canvas`): pixel centres at integers, y up; in region 1
//! the pixel nearest to the ellipse in each column, in region 2 in each
//! row; a midpoint exactly on the ellipse picks the inner pixel; the other
//! three quadrants are mirror images; every pixel is plotted once.

#[allow(unused_imports)]
use canvas::{MAX_COORD, Pixel};

/// The largest semi-axis [`midpoint_ellipse`] draws.
///
/// Its exact region test squares numbers of up to `2·20 + 21` bits, and
/// the square must fit an `i128`; larger ellipses plot nothing.
pub const MAX_SEMI_AXIS: i32 = 1 << 20;

/// Rasterizes the ellipse around `centre` with semi-axes `a` (along x) and
/// `b` (along y) and calls `plot` once per pixel, in no particular order.
///
/// With offsets `(x, y)` from the centre the ellipse is
/// `F(x, y) = b²x² + a²y² − a²b² = 0`, negative inside. In the first
/// quadrant the ellipse falls from `(0, b)` to `(a, 0)`; where its slope is
/// flatter than −1 it needs one pixel per column, where it is steeper one
/// per row. The other quadrants are mirror images `(±x, ±y)` (a zero
/// coordinate is not negated).
///
/// ```text
///    y
///    b ■■■■■■■■                     region 1: from (0, b), one pixel per
///      │       ■■■■                 column, steps E or SE
///      │           ■■■       ╱
///      │              ■■   ╱        the slope is −1 where the ellipse
///      │                ■╱          crosses the line a²y = b²x
///      │               ╱■
///      │           ╱    ■           region 2: from (a, 0), one pixel per
///      │       ╱        ■           row, steps N or NW: region 1 of the
///      │   ╱            ■           ellipse mirrored at the diagonal
///    0 ┼╱───────────────■──> x
///                       a
/// ```
///
/// **Region 1.** `d = 4·F(M)` at the midpoint `M = (x + 1, y − ½)` below the
/// next column's upper candidate (the factor 4 clears the halves):
///
/// ```text
///   start (0, b):  d = 4b² + a²(1 − 4b)
///   d < 0 → E:     d += 4b²(2x + 3)
///   d ≥ 0 → SE:    d += 4b²(2x + 3) − 8a²(y − 1)      (x, y before the step)
/// ```
///
/// `d = 0` (the midpoint on the ellipse) takes SE, the inner pixel, as the
/// circle's `d ≥ 0` does. Region 1 holds column `x` while the ellipse, in
/// that column, runs above the slope −1 line `a²y = b²x` lowered by half a
/// pixel; exactly, in integers (and only for `x ≤ a`):
///
/// ```text
///   2b²x − a² < 0   or   (2b²x − a²)² < 4a²b²(a² − x²)
/// ```
///
/// For a circle (`a = b = R`) this is `√(R² − x²) > x − ½`, which is the
/// slides' "while `y > x`": equal semi-axes give the midpoint circle.
///
/// A flat ellipse, exactly when `a > 2b²`, reaches the x axis while still
/// in region 1, which then runs to column `a`; on the axis region 1 steps
/// E only. (The midpoint `(x + 1, −½)` lies below the axis, where `F`
/// measures the mirror image: its sign says nothing about the upper half.)
///
/// **Region 2** is region 1 with x and y, and a and b, swapped: from
/// `(a, 0)` up, one pixel per row. The two regions meet diagonally or
/// share their last pixel, which is plotted once.
///
/// **Limits.** Semi-axis 0 draws the segment along the other axis (both 0:
/// the centre). A negative semi-axis, one beyond [`MAX_SEMI_AXIS`], or an
/// ellipse reaching beyond ±[`MAX_COORD`] plots nothing. The arithmetic is
/// `i128`: `a²b²` alone needs 80 bits.
#[transcript::task]
pub fn midpoint_ellipse(centre: Pixel, a: i32, b: i32, mut plot: impl FnMut(Pixel)) {
    // Unused until you write the body:
    let _ = (&centre, &a, &b, &mut plot);
    todo!("midpoint_ellipse: region 1 by columns from (0, b), region 2 by rows from (a, 0)")
}
