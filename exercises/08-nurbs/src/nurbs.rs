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

#[allow(unused_imports)]
use glam::{DVec3, DVec4};

#[allow(unused_imports)]
use crate::knots::{KnotVector, MAX_GRID_POINTS, NurbsError};
#[allow(unused_imports)]
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
        // Unused until you write the body:
        let _ = &u;
        todo!("nurbs: span, basis, a weighted sum of p + 1 homogeneous points, project")
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
        // Unused until you write the body:
        let _ = &u;
        todo!("nurbs: homogeneous value and derivative from N and N′, then C′ = (A′ − w′C)/w")
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
        // Unused until you write the body:
        let _ = (&u, &v);
        todo!("nurbs: spans and bases in u and v, the (p+1)(q+1) weighted sum, project")
    }

    /// `S(u, v)` with the partial derivatives `S_u` and `S_v`, for `(u, v)`
    /// in the domain (one-sided at knots, as for curves).
    ///
    /// Errors: `u` or `v` outside its domain or NaN ([`NurbsError::OutOfDomain`]).
    #[transcript::task]
    pub fn derivatives(&self, u: f64, v: f64) -> Result<SurfacePoint, NurbsError> {
        // Unused until you write the body:
        let _ = (&u, &v);
        todo!("nurbs: Sʷ, Sʷ_u, Sʷ_v from bases and their derivatives, then the quotient rule")
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
        // Unused until you write the body:
        let _ = (&u, &v);
        todo!("nurbs: the cross product of the tangents, refused when they are parallel")
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
        // Unused until you write the body:
        let _ = (&samples_u, &samples_v);
        todo!("nurbs: bases once per uᵢ and vⱼ, the u sums once per row, q + 1 products per point")
    }
}
