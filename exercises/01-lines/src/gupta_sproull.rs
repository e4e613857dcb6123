//! Antialiased lines after Gupta and Sproull (1981): lecture slides
//! "Anti-Aliasing: Gupta-Sproull Methode" (seed 002); the incremental
//! distance follows Foley et al., *Computer Graphics*, §3.17.
//!
//! Convention (see `canvas`): pixel centres at integers, y up; the middle
//! pixel of each column is the midpoint line's (ties to the smaller minor
//! coordinate), and the pixels on either side of it are added.

#[allow(unused_imports)]
use canvas::{MAX_COORD, Pixel};

/// Number of entries of the distance table (the slides: "Reduktion auf 24
/// mögliche Werte für D").
pub const TABLE_LEN: usize = 24;

/// Table entries per pixel of distance: entry `k` holds the filter value at
/// `D = k / 16`, so the table covers `0 ≤ D ≤ 23/16`, everything the
/// three pixels of a column can be from the line.
pub const STEPS_PER_PIXEL: f64 = 16.0;

/// The cone filter's value for a pixel whose centre lies `D` pixels from
/// the middle of the line, for `D = 0, 1/16, …, 23/16`, normalised so that
/// a pixel on the line gets 1.
///
/// The filter is a cone of radius 1 centred on the pixel; the line is a
/// strip one pixel wide. The intensity is the cone's volume over the strip,
/// `V(D) = ∫ S(u) du` over `u ∈ [D − ½, D + ½]`, where `S(u)` is the
/// cone's cross-section at distance `u` from its axis:
/// `S(u) = ρ − (u²/2)·ln((1 + ρ)/(1 − ρ))` with `ρ = √(1 − u²)` (the cone
/// height `1 − r` integrated along a chord), and 0 for `|u| ≥ 1`. The
/// integral is taken with Simpson's rule once, on first use.
#[must_use]
#[transcript::task]
pub fn distance_table() -> &'static [f32; TABLE_LEN] {
    todo!(
        "gupta_sproull: compute the table once (std::sync::OnceLock): the cone volume over the strip for D = k/16, divided by the value at D = 0"
    )
}

/// The filter value for a pixel at distance `distance` from the line: the
/// table entry nearest to it (0 beyond the table).
#[must_use]
pub fn filter(distance: f64) -> f32 {
    let k = (distance.abs() * STEPS_PER_PIXEL).round();
    if k < TABLE_LEN as f64 {
        distance_table()[k as usize]
    } else {
        0.0
    }
}

/// Draws the antialiased line from `from` to `to` and calls
/// `plot(pixel, intensity)` for three pixels per column of the major axis,
/// in this order: the midpoint line's pixel first, then its two neighbours
/// across the line (along the minor axis), each with the intensity
/// [`filter`] gives for its distance to the line.
///
/// ```text
///        · ·  ■ above: D = |v − 1|·cos θ
///   ─────────■────── the line; v = the line's offset from the
///        · ·  ■ below   middle pixel's centre along the minor axis,
///                       D = |v|·cos θ for the middle pixel
/// ```
///
/// The distance comes from the midpoint decision: in first-octant terms
/// `2v·Δx` is an integer that changes by `2Δy` per column and by `−2Δx`
/// per row, and `D = |2v·Δx| / (2·√(Δx² + Δy²))`.
///
/// Endpoints beyond ±[`MAX_COORD`] draw nothing.
#[transcript::task]
pub fn gupta_sproull_line(from: Pixel, to: Pixel, mut plot: impl FnMut(Pixel, f32)) {
    // Unused until you write the body:
    let _ = (&from, &to, &mut plot);
    todo!(
        "gupta_sproull: run the midpoint line and plot its pixel and both minor-axis neighbours with filter(distance to the line)"
    )
}
