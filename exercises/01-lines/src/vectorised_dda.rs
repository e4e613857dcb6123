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

#[allow(unused_imports)]
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
    // Unused until you write the body:
    let _ = (&from, &to, &mut batch, &mut plot);
    todo!(
        "vectorised_dda: per batch of LANES columns, the closed form in every lane (no running sum); report the batch, then plot its fragments"
    )
}
