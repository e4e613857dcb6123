//! A surface made of several Bézier patches in a rectangular grid, the
//! shape a NURBS surface takes after it is split into Bézier patches (seed
//! 001 §2.1: "NURBS surfaces are converted into a set of Bézier patches").
//!
//! Patch `(row, col)` covers the global parameters `u ∈ [col, col + 1]`,
//! `v ∈ [row, row + 1]`. Neighbours share their boundary curve exactly: the
//! last control row (`i = p`) of a patch is the first row (`i = 0`) of its
//! right neighbour, and its last control column (`j = q`) is the first
//! column (`j = 0`) of its upper neighbour.
//!
//! ```text
//!   v ▲  ┌────────┬────────┐
//!     │  │ (1, 0) │ (1, 1) │     the boundary curve between (0, 0) and (0, 1)
//!     │  ├────────┼────────┤     is one curve, evaluated once: both
//!     │  │ (0, 0) │ (0, 1) │     neighbours use the same points
//!     │  └────────┴────────┘
//!     └──────────────────────▶ u
//! ```

use glam::DVec3;

use crate::bezier::BezierPatch;
use crate::error::TessError;

/// Control points of neighbours must agree to this distance (relative to
/// the size of the control net) to count as one boundary curve.
pub const CONTINUITY_TOLERANCE: f64 = 1e-9;

/// The largest number of patches per direction.
pub const MAX_PATCHES: usize = 64;

/// Patches in `rows × cols`, row-major, sharing boundary curves.
#[derive(Clone, Debug, PartialEq)]
pub struct PatchGrid {
    rows: usize,
    cols: usize,
    patches: Vec<BezierPatch>,
}

impl PatchGrid {
    /// A grid of `rows × cols` patches, row-major (`patches[row · cols + col]`).
    ///
    /// # Errors
    /// [`TessError::Resolution`] for zero or more than [`MAX_PATCHES`] rows
    /// or columns, [`TessError::ControlGrid`] for the wrong number of
    /// patches, [`TessError::NotContinuous`] where neighbours do not share
    /// their boundary curve (different degrees along it, or control points
    /// further apart than [`CONTINUITY_TOLERANCE`] × the net's size).
    pub fn try_new(rows: usize, cols: usize, patches: Vec<BezierPatch>) -> Result<Self, TessError> {
        for n in [rows, cols] {
            if n == 0 || n > MAX_PATCHES {
                return Err(TessError::Resolution(n));
            }
        }
        if patches.len() != rows * cols {
            return Err(TessError::ControlGrid {
                degree_u: rows,
                degree_v: cols,
                expected: rows * cols,
                found: patches.len(),
            });
        }
        let size = patches
            .iter()
            .flat_map(|p| p.control_points())
            .fold(0.0_f64, |m, p| m.max(p.abs().max_element()))
            .max(1.0);
        let same = |a: &[DVec3], b: &[DVec3]| {
            a.len() == b.len()
                && a.iter()
                    .zip(b)
                    .all(|(x, y)| x.distance(*y) <= CONTINUITY_TOLERANCE * size)
        };
        let grid = Self {
            rows,
            cols,
            patches,
        };
        for row in 0..rows {
            for col in 0..cols {
                let patch = grid.patch(row, col);
                if col + 1 < cols
                    && !same(patch.row(patch.degree_u()), grid.patch(row, col + 1).row(0))
                {
                    return Err(TessError::NotContinuous {
                        row,
                        col,
                        side: "right",
                    });
                }
                if row + 1 < rows
                    && !same(
                        &patch.column(patch.degree_v()),
                        &grid.patch(row + 1, col).column(0),
                    )
                {
                    return Err(TessError::NotContinuous {
                        row,
                        col,
                        side: "upper",
                    });
                }
            }
        }
        Ok(grid)
    }

    /// A 2 × 2 grid of bicubic patches over `[0, 2]²`: a gentle slope with a
    /// bump in the upper-right patch, so that the patches want different
    /// resolutions. Control points are heights sampled on a 7 × 7 lattice;
    /// patch `(r, c)` takes lattice points `3c..=3c+3 × 3r..=3r+3`, so
    /// neighbours share a lattice row.
    #[must_use]
    pub fn example() -> Self {
        const LATTICE: usize = 7;
        let height = |x: f64, y: f64| {
            0.1 * x + 0.8 * (-((x - 1.5).powi(2) + (y - 1.5).powi(2)) / 0.15).exp()
        };
        let point = |a: usize, b: usize| {
            let (x, y) = (
                2.0 * a as f64 / (LATTICE - 1) as f64,
                2.0 * b as f64 / (LATTICE - 1) as f64,
            );
            DVec3::new(x, y, height(x, y))
        };
        let mut patches = Vec::new();
        for r in 0..2 {
            for c in 0..2 {
                let mut points = Vec::new();
                for i in 0..=3 {
                    for j in 0..=3 {
                        points.push(point(3 * c + i, 3 * r + j));
                    }
                }
                patches.push(BezierPatch::try_new(3, 3, points).expect("a 4 × 4 net"));
            }
        }
        Self::try_new(2, 2, patches).expect("neighbours share lattice rows")
    }

    /// Rows of patches (along `v`).
    #[must_use]
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Columns of patches (along `u`).
    #[must_use]
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// Patch `(row, col)`.
    ///
    /// # Panics
    /// If `row` or `col` is out of range.
    #[must_use]
    pub fn patch(&self, row: usize, col: usize) -> &BezierPatch {
        assert!(row < self.rows && col < self.cols, "patch out of range");
        &self.patches[row * self.cols + col]
    }

    /// The control polygon of the boundary curve `v = row` between `u = col`
    /// and `u = col + 1` (`row` in `0..=rows`): the lower boundary of patch
    /// `(row, col)`, or the upper boundary of the last row.
    #[must_use]
    pub fn horizontal_curve(&self, row: usize, col: usize) -> Vec<DVec3> {
        if row < self.rows {
            self.patch(row, col).column(0)
        } else {
            let patch = self.patch(row - 1, col);
            patch.column(patch.degree_v())
        }
    }

    /// The control polygon of the boundary curve `u = col` between `v = row`
    /// and `v = row + 1` (`col` in `0..=cols`).
    #[must_use]
    pub fn vertical_curve(&self, row: usize, col: usize) -> Vec<DVec3> {
        if col < self.cols {
            self.patch(row, col).row(0).to_vec()
        } else {
            let patch = self.patch(row, col - 1);
            patch.row(patch.degree_u()).to_vec()
        }
    }
}
