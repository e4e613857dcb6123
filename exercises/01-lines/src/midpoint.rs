//! The midpoint (Bresenham) line in all octants, integer arithmetic only:
//! lecture slides "Midpoint Line Algorithmus" (seed 002).
//!
//! Convention (see `canvas`): pixel centres at integers, y up; both
//! endpoints are drawn; a tie (the midpoint exactly on the line, `d = 0`)
//! goes to the pixel with the smaller minor coordinate.

#[allow(unused_imports)]
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
    // Unused until you write the body:
    let _ = (&from, &to, &mut plot);
    todo!(
        "midpoint: step along the major axis with an integer decision variable; at d = 0 take the smaller minor coordinate"
    )
}
