//! Per-patch adaptive tessellation of a surface of several Bézier patches,
//! without cracks (seed 001 §2.1, "adaptive tessellation", Figure 2.3).
//!
//! Every patch gets its own resolution `n_u × n_v` from a flatness
//! estimate; every boundary curve between two patches gets its own number
//! of segments, computed from the curve alone, and its points are
//! evaluated once and shared by both neighbours. Inside a patch, the cells
//! that do not touch the boundary become two triangles each as in the
//! uniform tessellation; the ring of border cells is triangulated between
//! the inner grid and the boundary curves' points (the zipper in
//! [`freeform::stitch`]). Two neighbours therefore meet in the very same
//! vertices: no T-junctions, no cracks.
//!
//! ```text
//!   ┌──·──·──·──┐   the boundary curves (dots) are split on their own;
//!   │ ╲│ ╱ ╲ │╱ │   the inner grid (+) on the patch's resolution;
//!   ·──+────+───·   the ring between them is zipped
//!   │  │ ╲  │   │
//!   ·──+────+───·
//!   │╱ ╲ │ ╱ ╲ ╲│
//!   └───·───·───┘
//! ```
//!
//! **Flatness estimate.** A Bézier curve `C` of degree `n` has
//! `|C''(t)| ≤ n(n − 1) · M` with `M = max_i |P_i+2 − 2P_i+1 + P_i|`, and
//! the chord of a parameter interval of length `h` stays within
//! `h²/8 · max|C''|` of the curve. With `k` equal segments (`h = 1/k`), the
//! polyline is within `tolerance` of the curve when
//!
//! ```text
//!   k ≥ sqrt( n(n − 1) · M / (8 · tolerance) )
//! ```
//!
//! A patch uses the same bound per direction, with `M` the largest second
//! difference of its control columns (for `u`) or rows (for `v`); this
//! ignores the twist term `S_uv`, an estimate rather than a guarantee. The
//! seed leaves the estimate open ("depends on the viewpoint and the shape");
//! a screen-size estimate would use projected control points instead.

#[allow(unused_imports)]
use glam::{DVec2, DVec3};

#[allow(unused_imports)]
use crate::bezier::SurfaceSample;
use crate::error::TessError;
use crate::mesh::Mesh;
use crate::patch_grid::{GridPatch, PatchGrid};
#[allow(unused_imports)]
use freeform::stitch;

/// The most segments a curve or a patch direction gets, however curved.
pub const MAX_SEGMENTS: usize = 64;

/// The fewest cells per direction inside a patch: with 2 the inner grid is
/// at least a point, which the ring of border cells needs (a limit of this
/// construction: a flat patch still gets 2 × 2 cells).
pub const MIN_INNER_SEGMENTS: usize = 2;

/// The number of equal parameter segments that keep the polyline of a
/// Bézier curve (given by its control polygon) within `tolerance` of it,
/// by the bound in the module documentation:
/// `k = ⌈sqrt(n(n − 1) M / (8 · tolerance))⌉`, at least 1 and at most
/// [`MAX_SEGMENTS`]. A line (degree ≤ 1, or all second differences zero)
/// needs 1.
///
/// # Errors
/// [`TessError::NotPositive`] for a tolerance that is not a positive
/// finite number, [`TessError::NonFinite`] for a non-finite control point.
#[transcript::task]
pub fn curve_segments(control: &[DVec3], tolerance: f64) -> Result<usize, TessError> {
    // Unused until you write the body:
    let _ = (&control, &tolerance);
    todo!("per_patch: apply the chord bound to the largest second difference")
}

/// The resolution `[n_u, n_v]` of a patch: the bound of [`curve_segments`]
/// per direction, with `M` the largest second difference along `u` (over
/// all control columns) or along `v` (over all control rows), each at
/// least [`MIN_INNER_SEGMENTS`] and at most [`MAX_SEGMENTS`]. For a
/// rational patch the control points (not weighted) stand in for the
/// polygon ([`GridPatch`]): an estimate.
///
/// # Errors
/// [`TessError::NotPositive`] for a tolerance that is not a positive
/// finite number.
#[transcript::task]
pub fn patch_resolution(patch: &impl GridPatch, tolerance: f64) -> Result<[usize; 2], TessError> {
    // Unused until you write the body:
    let _ = (&patch, &tolerance);
    todo!("per_patch: the curve bound along the columns (u) and rows (v)")
}

/// Tessellates every patch of `grid` with its own resolution
/// ([`patch_resolution`]) and every boundary curve with its own number of
/// segments ([`curve_segments`] of the curve's control polygon), so that
/// neighbouring patches share the points of their common curve: the mesh
/// is watertight, every edge inside the surface is shared by exactly two
/// triangles.
///
/// Vertices: the patch corners, then the inner points of every boundary
/// curve, then per patch its inner grid `(i/n_u, j/n_v)`, `0 < i < n_u`,
/// `0 < j < n_v`. A shared vertex is evaluated once, by one of its patches
/// (normals of neighbours agree only if the surface is smooth there).
/// Parameters in the mesh are global (patch `(r, c)` covers
/// `[c, c + 1] × [r, r + 1]`); triangles are counter-clockwise in them.
/// The patches may be Bézier or rational ones (a NURBS surface split into
/// its patches): the construction is the same.
///
/// # Errors
/// [`TessError::NotPositive`] for a tolerance that is not a positive
/// finite number.
#[transcript::task]
pub fn tessellate_patch_grid(
    grid: &PatchGrid<impl GridPatch>,
    tolerance: f64,
) -> Result<Mesh, TessError> {
    // Unused until you write the body:
    let _ = (&grid, &tolerance);
    todo!("per_patch: share corners and boundary-curve points, then grid + zipped ring per patch")
}
