//! ASCII art of rasters: what snapshots store and what the grader prints.
//!
//! ```text
//!  y  '.' empty · '#' full · '1'..'9' partial ink in tenths
//!  2 |..#
//!  1 |.#.
//!  0 |#..
//!    +---
//!     012
//! ```

use crate::Pixel;

/// The legend printed above every ASCII raster.
pub const ASCII_LEGEND: &str = "'.' empty, '#' full, '1'..'9' partial ink in tenths";

/// The character for a pixel's ink (its brightest channel, in `[0, 1]`):
/// `'.'` for none, `'#'` for full, and the digit of the nearest tenth for
/// anything in between (never `'0'` or `'#'` for partial ink, so a faint
/// pixel is never mistaken for an empty or a full one).
#[must_use]
pub fn ink_char(ink: f32) -> char {
    // Ink within this distance of 0 or 1 counts as empty or full: it
    // absorbs float rounding in blends, nothing a viewer could see.
    const SNAP: f32 = 1e-4;
    if ink.is_nan() || ink <= SNAP {
        '.'
    } else if ink >= 1.0 - SNAP {
        '#'
    } else {
        let tenth = (ink * 10.0).round().clamp(1.0, 9.0) as u32;
        char::from_digit(tenth, 10).unwrap_or('?')
    }
}

/// Renders a `width × height` grid, one character per pixel from `cell`,
/// top row first, with y labels on the left, x labels (the last digit of
/// each column) below, and the legend above.
#[must_use]
pub fn ascii_grid(width: u32, height: u32, cell: impl Fn(Pixel) -> char) -> String {
    let label_width = height.saturating_sub(1).to_string().len();
    let mut out = format!("{:>label_width$}  {ASCII_LEGEND}\n", "y");
    for y in (0..height).rev() {
        out += &format!("{y:>label_width$} |");
        for x in 0..width {
            out.push(cell(Pixel::new(x as i32, y as i32)));
        }
        out.push('\n');
    }
    out += &format!("{:>label_width$} +{}\n", "", "-".repeat(width as usize));
    out += &format!("{:>label_width$}  ", "");
    for x in 0..width {
        out.push(char::from_digit(x % 10, 10).unwrap_or('?'));
    }
    out += " x\n";
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ramp_never_confuses_partial_with_empty_or_full() {
        assert_eq!(ink_char(0.0), '.');
        assert_eq!(ink_char(0.001), '1');
        assert_eq!(ink_char(0.5), '5');
        assert_eq!(ink_char(0.999), '9');
        assert_eq!(ink_char(1.0), '#');
        assert_eq!(ink_char(f32::NAN), '.');
    }

    #[test]
    fn grid_has_axes_and_top_row_first() {
        let art = ascii_grid(3, 2, |p| if p == Pixel::new(2, 1) { '#' } else { '.' });
        assert_eq!(
            art,
            format!("y  {ASCII_LEGEND}\n1 |..#\n0 |...\n  +---\n   012 x\n")
        );
    }
}
