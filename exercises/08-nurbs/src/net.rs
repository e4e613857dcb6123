//! Homogeneous control points, control nets, and the NURBS curve and
//! surface types (given code: read it, do not edit it). The Bézier
//! patches a surface splits into are the course library's
//! `freeform::RationalPatch`: points `P = Pʷ.xyz / w` and weights `w`.
//!
//! **Homogeneous coordinates.** A control point `P = (x, y, z)` with weight
//! `w > 0` is stored as the 4-vector `Pʷ = (w·x, w·y, w·z, w)` (The NURBS
//! Book, §4.2). A rational curve is then a *polynomial* (B-spline or
//! Bézier) curve `Cʷ(u) = Σ Nᵢ(u) Pᵢʷ` in four dimensions, and the point is
//! its projection `C(u) = Cʷ.xyz / Cʷ.w` — seed 001's equations (1.4), (1.12)
//! and (1.15) written as one sum. Every algorithm of this crate works on
//! `Pʷ` and projects once at the end.
//!
//! **Nets.** A control net has `rows × columns` points, row `i` along `u`
//! and column `j` along `v`: `P_{i,j}` is stored at `i·columns + j`, so
//! `S(u, v) = Σᵢ Σⱼ N_{i,p}(u) N_{j,q}(v) P_{i,j}` as in seed 001 (1.15).
//!
//! ```text
//!        j →  (v)
//!   i  P00 P01 P02 P03
//!   ↓  P10 P11 P12 P13     rows = 3 (u), columns = 4 (v)
//!  (u) P20 P21 P22 P23
//! ```

use glam::{DVec3, DVec4};

use crate::knots::{Domain, KnotVector, NurbsError};

/// `Pʷ = (w·x, w·y, w·z, w)`: the homogeneous form of `point` with `weight`.
#[must_use]
pub fn homogeneous(point: DVec3, weight: f64) -> DVec4 {
    (point * weight).extend(weight)
}

/// `P = Pʷ.xyz / Pʷ.w`: the point a homogeneous vector stands for
/// (the perspective map `H` of The NURBS Book, §4.2). Infinite or NaN for
/// `w = 0`; the types of this crate never let that happen.
#[must_use]
pub fn project(homogeneous: DVec4) -> DVec3 {
    homogeneous.truncate() / homogeneous.w
}

/// Checks homogeneous control points: finite, with finite weights `> 0`.
pub fn check_homogeneous(points: &[DVec4]) -> Result<(), NurbsError> {
    if points.is_empty() {
        return Err(NurbsError::NoControlPoints);
    }
    for (index, p) in points.iter().enumerate() {
        if !(p.w.is_finite() && p.w > 0.0) {
            return Err(NurbsError::BadWeight { index, weight: p.w });
        }
        if !p.is_finite() {
            return Err(NurbsError::NonFinitePoint { index });
        }
    }
    Ok(())
}

/// A point on a curve and the first derivative there, `C(u)` and
/// `C′(u) = dC/du` (the course library's record, `freeform::CurvePoint`).
pub use freeform::CurvePoint;

/// A point on a surface and its two partial derivatives there, `S(u, v)`,
/// `S_u = ∂S/∂u` and `S_v = ∂S/∂v` (the course library's record,
/// `freeform::SurfacePoint`).
pub use freeform::SurfacePoint;

/// A grid of homogeneous control points, row `i` along `u`, column `j`
/// along `v` (see the module documentation).
#[transcript::evidence]
#[derive(Clone, Debug, PartialEq)]
pub struct ControlNet {
    rows: usize,
    columns: usize,
    points: Vec<DVec4>,
}

impl ControlNet {
    /// A net of `rows × columns` homogeneous points, row-major; checks the
    /// count, finiteness and weights `> 0`.
    pub fn try_new(rows: usize, columns: usize, points: Vec<DVec4>) -> Result<Self, NurbsError> {
        let expected = rows.saturating_mul(columns);
        if points.len() != expected {
            return Err(NurbsError::WrongCount {
                expected,
                got: points.len(),
            });
        }
        check_homogeneous(&points)?;
        Ok(Self {
            rows,
            columns,
            points,
        })
    }

    /// Points `P_{i,j}` as `rows` vectors of `columns` points each, with
    /// weights `w_{i,j}` in the same shape.
    pub fn from_points(points: &[Vec<DVec3>], weights: &[Vec<f64>]) -> Result<Self, NurbsError> {
        let rows = points.len();
        let columns = points.first().map_or(0, Vec::len);
        if weights.len() != rows {
            return Err(NurbsError::WrongCount {
                expected: rows,
                got: weights.len(),
            });
        }
        let mut net = Vec::with_capacity(rows * columns);
        for (row, row_weights) in points.iter().zip(weights) {
            for got in [row.len(), row_weights.len()] {
                if got != columns {
                    return Err(NurbsError::WrongCount {
                        expected: columns,
                        got,
                    });
                }
            }
            net.extend(
                row.iter()
                    .zip(row_weights)
                    .map(|(&p, &w)| homogeneous(p, w)),
            );
        }
        Self::try_new(rows, columns, net)
    }

    /// The number of rows (points along `u`).
    #[must_use]
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// The number of columns (points along `v`).
    #[must_use]
    pub fn columns(&self) -> usize {
        self.columns
    }

    /// `P_{i,j}ʷ`. Panics if `i ≥ rows` or `j ≥ columns`, like slice indexing.
    #[must_use]
    pub fn get(&self, i: usize, j: usize) -> DVec4 {
        assert!(j < self.columns, "column {j} of {}", self.columns);
        self.points[i * self.columns + j]
    }

