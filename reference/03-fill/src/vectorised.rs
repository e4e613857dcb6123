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
    // BEGIN SOLUTION vectorised: set up as in task 5; per row, batches of LANES pixels: edge functions, coverage mask, weights, depth and colour as arrays of lanes; report each batch, then plot its covered lanes
    let mut v = vertices;
    let mut p = [[0_i64; 2]; 3];
    for (k, vertex) in v.iter().enumerate() {
        match (snap(vertex.position.x), snap(vertex.position.y)) {
            (Some(x), Some(y)) => p[k] = [x, y],
            _ => return,
        }
    }
    let cross = |a: [i64; 2], b: [i64; 2], c: [i64; 2]| {
        i128::from(b[0] - a[0]) * i128::from(c[1] - a[1])
            - i128::from(b[1] - a[1]) * i128::from(c[0] - a[0])
    };
    let mut area = cross(p[0], p[1], p[2]);
    if area == 0 || viewport.is_empty() {
        return;
    }
    let mut given = [0, 1, 2];
    if area > 0 {
        v.swap(1, 2);
        p.swap(1, 2);
        given.swap(1, 2);
        area = -area;
    }
    let mut a = [0_i128; 3];
    let mut b = [0_i128; 3];
    let mut c = [0_i128; 3];
    let mut bias = [0_i128; 3];
    for i in 0..3 {
        let (from, to) = (p[i], p[(i + 1) % 3]);
        let (ex, ey) = (to[0] - from[0], to[1] - from[1]);
        a[i] = i128::from(-ey);
        b[i] = i128::from(ex);
        c[i] = -(a[i] * i128::from(from[0]) + b[i] * i128::from(from[1]));
        bias[i] = i128::from(!(ey > 0 || (ey == 0 && ex > 0)));
    }
    let lo = |k: usize| p.iter().map(|q| q[k]).min().unwrap_or(0);
    let hi = |k: usize| p.iter().map(|q| q[k]).max().unwrap_or(0);
    let first = |fixed: i64, bound: i32| (-(-fixed).div_euclid(ONE)).max(i64::from(bound));
    let last = |fixed: i64, bound: i32| fixed.div_euclid(ONE).min(i64::from(bound));
    let (x0, x1) = (first(lo(0), viewport.x_min), last(hi(0), viewport.x_max));
    let (y0, y1) = (first(lo(1), viewport.y_min), last(hi(1), viewport.y_max));
    if x0 > x1 || y0 > y1 {
        return;
    }
    let inv_area = 1.0 / area as f64;
    // The lanes' offsets k·A_i·2⁸, the same in every batch: |A_i| ≤ 2³³,
    // so they stay below 2⁴⁴.
    #[allow(clippy::cast_possible_truncation)] // |A_i| ≤ 2³³
    let offset: [[i64; LANES]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|k| k as i64 * a[i] as i64 * ONE));
    let offset_f: [[f64; LANES]; 3] = offset.map(|lanes| lanes.map(|o| o as f64));
    // The values to mix, per vertex as given (λ is kept in that order).
    let [u0, u1, u2] = vertices;
    let depth = [u0.depth, u1.depth, u2.depth];
    let channel = |f: fn(&Rgba) -> f32| [f(&u0.colour), f(&u1.colour), f(&u2.colour)];
    let colours = [
        channel(|c| c.r),
        channel(|c| c.g),
        channel(|c| c.b),
        channel(|c| c.a),
    ];
    for y in y0..=y1 {
        let mut bx = x0;
        while bx <= x1 {
            let len = (x1 - bx + 1).min(LANES as i64) as usize;
            #[allow(clippy::cast_possible_truncation)] // in the viewport
            let (row, column) = (y as i32, bx as i32);
            let base: [i128; 3] = std::array::from_fn(|i| {
                a[i] * i128::from(bx * ONE) + b[i] * i128::from(y * ONE) + c[i]
            });
            #[allow(clippy::cast_possible_truncation)] // clamped to ±2⁶²
            let threshold = [0, 1, 2].map(|i| (-(base[i] + bias[i])).clamp(-CLAMP, CLAMP) as i64);
            // The data-parallel loops: no lane reads another.
            let mut covered: [bool; LANES] = std::array::from_fn(|k| k < len);
            for i in 0..3 {
                for (flag, &o) in covered.iter_mut().zip(&offset[i]) {
                    *flag &= o <= threshold[i];
                }
            }
            // λ(i+2) = O_i / D, lane by lane, for the vertices as given.
            let mut lambda = [[0.0_f32; LANES]; 3];
            for i in 0..3 {
                let start = base[i] as f64;
                let vertex = given[(i + 2) % 3];
                for k in 0..len {
                    #[allow(clippy::cast_possible_truncation)] // a weight in f32, as task 5
                    let w = ((start + offset_f[i][k]) * inv_area) as f32;
                    lambda[vertex][k] = w;
                }
            }
            // Σ λ_v · value_v in every lane: the lanes past `len` mix
            // zero weights to zero.
            let mix = |values: [f32; 3]| -> [f32; LANES] {
                std::array::from_fn(|k| {
                    lambda[0][k] * values[0] + lambda[1][k] * values[1] + lambda[2][k] * values[2]
                })
            };
            let [r, g, bl, al] = colours.map(mix);
            let lanes = Batch {
                y: row,
                x: column,
                len,
                covered,
                lambda,
                depth: mix(depth),
                colour: std::array::from_fn(|k| Rgba::new(r[k], g[k], bl[k], al[k])),
            };
            batch(&lanes);
            for k in (0..len).filter(|&k| covered[k]) {
                let mut exact = [0; 3];
                for i in 0..3 {
                    exact[given[(i + 2) % 3]] = -(base[i] + i128::from(offset[i][k]));
                }
                let fragment = Fragment {
                    pixel: Pixel::new(column + k as i32, row),
                    depth: lanes.depth[k],
                    colour: lanes.colour[k],
                };
                plot(fragment, exact);
            }
            bx += LANES as i64;
        }
    }
    // END SOLUTION
}
