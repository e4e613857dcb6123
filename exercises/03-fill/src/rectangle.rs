//! Filling an axis-parallel rectangle with the half-pixel convention of the
//! lecture slides (seed 002, §5.4 "Füllen von Rechtecken").
//!
//! Convention (see `canvas`): pixel centres at integers, y up. A pixel is
//! filled when its centre lies in the half-open box `[min, max)`: left and
//! bottom edges included, right and top edges excluded.

use canvas::{Pixel, Vec2, Viewport};

/// Fills the rectangle with continuous corners `min` and `max` and calls
/// `plot` once per pixel inside `viewport`, in no particular order.
///
/// **Which pixels.** Pixel `(x, y)` is filled exactly when
///
/// ```text
///   min.x ≤ x < max.x   and   min.y ≤ y < max.y
///   that is  x = ⌈min.x⌉ ..= ⌈max.x⌉ − 1,  y = ⌈min.y⌉ ..= ⌈max.y⌉ − 1
/// ```
///
/// The slides' naïve loop `for x in x_min..=x_max` fills one column and
/// one row too many, so two rectangles sharing an edge both fill it. Their
/// remedy, "shift the raster by half a pixel to the left and down", is the
/// rule above: the box `[0.5, 4.5) × [0.5, 3.5)` fills 4 × 3 pixels, and
/// rectangles `[a, b)` and `[b, c)` that share the edge `b` fill every
/// pixel of `[a, c)` exactly once — whether `b` is an integer, a
/// half-integer or anything else.
///
/// ```text
///   3.5 ┌───────────────┐        · = pixel centre
///       │ ·   ·   ·   · │        the top and right edges pass
///       │ ·   ·   ·   · │        between centres here; a centre
///       │ ·   ·   ·   · │        exactly on them is left out
///   0.5 └───────────────┘
///      0.5             4.5
/// ```
///
/// An empty box (`max.x ≤ min.x` or `max.y ≤ min.y`) or a corner with a NaN
/// coordinate plots nothing. Infinite or huge corners are fine: the box is
/// clipped to `viewport` (inclusive bounds) before any pixel is visited, so
/// the work is at most the number of pixels plotted.
#[transcript::task]
pub fn fill_rectangle(min: Vec2, max: Vec2, viewport: Viewport, mut plot: impl FnMut(Pixel)) {
    // Unused until you write the body:
    let _ = (&min, &max, &viewport, &mut plot);
    todo!("rectangle: fill centres in [min, max): x from ⌈min.x⌉ to ⌈max.x⌉ − 1, clipped")
}
