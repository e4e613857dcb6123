//! Antialiased lines after Gupta and Sproull (1981): lecture slides
//! "Anti-Aliasing: Gupta-Sproull Methode" (seed 002); the incremental
//! distance follows Foley et al., *Computer Graphics*, §3.17.
//!
//! Convention (see `canvas`): pixel centres at integers, y up; the middle
//! pixel of each column is the midpoint line's (ties to the smaller minor
//! coordinate), and the pixels on either side of it are added.

// BEGIN SOLUTION
use std::sync::OnceLock;
// END SOLUTION

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
    // BEGIN SOLUTION gupta_sproull: compute the table once (std::sync::OnceLock): the cone volume over the strip for D = k/16, divided by the value at D = 0
    static TABLE: OnceLock<[f32; TABLE_LEN]> = OnceLock::new();
    TABLE.get_or_init(|| {
        let volume = |d: f64| simpson(cone_section, d - 0.5, d + 0.5);
        let full = volume(0.0);
        std::array::from_fn(|k| (volume(k as f64 / STEPS_PER_PIXEL) / full) as f32)
    })
    // END SOLUTION
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
    // BEGIN SOLUTION gupta_sproull: run the midpoint line and plot its pixel and both minor-axis neighbours with filter(distance to the line)
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
    let diagonal_on_tie = if x_major { sy < 0 } else { sx < 0 };
    // A single pixel has no direction: treat it as a horizontal line.
    let inv_denom = 1.0 / (2.0 * ((long * long + short * short) as f64).sqrt().max(1.0));
    // (i, j) in first-octant terms, mapped back to the line's octant.
    let pixel = |i: i64, j: i64| {
        let (major, minor) = (i as i32, j as i32);
        if x_major {
            Pixel::new(from.x + sx * major, from.y + sy * minor)
        } else {
            Pixel::new(from.x + sx * minor, from.y + sy * major)
        }
    };
    let mut d = 2 * short - long;
    let mut two_v_dx = 0_i64; // 2·v·Δx for the middle pixel of column i
    let mut j = 0;
    for i in 0..=long {
        plot(pixel(i, j), filter(two_v_dx as f64 * inv_denom));
        plot(
            pixel(i, j + 1),
            filter((two_v_dx - 2 * long) as f64 * inv_denom),
        );
        plot(
            pixel(i, j - 1),
            filter((two_v_dx + 2 * long) as f64 * inv_denom),
        );
        if d > 0 || (d == 0 && diagonal_on_tie) {
            j += 1;
            two_v_dx += 2 * (short - long);
            d += 2 * (short - long);
        } else {
            two_v_dx += 2 * short;
            d += 2 * short;
        }
    }
    // END SOLUTION
}

// BEGIN SOLUTION
/// The cone's cross-section at distance `u` from its axis (see
/// [`distance_table`]).
fn cone_section(u: f64) -> f64 {
    let u = u.abs();
    if u >= 1.0 {
        return 0.0;
    }
    if u == 0.0 {
        return 1.0;
    }
    let rho = (1.0 - u * u).sqrt();
    rho - 0.5 * u * u * ((1.0 + rho) / (1.0 - rho)).ln()
}

/// Simpson's rule for `∫ f` over `[a, b]` with 512 intervals.
fn simpson(f: fn(f64) -> f64, a: f64, b: f64) -> f64 {
    const INTERVALS: usize = 512;
    let h = (b - a) / INTERVALS as f64;
    let inner: f64 = (1..INTERVALS)
        .map(|k| f(a + k as f64 * h) * if k % 2 == 1 { 4.0 } else { 2.0 })
        .sum();
    (f(a) + inner + f(b)) * h / 3.0
}
// END SOLUTION
