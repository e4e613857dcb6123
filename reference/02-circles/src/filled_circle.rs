//! The filled circle, drawn as one horizontal span per row between
//! symmetric points of the midpoint circle: an extension of the lecture
//! slides' "Midpoint Circle Algorithmus" (seed 002) towards their "Füllen"
//! section.
//!
//! Convention (see `canvas`): pixel centres at integers, y up; the filled
//! circle is the outline of `midpoint_circle` together with every pixel
//! inside it, each pixel plotted once.

use canvas::{MAX_COORD, Pixel};

/// Fills the circle of `radius` around `centre` and calls `plot` once per
/// pixel, row by row in no particular order.
///
/// **Which pixels.** In every row, those from the leftmost to the
/// rightmost pixel of the midpoint circle's outline in that row. Written
/// directly, with offsets `(x, y)` from the centre, `m = max(|x|, |y|)` and
/// `n = min(|x|, |y|)`: the pixel is filled exactly when
///
/// ```text
///   (m − ½)² + n² < R²      in integers:  m² − m + n² < R²
/// ```
///
/// that is, when the midpoint between the pixel and its neighbour one step
/// towards the centre (along its larger offset) lies inside the circle;
/// for radius 0 the centre alone is filled. This contains every pixel
/// whose centre lies in the circle (`x² + y² ≤ R²`) and, in addition, the
/// outline pixels just outside it; so drawing the outline over the filled
/// circle adds nothing, and filling never leaks past the outline.
///
/// **How.** Walk the second octant as the midpoint circle does. Each
/// pixel `(x, y)` of the walk has mirror images in four rows:
///
/// ```text
///   row +y   · · ■━━━━━■ · ·    (±x, ±y): rows ±y, from −x to x; the walk
///   row +x   ■━━━━━━━━━━━━━■    visits a row ±y once per pixel on it, and
///   row −x   ■━━━━━━━━━━━━━■    only its last (widest) span is wanted
///   row −y   · · ■━━━━━■ · ·    (±y, ±x): rows ±x, from −y to y; the walk
///                               visits each x once: always the widest
/// ```
///
/// Rows `±x` are filled at every step. Row `±y` is filled when the walk
/// leaves it (an SE step), from its last pixel `(x, y)`, and only when
/// `y > x`: rows up to the last column of the octant were already filled
/// as rows `±x`. Row 0 is one row, not two. So no row, and no pixel, is
/// drawn twice.
///
/// A negative radius, or a circle reaching beyond ±[`MAX_COORD`]
/// (`|centre.x| + radius > MAX_COORD`, or the same for y), plots nothing.
/// The work grows with the area, `πR²` pixels.
#[transcript::task]
pub fn filled_circle(centre: Pixel, radius: i32, mut plot: impl FnMut(Pixel)) {
    // BEGIN SOLUTION filled_circle: walk the octant; fill rows ±x at each step, rows ±y as you leave them
    let reach = |c: i32| i64::from(c).abs() + i64::from(radius);
    if radius < 0
        || reach(centre.x) > i64::from(MAX_COORD)
        || reach(centre.y) > i64::from(MAX_COORD)
    {
        return;
    }
    // Rows `centre.y ± row` (one row when `row` is 0), from
    // `centre.x − half` to `centre.x + half`.
    let mut span = |row: i32, half: i32| {
        let rows = if row == 0 { 1 } else { 2 };
        for y in [centre.y + row, centre.y - row].into_iter().take(rows) {
            for x in centre.x - half..=centre.x + half {
                plot(Pixel::new(x, y));
            }
        }
    };
    let (mut x, mut y) = (0, radius);
    let mut h = 1 - i64::from(radius); // the integer decision variable d − ¼
    while x <= y {
        span(x, y);
        let row = y;
        if h < 0 {
            h += 2 * i64::from(x) + 3;
        } else {
            h += 2 * i64::from(x - y) + 5;
            y -= 1;
        }
        x += 1;
        if y < row && row >= x {
            // The walk left row `row`; its last pixel was (x − 1, row).
            span(row, x - 1);
        }
    }
    // END SOLUTION
}
