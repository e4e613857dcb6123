//! The triangle in lanes over its bounding box: seed 004's vectorised
//! bonus (§6.4: "the line equations can be applied to all pixels of the
//! bounding box of a triangle at once"), as data-parallel Rust.
//!
//! Task 5 walks the box pixel by pixel: each pixel's edge functions are
//! the previous pixel's plus a step, and each pixel branches on its own
//! test before it mixes depth and colour. The seed's MATLAB version has no
//! loop at all: the edge functions, the coverage mask and the barycentric
//! mix of colour and depth are matrices over the whole box. Here a row of
//! the box is cut into batches of [`LANES`] pixels, and every quantity of a
//! batch is an array with one lane per pixel, computed by a loop whose
//! iterations do not depend on each other — the loop a compiler turns into
//! vector instructions, and the shape of the seed's matrices:
//!
//! ```text
//!   row y:   x₀ … x₀+7 │ x₀+8 … x₀+15 │ … │ … x₁
//!            batch 1     batch 2             last (fewer lanes)
//!   per lane k:  O_i = base_i + k·A_i·2⁸   covered = all O_i + bias_i ≤ 0
//!                λ(i+2) = O_i / D          depth, colour = Σ λ · value
//! ```
//!
//! Convention (see `canvas`): pixel centres at integers, y up; exactly the
//! fragments of `edge_function::fill_triangle` (snapped to 1/256 pixel,
//! inside where all `O_i + bias_i ≤ 0`, top-left rule), the same exact
//! edge weights, depth and colour from the same barycentric weights.

#[allow(unused_imports)]
use canvas::{Fragment, MAX_COORD, Pixel, Rgba, Vertex, Viewport};

/// Pixels per batch: eight lanes, one AVX-512 register of `i64` or `f64`
/// (two AVX2 ones).
pub const LANES: usize = 8;

/// Fixed-point fractional bits, as in `edge_function`.
pub const SUBPIXEL_BITS: u32 = 8;

/// One pixel in fixed-point units.
const ONE: i64 = 1 << SUBPIXEL_BITS;

/// Where a lane's threshold `−(base_i + bias_i)` is clamped so that it fits
/// `i64`: the lanes' offsets stay below 2⁴⁴, so beyond ±2⁶² none of them
/// can reach it and the comparison keeps its answer.
#[allow(dead_code)]
const CLAMP: i128 = 1 << 62;

/// The exact edge functions at a pixel, as in `edge_function`:
/// `weights[k]` belongs to vertex `k` as given, `≥ 0` inside.
pub type EdgeWeights = [i128; 3];

/// Snaps a coordinate as `edge_function::snap` does: `round(v · 256)`,
/// `None` for NaN, infinities and `|v| > MAX_COORD`.
#[must_use]
pub fn snap(v: f32) -> Option<i64> {
    if !v.is_finite() || v.abs() > MAX_COORD as f32 {
        return None;
    }
    #[allow(clippy::cast_possible_truncation)] // |v · 256| ≤ 2³², exact
    Some((f64::from(v) * ONE as f64).round() as i64)
}

/// One batch: up to [`LANES`] consecutive pixels of a row of the clipped
/// bounding box, every lane computed on its own.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Batch {
    /// The row.
    pub y: i32,
    /// The column of lane 0; lane `k` is the pixel `(x + k, y)`.
    pub x: i32,
    /// How many lanes lie in the box: [`LANES`], fewer only at the row's
    /// right end.
    pub len: usize,
    /// Per lane: whether the pixel's centre is covered (top-left rule);
    /// `false` from `len` on.
    pub covered: [bool; LANES],
    /// Per vertex as given, per lane: the barycentric weight `λ` of that
    /// vertex at the lane's pixel (the exact edge weight over twice the
    /// area, see [`fill_triangle_vectorised`]), in every lane below `len`,
    /// covered or not (outside the triangle some are negative); 0 from
    /// `len` on.
    pub lambda: [[f32; LANES]; 3],
    /// Per lane: the depth mixed there, `Σ λ_v · depth_v`, in every lane
    /// below `len`, covered or not, as the seed's matrices hold it for
    /// every pixel of the box; 0 from `len` on.
    pub depth: [f32; LANES],
    /// Per lane: the colour mixed there likewise, channel by channel;
    /// [`Rgba::TRANSPARENT`] from `len` on.
    pub colour: [Rgba; LANES],
}

/// Rasterizes the triangle like task 5 and calls `plot` once per covered
/// pixel inside `viewport`, with depth and colour interpolated and the
/// pixel's exact [`EdgeWeights`]; the work is done [`LANES`] pixels at a
/// time, each batch reported to `batch` before its fragments are plotted.
///
/// - **Set-up**, as in task 5: snap, twice the signed area `D` (zero
///   draws nothing), a counter-clockwise triangle made clockwise by
///   swapping `V1` and `V2`, `A_i`, `B_i`, `C_i` in `i128` and the top-left
///   bias.
/// - **Batches.** The box is task 5's (pixels whose centres lie between the
///   snapped minimum and maximum, clipped to `viewport`). Walk its rows
///   bottom to top; cut each row into batches of [`LANES`] pixels from its
///   left end (only the last of a row is shorter).
/// - **Lanes.** In a batch starting at column `x`, `base_i = O_i(x, y)` is
///   computed once in `i128`; lane `k` holds `base_i + k·A_i·2⁸`, whose
///   offsets `k·A_i·2⁸` are below 2⁴⁴ and fit `i64`. The lane is covered
///   when `offset ≤ −(base_i + bias_i)` for all three edges, with the
///   right side clamped to ±2⁶² so that it fits `i64` too (beyond the
///   clamp no offset changes the answer). Lanes past `len` are switched
///   off.
/// - **Interpolation**, in every lane below `len`, covered or not (the
///   seed mixes the whole box; a lane does not branch on its coverage):
///   `λ(i+2) = (base_i + offset) · (1/D)` in `f64`, `1/D` computed once,
///   then rounded to `f32`; depth `λ0·d0 + λ1·d1 + λ2·d2` and each channel
///   of the colour likewise, in `f32`. Lanes from `len` on hold zeros.
/// - **Report** the batch with its coverage, weights, depths and colours,
///   then **plot** its covered lanes in order, each with its lane's depth
///   and colour and the exact weights: `weights[k]` for vertex `k` as
///   given is `−O_i` for the vertex `i + 2` of the clockwise triangle.
///
/// A position that is NaN, infinite or beyond ±[`MAX_COORD`] plots nothing
/// and reports no batch.
#[transcript::task]
pub fn fill_triangle_vectorised(
    vertices: [Vertex; 3],
    viewport: Viewport,
    mut batch: impl FnMut(&Batch),
    mut plot: impl FnMut(Fragment, EdgeWeights),
) {
    // Unused until you write the body:
    let _ = (&vertices, &viewport, &mut batch, &mut plot);
    todo!(
        "vectorised: set up as in task 5; per row, batches of LANES pixels: edge functions, coverage mask, weights, depth and colour as arrays of lanes; report each batch, then plot its covered lanes"
    )
}
