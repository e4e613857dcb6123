//! Evaluating NURBS curves and surfaces: points, first derivatives,
//! normals and a fast regular grid, after seed 001 (NURBS tessellation
//! thesis), §1.3, Definitions 1.3.1–1.3.3, and The NURBS Book (Piegl &
//! Tiller): A2.1 `FindSpan`, A2.2 `BasisFuns`, A4.1/A4.3 (points of NURBS
//! curves and surfaces via `Pʷ`) and §4.3–4.5 (derivatives of rational
//! curves and surfaces).
//!
//! **Points.** In homogeneous form a NURBS surface is the polynomial
//! B-spline surface `Sʷ(u, v) = Σᵢ Σⱼ N_{i,p}(u) N_{j,q}(v) P_{i,j}ʷ`; only
//! the `(p + 1) × (q + 1)` control points of span `(s, t)` contribute, and
//! `S = Sʷ.xyz / Sʷ.w` (seed 001, (1.15)).
//!
//! **Derivatives.** Write `Sʷ = (A, w)`. From `A = w·S` and the product
//! rule, `A_u = w_u S + w S_u`, so
//!
//! ```text
//!   S_u = (A_u − w_u S) / w,        S_v = (A_v − w_v S) / w
//! ```
//!
//! (NURBS Book (4.20), first order), where `A_u`, `w_u` come from the
//! derivatives of the basis functions,
//! `N′_{i,p} = p/(u_{i+p} − u_i) N_{i,p−1} − p/(u_{i+p+1} − u_{i+1}) N_{i+1,p−1}`
//! (NURBS Book (2.7)). The same holds for curves.
//!
//! **Normals** (seed 001, (1.18)): `N = (S_u × S_v) / |S_u × S_v|`.
//!
//! Each task stands alone: this file needs its own span search and basis
//! evaluation as private helpers (task `basis` writes the same
//! algorithms; copy them, do not call them).

use glam::{DVec3, DVec4};

use crate::knots::{KnotVector, MAX_GRID_POINTS, NurbsError};
use crate::net::{CurvePoint, NurbsCurve, NurbsSurface, SurfacePoint, project};

/// Tangents whose cross product is shorter than this fraction of
/// `|S_u|·|S_v|` (the sine of the angle between them) count as parallel:
/// no normal. `1e-12` is far above rounding noise of `f64` products (about
/// `1e-16`) and far below any angle a real surface has.
pub const PARALLEL_TOLERANCE: f64 = 1e-12;

impl NurbsCurve {
    /// `C(u) = Σ N_{i,p}(u) Pᵢʷ`, projected (seed 001, (1.12)), for `u` in
    /// the domain.
    ///
    /// Find the span `s` of `u`, the `p + 1` basis functions of it,
    /// combine `P_{s−p}ʷ … P_sʷ`, project.
    ///
    /// Errors: `u` outside the domain or NaN ([`NurbsError::OutOfDomain`]).
    #[transcript::task]
    pub fn point(&self, u: f64) -> Result<DVec3, NurbsError> {
        // BEGIN SOLUTION nurbs: span, basis, a weighted sum of p + 1 homogeneous points, project
        let knots = self.knots();
        let span = span_of(knots, u)?;
        let basis = basis_of(knots, span, u);
        let start = span - knots.degree();
        let cw: DVec4 = basis
            .iter()
            .zip(&self.points()[start..])
            .map(|(&n, &pw)| pw * n)
            .sum();
        Ok(project(cw))
        // END SOLUTION
    }

    /// `C(u)` and `C′(u)`, for `u` in the domain.
    ///
    /// At an interior knot of multiplicity `p` the curve may have a corner:
    /// the derivative returned there is the one from the right (the span
    /// `u` starts), at the domain's end the one from the left.
    ///
    /// Errors: `u` outside the domain or NaN ([`NurbsError::OutOfDomain`]).
    #[transcript::task]
    pub fn derivative(&self, u: f64) -> Result<CurvePoint, NurbsError> {
        // BEGIN SOLUTION nurbs: homogeneous value and derivative from N and N′, then C′ = (A′ − w′C)/w
        let knots = self.knots();
        let span = span_of(knots, u)?;
        let (basis, derivative) = basis_and_derivative_of(knots, span, u);
        let start = span - knots.degree();
        let mut cw = DVec4::ZERO;
        let mut cw_u = DVec4::ZERO;
        for ((&n, &dn), &pw) in basis.iter().zip(&derivative).zip(&self.points()[start..]) {
            cw += pw * n;
            cw_u += pw * dn;
        }
        let point = project(cw);
        let derivative = (cw_u.truncate() - cw_u.w * point) / cw.w;
        Ok(CurvePoint { point, derivative })
        // END SOLUTION
    }
}

