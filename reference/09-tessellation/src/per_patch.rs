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

use glam::{DVec2, DVec3};

use crate::bezier::SurfaceSample;
use crate::error::TessError;
use crate::mesh::Mesh;
use crate::patch_grid::{GridPatch, PatchGrid};
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
    // BEGIN SOLUTION per_patch: apply the chord bound to the largest second difference
    check_tolerance(tolerance)?;
    if !control.iter().all(|p| p.is_finite()) {
        return Err(TessError::NonFinite {
            what: "a control point",
        });
    }
    let second = control
        .windows(3)
        .map(|w| (w[2] - 2.0 * w[1] + w[0]).length())
        .fold(0.0, f64::max);
    Ok(segments(control.len().saturating_sub(1), second, tolerance))
    // END SOLUTION
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
    // BEGIN SOLUTION per_patch: the curve bound along the columns (u) and rows (v)
    check_tolerance(tolerance)?;
    let largest = |polygons: Vec<Vec<DVec3>>| {
        polygons
            .iter()
            .flat_map(|p| p.windows(3).map(|w| (w[2] - 2.0 * w[1] + w[0]).length()))
            .fold(0.0, f64::max)
    };
    let (p, q) = patch.degrees();
    let m_u = largest((0..=q).map(|j| patch.control_column(j)).collect());
    let m_v = largest((0..=p).map(|i| patch.control_row(i)).collect());
    Ok([
        segments(p, m_u, tolerance).max(MIN_INNER_SEGMENTS),
        segments(q, m_v, tolerance).max(MIN_INNER_SEGMENTS),
    ])
    // END SOLUTION
}

// BEGIN SOLUTION
/// `⌈sqrt(n(n − 1) M / (8 · tolerance))⌉` clamped to `1..=MAX_SEGMENTS`.
fn segments(degree: usize, second_difference: f64, tolerance: f64) -> usize {
    if degree < 2 {
        return 1;
    }
    let k = (degree as f64 * (degree - 1) as f64 * second_difference / (8.0 * tolerance))
        .sqrt()
        .ceil();
    // NaN (never, with finite inputs) and huge values end up at the limit.
    if k >= MAX_SEGMENTS as f64 || k.is_nan() {
        MAX_SEGMENTS
    } else {
        (k as usize).max(1)
    }
}

fn check_tolerance(tolerance: f64) -> Result<(), TessError> {
    if tolerance.is_finite() && tolerance > 0.0 {
        Ok(())
    } else {
        Err(TessError::NotPositive {
            what: "the tolerance",
            value: tolerance,
        })
    }
}

/// A point of patch `(row, col)` at local parameters `local`, with its
/// global parameters `(col + u, row + v)`.
fn sample(grid: &PatchGrid<impl GridPatch>, row: usize, col: usize, local: DVec2) -> SurfaceSample {
    let point = grid.patch(row, col).sample(local);
    SurfaceSample {
        uv: local + DVec2::new(col as f64, row as f64),
        ..point
    }
}