    /// All points, row-major.
    #[must_use]
    pub fn points(&self) -> &[DVec4] {
        &self.points
    }

    /// Row `i` (the points `P_{i,0} … P_{i,columns−1}`).
    #[must_use]
    pub fn row(&self, i: usize) -> &[DVec4] {
        &self.points[i * self.columns..(i + 1) * self.columns]
    }

    /// The same net with `f` applied to every homogeneous point (for
    /// example an affine map applied as `homogeneous(A·project(p), w)`).
    pub fn try_map(&self, f: impl Fn(DVec4) -> DVec4) -> Result<Self, NurbsError> {
        Self::try_new(
            self.rows,
            self.columns,
            self.points.iter().copied().map(f).collect(),
        )
    }
}

/// A NURBS curve `C(u) = Σ N_{i,p}(u) wᵢ Pᵢ / Σ N_{i,p}(u) wᵢ` (seed 001,
/// Definition 1.3.1) on the domain of its knot vector.
#[transcript::evidence]
#[derive(Clone, Debug, PartialEq)]
pub struct NurbsCurve {
    knots: KnotVector,
    points: Vec<DVec4>,
}

impl NurbsCurve {
    /// A curve from a knot vector (which carries the degree) and homogeneous
    /// control points `Pᵢʷ`; their number must be `m − p`.
    pub fn try_new(knots: KnotVector, points: Vec<DVec4>) -> Result<Self, NurbsError> {
        check_homogeneous(&points)?;
        if points.len() != knots.control_points() {
            return Err(NurbsError::WrongCount {
                expected: knots.control_points(),
                got: points.len(),
            });
        }
        Ok(Self { knots, points })
    }

    /// A curve from points `Pᵢ` and weights `wᵢ`.
    pub fn from_points(
        knots: KnotVector,
        points: &[DVec3],
        weights: &[f64],
    ) -> Result<Self, NurbsError> {
        if weights.len() != points.len() {
            return Err(NurbsError::WrongCount {
                expected: points.len(),
                got: weights.len(),
            });
        }
        let homogeneous = points
            .iter()
            .zip(weights)
            .map(|(&p, &w)| homogeneous(p, w))
            .collect();
        Self::try_new(knots, homogeneous)
    }

    /// The degree `p`.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.knots.degree()
    }

    /// The knot vector.
    #[must_use]
    pub fn knots(&self) -> &KnotVector {
        &self.knots
    }

    /// The homogeneous control points `Pᵢʷ`.
    #[must_use]
    pub fn points(&self) -> &[DVec4] {
        &self.points
    }

    /// The parameter domain.
    #[must_use]
    pub fn domain(&self) -> Domain {
        self.knots.domain()
    }
}

/// A NURBS surface (seed 001, Definition 1.3.2): a control net, degree `p`
/// and knots `U` along `u` (rows), degree `q` and knots `V` along `v`
/// (columns).
#[transcript::evidence]
#[derive(Clone, Debug, PartialEq)]
pub struct NurbsSurface {
    knots_u: KnotVector,
    knots_v: KnotVector,
    net: ControlNet,
}

impl NurbsSurface {
    /// A surface; the net must have `knots_u.control_points()` rows and
    /// `knots_v.control_points()` columns.
    pub fn try_new(
        knots_u: KnotVector,
        knots_v: KnotVector,
        net: ControlNet,
    ) -> Result<Self, NurbsError> {
        if net.rows() != knots_u.control_points() {
            return Err(NurbsError::WrongCount {
                expected: knots_u.control_points(),
                got: net.rows(),
            });
        }
        if net.columns() != knots_v.control_points() {
            return Err(NurbsError::WrongCount {
                expected: knots_v.control_points(),
                got: net.columns(),
            });
        }
        Ok(Self {
            knots_u,
            knots_v,
            net,
        })
    }

    /// The knot vector along `u` (with degree `p`).
    #[must_use]
    pub fn knots_u(&self) -> &KnotVector {
        &self.knots_u
    }

    /// The knot vector along `v` (with degree `q`).
    #[must_use]
    pub fn knots_v(&self) -> &KnotVector {
        &self.knots_v
    }

    /// The control net.
    #[must_use]
    pub fn net(&self) -> &ControlNet {
        &self.net
    }

    /// The domain along `u`.
    #[must_use]
    pub fn domain_u(&self) -> Domain {
        self.knots_u.domain()
    }

    /// The domain along `v`.
    #[must_use]
    pub fn domain_v(&self) -> Domain {
        self.knots_v.domain()
    }

    /// The surface `data` describes (one of the course's NURBS surfaces,
    /// [`freeform::NurbsSurfaceData`]: the torus, or the vase whose
    /// interior knots are single), checked as [`Self::try_new`] checks.
    pub fn from_data(data: &freeform::NurbsSurfaceData) -> Result<Self, NurbsError> {
        let knots_u = KnotVector::try_new(data.degree_u, data.knots_u.clone())?;
        let knots_v = KnotVector::try_new(data.degree_v, data.knots_v.clone())?;
        if data.weights.len() != data.points.len() {
            return Err(NurbsError::WrongCount {
                expected: data.points.len(),
                got: data.weights.len(),
            });
        }
        let points = data
            .points
            .iter()
            .zip(&data.weights)
            .map(|(&p, &w)| homogeneous(p, w))
            .collect();
        let net = ControlNet::try_new(data.rows, data.columns, points)?;
        Self::try_new(knots_u, knots_v, net)
    }
}
