//! Bézier curves and tensor-product Bézier patches, evaluated through their
//! power form (seed 001 §1.1, Definitions 1.1.1 and 1.1.4 with all weights
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

/// The largest degree a curve or patch may have.
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

/// The power form of a Bézier curve of degree `n = points.len() − 1`: the
/// coefficients `a_k` of `C(t) = Σ_k a_k tᵏ`, which are the forward
/// differences of the control points, `a_k = C(n, k) · Δᵏ P_0`
/// (`Δ P_i = P_(i+1) − P_i`). Converting once and evaluating with Horner's
/// rule ([`horner`]) is cheap for a curve or patch evaluated at many
/// points. It is not de Casteljau's algorithm, which topic 07 teaches and
/// which is the stabler of the two at high degrees; here the degree is at
/// most [`MAX_DEGREE`], and `f64` keeps the error far below what any
/// tessellation shows.
fn power_form(points: &[DVec3]) -> Vec<DVec3> {
    let mut differences = points.to_vec();
    let mut coefficients = Vec::with_capacity(points.len());
    let n = points.len().saturating_sub(1);
    let mut choose = 1.0; // C(n, k)
    for k in 0..points.len() {
        coefficients.push(differences[0] * choose);
        // Δᵏ⁺¹ P_i = Δᵏ P_(i+1) − Δᵏ P_i.
        for i in 0..differences.len() - 1 {
            differences[i] = differences[i + 1] - differences[i];
        }
        differences.pop();
        choose = choose * (n - k) as f64 / (k + 1) as f64;
    }
    coefficients
}

/// `(p(t), p'(t))` of the polynomial `p(t) = Σ_k a_k tᵏ` by Horner's rule;
/// zeros for no coefficients.
fn horner(coefficients: &[DVec3], t: f64) -> (DVec3, DVec3) {
    let mut value = DVec3::ZERO;
    let mut derivative = DVec3::ZERO;
    for &a in coefficients.iter().rev() {
        derivative = derivative * t + value;
        value = value * t + a;
    }
    (value, derivative)
}

/// A Bézier curve of degree `n = points.len() − 1` at `t`: `C(t)` and the
/// derivative `C'(t)`, through its [`power_form`]. The curve interpolates
/// its end points: `C(0) = P_0`, `C(1) = P_n` (the seed's Example 1.1.2
/// writes `P_1 = C(1)` for its quadratic; it is `P_2`).
///
/// An empty slice gives zeros; a single point is a constant curve.
#[must_use]
pub fn curve(points: &[DVec3], t: f64) -> (DVec3, DVec3) {
    horner(&power_form(points), t)
}

/// A tensor-product Bézier patch (non-rational: all weights 1).
#[derive(Clone, Debug, PartialEq)]
pub struct BezierPatch {
    degree_u: usize,
    degree_v: usize,
    points: Vec<DVec3>,
    /// The power form `S(u, v) = Σ_k Σ_l c_kl uᵏ vˡ`, row by row like the
    /// control points (see [`BezierPatch::derivatives`]).
    coefficients: Vec<DVec3>,
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
        Ok(Self::from_points(degree_u, degree_v, points))
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
        Self::from_points(3, 2, points)
    }

    /// The patch of checked control points, with its power form: each row
    /// converted in `v`, then each column of the results in `u`.
    fn from_points(degree_u: usize, degree_v: usize, points: Vec<DVec3>) -> Self {
        let row = degree_v + 1;
        let rows: Vec<Vec<DVec3>> = points.chunks(row).map(power_form).collect();
        let mut coefficients = vec![DVec3::ZERO; points.len()];
        for l in 0..row {
            let column: Vec<DVec3> = rows.iter().map(|r| r[l]).collect();
            for (k, c) in power_form(&column).into_iter().enumerate() {
                coefficients[k * row + l] = c;
            }
        }
        Self {
            degree_u,
            degree_v,
            points,
            coefficients,
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

    /// `S(u, v)` and the tangents `S_u`, `S_v`, from the power form: each
    /// row `k` of coefficients is a polynomial `r_k(v)` (Horner's rule gives
    /// it and `r_k'(v)`); then `S = Σ r_k uᵏ`, `S_u` its `u`-derivative and
    /// `S_v = Σ r_k' uᵏ`, Horner's rule again.
    #[must_use]
    pub fn derivatives(&self, uv: DVec2) -> [DVec3; 3] {
        let mut across = [DVec3::ZERO; MAX_DEGREE + 1];
        let mut across_dv = [DVec3::ZERO; MAX_DEGREE + 1];
        let row = self.degree_v + 1;
        for (k, coefficients) in self.coefficients.chunks(row).enumerate() {
            (across[k], across_dv[k]) = horner(coefficients, uv.y);
        }
        let columns = self.degree_u + 1;
        let (position, du) = horner(&across[..columns], uv.x);
        let (dv, _) = horner(&across_dv[..columns], uv.x);
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

#[cfg(test)]
mod tests {
    use super::*;
    use testkit::oracles::bernstein;

    /// `C(t)` by the definition, `Σ B_i,n(t) P_i`.
    fn by_definition(points: &[DVec3], t: f64) -> DVec3 {
        let n = points.len() - 1;
        (0..=n).map(|i| points[i] * bernstein(i, n, t)).sum()
    }

    #[test]
    fn the_power_form_is_the_bernstein_form_up_to_the_largest_degree() {
        for n in 0..=MAX_DEGREE {
            // A wiggly control polygon of size about 10.
            let points: Vec<DVec3> = (0..=n)
                .map(|i| {
                    let i = i as f64;
                    DVec3::new(i, 10.0 * (1.7 * i).sin(), 5.0 * (0.9 * i).cos())
                })
                .collect();
            for step in 0..=20 {
                let t = f64::from(step) / 20.0;
                let (point, derivative) = curve(&points, t);
                let error = (point - by_definition(&points, t)).length();
                assert!(error < 1e-9, "degree {n} at t = {t}: off by {error}");
                // The derivative against a central difference.
                let h = 1e-6;
                let (before, after) =
                    (by_definition(&points, t - h), by_definition(&points, t + h));
                let difference = (after - before) / (2.0 * h);
                let off = (derivative - difference).length() / difference.length().max(1.0);
                assert!(off < 1e-5, "degree {n} at t = {t}: derivative off by {off}");
            }
        }
        assert_eq!(curve(&[], 0.5), (DVec3::ZERO, DVec3::ZERO));
    }

    #[test]
    fn a_patch_is_curves_of_curves() {
        let patch = BezierPatch::seed_surface();
        for (u, v) in [(0.0, 0.0), (0.3, 0.8), (1.0, 0.5), (0.5, 1.0)] {
            let across: Vec<DVec3> = (0..=3).map(|i| by_definition(&patch.row(i), v)).collect();
            let expected = by_definition(&across, u);
            let got = patch.position(DVec2::new(u, v));
            assert!(
                (got - expected).length() < 1e-12,
                "at ({u}, {v}): {got} vs {expected}"
            );
        }
        assert_eq!(patch.position(DVec2::ZERO), patch.control_point(0, 0));
        assert_eq!(patch.position(DVec2::ONE), patch.control_point(3, 2));
    }
}