/// `0, 1/k, …, 1` without rounding drift at the end.
fn steps(k: usize) -> Vec<f64> {
    (0..=k)
        .map(|s| if s == k { 1.0 } else { s as f64 / k as f64 })
        .collect()
}
// END SOLUTION

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
    // BEGIN SOLUTION per_patch: share corners and boundary-curve points, then grid + zipped ring per patch
    check_tolerance(tolerance)?;
    let (rows, cols) = (grid.rows(), grid.cols());
    let mut mesh = Mesh::new();
    // Corners, evaluated by the patch below-left of them where there is one.
    let mut corner = vec![vec![0_u32; cols + 1]; rows + 1];
    for (r, line) in corner.iter_mut().enumerate() {
        for (c, index) in line.iter_mut().enumerate() {
            let (pr, pc) = (r.min(rows - 1), c.min(cols - 1));
            let local = DVec2::new((c - pc) as f64, (r - pr) as f64);
            *index = mesh.push_vertex(sample(grid, pr, pc, local));
        }
    }
    // Boundary curves: inner points with their local parameters.
    let mut horizontal = vec![vec![(Vec::new(), Vec::new()); cols]; rows + 1];
    for (r, line) in horizontal.iter_mut().enumerate() {
        for (c, curve) in line.iter_mut().enumerate() {
            let k = curve_segments(&grid.horizontal_curve(r, c), tolerance)?;
            let ts = steps(k);
            let pr = r.min(rows - 1);
            let v = (r - pr) as f64;
            let ids = ts[1..k]
                .iter()
                .map(|&t| mesh.push_vertex(sample(grid, pr, c, DVec2::new(t, v))))
                .collect();
            *curve = (ids, ts);
        }
    }
    let mut vertical = vec![vec![(Vec::new(), Vec::new()); cols + 1]; rows];
    for (r, line) in vertical.iter_mut().enumerate() {
        for (c, curve) in line.iter_mut().enumerate() {
            let k = curve_segments(&grid.vertical_curve(r, c), tolerance)?;
            let ts = steps(k);
            let pc = c.min(cols - 1);
            let u = (c - pc) as f64;
            let ids = ts[1..k]
                .iter()
                .map(|&t| mesh.push_vertex(sample(grid, r, pc, DVec2::new(u, t))))
                .collect();
            *curve = (ids, ts);
        }
    }
    for r in 0..rows {
        for c in 0..cols {
            let [n_u, n_v] = patch_resolution(grid.patch(r, c), tolerance)?;
            let (us, vs) = (steps(n_u), steps(n_v));
            // Inner grid (i, j) for 0 < i < n_u, 0 < j < n_v.
            let first = mesh.vertex_count() as u32;
            for &v in &vs[1..n_v] {
                for &u in &us[1..n_u] {
                    mesh.push_vertex(sample(grid, r, c, DVec2::new(u, v)));
                }
            }
            let inner = |i: usize, j: usize| first + ((j - 1) * (n_u - 1) + (i - 1)) as u32;
            for j in 1..n_v - 1 {
                for i in 1..n_u - 1 {
                    let (a, b, cc, d) = (
                        inner(i, j),
                        inner(i + 1, j),
                        inner(i + 1, j + 1),
                        inner(i, j + 1),
                    );
                    mesh.triangles.push([a, b, cc]);
                    mesh.triangles.push([a, cc, d]);
                }
            }
            // The ring, side by side, counter-clockwise: keys run along each side.
            let path = |start: u32, middle: &[u32], end: u32| {
                let mut ids = vec![start];
                ids.extend_from_slice(middle);
                ids.push(end);
                ids
            };
            let flip = |ts: &[f64]| ts.iter().rev().map(|t| 1.0 - t).collect::<Vec<_>>();
            let reversed = |ids: &[u32]| ids.iter().rev().copied().collect::<Vec<_>>();
            let (bottom, bottom_t) = &horizontal[r][c];
            let (top, top_t) = &horizontal[r + 1][c];
            let (left, left_t) = &vertical[r][c];
            let (right, right_t) = &vertical[r][c + 1];
            let row_keys: Vec<f64> = us[1..n_u].to_vec();
            let col_keys: Vec<f64> = vs[1..n_v].to_vec();
            let sides = [
                (
                    path(corner[r][c], bottom, corner[r][c + 1]),
                    bottom_t.clone(),
                    (1..n_u).map(|i| inner(i, 1)).collect::<Vec<_>>(),
                    row_keys.clone(),
                ),
                (
                    path(corner[r][c + 1], right, corner[r + 1][c + 1]),
                    right_t.clone(),
                    (1..n_v).map(|j| inner(n_u - 1, j)).collect(),
                    col_keys.clone(),
                ),
                (
                    path(corner[r + 1][c + 1], &reversed(top), corner[r + 1][c]),
                    flip(top_t),
                    (1..n_u).rev().map(|i| inner(i, n_v - 1)).collect(),
                    flip(&row_keys),
                ),
                (
                    path(corner[r + 1][c], &reversed(left), corner[r][c]),
                    flip(left_t),
                    (1..n_v).rev().map(|j| inner(1, j)).collect(),
                    flip(&col_keys),
                ),
            ];
            for (outer, outer_keys, inner_ids, inner_keys) in &sides {
                stitch(
                    outer,
                    outer_keys,
                    inner_ids,
                    inner_keys,
                    &mut mesh.triangles,
                );
            }
        }
    }
    Ok(mesh)
    // END SOLUTION
}
