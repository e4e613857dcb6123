//! The DDA (digital differential analyzer) line with colour and depth
//! interpolation: TU Wien "Rasterisierung" sheet (seed 004), §4.2–4.3.
//!
//! Convention (see `canvas`): pixel centres at integers, y up, rounding
//! half away from zero; the line covers one pixel per column of its major
//! axis, from the column of the first endpoint to that of the last,
//! both included.

#[allow(unused_imports)]
use canvas::{Fragment, Pixel, Vertex, round_half_away, within_limits};

/// Rasterizes the line from `from` to `to` with the DDA and calls `plot`
/// once per pixel, in order from `from` to `to`.
///
/// ```text
///   minor                       one pixel per major column:
///     ^        · · ·■■          major = the axis with the larger |Δ|
///     |    · ·■■■ · ·           minor += slope each column, then round
///     |  ■■■ · · · · ·          (|slope| ≤ 1, so the pixels touch)
///     +-----------------> major
/// ```
///
/// - The major axis is x when `|Δx| ≥ |Δy|`, else y. The columns run from
///   `round(from.major)` to `round(to.major)`; in each column `X` the minor
///   coordinate is the ideal line's, `from.minor + slope · (X − from.major)`,
///   rounded half away from zero.
/// - Colour and depth are mixed with `t = (X − from.major) / Δmajor`, the
///   distance of the column from the first endpoint over the line's length,
///   clamped to `[0, 1]` (the rounded first column can lie up to half a
///   pixel before the endpoint). With integer endpoints the first fragment
///   has exactly `from`'s colour and depth and the last exactly `to`'s.
/// - The sum `minor += slope` is kept in `f64`: in `f32` its rounding
///   errors add up over a long line (millions of columns within
///   ±`MAX_COORD`) to thousands of pixels off the line.
/// - A zero-length line plots one fragment with `from`'s attributes.
/// - Endpoints that are not finite or lie beyond ±`MAX_COORD` draw nothing.
#[transcript::task]
pub fn dda_line(from: &Vertex, to: &Vertex, mut plot: impl FnMut(Fragment)) {
    // Unused until you write the body:
    let _ = (&from, &to, &mut plot);
    todo!(
        "dda: plot one fragment per major-axis column, interpolating colour and depth with t in [0, 1]"
    )
}
