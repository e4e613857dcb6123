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
    // BEGIN SOLUTION midpoint_ellipse: region 1 by columns from (0, b), region 2 by rows from (a, 0)
    let reach = |c: i32, r: i32| i64::from(c).abs() + i64::from(r);
    if a < 0
        || b < 0
        || a > MAX_SEMI_AXIS
        || b > MAX_SEMI_AXIS
        || reach(centre.x, a) > i64::from(MAX_COORD)
        || reach(centre.y, b) > i64::from(MAX_COORD)
    {
        return;
    }
    let mut four = |x: i32, y: i32| {
        plot(Pixel::new(centre.x + x, centre.y + y));
        if x != 0 {
            plot(Pixel::new(centre.x - x, centre.y + y));
        }
        if y != 0 {
            plot(Pixel::new(centre.x + x, centre.y - y));
        }
        if x != 0 && y != 0 {
            plot(Pixel::new(centre.x - x, centre.y - y));
        }
    };
    if a == 0 {
        (0..=b).for_each(|y| four(0, y));
        return;
    }
    if b == 0 {
        (0..=a).for_each(|x| four(x, 0));
        return;
    }
    let last = region_one(a, b, &mut |x, y| four(x, y));
    region_one(b, a, &mut |y, x| {
        if (x, y) != last {
            four(x, y);
        }
    });
    // END SOLUTION
}
// BEGIN SOLUTION

/// Region 1 of the ellipse with semi-axes `a` (along x) and `b`: from
/// `(0, b)`, one pixel per column while the region test holds. Calls
/// `plot(x, y)` with first-quadrant offsets and returns the last pixel.
fn region_one(a: i32, b: i32, plot: &mut impl FnMut(i32, i32)) -> (i32, i32) {
    let (a2, b2) = (i128::from(a).pow(2), i128::from(b).pow(2));
    // Column x lies in region 1 while the ellipse there is above the line
    // a²y = b²x lowered by ½: 2ab·√(a² − x²) > 2b²x − a².
    let in_region = |x: i32| {
        let x = i128::from(x);
        let lowered = 2 * b2 * x - a2;
        x <= i128::from(a) && (lowered < 0 || lowered * lowered < 4 * a2 * b2 * (a2 - x * x))
    };
    let (mut x, mut y) = (0, b);
    let mut d = 4 * b2 + a2 * (1 - 4 * i128::from(b));
    plot(x, y);
    while in_region(x + 1) {
        let (xi, yi) = (i128::from(x), i128::from(y));
        if d < 0 || y == 0 {
            // On the axis the walk stays there (see "A flat ellipse" above).
            d += 4 * b2 * (2 * xi + 3);
        } else {
            d += 4 * b2 * (2 * xi + 3) - 8 * a2 * (yi - 1);
            y -= 1;
        }
        x += 1;
        plot(x, y);
    }
    (x, y)
}
// END SOLUTION
