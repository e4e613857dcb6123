//! The tensor-product Bézier patch (seed 000 §2.4, seed 001 Definition
//! 1.1.4 with all weights 1): its control net, validated once, in the one
//! layout every topic uses.
//!
//! A patch of degree `p × q` has `(p + 1)(q + 1)` control points `P_ij`,
//! `i` along `u`, `j` along `v`, stored row by row with `j` running fastest
//! (`P_ij` at `i · (q + 1) + j`, the order of geomdl's
//! `set_ctrlpts(points, size_u, size_v)` in seed 001):
//!
//! ```text
//!   S(u, v) = Σ_i Σ_j B_i,p(u) B_j,q(v) P_ij,     0 ≤ u, v ≤ 1
//!
//!        v ↑   P_03  P_13  P_23  P_33        row i = P_i0 … P_iq: a curve in v
//!          │   P_02    ·     ·   P_32        column j = P_0j … P_pj: a curve in u
//!          │   P_01    ·     ·   P_31
//!          │   P_00  P_10  P_20  P_30
//!          └──────────────────────────→ u
//! ```
//!
//! (The seed's GPU patch buffer of 16 vertices is the transpose: its
//! consecutive vertices run along u, index `4 j + i`; topic 10 writes it
//! that way for the GPU.)
//!
//! Evaluating a patch is what the topics teach (de Casteljau in topic 07
//! and in topic 10's WGSL) or give in their own way (topic 09's power
//! form): this module holds only the points.

use glam::{DVec2, DVec3};

/// The largest degree in either direction.
pub const MAX_DEGREE: usize = 32;

/// Why a control net is not a patch.
#[transcript::evidence]
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PatchError {
    /// A degree above [`MAX_DEGREE`].
    #[error("degree {degree} is above the maximum {max}")]
    DegreeTooHigh {
        /// The degree asked for.
        degree: usize,
        /// [`MAX_DEGREE`].
        max: usize,
    },
    /// Not `(degree_u + 1) · (degree_v + 1)` control points.
    #[error("a patch of degree {degree_u} × {degree_v} has {expected} control points, not {found}")]
    Shape {
        /// Degree in u.
        degree_u: usize,
        /// Degree in v.
        degree_v: usize,
        /// `(degree_u + 1) · (degree_v + 1)`.
        expected: usize,
        /// What was given.
        found: usize,
    },
    /// A NaN or infinite coordinate.
    #[error("control point {index} is not finite")]
    NonFinite {
        /// Its index in the row-by-row order.
        index: usize,
    },
    /// A weight of a rational patch that is not finite and positive.
    #[error("weight {index} is not finite and positive")]
    Weight {
        /// Its index in the row-by-row order.
        index: usize,
    },
    /// Degree elevation asked to lower a degree.
    #[error("a patch of degree {degree_u} × {degree_v} cannot be elevated to {to_u} × {to_v}")]
    Lower {
        /// Degree in u.
        degree_u: usize,
        /// Degree in v.
        degree_v: usize,
        /// The degree asked for in u.
        to_u: usize,
        /// The degree asked for in v.
        to_v: usize,
    },
}

/// A tensor-product Bézier patch: degree `p × q` and its control points,
/// row by row (module documentation). Every patch that exists is valid:
/// degrees at most [`MAX_DEGREE`], the right number of points, all finite.
#[derive(Clone, Debug, PartialEq)]
pub struct BezierPatch {
    degree_u: usize,
    degree_v: usize,
    points: Vec<DVec3>,
}

impl BezierPatch {
    /// A patch of degree `degree_u × degree_v` from its control points, row
    /// by row (`P_00, P_01, …, P_0q, P_10, …`).
    ///
    /// # Errors
    /// [`PatchError::DegreeTooHigh`] above [`MAX_DEGREE`],
    /// [`PatchError::Shape`] for a wrong number of points,
    /// [`PatchError::NonFinite`] for a NaN or infinite coordinate.
    pub fn try_new(
        degree_u: usize,
        degree_v: usize,
        points: Vec<DVec3>,
    ) -> Result<Self, PatchError> {
        for degree in [degree_u, degree_v] {
            if degree > MAX_DEGREE {
                return Err(PatchError::DegreeTooHigh {
                    degree,
                    max: MAX_DEGREE,
                });
            }
        }
        let expected = (degree_u + 1) * (degree_v + 1);
        if points.len() != expected {
            return Err(PatchError::Shape {
                degree_u,
                degree_v,
                expected,
                found: points.len(),
            });
        }
        if let Some(index) = points.iter().position(|p| !p.is_finite()) {
            return Err(PatchError::NonFinite { index });
        }
        Ok(Self {
            degree_u,
            degree_v,
            points,
        })
    }

