//! Antialiasing by unweighted area sampling: lecture slides
//! "Anti-Aliasing: ungewichtete Abtastung" (seed 002).
//!
//! Convention (see `canvas`): pixel `(x, y)` is the unit square around its
//! centre `(x, y)`, y up; the line is a rectangle one pixel wide whose
//! middle line runs from `from` to `to` (no caps beyond the endpoints).

#[allow(unused_imports)]
use canvas::{Pixel, Vec2, within_limits};
#[allow(unused_imports)]
use glam::DVec2;

/// Draws the line from `from` to `to` as a rectangle one pixel wide and
/// calls `plot(pixel, intensity)` for every pixel it overlaps, with the
/// intensity equal to the overlapped area of the pixel's square (in
/// `(0, 1]`).
///
/// ```text
///   ┌───┬───┬───┐      the pixel's intensity is the area of its
///   │  ╱│▒▒▒│▒▒▒│      square inside the 1-wide rectangle; where in
///   │╱▒▒│▒▒▒│▒▒╱│      the square that area lies does not matter
///   │▒▒▒│▒▒▒│╱  │      ("ungewichtet": unweighted)
///   └───┴───┴───┘
/// ```
///
/// The intensities add up to the rectangle's area, the line's length.
/// A zero-length line covers no area and draws nothing; endpoints that are
/// not finite or lie beyond ±`MAX_COORD` draw nothing.
#[transcript::task]
pub fn area_sampling_line(from: Vec2, to: Vec2, mut plot: impl FnMut(Pixel, f32)) {
    // Unused until you write the body:
    let _ = (&from, &to, &mut plot);
    todo!(
        "area_sampling: intersect each nearby pixel square with the 1-pixel-wide rectangle around the line and plot the overlapped area"
    )
}
