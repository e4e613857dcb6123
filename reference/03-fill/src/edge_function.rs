//! Triangle rasterization with edge functions and barycentric interpolation,
//! after the TU Wien exercise sheet (seed 004, §6 "Fill Rasterization":
//! Kantenfunktionen, baryzentrische Koordinaten), with a top-left fill rule.
//!
//! Convention (see `canvas`): pixel centres at integers, y up. A pixel is
//! covered when its centre lies inside the triangle; a centre exactly on an
//! edge belongs to the triangle only if that edge is a left or top edge.

use canvas::{Fragment, MAX_COORD, Pixel, Vertex, Viewport};

/// Vertex positions are snapped to a fixed-point grid with this many
/// fractional bits ("24.8", as GPUs do) before any edge function is
/// evaluated. Departure from the sheet, which evaluates in floats: with
/// integers, the edge shared by two triangles gives exactly opposite values
/// in both, so the fill rule can hand every pixel to exactly one of them.
pub const SUBPIXEL_BITS: u32 = 8;

/// One pixel in fixed-point units, `2^SUBPIXEL_BITS`.
const ONE: i64 = 1 << SUBPIXEL_BITS;

/// The edge functions at a covered pixel's centre as exact integers, in
/// snapped units (1/256 pixel, so one pixel² is `2¹⁶`): `weights[k]` is the
/// edge function of the edge opposite vertex `k`, signed so that it is
/// `≥ 0` inside, i.e. vertex `k`'s barycentric weight times twice the
/// triangle's area. Vertex `k` is the `k`-th of the vertices as given; the
/// three always sum to twice the snapped triangle's area.
///
/// The tests compare these with the snapped edge functions at every pixel:
/// they are how a fill shows that it snaps and decides in integers.
pub type EdgeWeights = [i128; 3];

/// Snaps a coordinate to the fixed-point grid: `round(v · 2^SUBPIXEL_BITS)`
/// (ties away from zero). `None` for NaN, infinities and `|v| > MAX_COORD`.
#[must_use]
pub fn snap(v: f32) -> Option<i64> {
    if !v.is_finite() || v.abs() > MAX_COORD as f32 {
        return None;
    }
    #[allow(clippy::cast_possible_truncation)] // |v · 256| ≤ 2³², exact in f64 and i64
    Some((f64::from(v) * ONE as f64).round() as i64)
}

