//! Wu's antialiased line (Xiaolin Wu, "An efficient antialiasing
//! technique", SIGGRAPH 1991): lecture slides "Anti-Aliasing: Wu-Methode"
//! (seed 002), with the integer error accumulator of Abrash's formulation.
//!
//! Convention (see `canvas`): pixel centres at integers, y up; each column
//! of the major axis gets the two pixels that straddle the ideal line,
//! weighted by how near each is; both endpoints are drawn at full
//! intensity.

use canvas::{MAX_COORD, Pixel};

/// Draws the antialiased line from `from` to `to` and calls
/// `plot(pixel, intensity)` for the two pixels of each major-axis column
/// that straddle the ideal line (one pixel for the first and last
/// columns, and for axis-parallel and diagonal lines), reporting the
/// error accumulator of each column to `error` before its two pixels.
///
/// ```text
///   row j+1  ·  ·  ▒  ▓  the ideal line passes row j + f in each
///   ────────────────────  column: row j gets 1 − f, row j + 1 gets f,
///   row j    ■  ▓  ▒  ·  so every column sums to exactly 1
/// ```
///
/// The fraction `f` lives in an unsigned error accumulator, a "0.64"
/// fixed-point number (a `u64` counting 2⁻⁶⁴ rows) that starts at 0 in
/// `from`'s column: each further column adds `⌈Δminor / Δmajor · 2⁶⁴⌉`
/// (rounded *up*, so that a column where the ideal line passes a pixel
/// centre wraps exactly there), and an addition that overflows (wraps
/// around) is the step to the next row `j`. The intensity is the
/// accumulator's top 8 bits, as in Wu's original: `f = (error >> 56) /
/// 256`, exactly. (Wu used 16 bits; 64 keep the accumulated rounding
/// error below `Δmajor / 2⁶⁴`, so a line through a pixel centre lands on
/// it exactly.)
///
/// **Reporting rule.** In order: `plot(from, 1.0)`; then for each column
/// strictly between the endpoints, `error(e)` with the accumulator `e`
/// just after that column's (wrapping) addition, then the pixel on row
/// `j` with `1 − f`, then the pixel on row `j + 1` with `f` (rows in
/// first-octant terms, counted along the minor axis away from `from`);
/// finally `plot(to, 1.0)`. Axis-parallel and diagonal lines, which pass
/// through every pixel centre, plot one pixel per column at `1.0` and
/// report nothing; a zero-length line plots `from` alone.
///
/// Endpoints beyond ±[`MAX_COORD`] draw nothing.
#[transcript::task]
pub fn wu_line_traced(
    from: Pixel,
    to: Pixel,
    mut plot: impl FnMut(Pixel, f32),
    mut error: impl FnMut(u64),
) {
    // BEGIN SOLUTION wu: accumulate the fractional minor coordinate in a u64 0.64 fixed-point error, stepping a row on wrap-around; report each column's error to `error`, then split the column between two pixels by its top 8 bits
    if [from.x, from.y, to.x, to.y]
        .iter()
        .any(|c| c.unsigned_abs() > MAX_COORD as u32)
    {
        return;
    }
    let (dx, dy) = (i64::from(to.x - from.x), i64::from(to.y - from.y));
    let (sx, sy) = (if dx < 0 { -1 } else { 1 }, if dy < 0 { -1 } else { 1 });
    let x_major = dx.abs() >= dy.abs();
    let (long, short) = if x_major {
        (dx.abs(), dy.abs())
    } else {
        (dy.abs(), dx.abs())
    };
    let pixel = |i: i64, j: i64| {
        let (major, minor) = (i as i32, j as i32);
        if x_major {
            Pixel::new(from.x + sx * major, from.y + sy * minor)
        } else {
            Pixel::new(from.x + sx * minor, from.y + sy * major)
        }
    };
    plot(from, 1.0);
    if long == 0 {
        return;
    }
    if short == 0 || short == long {
        // Axis-parallel and diagonal lines pass through every pixel centre.
        for i in 1..long {
            plot(pixel(i, if short == 0 { 0 } else { i }), 1.0);
        }
        plot(to, 1.0);
        return;
    }
    // short < long, so the step is below 1: a 0.64 fixed-point fraction,
    // rounded up so that reaching a whole row wraps exactly there.
    let error_adjust =
        ((u128::from(short.unsigned_abs()) << 64).div_ceil(u128::from(long.unsigned_abs()))) as u64;
    let mut accumulator = 0_u64;
    let mut j = 0;
    for i in 1..long {
        let wrapped;
        (accumulator, wrapped) = accumulator.overflowing_add(error_adjust);
        if wrapped {
            j += 1;
        }
        error(accumulator);
        // The top 8 bits of the fraction weigh the far pixel (Wu's 8-bit
        // intensities); the near pixel gets the rest.
        let far = (accumulator >> 56) as f32 / 256.0;
        plot(pixel(i, j), 1.0 - far);
        plot(pixel(i, j + 1), far);
    }
    plot(to, 1.0);
    // END SOLUTION
}

/// Draws the antialiased line of [`wu_line_traced`] without its report
/// (given: the viewer and the benchmarks use it).
pub fn wu_line(from: Pixel, to: Pixel, plot: impl FnMut(Pixel, f32)) {
    wu_line_traced(from, to, plot, |_| {});
}
