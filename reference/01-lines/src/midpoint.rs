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
    let (dx, dy) = (to.x - from.x, to.y - from.y);
    // The octant is settled here, once: `walk` steps along the major axis
    // and `pixel` puts its (major, minor) coordinates back in place. Each
    // call is compiled with its own `pixel`, so the loop that runs per
    // pixel chooses nothing.
    if dx.abs() >= dy.abs() {
        walk(from.x, from.y, dx, dy, Pixel::new, &mut plot);
    } else {
        walk(from.y, from.x, dy, dx, |major, minor| Pixel::new(minor, major), &mut plot);
    }
    // END SOLUTION
}

// BEGIN SOLUTION

/// The midpoint walk in the first octant's terms: from `(major, minor)`,
/// `|d_major|` steps of one pixel along the major axis, each also a step
/// along the minor axis when the decision variable says so. A tie takes
/// the diagonal step exactly when the minor axis runs backwards, so that
/// it leads to the smaller minor coordinate.
#[inline(always)] // the caller's `pixel` and `plot` inlined into the loop
fn walk(
    mut major: i32,
    mut minor: i32,
    d_major: i32,
    d_minor: i32,
    pixel: impl Fn(i32, i32) -> Pixel,
    plot: &mut impl FnMut(Pixel),
) {
    let (long, short) = (i64::from(d_major).abs(), i64::from(d_minor).abs());
    let (step_major, step_minor) = (d_major.signum(), d_minor.signum());
    // "d > 0, or d = 0 when ties take the diagonal" is, for integers,
    // "d + 1 > 0" in the second case: one comparison per pixel.
    let tie_bias = i64::from(d_minor < 0);
    let mut d = 2 * short - long;
    plot(pixel(major, minor));
    for _ in 0..long {
        if d + tie_bias > 0 {
            d += 2 * (short - long);
            minor += step_minor;
        } else {
            d += 2 * short;
        }
        major += step_major;
        plot(pixel(major, minor));
    }
}
// END SOLUTION