    /// The patch whose `P_ij` is `point(i, j)`.
    ///
    /// # Errors
    /// As [`BezierPatch::try_new`] (the shape is right by construction).
    pub fn from_fn(
        degree_u: usize,
        degree_v: usize,
        mut point: impl FnMut(usize, usize) -> DVec3,
    ) -> Result<Self, PatchError> {
        if degree_u.max(degree_v) > MAX_DEGREE {
            return Self::try_new(degree_u, degree_v, Vec::new());
        }
        let mut points = Vec::with_capacity((degree_u + 1) * (degree_v + 1));
        for i in 0..=degree_u {
            for j in 0..=degree_v {
                points.push(point(i, j));
            }
        }
        Self::try_new(degree_u, degree_v, points)
    }

    /// Seed 001's example surface (Example 1.1.5): 4 × 3 control points,
    /// degree 3 in `u` and 2 in `v`. Its corner `(0, 0)` is degenerate:
    /// `P_01 = P_10`, so both tangents there are parallel (this is the
    /// "magnitude of the vector is zero" the seed's code catches).
    #[must_use]
    pub fn seed_surface() -> Self {
        let p = |x: f64, y: f64, z: f64| DVec3::new(x, y, z);
        let points = vec![
            p(4.0, 7.0, 11.0),
            p(6.0, 8.0, 11.0),
            p(5.0, 5.0, 5.0),
            p(6.0, 8.0, 11.0),
            p(7.0, 10.0, 12.0),
            p(6.0, 11.0, 3.0),
            p(7.0, 5.0, 3.0),
            p(7.0, 7.0, 3.0),
            p(7.0, 11.0, 6.0),
            p(9.0, 7.0, 3.0),
            p(9.0, 9.0, 0.0),
            p(9.0, 11.0, 5.0),
        ];
        Self {
            degree_u: 3,
            degree_v: 2,
            points,
        }
    }

    /// Seed 000's default surface (Listing 16): a flat bicubic grid over
    /// `[-0.5, 0.5]²` in the plane y = 0 whose four inner points are lifted
    /// to y = 0.5 — a hill. u runs along +x, v along −z, so the normal
    /// `∂S/∂u × ∂S/∂v` points up (+y).
    #[must_use]
    pub fn seed_hill() -> Self {
        Self::grid(|i, j| {
            let x = -0.5 + i as f64 / 3.0;
            let z = 0.5 - j as f64 / 3.0;
            let inner = (1..=2).contains(&i) && (1..=2).contains(&j);
            DVec3::new(x, if inner { 0.5 } else { 0.0 }, z)
        })
    }

    /// The flat bicubic patch over `[lo.x, hi.x] × [lo.y, hi.y]` at height
    /// `z`, control points evenly spaced, so that
    /// `S(u, v) = (lerp(lo.x, hi.x, u), lerp(lo.y, hi.y, v), z)` exactly
    /// (Bernstein polynomials reproduce linear functions).
    ///
    /// # Panics
    /// If a coordinate is not finite.
    #[must_use]
    pub fn flat(lo: DVec2, hi: DVec2, z: f64) -> Self {
        Self::height_field(lo, hi, [[z; 4]; 4])
    }

    /// A bicubic height field over `[lo.x, hi.x] × [lo.y, hi.y]`: `P_ij` at
    /// `(lerp(lo.x, hi.x, i/3), lerp(lo.y, hi.y, j/3), heights[j][i])`, so
    /// that `x` and `y` are linear in `u` and `v`. (`heights` is written as
    /// seen from above: row `j` along `u`.)
    ///
    /// # Panics
    /// If a coordinate is not finite.
    #[must_use]
    pub fn height_field(lo: DVec2, hi: DVec2, heights: [[f64; 4]; 4]) -> Self {
        Self::grid(|i, j| {
            let s = DVec2::new(i as f64, j as f64) / 3.0;
            (lo + (hi - lo) * s).extend(heights[j][i])
        })
    }

    /// A bicubic patch of the points `point(i, j)`.
    fn grid(point: impl FnMut(usize, usize) -> DVec3) -> Self {
        Self::from_fn(3, 3, point).expect("a bicubic patch of finite points")
    }

