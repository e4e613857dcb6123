//! Wu's antialiased line (Xiaolin Wu, "An efficient antialiasing
//! technique", SIGGRAPH 1991): lecture slides "Anti-Aliasing: Wu-Methode"
//! (seed 002), with the integer error accumulator of Abrash's formulation.
//!
//! Convention (see `canvas`): pixel centres at integers, y up; each column
//! of the major axis gets the two pixels that straddle the ideal line,
//! weighted by how near each is; both endpoints are drawn at full
//! intensity.

#[allow(unused_imports)]
use canvas::{MAX_COORD, Pixel};

/// Draws the antialiased line from `from` to `to` and calls
/// `plot(pixel, intensity)` for the two pixels of each major-axis column
/// that straddle the ideal line (one pixel for the first and last
/// columns, and for axis-parallel and diagonal lines).
///
/// ```text
///   row j+1  ·  ·  ▒  ▓  the ideal line passes row j + f in each
///   ────────────────────  column: row j gets 1 − f, row j + 1 gets f,
///   row j    ■  ▓  ▒  ·  so every column sums to exactly 1
/// ```
///
/// The fraction `f` lives in an unsigned error accumulator, a "0.64"
/// fixed-point number: each column adds `⌈Δminor / Δmajor · 2⁶⁴⌉`, and an
/// overflow (wrap-around) is the step to the next row. The intensity is
/// the accumulator's top 8 bits, as in Wu's original. (Wu used 16 bits;
/// 64 keep the accumulated rounding error below `Δmajor / 2⁶⁴`, so a line
/// through a pixel centre lands on it exactly.)
///
/// Endpoints beyond ±[`MAX_COORD`] draw nothing.
pub fn wu_line(from: Pixel, to: Pixel, mut plot: impl FnMut(Pixel, f32)) {
    // Unused until you write the body:
    let _ = (&from, &to, &mut plot);
    todo!(
        "wu: accumulate the fractional minor coordinate in an unsigned fixed-point error, stepping a row on wrap-around, and split each column between two pixels"
    )
}
