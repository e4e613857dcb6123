//! Outline parity fill: mark one pixel per edge crossing, then toggle
//! inside/outside along each row, after the lecture slides (seed 002,
//! §5.4 "Füllen von Polygonen: Modifikation").
//!
//! Convention (see `canvas`): pixel centres at integers, y up; the filled
//! pixels are exactly those of `scanline` (even-odd rule, left ends of
//! spans included, right ends excluded).

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
    // BEGIN SOLUTION parity: toggle a mark at ⌈s⌉ per crossing (report it to `toggle`), then flip inside/outside along each row
    if vertices.len() < 3 || viewport.is_empty() || !vertices.iter().all(|v| v.is_finite()) {
        return;
    }
    let lo = vertices.iter().copied().fold(Vec2::INFINITY, Vec2::min);
    let hi = vertices.iter().copied().fold(Vec2::NEG_INFINITY, Vec2::max);
    // Columns ⌈lo.x⌉ ..= ⌈hi.x⌉ − 1 can be inside; the same for rows.
    let first = |v: f32, bound: i32| f64::from(v).ceil().max(f64::from(bound));
    let last = |v: f32, bound: i32| (f64::from(v).ceil() - 1.0).min(f64::from(bound));
    let (x0, x1) = (first(lo.x, viewport.x_min), last(hi.x, viewport.x_max));
    let (y0, y1) = (first(lo.y, viewport.y_min), last(hi.y, viewport.y_max));
    if x0 > x1 || y0 > y1 {
        return;
    }
    #[allow(clippy::cast_possible_truncation)] // clipped to the viewport
    let (x0, x1, y0, y1) = (x0 as i32, x1 as i32, y0 as i32, y1 as i32);
    let width = (i64::from(x1) - i64::from(x0) + 1) as usize;
    let height = (i64::from(y1) - i64::from(y0) + 1) as usize;
    if (width as u64).saturating_mul(height as u64) > Canvas::MAX_PIXELS {
        return; // a buffer no canvas could hold
    }
    let mut marks = vec![false; width * height];
    let n = vertices.len();
    for i in 0..n {
        let (a, b) = (vertices[i], vertices[(i + 1) % n]);
        let rows_from = first(a.y.min(b.y), y0);
        let rows_to = last(a.y.max(b.y), y1);
        if rows_from > rows_to {
            continue; // horizontal, or outside the buffer
        }
        #[allow(clippy::cast_possible_truncation)] // clipped to the buffer
        for y in rows_from as i32..=rows_to as i32 {
            let column = crossing(a, b, y).ceil().max(f64::from(x0));
            if column <= f64::from(x1) {
                #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
                let index = (y - y0) as usize * width + (column as i32 - x0) as usize;
                marks[index] = !marks[index];
                #[allow(clippy::cast_possible_truncation)] // in the buffer
                toggle(Pixel::new(column as i32, y));
            }
        }
    }
    for (row, y) in marks.chunks_exact(width).zip(y0..) {
        let mut inside = false;
        for (&mark, x) in row.iter().zip(x0..) {
            inside ^= mark;
            if inside {
                plot(Pixel::new(x, y));
            }
        }
    }
    // END SOLUTION
}
