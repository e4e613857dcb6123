//! The midpoint (Bresenham) line in all octants, integer arithmetic only:
//! lecture slides "Midpoint Line Algorithmus" (seed 002).
//!
//! Convention (see `canvas`): pixel centres at integers, y up; both
//! endpoints are drawn; a tie (the midpoint exactly on the line, `d = 0`)
//! goes to the pixel with the smaller minor coordinate.

use canvas::{MAX_COORD, Pixel};

/// Rasterizes the line from `from` to `to` with the midpoint algorithm and
/// calls `plot` once per pixel, in order from `from` to `to`.
///
/// In the first octant (`0 ≤ Δy ≤ Δx`) each step goes E or NE; the
/// decision variable is twice the implicit line equation at the midpoint
/// `M` between the two candidates:
///
/// ```text
///        NE ·          d = 2·F(M),  d₀ = 2Δy − Δx
///      M  ×            d > 0: M below the line → NE, d += 2(Δy − Δx)
///   ■    E ·           d < 0: M above the line → E,  d += 2Δy
///   P                  d = 0: a tie
/// ```
///
/// The other octants swap the axes (steep lines step in y) and mirror the
/// directions. **Direction independence** (the slides: "E when drawing
/// left to right, SW when drawing right to left"): at a tie the step
/// goes to the smaller minor coordinate — the lower pixel of a flat line,
/// the left pixel of a steep one — so `A → B` and `B → A` cover the same
/// pixels.
///
/// Endpoints beyond ±[`MAX_COORD`] draw nothing (use the viewport version,
/// `clipped_midpoint_line`, for lines that reach far outside).
#[transcript::task]
pub fn midpoint_line(from: Pixel, to: Pixel, mut plot: impl FnMut(Pixel)) {
    // BEGIN SOLUTION midpoint: step along the major axis with an integer decision variable; at d = 0 take the smaller minor coordinate
    if [from.x, from.y, to.x, to.y]
        .iter()
        .any(|c| c.unsigned_abs() > MAX_COORD as u32)
    {
        return;
    }
    let (dx, dy) = (i64::from(to.x - from.x), i64::from(to.y - from.y));
    let (sx, sy) = (if dx < 0 { -1 } else { 1 }, if dy < 0 { -1 } else { 1 });
    let x_major = dx.abs() >= dy.abs();
    let (long, short) = if x_major {
        (dx.abs(), dy.abs())
    } else {
        (dy.abs(), dx.abs())
    };
    // The diagonal step leads to the smaller minor coordinate exactly when
    // the minor axis runs backwards: then a tie takes it.
    let diagonal_on_tie = if x_major { sy < 0 } else { sx < 0 };
    // "d > 0, or d = 0 when ties take the diagonal" is, for integers,
    // "d + 1 > 0" in the second case: one comparison per pixel.
    let tie_bias = i64::from(diagonal_on_tie);
    let diagonal = (sx, sy);
    let straight = if x_major { (sx, 0) } else { (0, sy) };
    let mut d = 2 * short - long;
    let (mut x, mut y) = (from.x, from.y);
    plot(Pixel::new(x, y));
    for _ in 0..long {
        let step = if d + tie_bias > 0 {
            d += 2 * (short - long);
            diagonal
        } else {
            d += 2 * short;
            straight
        };
        x += step.0;
        y += step.1;
        plot(Pixel::new(x, y));
    }
    // END SOLUTION
}