    /// Degree in `u`, `p`.
    #[must_use]
    pub fn degree_u(&self) -> usize {
        self.degree_u
    }

    /// Degree in `v`, `q`.
    #[must_use]
    pub fn degree_v(&self) -> usize {
        self.degree_v
    }

    /// Control point `P_ij` (`i ≤ p`, `j ≤ q`).
    ///
    /// # Panics
    /// If `i` or `j` is out of range (a programming error, like slice
    /// indexing).
    #[must_use]
    pub fn control_point(&self, i: usize, j: usize) -> DVec3 {
        assert!(
            i <= self.degree_u && j <= self.degree_v,
            "P_{i}{j} is outside a patch of degree {} × {}",
            self.degree_u,
            self.degree_v
        );
        self.points[i * (self.degree_v + 1) + j]
    }

    /// All control points, row by row.
    #[must_use]
    pub fn control_points(&self) -> &[DVec3] {
        &self.points
    }

    /// Row `i`, `P_i0 … P_iq`: the control polygon of a curve in `v`.
    ///
    /// # Panics
    /// If `i > p`.
    #[must_use]
    pub fn row(&self, i: usize) -> &[DVec3] {
        let n = self.degree_v + 1;
        &self.points[i * n..(i + 1) * n]
    }

    /// Column `j`, `P_0j … P_pj`: the control polygon of a curve in `u`.
    ///
    /// # Panics
    /// If `j > q`.
    #[must_use]
    pub fn column(&self, j: usize) -> Vec<DVec3> {
        (0..=self.degree_u)
            .map(|i| self.control_point(i, j))
            .collect()
    }

    /// The patch with every control point mapped by `f` (an affine map
    /// gives the mapped surface: Bézier patches are affinely invariant).
    ///
    /// # Errors
    /// [`PatchError::NonFinite`] if `f` makes a point NaN or infinite.
    pub fn map(&self, f: impl Fn(DVec3) -> DVec3) -> Result<Self, PatchError> {
        Self::try_new(
            self.degree_u,
            self.degree_v,
            self.points.iter().map(|&p| f(p)).collect(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_are_stored_row_by_row() {
        let patch = BezierPatch::from_fn(2, 1, |i, j| DVec3::new(i as f64, j as f64, 0.0)).unwrap();
        assert_eq!(patch.control_points()[3], DVec3::new(1.0, 1.0, 0.0));
        assert_eq!(
            patch.row(2),
            &[DVec3::new(2.0, 0.0, 0.0), DVec3::new(2.0, 1.0, 0.0)]
        );
        assert_eq!(patch.column(1).len(), 3);
        assert_eq!(patch.control_point(1, 0), DVec3::X);
    }

    #[test]
    fn bad_nets_are_clear_errors() {
        assert_eq!(
            BezierPatch::try_new(1, 1, vec![DVec3::ZERO; 3]),
            Err(PatchError::Shape {
                degree_u: 1,
                degree_v: 1,
                expected: 4,
                found: 3
            })
        );
        assert_eq!(
            BezierPatch::from_fn(MAX_DEGREE + 1, 0, |_, _| DVec3::ZERO),
            Err(PatchError::DegreeTooHigh {
                degree: MAX_DEGREE + 1,
                max: MAX_DEGREE
            })
        );
        let mut points = vec![DVec3::ZERO; 4];
        points[2].y = f64::NAN;
        assert_eq!(
            BezierPatch::try_new(1, 1, points),
            Err(PatchError::NonFinite { index: 2 })
        );
        let hill = BezierPatch::seed_hill();
        assert!(matches!(
            hill.map(|p| p * f64::INFINITY),
            Err(PatchError::NonFinite { .. })
        ));
    }

    #[test]
    fn height_fields_are_linear_in_x_and_y() {
        let patch = BezierPatch::flat(DVec2::new(-1.0, 0.0), DVec2::new(2.0, 3.0), 0.5);
        assert_eq!(patch.control_point(0, 0), DVec3::new(-1.0, 0.0, 0.5));
        assert_eq!(patch.control_point(3, 0), DVec3::new(2.0, 0.0, 0.5));
        assert_eq!(patch.control_point(0, 3), DVec3::new(-1.0, 3.0, 0.5));
        assert_eq!(patch.control_point(1, 2), DVec3::new(0.0, 2.0, 0.5));
    }
}
