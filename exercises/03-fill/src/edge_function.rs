//! Triangle rasterization with edge functions and barycentric interpolation,
//! after the TU Wien exercise sheet (seed 004, §6 "Fill Rasterization":
//! Kantenfunktionen, baryzentrische Koordinaten), with a top-left fill rule.
//!
//! Convention (see `canvas`): pixel centres at integers, y up. A pixel is
//! covered when its centre lies inside the triangle; a centre exactly on an
//! edge belongs to the triangle only if that edge is a left or top edge.

#[allow(unused_imports)]
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
    // Unused until you write the body:
    let _ = (&vertices, &viewport, &mut plot);
    todo!(
        "edge_function: set up A, B, C per edge; walk the clipped box; top-left rule; interpolate; pass the exact weights on"
    )
}
