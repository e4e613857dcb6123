//! The DDA line in lanes: seed 004's vectorised bonus (§4.4, "the step
//! widths of all points of the line can be stored in a vector and used for
//! the interpolation"), as data-parallel Rust.
//!
//! Task 1 walks the line with a running sum, `minor += slope`: each column
//! waits for the one before it. Here every column is computed on its own,
//! from the closed form
//!
//! ```text
//!   minor(X) = from.minor + slope · (X − from.major)      slope = Δminor / Δmajor   (f64)
//!   t(X)     = clamp((X − from.major) / Δmajor, 0, 1)                                (f32)
//! ```
//!
//! so that [`LANES`] columns at a time are one loop whose iterations do not
//! depend on each other. That is the shape a compiler turns into vector
//! instructions (eight `f64` lanes are one AVX-512 register), and the shape
//! MATLAB's array operations have in the seed: the batch is the vector.
//!
//! ```text
//!   major:  X₀  X₀+1  X₀+2 … X₀+7 │ X₀+8 … X₀+15 │ X₀+16 … last
//!           └──── batch 1 ──────┘ └── batch 2 ──┘ └─ batch 3 (fewer) ─┘
//!   minor:  each lane from the closed form, rounded half away from zero
//! ```
//!
//! Convention (see `canvas`): pixel centres at integers, y up, rounding
//! half away from zero; the same pixels, colours and depths as task 1's
//! `dda_line` (one per column of the major axis, both ends included).

use canvas::{Fragment, Pixel, Vertex, round_half_away, within_limits};

/// Columns per batch: the width of the data-parallel loop.
pub const LANES: usize = 8;

/// One batch of the line: up to [`LANES`] consecutive columns of the major
/// axis, each lane computed on its own.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Batch {
    /// How many lanes hold a column: [`LANES`], fewer only in the line's
    /// last batch. Lanes from `len` on are unspecified.
    pub len: usize,
    /// Per lane: the column, along the major axis.
    pub major: [i32; LANES],
    /// Per lane: the ideal line's minor coordinate in that column, before
    /// rounding: `from.minor + slope · (major − from.major)`, in `f64`, as
    /// the module documentation writes it.
    pub minor: [f64; LANES],
}

/// Rasterizes the line from `from` to `to` like task 1's DDA, [`LANES`]
/// columns at a time: each batch is reported to `batch`, then its
/// fragments are plotted, in order from `from` to `to`.
///
/// - The major axis is x when `|Δx| ≥ |Δy|`, else y; the columns run from
///   `round(from.major)` to `round(to.major)`, one per lane, in batches of
///   [`LANES`] starting at the first column (only the last batch is
///   shorter).
/// - Every lane is the closed form of the module documentation:
///   `minor = f64(from.minor) + slope · (f64(major) − f64(from.major))`
///   with `slope = f64(Δminor) / f64(Δmajor)`, where `Δ = to − from` is
///   taken in `f32` (the positions' type) and then widened, evaluated
///   exactly so (the tests compare it bit for bit; a running sum, or the
///   differences taken in `f64`, differ in the last bits).
///   The pixel is `(major, round(minor))`, swapped back for a steep line.
/// - Colour and depth are mixed with `t = clamp((major − from.major) /
///   Δmajor, 0, 1)` in `f32`, as in task 1.
/// - A zero-length line is one batch of one lane (`minor = from.minor`)
///   and one fragment with `from`'s attributes.
/// - Endpoints that are not finite or lie beyond ±`MAX_COORD` draw nothing
///   and report no batch.
#[transcript::task]
pub fn vectorised_dda_line(
    from: &Vertex,
    to: &Vertex,
    mut batch: impl FnMut(&Batch),
    mut plot: impl FnMut(Fragment),
) {
    // BEGIN SOLUTION vectorised_dda: per batch of LANES columns, the closed form in every lane (no running sum); report the batch, then plot its fragments
    let (a, b) = (from.position, to.position);
    if ![a.x, a.y, b.x, b.y].into_iter().all(within_limits) {
        return;
    }
    let d = b - a;
    let x_major = d.x.abs() >= d.y.abs();
    let (a_major, a_minor, d_major, d_minor) = if x_major {
        (a.x, a.y, d.x, d.y)
    } else {
        (a.y, a.x, d.y, d.x)
    };
    let slope = if d_major == 0.0 {
        0.0
    } else {
        f64::from(d_minor) / f64::from(d_major)
    };
    let first = round_half_away(a_major);
    let last = round_half_away(a_major + d_major);
    let step = if last >= first { 1 } else { -1 };
    let columns = i64::from(last - first).abs() + 1;
    let mut done: i64 = 0;
    while done < columns {
        let len = (columns - done).min(LANES as i64) as usize;
        let mut lanes = Batch {
            len,
            major: [0; LANES],
            minor: [0.0; LANES],
        };
        let mut t = [0.0_f32; LANES];
        let mut rounded = [0_i32; LANES];
        // The data-parallel loop: no lane reads another. Lanes past `len`
        // compute columns beyond the line, which are never plotted.
        for k in 0..LANES {
            let offset = done + k as i64;
            #[allow(clippy::cast_possible_truncation)] // within ±2·MAX_COORD + LANES
            let major = first + step * offset as i32;
            lanes.major[k] = major;
            let minor = f64::from(a_minor) + slope * (f64::from(major) - f64::from(a_major));
            lanes.minor[k] = minor;
            // Half away from zero without a call to `round` (which the
            // vector units of a plain x86-64 target lack): truncate, then
            // step one away from zero where the fraction reaches ½.
            #[allow(clippy::cast_possible_truncation)] // within the limits
            let whole = minor as i32;
            let fraction = minor - f64::from(whole);
            rounded[k] = whole + i32::from(fraction >= 0.5) - i32::from(fraction <= -0.5);
            t[k] = if d_major == 0.0 {
                0.0
            } else {
                ((major as f32 - a_major) / d_major).clamp(0.0, 1.0)
            };
        }
        batch(&lanes);
        for k in 0..len {
            let rounded = rounded[k];
            let pixel = if x_major {
                Pixel::new(lanes.major[k], rounded)
            } else {
                Pixel::new(rounded, lanes.major[k])
            };
            plot(Fragment {
                pixel,
                depth: from.depth * (1.0 - t[k]) + to.depth * t[k],
                colour: from.colour.lerp(to.colour, t[k]),
            });
        }
        done += len as i64;
    }
    // END SOLUTION
}
