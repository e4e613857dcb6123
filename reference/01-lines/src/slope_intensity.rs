//! Intensity compensation for the slope of aliased lines: lecture slides
//! "Intensitätsschwankungen" (seed 002).
//!
//! Convention (see `canvas`): an aliased line has one pixel per column of
//! its major axis, whatever its slope.

use canvas::Pixel;

/// The intensity in `(0, 1]` to draw the aliased line from `from` to `to`
/// with, so that lines of every slope show the same ink per unit length.
///
/// A line with `n = max(|Δx|, |Δy|)` steps has `n + 1` pixels whether it
/// is horizontal (length `n`) or diagonal (length `n·√2`), so a diagonal
/// line looks up to `√2` times fainter. Scaling each pixel by
/// `length / (n·√2)` evens that out without ever exceeding full
/// intensity: `1/√2` for axis-parallel lines, `1` for diagonals. A
/// zero-length line (one pixel) gets the axis-parallel value `1/√2`.
#[must_use]
#[transcript::task]
pub fn slope_intensity(from: Pixel, to: Pixel) -> f32 {
    // BEGIN SOLUTION slope_intensity: return length / (max(|dx|, |dy|) * sqrt 2), and 1/sqrt 2 for a zero-length line
    let (dx, dy) = (
        (f64::from(to.x) - f64::from(from.x)).abs(),
        (f64::from(to.y) - f64::from(from.y)).abs(),
    );
    let steps = dx.max(dy);
    if steps == 0.0 {
        return std::f32::consts::FRAC_1_SQRT_2;
    }
    (dx.hypot(dy) / (steps * std::f64::consts::SQRT_2)) as f32
    // END SOLUTION
}