/// Rasterizes the triangle and calls `plot` once per covered pixel inside
/// `viewport` (inclusive bounds), with depth and colour interpolated and
/// the pixel's [`EdgeWeights`].
///
/// **Edge functions.** With vertices `V0, V1, V2` (snapped, see
/// [`SUBPIXEL_BITS`]), edge `i` runs from `Vi` to `V(i+1)` (indices mod 3):
///
/// ```text
///   e_i = V(i+1) − Vi,   A_i = −e_i.y,   B_i = e_i.x,   C_i = −(A_i·Vi.x + B_i·Vi.y)
///   O_i(P) = A_i·P.x + B_i·P.y + C_i      (= e_i × (P − Vi), twice a signed area)
/// ```
///
/// `O_i(P) < 0` means `P` lies right of edge `i`. A clockwise triangle
/// (y up) has its inside right of all three edges: `O_0, O_1, O_2 ≤ 0`. A
/// counter-clockwise triangle is made clockwise first by swapping `V1` and
/// `V2`, so both windings fill the same pixels.
///
/// **Fill rule (top-left).** A centre with `O_i(P) = 0` lies on edge `i`;
/// it is covered only when edge `i` is a *left* edge (`e.y > 0`, going up
/// in a clockwise triangle) or a *top* edge (`e.y = 0, e.x > 0`). Two
/// triangles sharing an edge run along it in opposite directions, so
/// exactly one of them takes it: a mesh covers every pixel once.
///
/// ```text
///          V0 ──top──▶ V1          clockwise, y up:
///            ▲        ╱            left edges go up,
///        left │      ╱ right       the top edge goes right
///            │    ╱
///            V2 ◀
/// ```
///
/// **Barycentric interpolation.** `O_i(V(i+2)) = D` is the same for every
/// `i` (twice the signed area; negative after the winding fix). The weight
/// of vertex `V(i+2)` at `P` is `λ(i+2) = O_i(P) / D`, with `1/D` computed
/// once. The three weights sum to 1, are all in `[0, 1]` inside, and are
/// 1 at their own vertex; depth and colour are `Σ λ_k · value_k`. `plot`
/// also gets the exact numerators: `weights[k] = λ_k · |D|`, in the
/// vertices' order as given (before the winding fix).
///
/// **Work.** The bounding box of the snapped vertices, clipped to
/// `viewport`; within a row `O_i` grows by `A_i · 2⁸` per pixel (a pixel
/// is 2⁸ snapped units: `A_i` alone moves 1/256 pixel), within a column by
/// `B_i · 2⁸` (all integer arithmetic).
///
/// A triangle of zero area (after snapping), or with a position that is
/// NaN, infinite or beyond ±[`MAX_COORD`], plots nothing.
#[transcript::task]
pub fn fill_triangle(
    vertices: [Vertex; 3],
    viewport: Viewport,
    mut plot: impl FnMut(Fragment, EdgeWeights),
) {
    // BEGIN SOLUTION edge_function: set up A, B, C per edge; walk the clipped box; top-left rule; interpolate; pass the exact weights on
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
    // Which given vertex each of v[0], v[1], v[2] is.
    let mut given = [0, 1, 2];
    if area > 0 {
        // Counter-clockwise: make it clockwise so that inside is O ≤ 0.
        v.swap(1, 2);
        p.swap(1, 2);
        given.swap(1, 2);
        area = -area;
    }
    // Per edge: A, B, C and the fill-rule bias (0 where a centre on the
    // edge counts as inside, 1 where it does not: O + bias ≤ 0).
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
        let top_left = ey > 0 || (ey == 0 && ex > 0);
        bias[i] = i128::from(!top_left);
    }
    // Bounding box in pixels: centres x · ONE within [min, max].
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
    let edge_at =
        |i: usize, x: i64, y: i64| a[i] * i128::from(x * ONE) + b[i] * i128::from(y * ONE) + c[i];
    let mut row = [edge_at(0, x0, y0), edge_at(1, x0, y0), edge_at(2, x0, y0)];
    // The weights O_i / D step by A_i · ONE / D per pixel: kept in f64
    // beside the exact O_i (which alone decide inside or out), they save
    // an i128 → f64 conversion, a library call, per weight and pixel.
    let step = [0, 1, 2].map(|i| (a[i] * i128::from(ONE)) as f64 * inv_area);
    for y in y0..=y1 {
        let mut o = row;
        let mut weight = row.map(|o| o as f64 * inv_area);
        for x in x0..=x1 {
            if (0..3).all(|i| o[i] + bias[i] <= 0) {
                // Weight of V(i+2) is O_i / D.
                let w = |i: usize| weight[i] as f32;
                let (l2, l0, l1) = (w(0), w(1), w(2));
                #[allow(clippy::cast_possible_truncation)] // clipped to the viewport
                let pixel = Pixel::new(x as i32, y as i32);
                // O_i ≤ 0 inside: −O_i is V(i+2)'s weight times |D|.
                let mut exact = [0; 3];
                for i in 0..3 {
                    exact[given[(i + 2) % 3]] = -o[i];
                }
                let fragment = Fragment {
                    pixel,
                    depth: l0 * v[0].depth + l1 * v[1].depth + l2 * v[2].depth,
                    colour: v[0].colour * l0 + v[1].colour * l1 + v[2].colour * l2,
                };
                plot(fragment, exact);
            }
            for i in 0..3 {
                o[i] += a[i] * i128::from(ONE);
                weight[i] += step[i];
            }
        }
        for i in 0..3 {
            row[i] += b[i] * i128::from(ONE);
        }
    }
    // END SOLUTION
}