impl NurbsSurface {
    /// `S(u, v)` (seed 001, (1.15)), for `(u, v)` in the domain.
    ///
    /// Spans `s` along `u` and `t` along `v`, their basis functions, then
    /// the `(p + 1) × (q + 1)` homogeneous control points of the span
    /// combined and projected.
    ///
    /// Errors: `u` or `v` outside its domain or NaN ([`NurbsError::OutOfDomain`]).
    #[transcript::task]
    pub fn point(&self, u: f64, v: f64) -> Result<DVec3, NurbsError> {
        // BEGIN SOLUTION nurbs: spans and bases in u and v, the (p+1)(q+1) weighted sum, project
        let (ku, kv) = (self.knots_u(), self.knots_v());
        let (s, t) = (span_of(ku, u)?, span_of(kv, v)?);
        let (nu, nv) = (basis_of(ku, s, u), basis_of(kv, t, v));
        let (i0, j0) = (s - ku.degree(), t - kv.degree());
        let mut sw = DVec4::ZERO;
        for (a, &nu_a) in nu.iter().enumerate() {
            let row = &self.net().row(i0 + a)[j0..];
            let along_v: DVec4 = nv.iter().zip(row).map(|(&n, &pw)| pw * n).sum();
            sw += along_v * nu_a;
        }
        Ok(project(sw))
        // END SOLUTION
    }

    /// `S(u, v)` with the partial derivatives `S_u` and `S_v`, for `(u, v)`
    /// in the domain (one-sided at knots, as for curves).
    ///
    /// Errors: `u` or `v` outside its domain or NaN ([`NurbsError::OutOfDomain`]).
    #[transcript::task]
    pub fn derivatives(&self, u: f64, v: f64) -> Result<SurfacePoint, NurbsError> {
        // BEGIN SOLUTION nurbs: Sʷ, Sʷ_u, Sʷ_v from bases and their derivatives, then the quotient rule
        let (ku, kv) = (self.knots_u(), self.knots_v());
        let (s, t) = (span_of(ku, u)?, span_of(kv, v)?);
        let (nu, dnu) = basis_and_derivative_of(ku, s, u);
        let (nv, dnv) = basis_and_derivative_of(kv, t, v);
        let (i0, j0) = (s - ku.degree(), t - kv.degree());
        let (mut sw, mut sw_u, mut sw_v) = (DVec4::ZERO, DVec4::ZERO, DVec4::ZERO);
        for a in 0..nu.len() {
            let row = &self.net().row(i0 + a)[j0..];
            let (mut along_v, mut along_v_dv) = (DVec4::ZERO, DVec4::ZERO);
            for ((&n, &dn), &pw) in nv.iter().zip(&dnv).zip(row) {
                along_v += pw * n;
                along_v_dv += pw * dn;
            }
            sw += along_v * nu[a];
            sw_u += along_v * dnu[a];
            sw_v += along_v_dv * nu[a];
        }
        let point = project(sw);
        Ok(SurfacePoint {
            position: point,
            du: (sw_u.truncate() - sw_u.w * point) / sw.w,
            dv: (sw_v.truncate() - sw_v.w * point) / sw.w,
        })
        // END SOLUTION
    }

    /// The unit normal `(S_u × S_v) / |S_u × S_v|` (seed 001, (1.18)), for
    /// `(u, v)` in the domain. It points to the side from which `u` runs
    /// counter-clockwise to `v`.
    ///
    /// Errors: `u` or `v` outside its domain or NaN ([`NurbsError::OutOfDomain`]);
    /// parallel or zero tangents, as at the pole of a sphere
    /// ([`NurbsError::DegenerateNormal`], see [`PARALLEL_TOLERANCE`]).
    #[transcript::task]
    pub fn normal(&self, u: f64, v: f64) -> Result<DVec3, NurbsError> {
        // BEGIN SOLUTION nurbs: the cross product of the tangents, refused when they are parallel
        let d = self.derivatives(u, v)?;
        let cross = d.du.cross(d.dv);
        let scale = d.du.length() * d.dv.length();
        let length = cross.length();
        // Written so that NaN (from infinite tangents) is refused too.
        let parallel = length.is_nan() || length <= PARALLEL_TOLERANCE * scale;
        if parallel || !length.is_finite() {
            return Err(NurbsError::DegenerateNormal { u, v });
        }
        Ok(cross / length)
        // END SOLUTION
    }

