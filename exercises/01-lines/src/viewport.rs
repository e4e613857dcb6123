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
    // Unused until you write the body:
    let _ = (&from, &to, &viewport, &mut plot);
    todo!(
        "viewport: compute the first and last visible column and the decision variable there, then step only through the visible part"
    )
}
