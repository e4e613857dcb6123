//! A blocked, data-parallel triangle rasterizer: edge functions evaluated
//! for 8 × 8 blocks of pixels at once, whole blocks accepted or rejected
//! from their corners (after Pineda, "A Parallel Algorithm for Polygon
//! Rasterization", SIGGRAPH 1988; the setup is seed 004, §6, as in
//! `edge_function`).
//!
//! Convention (see `canvas`): pixel centres at integers, y up; exactly the
//! pixels of `edge_function::fill_triangle` (snapped to 1/256 pixel,
//! inside where all `O_i + bias_i ≤ 0`, top-left rule).

use canvas::{MAX_COORD, Pixel, Vec2, Viewport};

/// Pixels per block side. 8 lanes of `i64` are one AVX-512 register, or
/// two AVX2 ones; the inner loop over a block row has no branches.
pub const BLOCK: i64 = 8;

/// Fixed-point fractional bits, as in `edge_function`.
pub const SUBPIXEL_BITS: u32 = 8;

/// One pixel in fixed-point units.
const ONE: i64 = 1 << SUBPIXEL_BITS;

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

/// How a block's corners classify it, before any pixel of it is tested.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Coverage {
    /// Some edge has `O_i + bias_i > 0` at all four corners: skipped.
    Outside,
    /// Every edge has `O_i + bias_i ≤ 0` at all four corners: filled whole.
    Inside,
    /// Some edge straddles 0: its pixels are tested in lanes.
    Partial,
}

/// One block of the clipped bounding box: pixels `min` to `max`, corners
/// included (8 × 8, less at the box's right and top ends).
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Block {
    /// The lower left pixel.
    pub min: Pixel,
    /// The upper right pixel.
    pub max: Pixel,
    /// What its corners say.
    pub coverage: Coverage,
}

/// Rasterizes the triangle through `positions` and calls `plot` once per
/// covered pixel inside `viewport`: the same pixels as task 5, found block
/// by block. Each block is reported to `block`, with its [`Coverage`],
/// before its pixels are plotted.
///
/// **Blocks.** Cover the clipped bounding box with 8 × 8 blocks. An edge
/// function is linear, so over a block it takes its extremes at the four
/// corner pixels. For each edge `i` and block:
///
/// ```text
///   all corners  O_i + bias_i > 0   → no pixel of the block is inside: skip it
///   all corners  O_i + bias_i ≤ 0   → edge i needs no test in this block
///   otherwise                       → test edge i per pixel
/// ```
///
/// A block that no edge needs to test is filled whole. In the partial case
/// the values straddle 0, so they are at most `(|A| + |B|) · 8 · 256` in
/// size: `i64` lanes suffice, although the corners are computed in `i128`
/// (far from the triangle, `O` can reach 2⁶⁶).
///
/// **Lanes.** Within a block row the eight values `t + k·A·2⁸` (`k = 0..8`)
/// of each partial edge are computed and compared as one array — no
/// branch per pixel, the shape compilers vectorise.
///
/// Zero area, or a position NaN, infinite or beyond ±[`MAX_COORD`], plots
/// nothing.
#[transcript::task]
pub fn fill_triangle_blocked(
    positions: [Vec2; 3],
    viewport: Viewport,
    mut plot: impl FnMut(Pixel),
    mut block: impl FnMut(Block),
) {
    // Unused until you write the body:
    let _ = (&positions, &viewport, &mut plot, &mut block);
    todo!(
        "blocked: set up as in task 5; per 8×8 block reject/accept by corners and report it to `block`, else test 8 lanes"
    )
}
