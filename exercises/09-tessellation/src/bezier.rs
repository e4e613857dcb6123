//! Bézier curves and tensor-product Bézier patches, evaluated by de
//! Casteljau (seed 001 §1.1, Definitions 1.1.1 and 1.1.4 with all weights
//! `w_ij = 1`; the surface normal is the seed's equation (1.18)).
//!
//! A patch of degree `p × q` has `(p + 1)(q + 1)` control points `P_ij`,
//! `i` along `u`, `j` along `v`, stored row by row with `j` running fastest
//! (the order of geomdl's `set_ctrlpts(points, size_u, size_v)` in the seed):
//!
//! ```text
//!   S(u, v) = Σ_i Σ_j B_i,p(u) B_j,q(v) P_ij,     0 ≤ u, v ≤ 1
//!   B_i,n(t) = n! / (i! (n − i)!) · tⁱ (1 − t)ⁿ⁻ⁱ
//!   N(u, v) = (S_u × S_v) / |S_u × S_v|
//! ```

use glam::{DVec2, DVec3};

use crate::error::TessError;

/// The largest degree a curve or patch may have (de Casteljau costs `n²`).
pub const MAX_DEGREE: usize = 16;

/// The largest number of cells or segments per direction any function of
/// this crate accepts or produces: bounds memory and time on hostile input.
pub const MAX_RESOLUTION: usize = 1024;

/// Where the normal is degenerate (`|S_u × S_v|` below this, e.g. at a
/// corner where two control-polygon edges are parallel), it is taken a
/// little inside the patch instead, see [`BezierPatch::normal`].
pub const DEGENERATE_NORMAL: f64 = 1e-12;

/// How far towards the centre of the parameter square a degenerate normal
/// is evaluated instead: small enough to be the limit for any picture.
pub const NORMAL_NUDGE: f64 = 1e-6;

/// A point of a surface with what the tessellations need: its parameters,
/// its position and its unit normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfacePoint {
    /// Parameters `(u, v)` in `[0, 1]²`.
    pub uv: DVec2,
    /// `S(u, v)`.
    pub position: DVec3,
    /// The unit normal `N(u, v)` (zero only if the patch is degenerate
    /// everywhere near `(u, v)`).
    pub normal: DVec3,
}

/// De Casteljau's algorithm for a Bézier curve of degree `n = points.len() − 1`:
/// returns `C(t)` and the derivative `C'(t)`, which is `n` times the
/// difference of the two points of the penultimate step. The curve
/// interpolates its end points: `C(0) = P_0`, `C(1) = P_n` (the seed's
/// Example 1.1.2 writes `P_1 = C(1)` for its quadratic; it is `P_2`).
///
/// An empty slice gives zeros; a single point is a constant curve.
#[must_use]
pub fn de_casteljau(points: &[DVec3], t: f64) -> (DVec3, DVec3) {
    let n = points.len();
    if n <= MAX_DEGREE + 1 {
        // The common case works in a buffer on the stack: no allocation.
        let mut work = [DVec3::ZERO; MAX_DEGREE + 1];
        work[..n].copy_from_slice(points);
        de_casteljau_in_place(&mut work[..n], t)
    } else {
        de_casteljau_in_place(&mut points.to_vec(), t)
    }
}

/// [`de_casteljau`] on a scratch copy of the control points.
fn de_casteljau_in_place(work: &mut [DVec3], t: f64) -> (DVec3, DVec3) {
    let n = work.len();
    match n {
        0 => return (DVec3::ZERO, DVec3::ZERO),
        1 => return (work[0], DVec3::ZERO),
        _ => {}
    }
    // Levels 1 ..= n − 2 leave two points: the penultimate step.
    for level in 1..n - 1 {
        for k in 0..n - level {
            work[k] = work[k].lerp(work[k + 1], t);
        }
    }
    let derivative = (n - 1) as f64 * (work[1] - work[0]);
    (work[0].lerp(work[1], t), derivative)
}

/// A tensor-product Bézier patch (non-rational: all weights 1).
#[derive(Clone, Debug, PartialEq)]
pub struct BezierPatch {
    degree_u: usize,
    degree_v: usize,
    points: Vec<DVec3>,
}

