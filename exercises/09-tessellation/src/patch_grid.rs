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

use crate::bezier::{BezierPatch, Evaluate, RationalPatch};
use crate::error::TessError;

/// Control points of neighbours must agree to this distance (relative to
/// the size of the control net) to count as one boundary curve.
pub const CONTINUITY_TOLERANCE: f64 = 1e-9;

/// The largest number of patches per direction.
pub const MAX_PATCHES: usize = 64;

/// What a patch of a grid offers besides evaluation: its degrees and its
/// control polygons, with their weights (all 1 for a polynomial patch).
/// A [`RationalPatch`]'s polygons are its control points `P_ij`, not
/// weighted: a flatness bound drawn from them (task 2) is an estimate for a
/// rational patch, as it already is across a patch's twist.
pub trait GridPatch: Evaluate {
    /// Its degrees `(p, q)` in `u` and `v`.
    fn degrees(&self) -> (usize, usize);
    /// Row `i` of the control net, `P_i0 … P_iq`: a curve in `v`.
    fn control_row(&self, i: usize) -> Vec<DVec3>;
    /// Column `j` of the control net, `P_0j … P_pj`: a curve in `u`.
    fn control_column(&self, j: usize) -> Vec<DVec3>;
    /// The weights of row `i`.
    fn row_weights(&self, i: usize) -> Vec<f64>;
    /// The weights of column `j`.
    fn column_weights(&self, j: usize) -> Vec<f64>;
}

impl GridPatch for BezierPatch {
    fn degrees(&self) -> (usize, usize) {
        (self.degree_u(), self.degree_v())
    }
    fn control_row(&self, i: usize) -> Vec<DVec3> {
        self.row(i).to_vec()
    }
    fn control_column(&self, j: usize) -> Vec<DVec3> {
        self.column(j)
    }
    fn row_weights(&self, _: usize) -> Vec<f64> {
        vec![1.0; self.degree_v() + 1]
    }
    fn column_weights(&self, _: usize) -> Vec<f64> {
        vec![1.0; self.degree_u() + 1]
    }
}

impl GridPatch for RationalPatch {
    fn degrees(&self) -> (usize, usize) {
        (self.points().degree_u(), self.points().degree_v())
    }
    fn control_row(&self, i: usize) -> Vec<DVec3> {
        self.points().row(i).to_vec()
    }
    fn control_column(&self, j: usize) -> Vec<DVec3> {
        self.points().column(j)
    }
    fn row_weights(&self, i: usize) -> Vec<f64> {
        (0..=self.points().degree_v())
            .map(|j| self.weight(i, j))
            .collect()
    }
    fn column_weights(&self, j: usize) -> Vec<f64> {
        (0..=self.points().degree_u())
            .map(|i| self.weight(i, j))
            .collect()
    }
}

/// Patches in `rows × cols`, row-major, sharing boundary curves:
/// [`BezierPatch`]es, or [`RationalPatch`]es (a NURBS surface split into
/// its Bézier patches).
#[derive(Clone, Debug, PartialEq)]
pub struct PatchGrid<P = BezierPatch> {
    rows: usize,
    cols: usize,
    patches: Vec<P>,
}

impl<P: GridPatch> PatchGrid<P> {
    /// A grid of `rows × cols` patches, row-major (`patches[row · cols + col]`).
    ///
    /// # Errors
    /// [`TessError::Resolution`] for zero or more than [`MAX_PATCHES`] rows
    /// or columns, [`TessError::ControlGrid`] for the wrong number of
    /// patches, [`TessError::NotContinuous`] where neighbours do not share
    /// their boundary curve (different degrees along it, or control points
    /// further apart than [`CONTINUITY_TOLERANCE`] × the net's size).
    pub fn try_new(rows: usize, cols: usize, patches: Vec<P>) -> Result<Self, TessError> {
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
            .flat_map(|p| (0..=p.degrees().0).flat_map(|i| p.control_row(i)))
            .fold(0.0_f64, |m, p| m.max(p.abs().max_element()))
            .max(1.0);
        let same = |(a, wa): (Vec<DVec3>, Vec<f64>), (b, wb): (Vec<DVec3>, Vec<f64>)| {
            a.len() == b.len()
                && wa == wb
                && a.iter()
                    .zip(&b)
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
                let (p, q) = patch.degrees();
                let row_of = |patch: &P, i: usize| (patch.control_row(i), patch.row_weights(i));
                let column_of =
                    |patch: &P, j: usize| (patch.control_column(j), patch.column_weights(j));
                if col + 1 < cols && !same(row_of(patch, p), row_of(grid.patch(row, col + 1), 0)) {
                    return Err(TessError::NotContinuous {
                        row,
                        col,
                        side: "right",
                    });
                }
                if row + 1 < rows
                    && !same(column_of(patch, q), column_of(grid.patch(row + 1, col), 0))
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
    pub fn patch(&self, row: usize, col: usize) -> &P {
        assert!(row < self.rows && col < self.cols, "patch out of range");
        &self.patches[row * self.cols + col]
    }

    /// The control polygon of the boundary curve `v = row` between `u = col`
    /// and `u = col + 1` (`row` in `0..=rows`): the lower boundary of patch
    /// `(row, col)`, or the upper boundary of the last row.
    #[must_use]
    pub fn horizontal_curve(&self, row: usize, col: usize) -> Vec<DVec3> {
        if row < self.rows {
            self.patch(row, col).control_column(0)
        } else {
            let patch = self.patch(row - 1, col);
            patch.control_column(patch.degrees().1)
        }
    }

    /// The control polygon of the boundary curve `u = col` between `v = row`
    /// and `v = row + 1` (`col` in `0..=cols`).
    #[must_use]
    pub fn vertical_curve(&self, row: usize, col: usize) -> Vec<DVec3> {
        if col < self.cols {
            self.patch(row, col).control_row(0)
        } else {
            let patch = self.patch(row, col - 1);
            patch.control_row(patch.degrees().0)
        }
    }
}

impl PatchGrid {
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
}

impl PatchGrid<RationalPatch> {
    /// The NURBS torus around the `z` axis ([`RationalPatch::torus`]) as a
    /// 4 × 4 grid: row `r` the quarter `r` of the tube, column `c` the
    /// quarter `c` around the axis. The grid's outer boundary curves meet
    /// again where the torus closes (column 4's curve is column 0's, row
    /// 4's is row 0's): the same control points, so a tessellation that
    /// splits each curve from its control polygon alone puts the same
    /// points on both.
    ///
    /// # Panics
    /// Unless `0 < minor < major`.
    #[must_use]
    pub fn torus(major: f64, minor: f64) -> Self {
        Self::try_new(4, 4, RationalPatch::torus(major, minor)).expect("the torus's patches meet")
    }
}
