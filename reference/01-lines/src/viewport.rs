//! Starting and ending a midpoint line at the viewport border without
//! rounding the slope: lecture slides "Schnittpunkt mit Viewport"
//! (seed 002), after Foley et al., *Computer Graphics*, §3.2.3.
//!
//! Convention (see `canvas`): pixel centres at integers, y up; the pixels
//! drawn are exactly those of `midpoint_line(from, to)` that lie inside
//! the viewport (bounds inclusive), ties to the smaller minor coordinate.

use canvas::{Pixel, Viewport};

/// Draws the part of the midpoint line from `from` to `to` that lies inside
/// `viewport`, calling `plot` once per visible pixel in order from `from`
/// to `to`; any `i32` endpoints are allowed.
///
/// Clipping the line first and rasterizing the clipped piece would round
/// the intersection points and change the slope, so the pixels would no
/// longer be the original line's. Instead the loop *starts* at the first
/// visible column with the decision variable the original line has there:
///
/// ```text
///   y_max + ½ ┄┄┄┄┄┄┄┄┄┄┄┄┄┄┄┄┄┄┄┄╱┄┄  last row y_max: the line is
///             ┃               ■■■╱      still below y_max + ½
///             ┃         ■■■■■  ╱
///             ┃   ■■■■■      ╱          first row y_min: the first
///   y_min − ½ ┄┄┄┄┄┄┄┄┄┄┄┄╱┄┄┄┄┄┄┄┄┄┄  column where the line is above
///                      ╱                y_min − ½ (not y_min!)
/// ```
///
/// A left/right border gives the first/last column directly; a bottom/top
/// border is intersected with `y_min − ½` / `y_max + ½` (for a steep line
/// the roles of x and y swap). Only the visible columns are visited, so a
/// line billions of pixels long costs no more than its visible part.
#[transcript::task]
pub fn clipped_midpoint_line(
    from: Pixel,
    to: Pixel,
    viewport: Viewport,
    mut plot: impl FnMut(Pixel),
) {
    // BEGIN SOLUTION viewport: compute the first and last visible column and the decision variable there, then step only through the visible part
    if viewport.is_empty() {
        return;
    }
    let (dx, dy) = (
        i64::from(to.x) - i64::from(from.x),
        i64::from(to.y) - i64::from(from.y),
    );
    let (sx, sy) = (if dx < 0 { -1 } else { 1 }, if dy < 0 { -1 } else { 1 });
    let x_major = dx.abs() >= dy.abs();
    let (long, short) = if x_major {
        (dx.abs(), dy.abs())
    } else {
        (dy.abs(), dx.abs())
    };
    let diagonal_on_tie = if x_major { sy < 0 } else { sx < 0 };
    // In first-octant terms the line's pixels are (i, j(i)) for i in
    // 0..=long, with j(i) the row nearest to i·short/long. Translate the
    // viewport into ranges of i and j: along an axis with sign s starting at
    // c, coordinate v = c + s·k, so k ranges over (lo − c)·s ..= (hi − c)·s.
    let range = |c: i32, s: i64, lo: i32, hi: i32| {
        let (a, b) = (
            (i64::from(lo) - i64::from(c)) * s,
            (i64::from(hi) - i64::from(c)) * s,
        );
        (a.min(b), a.max(b))
    };
    let (x_range, y_range) = (
        range(from.x, sx, viewport.x_min, viewport.x_max),
        range(from.y, sy, viewport.y_min, viewport.y_max),
    );
    let ((i_lo, i_hi), (j_lo, j_hi)) = if x_major {
        (x_range, y_range)
    } else {
        (y_range, x_range)
    };
    // The first i whose row is at least j_lo: where the ideal line crosses
    // j_lo − ½, in exact integer arithmetic (2·i·short against
    // (2·j_lo − 1)·long); a crossing exactly at the half is a tie.
    // Likewise the last i whose row is at most j_hi crosses j_hi + ½.
    let (mut first, mut last) = (i_lo.max(0), i_hi.min(long));
    if short == 0 {
        if !(j_lo..=j_hi).contains(&0) {
            return;
        }
    } else {
        let (long, short) = (i128::from(long), i128::from(short));
        let below = (2 * i128::from(j_lo) - 1) * long;
        let above = (2 * i128::from(j_hi) + 1) * long;
        // Row j(i) ≥ j_lo ⇔ 2·i·short > below (or ≥ when ties go up).
        let i_min = if diagonal_on_tie {
            div_ceil(below, 2 * short)
        } else {
            below.div_euclid(2 * short) + 1
        };
        // Row j(i) ≤ j_hi ⇔ 2·i·short ≤ above (or < when ties go up).
        let i_max = if diagonal_on_tie {
            div_ceil(above, 2 * short) - 1
        } else {
            above.div_euclid(2 * short)
        };
        first = first.max(i_min.clamp(0, long + 1) as i64);
        last = last.min(i_max.clamp(-1, long) as i64);
    }
    if first > last {
        return;
    }
    // The row at the first visible column, rounded to nearest with the tie
    // rule, and the decision variable of the midpoint after it:
    // d = 2·short·(i + 1) − long·(2j + 1).
    let (l, s) = (i128::from(long), i128::from(short));
    let twice = 2 * i128::from(first) * s; // 2·i·short = 2·long·(ideal row)
    let mut j = if diagonal_on_tie {
        (twice + l).div_euclid(2 * l)
    } else {
        div_ceil(twice - l, 2 * l)
    } as i64;
    let mut d = (2 * s * (i128::from(first) + 1) - l * (2 * i128::from(j) + 1)) as i64;
    let pixel = |i: i64, j: i64| {
        let (major, minor) = (
            i * if x_major { sx } else { sy },
            j * if x_major { sy } else { sx },
        );
        let (px, py) = if x_major {
            (major, minor)
        } else {
            (minor, major)
        };
        Pixel::new(
            (i64::from(from.x) + px) as i32,
            (i64::from(from.y) + py) as i32,
        )
    };
    let mut i = first;
    loop {
        plot(pixel(i, j));
        if i == last {
            break;
        }
        if d > 0 || (d == 0 && diagonal_on_tie) {
            j += 1;
            d += 2 * (short - long);
        } else {
            d += 2 * short;
        }
        i += 1;
    }
    // END SOLUTION
}

// BEGIN SOLUTION
/// `⌈a / b⌉` for `b > 0`, rounding towards +∞ also for negative `a`.
fn div_ceil(a: i128, b: i128) -> i128 {
    -(-a).div_euclid(b)
}
// END SOLUTION