impl BezierPatch {
    /// A patch of degree `degree_u × degree_v` from its control points,
    /// row by row (`P_00, P_01, …, P_0q, P_10, …`).
    ///
    /// # Errors
    /// [`TessError::Degree`] above [`MAX_DEGREE`], [`TessError::ControlGrid`]
    /// for a wrong number of points, [`TessError::NonFinite`] for a NaN or
    /// infinite coordinate.
    pub fn try_new(
        degree_u: usize,
        degree_v: usize,
        points: Vec<DVec3>,
    ) -> Result<Self, TessError> {
        for degree in [degree_u, degree_v] {
            if degree > MAX_DEGREE {
                return Err(TessError::Degree(degree));
            }
        }
        let expected = (degree_u + 1) * (degree_v + 1);
        if points.len() != expected {
            return Err(TessError::ControlGrid {
                degree_u,
                degree_v,
                expected,
                found: points.len(),
            });
        }
        if !points.iter().all(|p| p.is_finite()) {
            return Err(TessError::NonFinite {
                what: "a control point",
            });
        }
        Ok(Self {
            degree_u,
            degree_v,
            points,
        })
    }

    /// The seed's example surface (seed 001, Example 1.1.5): 4 × 3 control
    /// points, degree 3 in `u` and 2 in `v`. Its corner `(0, 0)` is
    /// degenerate: `P_01 = P_10`, so both tangents there are parallel (this
    /// is the "magnitude of the vector is zero" the seed's code catches).
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

    /// Degree in `u`.
    #[must_use]
    pub fn degree_u(&self) -> usize {
        self.degree_u
    }

    /// Degree in `v`.
    #[must_use]
    pub fn degree_v(&self) -> usize {
        self.degree_v
    }

    /// Control point `P_ij` (`i ≤ degree_u`, `j ≤ degree_v`).
    ///
    /// # Panics
    /// If `i` or `j` is out of range.
    #[must_use]
    pub fn control_point(&self, i: usize, j: usize) -> DVec3 {
        assert!(
            i <= self.degree_u && j <= self.degree_v,
            "control point out of range"
        );
        self.points[i * (self.degree_v + 1) + j]
    }

    /// All control points, row by row.
    #[must_use]
    pub fn control_points(&self) -> &[DVec3] {
        &self.points
    }

    /// The control polygon of row `i` (fixed `i`, `j = 0..=q`): a curve in `v`.
    #[must_use]
    pub fn row(&self, i: usize) -> Vec<DVec3> {
        (0..=self.degree_v)
            .map(|j| self.control_point(i, j))
            .collect()
    }

    /// The control polygon of column `j` (fixed `j`, `i = 0..=p`): a curve in `u`.
    #[must_use]
    pub fn column(&self, j: usize) -> Vec<DVec3> {
        (0..=self.degree_u)
            .map(|i| self.control_point(i, j))
            .collect()
    }

    /// `S(u, v)` and the tangents `S_u`, `S_v`: de Casteljau in `v` along
    /// every row, then in `u` across the results (and their `v`-derivatives).
    #[must_use]
    pub fn derivatives(&self, uv: DVec2) -> [DVec3; 3] {
        let mut across = [DVec3::ZERO; MAX_DEGREE + 1];
        let mut across_dv = [DVec3::ZERO; MAX_DEGREE + 1];
        let row = self.degree_v + 1;
        for i in 0..=self.degree_u {
            let start = i * row;
            let (point, dv) = de_casteljau(&self.points[start..start + row], uv.y);
            across[i] = point;
            across_dv[i] = dv;
        }
        let columns = self.degree_u + 1;
        let (position, du) = de_casteljau(&across[..columns], uv.x);
        let (dv, _) = de_casteljau(&across_dv[..columns], uv.x);
        [position, du, dv]
    }

    /// `S(u, v)`.
    #[must_use]
    pub fn position(&self, uv: DVec2) -> DVec3 {
        self.derivatives(uv)[0]
    }

    /// The unit normal `(S_u × S_v) / |S_u × S_v|`. Where the cross product
    /// is shorter than [`DEGENERATE_NORMAL`] (a degenerate corner or edge)
    /// the normal is taken at a point [`NORMAL_NUDGE`] closer to the centre
    /// `(½, ½)`: the limit seen from inside. Zero only if that fails too.
    #[must_use]
    pub fn normal(&self, uv: DVec2) -> DVec3 {
        let [_, du, dv] = self.derivatives(uv);
        self.normal_from(uv, du, dv)
    }

    /// The normal from the tangents at `uv`, with the fallback of [`Self::normal`].
    fn normal_from(&self, uv: DVec2, du: DVec3, dv: DVec3) -> DVec3 {
        let n = du.cross(dv);
        if n.length() > DEGENERATE_NORMAL {
            return n.normalize();
        }
        let inside = uv + (DVec2::splat(0.5) - uv) * NORMAL_NUDGE;
        let [_, du, dv] = self.derivatives(inside);
        du.cross(dv).normalize_or_zero()
    }

    /// Position and normal at `(u, v)`.
    #[must_use]
    pub fn sample(&self, uv: DVec2) -> SurfacePoint {
        let [position, du, dv] = self.derivatives(uv);
        SurfacePoint {
            uv,
            position,
            normal: self.normal_from(uv, du, dv),
        }
    }
}
