//! Given code: the control net of a tensor-product Bézier surface
//! (seed 000, §2.4), validated once on construction.

use glam::DVec3;

use crate::basics::{BezierError, MAX_DEGREE};

/// The `n_u × n_v` control points `P_{i,j}` of a Bézier surface
///
/// ```text
///   P(u, v) = Σ_{i=0}^{n} Σ_{j=0}^{m} B_{i,n}(u) · B_{j,m}(v) · P_{i,j}
///   with n = n_u − 1 (degree in u), m = n_v − 1 (degree in v)
/// ```
///
/// stored row-major: `P_{i,j}` at index `i · n_v + j`, so row `i` is the
/// v-curve `P_{i,0} … P_{i,m}`. (The seed's patch buffer of 16 vertices is
/// the transpose: its consecutive vertices run along u, index `4 j + i`.)
///
/// ```text
///        v ↑   P_{0,3} P_{1,3} P_{2,3} P_{3,3}
///          │   P_{0,2}   ·       ·   P_{3,2}
///          │   P_{0,1}   ·       ·   P_{3,1}
///          │   P_{0,0} P_{1,0} P_{2,0} P_{3,0}
///          └──────────────────────────────→ u
/// ```
///
/// Every net that exists is valid: at least 1 × 1 points, at most
/// `MAX_DEGREE + 1` in each direction, all finite.
#[derive(Clone, Debug, PartialEq)]
pub struct ControlNet {
    n_u: usize,
    n_v: usize,
    points: Vec<DVec3>,
}

impl ControlNet {
    /// A net of `n_u × n_v` points given row-major (`P_{i,j}` at `i · n_v + j`).
    ///
    /// # Errors
    /// [`BezierError::Empty`] if a dimension is 0,
    /// [`BezierError::DegreeTooHigh`] if one exceeds `MAX_DEGREE + 1`,
    /// [`BezierError::NetShape`] if `points.len() ≠ n_u · n_v`,
    /// [`BezierError::NonFinitePoint`] for a NaN or infinite coordinate.
    pub fn new(n_u: usize, n_v: usize, points: Vec<DVec3>) -> Result<Self, BezierError> {
        if n_u == 0 || n_v == 0 {
            return Err(BezierError::Empty);
        }
        let degree = n_u.max(n_v) - 1;
        if degree > MAX_DEGREE {
            return Err(BezierError::DegreeTooHigh {
                degree,
                max: MAX_DEGREE,
            });
        }
        let expected = n_u * n_v;
        if points.len() != expected {
            return Err(BezierError::NetShape {
                n_u,
                n_v,
                expected,
                got: points.len(),
            });
        }
        if let Some(index) = points.iter().position(|p| !p.is_finite()) {
            return Err(BezierError::NonFinitePoint { index });
        }
        Ok(Self { n_u, n_v, points })
    }

    /// The seed's default surface (Listing 16): a flat 4 × 4 grid over
    /// `[-0.5, 0.5]²` in the plane y = 0 whose four inner points are
    /// lifted to y = 0.5 — a hill. u runs along +x, v along −z, so the
    /// normal `∂P/∂u × ∂P/∂v` points up (+y).
    #[must_use]
    pub fn seed_hill() -> Self {
        let mut points = Vec::with_capacity(16);
        for i in 0..4 {
            for j in 0..4 {
                let x = -0.5 + f64::from(i) / 3.0;
                let z = 0.5 - f64::from(j) / 3.0;
                let inner = (1..=2).contains(&i) && (1..=2).contains(&j);
                let y = if inner { 0.5 } else { 0.0 };
                points.push(DVec3::new(x, y, z));
            }
        }
        Self {
            n_u: 4,
            n_v: 4,
            points,
        }
    }

    /// Points in u (`n + 1`).
    #[must_use]
    pub fn n_u(&self) -> usize {
        self.n_u
    }

    /// Points in v (`m + 1`).
    #[must_use]
    pub fn n_v(&self) -> usize {
        self.n_v
    }

    /// The degree in u, `n = n_u − 1`.
    #[must_use]
    pub fn degree_u(&self) -> usize {
        self.n_u - 1
    }

    /// The degree in v, `m = n_v − 1`.
    #[must_use]
    pub fn degree_v(&self) -> usize {
        self.n_v - 1
    }

    /// `P_{i,j}`.
    ///
    /// # Panics
    /// If `i ≥ n_u` or `j ≥ n_v` (a programming error, like slice indexing).
    #[must_use]
    pub fn point(&self, i: usize, j: usize) -> DVec3 {
        assert!(
            i < self.n_u && j < self.n_v,
            "P[{i}][{j}] is outside the net"
        );
        self.points[i * self.n_v + j]
    }

    /// Row `i`: the v-curve `P_{i,0} … P_{i,m}`.
    ///
    /// # Panics
    /// If `i ≥ n_u`.
    #[must_use]
    pub fn row(&self, i: usize) -> &[DVec3] {
        &self.points[i * self.n_v..(i + 1) * self.n_v]
    }

    /// Column `j`: the u-curve `P_{0,j} … P_{n,j}` (copied; it is strided).
    ///
    /// # Panics
    /// If `j ≥ n_v`.
    #[must_use]
    pub fn column(&self, j: usize) -> Vec<DVec3> {
        (0..self.n_u).map(|i| self.point(i, j)).collect()
    }

    /// All points, row-major.
    #[must_use]
    pub fn points(&self) -> &[DVec3] {
        &self.points
    }

    /// The net with `f` applied to every point, e.g. an affine map.
    ///
    /// # Errors
    /// [`BezierError::NonFinitePoint`] if `f` produces a NaN or infinity.
    pub fn map(&self, f: impl Fn(DVec3) -> DVec3) -> Result<Self, BezierError> {
        Self::new(
            self.n_u,
            self.n_v,
            self.points.iter().map(|&p| f(p)).collect(),
        )
    }
}
