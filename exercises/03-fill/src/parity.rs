//! Outline parity fill: mark one pixel per edge crossing, then toggle
//! inside/outside along each row, after the lecture slides (seed 002,
//! §5.4 "Füllen von Polygonen: Modifikation").
//!
//! Convention (see `canvas`): pixel centres at integers, y up; the filled
//! pixels are exactly those of `scanline` (even-odd rule, left ends of
//! spans included, right ends excluded).

#[allow(unused_imports)]
use canvas::{Canvas, Pixel, Vec2, Viewport};

/// Where the edge `a–b` crosses row `y`: the same formula, evaluated in
/// the same order, as `scanline::crossing` (lower endpoint first, `f64`).
#[must_use]
pub fn crossing(a: Vec2, b: Vec2, y: i32) -> f64 {
    let (lo, hi) = if a.y < b.y { (a, b) } else { (b, a) };
    let (lo_x, lo_y) = (f64::from(lo.x), f64::from(lo.y));
    let (hi_x, hi_y) = (f64::from(hi.x), f64::from(hi.y));
    lo_x + ((f64::from(y) - lo_y) * (hi_x - lo_x)) / (hi_y - lo_y)
}

/// Fills the closed polygon through `vertices` by outline parity and calls
/// `plot` once per pixel inside `viewport`, row by row; reports every
/// toggle of a mark to `toggle` (the pixel whose mark flips), all of them
/// before the first pixel is plotted.
///
/// **Marking.** Edge by edge (in any order, no sorting), for every row `y`
/// the edge crosses (`min(a.y, b.y) ≤ y < max(a.y, b.y)`, as in
/// `scanline`), toggle the mark of the first pixel at or right of the
/// crossing, `x = ⌈s⌉`. The slides "colour the first pixel with
/// `x > s_x + 0.5`" on their grid (centres at `k + ½`); departure: marks are
/// *toggled*, not set, because two crossings can fall into the same pixel
/// (a sliver narrower than a pixel) and must then cancel.
///
/// **Filling.** Walk each row left to right with a flag `inside = false`;
/// at every marked pixel flip the flag; plot the pixel when the flag is
/// set. A pixel is plotted exactly when an odd number of crossings lie at
/// or left of its centre: the even-odd rule, the same pixels as
/// `scanline::fill_polygon`.
///
/// ```text
///   crossings      |        |   |       |
///   marks       ...M........M...M.......M...
///   inside      ...#########....########....
/// ```
///
/// The marks live in a buffer over the polygon's bounding box clipped to
/// `viewport`; a crossing left of the buffer toggles its first column (the
/// parity of every pixel right of it changes all the same). Fewer than
/// three vertices, a NaN or infinite coordinate, or a buffer of more than
/// [`Canvas::MAX_PIXELS`] pixels (no canvas is that large) fill nothing.
#[transcript::task]
pub fn parity_fill(
    vertices: &[Vec2],
    viewport: Viewport,
    mut plot: impl FnMut(Pixel),
    mut toggle: impl FnMut(Pixel),
) {
    // Unused until you write the body:
    let _ = (&vertices, &viewport, &mut plot, &mut toggle);
    todo!(
        "parity: toggle a mark at ⌈s⌉ per crossing (report it to `toggle`), then flip inside/outside along each row"
    )
}
