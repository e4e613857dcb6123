//! Comparing rasters, with an ASCII diff a student can read.
//!
//! ```text
//!   y  '#' in both, '+' only in yours, '-' only expected, '.' in neither
//!   2 |..-+
//!   1 |.#..
//!   0 |#...
//! ```

use std::collections::BTreeSet;

use canvas::{Canvas, Pixel, Rgba, ascii_grid, ink_char};

/// The line that opens a raster diff in a panic message (the grader looks
/// for it).
pub use wire::RASTER_DIFF_BEGIN;
/// The line that closes a raster diff.
pub use wire::RASTER_DIFF_END;

/// The largest diff drawn in full; larger ones are cut to a window around
/// the first difference so that a terminal can still show them.
const MAX_DIFF_SIDE: i64 = 64;

/// A canvas of the given size with the listed pixels set to white.
#[must_use]
pub fn canvas_from_pixels(width: u32, height: u32, pixels: &[Pixel]) -> Canvas {
    let mut canvas = Canvas::new(width, height);
    for &p in pixels {
        canvas.set(p, Rgba::WHITE);
    }
    canvas
}

/// The ASCII diff of two pixel sets, or `None` when they are equal as sets.
///
/// The window is the bounding box of both sets plus a margin of one pixel,
/// cut to at most 64 × 64 around the first difference.
#[must_use]
pub fn pixel_diff(expected: &[Pixel], yours: &[Pixel]) -> Option<String> {
    let expected: BTreeSet<Pixel> = expected.iter().copied().collect();
    let yours: BTreeSet<Pixel> = yours.iter().copied().collect();
    let first = expected.symmetric_difference(&yours).next().copied()?;
    let all = expected.union(&yours);
    let (mut x0, mut y0, mut x1, mut y1) = (i64::MAX, i64::MAX, i64::MIN, i64::MIN);
    for p in all {
        x0 = x0.min(i64::from(p.x));
        y0 = y0.min(i64::from(p.y));
        x1 = x1.max(i64::from(p.x));
        y1 = y1.max(i64::from(p.y));
    }
    let (x0, x1) = window(x0 - 1, x1 + 1, i64::from(first.x));
    let (y0, y1) = window(y0 - 1, y1 + 1, i64::from(first.y));
    let grid = ascii_grid((x1 - x0 + 1) as u32, (y1 - y0 + 1) as u32, |q| {
        let p = Pixel::new((x0 + i64::from(q.x)) as i32, (y0 + i64::from(q.y)) as i32);
        match (expected.contains(&p), yours.contains(&p)) {
            (true, true) => '#',
            (false, true) => '+',
            (true, false) => '-',
            (false, false) => '.',
        }
    });
    let missing = expected.difference(&yours).count();
    let extra = yours.difference(&expected).count();
    Some(format!(
        "{RASTER_DIFF_BEGIN}\n\
         '#' in both, '+' only in yours ({extra}), '-' only expected ({missing}); \
         window origin ({x0}, {y0}), labels are offsets from it\n\
         {}{RASTER_DIFF_END}",
        strip_legend(&grid)
    ))
}

/// Cuts `[lo, hi]` to at most [`MAX_DIFF_SIDE`] values around `focus`.
fn window(lo: i64, hi: i64, focus: i64) -> (i64, i64) {
    if hi - lo < MAX_DIFF_SIDE {
        return (lo, hi);
    }
    let lo = (focus - MAX_DIFF_SIDE / 2).max(lo);
    (lo, (lo + MAX_DIFF_SIDE - 1).min(hi))
}

/// The grid without its first line (the ink legend, which a diff replaces).
fn strip_legend(grid: &str) -> &str {
    grid.split_once('\n').map_or(grid, |(_, rest)| rest)
}

/// Asserts that two pixel sets are equal (order and repetitions are
/// ignored); on failure panics with `what` and the ASCII diff.
#[track_caller]
pub fn assert_pixels_eq(expected: &[Pixel], yours: &[Pixel], what: &str) {
    if let Some(diff) = pixel_diff(expected, yours) {
        panic!("{what}: the pixels differ\n{diff}");
    }
}

/// Asserts that two canvases show the same ink everywhere (within
/// `tolerance` per pixel); on failure panics with both as ASCII art and a
/// row of `!` under each differing column.
#[track_caller]
pub fn assert_canvas_eq(expected: &Canvas, yours: &Canvas, tolerance: f32, what: &str) {
    assert_eq!(
        (expected.width(), expected.height()),
        (yours.width(), yours.height()),
        "{what}: canvas sizes differ"
    );
    let differs = |p: Pixel| {
        let e = expected.get(p).map_or(0.0, Rgba::ink);
        let y = yours.get(p).map_or(0.0, Rgba::ink);
        let d = (e - y).abs();
        d.is_nan() || d > tolerance
    };
    let count = expected.enumerate().filter(|&(p, _)| differs(p)).count();
    if count == 0 {
        return;
    }
    let ink = |c: &Canvas, p| ink_char(c.get(p).map_or(0.0, Rgba::ink));
    let marks = ascii_grid(expected.width(), expected.height(), |p| {
        if differs(p) { '!' } else { ink(yours, p) }
    });
    panic!(
        "{what}: {count} pixels differ by more than {tolerance}\n{RASTER_DIFF_BEGIN}\n\
         expected:\n{}yours ('!' marks a difference):\n{}{RASTER_DIFF_END}",
        expected.to_ascii(),
        strip_legend(&marks)
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_sets_have_no_diff_whatever_the_order() {
        let a = [Pixel::new(0, 0), Pixel::new(1, 1)];
        let b = [Pixel::new(1, 1), Pixel::new(0, 0), Pixel::new(0, 0)];
        assert_eq!(pixel_diff(&a, &b), None);
    }

    #[test]
    fn diff_marks_extra_and_missing_pixels() {
        let expected = [Pixel::new(0, 0), Pixel::new(1, 0)];
        let yours = [Pixel::new(0, 0), Pixel::new(1, 1)];
        let diff = pixel_diff(&expected, &yours).unwrap();
        let grid: Vec<&str> = diff.lines().filter(|l| l.contains('|')).collect();
        // Window is x in -1..=2, y in -1..=2; rows from the top.
        assert_eq!(grid, ["3 |....", "2 |..+.", "1 |.#-.", "0 |...."]);
        assert!(diff.contains("only in yours (1)"));
        assert!(diff.contains("only expected (1)"));
        assert!(diff.starts_with(RASTER_DIFF_BEGIN) && diff.ends_with(RASTER_DIFF_END));
    }

    #[test]
    fn huge_diffs_are_cut_to_a_window() {
        let expected = [Pixel::new(-1_000_000, 0)];
        let yours = [Pixel::new(1_000_000, 5)];
        let diff = pixel_diff(&expected, &yours).unwrap();
        assert!(diff.lines().count() < 80);
    }

    #[test]
    #[should_panic(expected = "pixels differ")]
    fn canvas_difference_panics() {
        let a = canvas_from_pixels(3, 3, &[Pixel::new(1, 1)]);
        let b = canvas_from_pixels(3, 3, &[Pixel::new(1, 2)]);
        assert_canvas_eq(&a, &b, 0.0, "test");
    }
}
