//! Collecting what a rasterizer plots, and writing expected pixels as
//! literal grids: the vocabulary every topic's tests share.
//!
//! A grid is written top row first (as it looks on screen, y up), `#` for
//! a pixel and any other character for none; its **bottom-left** character
//! is the pixel `origin`:
//!
//! ```text
//!   grid!(Pixel::new(10, 20);      pixels (10, 21), (12, 21), (11, 20)
//!       "#.#",
//!       ".#.",
//!   )
//! ```

use std::collections::{BTreeMap, BTreeSet};

use canvas::{Fragment, Pixel};

/// Calls `draw` with a `plot` closure and returns the pixels in order.
pub fn collect(draw: impl FnOnce(&mut dyn FnMut(Pixel))) -> Vec<Pixel> {
    let mut pixels = Vec::new();
    draw(&mut |p| pixels.push(p));
    pixels
}

/// Calls `draw` with a fragment `plot` closure and returns the fragments
/// in order.
pub fn collect_fragments(draw: impl FnOnce(&mut dyn FnMut(Fragment))) -> Vec<Fragment> {
    let mut fragments = Vec::new();
    draw(&mut |f| fragments.push(f));
    fragments
}

/// Calls `draw` with an antialiasing `plot(pixel, intensity)` closure and
/// returns the pairs in order.
pub fn collect_weighted(draw: impl FnOnce(&mut dyn FnMut(Pixel, f32))) -> Vec<(Pixel, f32)> {
    let mut pixels = Vec::new();
    draw(&mut |p, w| pixels.push((p, w)));
    pixels
}

/// Counts the pixels `draw` plots without keeping them (for input that
/// must draw nothing, where a wrong answer could be huge).
pub fn count(draw: impl FnOnce(&mut dyn FnMut(Pixel))) -> u64 {
    let mut n = 0;
    draw(&mut |_| n += 1);
    n
}

/// The first pixel that occurs twice, if any.
#[must_use]
pub fn first_duplicate(pixels: &[Pixel]) -> Option<Pixel> {
    let mut seen = BTreeSet::new();
    pixels.iter().copied().find(|&p| !seen.insert(p))
}

/// How often each pixel occurs.
#[must_use]
pub fn counts(pixels: &[Pixel]) -> BTreeMap<Pixel, u32> {
    let mut map = BTreeMap::new();
    for &p in pixels {
        *map.entry(p).or_insert(0) += 1;
    }
    map
}

/// The pixels marked `#` in `rows` (top row first), whose bottom-left
/// character is `origin`; see [`grid!`](crate::grid) for the literal form.
///
/// # Panics
/// On a ragged grid (rows of different lengths).
#[must_use]
pub fn grid_pixels(origin: Pixel, rows: &[&str]) -> Vec<Pixel> {
    let height = i32::try_from(rows.len()).expect("a grid of at most 2³¹ rows");
    let mut pixels = Vec::new();
    for (r, row) in (0..).zip(rows) {
        assert_eq!(
            row.chars().count(),
            rows[0].chars().count(),
            "ragged grid: row {r} is {row:?}"
        );
        for (c, ch) in (0..).zip(row.chars()) {
            if ch == '#' {
                pixels.push(Pixel::new(origin.x + c, origin.y + height - 1 - r));
            }
        }
    }
    pixels
}

/// The bottom-left pixel of a grid of odd width and height whose middle
/// character is `centre` (for shapes drawn around a centre).
///
/// # Panics
/// On an empty grid.
#[must_use]
pub fn origin_of_centred(centre: Pixel, rows: &[&str]) -> Pixel {
    let width = i32::try_from(rows[0].chars().count()).expect("a narrow grid");
    let height = i32::try_from(rows.len()).expect("a short grid");
    Pixel::new(centre.x - width / 2, centre.y - height / 2)
}

/// Expected pixels as a literal grid: `grid!(origin; "row", "row", ...)`,
/// rows top first, `#` for a pixel, the bottom-left character at `origin`
/// (see [`pixels`](crate::pixels)).
#[macro_export]
macro_rules! grid {
    ($origin:expr; $($row:expr),+ $(,)?) => {
        $crate::pixels::grid_pixels($origin, &[$($row),+])
    };
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bottom_left_character_is_the_origin() {
        let pixels = crate::grid!(Pixel::new(10, 20); "#.#", ".#.");
        assert_eq!(
            pixels,
            [Pixel::new(10, 21), Pixel::new(12, 21), Pixel::new(11, 20)]
        );
    }

    #[test]
    fn a_centred_grid_has_its_middle_at_the_centre() {
        let rows = ["...", ".#.", "..."];
        let origin = origin_of_centred(Pixel::new(5, 5), &rows);
        assert_eq!(grid_pixels(origin, &rows), [Pixel::new(5, 5)]);
    }

    #[test]
    fn duplicates_and_counts() {
        let pixels = [Pixel::new(0, 0), Pixel::new(1, 0), Pixel::new(0, 0)];
        assert_eq!(first_duplicate(&pixels), Some(Pixel::new(0, 0)));
        assert_eq!(counts(&pixels)[&Pixel::new(0, 0)], 2);
        assert_eq!(first_duplicate(&pixels[..2]), None);
    }
}
