//! The DDA (digital differential analyzer) line with colour and depth
//! interpolation: TU Wien "Rasterisierung" sheet (seed 004), §4.2–4.3.
//!
//! Convention (see `canvas`): pixel centres at integers, y up, rounding
//! half away from zero; the line covers one pixel per column of its major
//! axis, from the column of the first endpoint to that of the last,
//! both included.

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
    // BEGIN SOLUTION dda: plot one fragment per major-axis column, interpolating colour and depth with t in [0, 1]
    let (a, b) = (from.position, to.position);
    if ![a.x, a.y, b.x, b.y].into_iter().all(within_limits) {
        return;
    }
    let d = b - a;
    let x_major = d.x.abs() >= d.y.abs();
    // Work in (major, minor) coordinates so that one loop serves all octants.
    let (a_major, a_minor, d_major, d_minor) = if x_major {
        (a.x, a.y, d.x, d.y)
    } else {
        (a.y, a.x, d.y, d.x)
    };
    if d_major == 0.0 {
        plot(Fragment {
            pixel: Pixel::new(round_half_away(a.x), round_half_away(a.y)),
            depth: from.depth,
            colour: from.colour,
        });
        return;
    }
    // |slope| ≤ 1; in f64, so that adding it once per column stays exact
    // enough over the longest lines.
    let slope = f64::from(d_minor) / f64::from(d_major);
    let step = if d_major > 0.0 { 1 } else { -1 };
    let first = round_half_away(a_major);
    let last = round_half_away(a_major + d_major);
    let mut major = first;
    // The ideal line's minor coordinate at the first column's centre.
    let mut minor = f64::from(a_minor) + slope * (f64::from(first) - f64::from(a_major));
    loop {
        let t = ((major as f32 - a_major) / d_major).clamp(0.0, 1.0);
        // Half away from zero, as `round_half_away`; within the limits.
        #[allow(clippy::cast_possible_truncation)]
        let rounded = minor.round() as i32;
        let pixel = if x_major {
            Pixel::new(major, rounded)
        } else {
            Pixel::new(rounded, major)
        };
        plot(Fragment {
            pixel,
            depth: from.depth * (1.0 - t) + to.depth * t,
            colour: from.colour.lerp(to.colour, t),
        });
        if major == last {
            break;
        }
        major += step;
        minor += slope * f64::from(step);
    }
    // END SOLUTION
}