    /// The points on a regular grid of `samples_u × samples_v` parameters,
    /// `uᵢ = domain_u.lerp(i / (samples_u − 1))` and the same along `v`,
    /// row-major: `result[i·samples_v + j] = S(uᵢ, vⱼ)` (to rounding).
    ///
    /// The fast way: the spans and basis functions of every `uᵢ` and every
    /// `vⱼ` are computed once. For row `i`, first the `u` sums are done for
    /// *all* columns of the net, `Qₗʷ = Σₖ N_k(uᵢ) P_{s−p+k, l}ʷ` (a curve in
    /// `v`); then each point of the row costs only `q + 1` products,
    /// `Σₗ Nₗ(vⱼ) Q_{t−q+l}ʷ`, instead of `(p + 1)(q + 1)`.
    ///
    /// Errors: fewer than 2 samples along a side, or more than
    /// [`MAX_GRID_POINTS`] in all ([`NurbsError::BadGrid`]).
    #[transcript::task]
    pub fn sample_grid(
        &self,
        samples_u: usize,
        samples_v: usize,
    ) -> Result<Vec<DVec3>, NurbsError> {
        // BEGIN SOLUTION nurbs: bases once per uᵢ and vⱼ, the u sums once per row, q + 1 products per point
        let too_many = samples_u
            .checked_mul(samples_v)
            .is_none_or(|n| n > MAX_GRID_POINTS);
        if samples_u < 2 || samples_v < 2 || too_many {
            return Err(NurbsError::BadGrid {
                samples_u,
                samples_v,
            });
        }
        let (ku, kv) = (self.knots_u(), self.knots_v());
        let (p, q) = (ku.degree(), kv.degree());
        let bases_u = regular_bases(ku, samples_u)?;
        let bases_v = regular_bases(kv, samples_v)?;
        let columns = self.net().columns();
        let mut row_curve = vec![DVec4::ZERO; columns];
        let mut points = Vec::with_capacity(samples_u * samples_v);
        for (s, nu) in &bases_u {
            row_curve.fill(DVec4::ZERO);
            for (a, &n) in nu.iter().enumerate() {
                let row = self.net().row(s - p + a);
                for (q_l, &p_l) in row_curve.iter_mut().zip(row) {
                    *q_l += p_l * n;
                }
            }
            for (t, nv) in &bases_v {
                let curve = &row_curve[t - q..];
                let sw: DVec4 = nv.iter().zip(curve).map(|(&n, &pw)| pw * n).sum();
                points.push(project(sw));
            }
        }
        Ok(points)
        // END SOLUTION
    }
}

// BEGIN SOLUTION
/// The span and basis functions of `count` regularly spaced parameters.
fn regular_bases(knots: &KnotVector, count: usize) -> Result<Vec<(usize, Vec<f64>)>, NurbsError> {
    let domain = knots.domain();
    (0..count)
        .map(|i| {
            let u = domain.lerp(i as f64 / (count - 1) as f64);
            let span = span_of(knots, u)?;
            Ok((span, basis_of(knots, span, u)))
        })
        .collect()
}

/// A2.1 `FindSpan`: `u_s ≤ u < u_{s+1}`, the domain's end in span `n`.
fn span_of(knots: &KnotVector, u: f64) -> Result<usize, NurbsError> {
    let u = knots.domain().check(u)?;
    let (k, n) = (knots.knots(), knots.last_index());
    if u >= k[n + 1] {
        return Ok(n);
    }
    let (mut low, mut high) = (knots.degree(), n + 1);
    while high - low > 1 {
        let mid = low + (high - low) / 2;
        if u < k[mid] {
            high = mid;
        } else {
            low = mid;
        }
    }
    Ok(low)
}

/// A2.2 `BasisFuns` up to degree `degree`: `N_{s−degree,degree} … N_{s,degree}`.
fn basis_up_to(k: &[f64], span: usize, u: f64, degree: usize) -> Vec<f64> {
    let mut n = vec![0.0; degree + 1];
    n[0] = 1.0;
    for j in 1..=degree {
        raise_degree(k, span, u, &mut n, j);
    }
    n
}

/// One step of A2.2: from `N_{·,j−1}` (in `n[0..j]`) to `N_{·,j}` (in `n[0..=j]`).
fn raise_degree(k: &[f64], span: usize, u: f64, n: &mut [f64], j: usize) {
    let mut saved = 0.0;
    for r in 0..j {
        let right = k[span + r + 1] - u;
        let left = u - k[span + 1 + r - j];
        let temp = n[r] / (right + left);
        n[r] = saved + right * temp;
        saved = left * temp;
    }
    n[j] = saved;
}

/// The `p + 1` non-zero basis functions of span `s`.
fn basis_of(knots: &KnotVector, span: usize, u: f64) -> Vec<f64> {
    basis_up_to(knots.knots(), span, u, knots.degree())
}

/// The `p + 1` non-zero basis functions of span `s` and their first
/// derivatives, by NURBS Book (2.7) from the degree `p − 1` functions.
fn basis_and_derivative_of(knots: &KnotVector, span: usize, u: f64) -> (Vec<f64>, Vec<f64>) {
    let (k, p) = (knots.knots(), knots.degree());
    let mut n = basis_up_to(k, span, u, p - 1);
    n.push(0.0);
    // n[t] = N_{s−p+1+t, p−1}; the derivative of N_{i,p}, i = s − p + j,
    // needs N_{i,p−1} = n[j − 1] and N_{i+1,p−1} = n[j].
    let pf = p as f64;
    let derivative = (0..=p)
        .map(|j| {
            let i = span - p + j;
            let left = if j > 0 {
                n[j - 1] / (k[i + p] - k[i])
            } else {
                0.0
            };
            let right = if j < p {
                n[j] / (k[i + p + 1] - k[i + 1])
            } else {
                0.0
            };
            pf * (left - right)
        })
        .collect();
    raise_degree(k, span, u, &mut n, p);
    (n, derivative)
}
// END SOLUTION
