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
    // BEGIN SOLUTION blocked: set up as in task 5; per 8×8 block reject/accept by corners and report it to `block`, else test 8 lanes
    let mut p = [[0_i64; 2]; 3];
    for (k, v) in positions.iter().enumerate() {
        match (snap(v.x), snap(v.y)) {
            (Some(x), Some(y)) => p[k] = [x, y],
            _ => return,
        }
    }
    let cross = |a: [i64; 2], b: [i64; 2], c: [i64; 2]| {
        i128::from(b[0] - a[0]) * i128::from(c[1] - a[1])
            - i128::from(b[1] - a[1]) * i128::from(c[0] - a[0])
    };
    let area = cross(p[0], p[1], p[2]);
    if area == 0 || viewport.is_empty() {
        return;
    }
    if area > 0 {
        p.swap(1, 2);
    }
    let mut a = [0_i64; 3];
    let mut b = [0_i64; 3];
    let mut c = [0_i128; 3];
    let mut bias = [0_i128; 3];
    for i in 0..3 {
        let (from, to) = (p[i], p[(i + 1) % 3]);
        let (ex, ey) = (to[0] - from[0], to[1] - from[1]);
        a[i] = -ey;
        b[i] = ex;
        c[i] = -(i128::from(a[i]) * i128::from(from[0]) + i128::from(b[i]) * i128::from(from[1]));
        bias[i] = i128::from(!(ey > 0 || (ey == 0 && ex > 0)));
    }
    // t_i(x, y) = O_i + bias_i at the centre of pixel (x, y), in i128.
    let t = |i: usize, x: i64, y: i64| {
        i128::from(a[i]) * i128::from(x * ONE)
            + i128::from(b[i]) * i128::from(y * ONE)
            + c[i]
            + bias[i]
    };
    let lo = |k: usize| p.iter().map(|q| q[k]).min().unwrap_or(0);
    let hi = |k: usize| p.iter().map(|q| q[k]).max().unwrap_or(0);
    let x0 = (-(-lo(0)).div_euclid(ONE)).max(i64::from(viewport.x_min));
    let x1 = hi(0).div_euclid(ONE).min(i64::from(viewport.x_max));
    let y0 = (-(-lo(1)).div_euclid(ONE)).max(i64::from(viewport.y_min));
    let y1 = hi(1).div_euclid(ONE).min(i64::from(viewport.y_max));
    let mut by = y0;
    while by <= y1 {
        let (bty, top) = (by, (by + BLOCK - 1).min(y1));
        let mut bx = x0;
        while bx <= x1 {
            let right = (bx + BLOCK - 1).min(x1);
            let corners = [(bx, bty), (right, bty), (bx, top), (right, top)];
            // Per edge: None when it needs no test, Some(value at (bx, by)).
            let mut partial: [Option<i64>; 3] = [None; 3];
            let mut empty = false;
            for (i, slot) in partial.iter_mut().enumerate() {
                let values = corners.map(|(x, y)| t(i, x, y));
                if values.iter().all(|&v| v > 0) {
                    empty = true;
                    break;
                }
                if values.iter().any(|&v| v > 0) {
                    // Straddles 0: small enough for i64 (see above).
                    #[allow(clippy::cast_possible_truncation)]
                    let base = values[0] as i64;
                    *slot = Some(base);
                }
            }
            let coverage = if empty {
                Coverage::Outside
            } else if partial.iter().all(Option::is_none) {
                Coverage::Inside
            } else {
                Coverage::Partial
            };
            #[allow(clippy::cast_possible_truncation)] // in the viewport
            block(Block {
                min: Pixel::new(bx as i32, bty as i32),
                max: Pixel::new(right as i32, top as i32),
                coverage,
            });
            if !empty {
                for y in bty..=top {
                    // Lane k is pixel bx + k; lanes past `right` are masked.
                    let mut inside: [bool; BLOCK as usize] =
                        std::array::from_fn(|k| bx + k as i64 <= right);
                    for i in 0..3 {
                        if let Some(base) = partial[i] {
                            let row = base + (y - bty) * b[i] * ONE;
                            let step = a[i] * ONE;
                            let lanes: [i64; BLOCK as usize] =
                                std::array::from_fn(|k| row + k as i64 * step);
                            for (flag, v) in inside.iter_mut().zip(lanes) {
                                *flag &= v <= 0;
                            }
                        }
                    }
                    for (k, &flag) in inside.iter().enumerate() {
                        if flag {
                            #[allow(clippy::cast_possible_truncation)] // in the viewport
                            plot(Pixel::new((bx + k as i64) as i32, y as i32));
                        }
                    }
                }
            }
            bx += BLOCK;
        }
        by += BLOCK;
    }
    // END SOLUTION
}
