//! Rational Bézier curves and surfaces by de Casteljau's algorithm in
//! homogeneous coordinates, after seed 001 (NURBS tessellation thesis),
//! §1.1, Definitions 1.1.1–1.1.4, and The NURBS Book (Piegl & Tiller),
//! §1.4–1.5 (algorithm A1.5 for the surface, applied to `Pʷ`).
//!
//! The Bernstein polynomials (seed 001, (1.2)) are
//!
//! ```text
//!   B_{i,n}(u) = n! / (i! (n − i)!) · uⁱ (1 − u)ⁿ⁻ⁱ,    0 ≤ u ≤ 1,
//! ```
//!
//! and a rational Bézier curve (1.4) is
//! `C(u) = Σ B_{i,n}(u) wᵢ Pᵢ / Σ B_{i,n}(u) wᵢ`: the projection of the
//! *polynomial* Bézier curve with control points `Pᵢʷ = (wᵢPᵢ, wᵢ)` (see
//! [`crate::net`]). So de Casteljau's repeated linear interpolation, run on
//! the four-dimensional `Pᵢʷ`, followed by one division, evaluates it.
//!
//! Seed notes: after Example 1.1.2 the seed says "`P_0 = C(0)` and
//! `P_1 = C(1)`"; for that quadratic it is `P_2 = C(1)`. Equation (1.7)
//! calls the *rational* tensor-product surface simply "Bézier surface";
//! with all weights 1 it is the polynomial one.

use glam::{DVec3, DVec4};

use crate::knots::{Domain, NurbsError};
use crate::net::{ControlNet, check_homogeneous, project};

/// The Bernstein polynomial `B_{i,n}(u) = C(n, i) uⁱ (1 − u)ⁿ⁻ⁱ`
/// (seed 001, (1.2)); `0` for `i > n`.
///
/// Defined for every real `u` (the polynomial); on `[0, 1]` the `n + 1`
/// polynomials of degree `n` are non-negative and sum to 1. At the ends,
/// `B_{0,n}(0) = B_{n,n}(1) = 1` (with `0⁰ = 1`). Exact for `n ≤ 1020`,
/// where the binomial coefficient still fits an `f64`; beyond, it
/// overflows to infinity or NaN.
#[must_use]
#[transcript::task]
pub fn bernstein(n: usize, i: usize, u: f64) -> f64 {
    // BEGIN SOLUTION rational_bezier: the binomial coefficient times uⁱ (1 − u)ⁿ⁻ⁱ
    if i > n {
        return 0.0;
    }
    // C(n, i) as a running product, using the smaller of i and n − i.
    let k = i.min(n - i);
    let binomial = (0..k).fold(1.0, |c, j| c * (n - j) as f64 / (j + 1) as f64);
    let power = |x: f64, e: usize| (0..e).fold(1.0, |acc, _| acc * x);
    binomial * power(u, i) * power(1.0 - u, n - i)
    // END SOLUTION
}

/// `C(u)` of the rational Bézier curve with homogeneous control points
/// `Pᵢʷ = (wᵢPᵢ, wᵢ)`, of degree `n = points.len() − 1`, for `u ∈ [0, 1]`.
///
/// de Casteljau on the homogeneous points: `Pᵢʷ⁽ʳ⁾ = (1 − u) Pᵢʷ⁽ʳ⁻¹⁾ +
/// u P_{i+1}ʷ⁽ʳ⁻¹⁾` for `r = 1 … n`, then `C(u) = project(P₀ʷ⁽ⁿ⁾)`. Only
/// convex combinations: the result lies in the convex hull of the `Pᵢ`
/// (weights > 0).
///
/// Errors: no points ([`NurbsError::NoControlPoints`]), a weight that is not
/// finite and `> 0` ([`NurbsError::BadWeight`]), a non-finite point, or `u`
/// outside `[0, 1]` or NaN ([`NurbsError::OutOfDomain`]).
#[transcript::task]
pub fn rational_bezier_point(points: &[DVec4], u: f64) -> Result<DVec3, NurbsError> {
    // BEGIN SOLUTION rational_bezier: check the input, run de Casteljau on the homogeneous points, project
    check_homogeneous(points)?;
    let u = Domain::UNIT.check(u)?;
    Ok(project(de_casteljau(points.to_vec(), u)))
    // END SOLUTION
}

// BEGIN SOLUTION
/// de Casteljau in place on homogeneous points: the polynomial curve's
/// value `Cʷ(u)`.
fn de_casteljau(mut points: Vec<DVec4>, u: f64) -> DVec4 {
    let n = points.len() - 1;
    for r in 1..=n {
        for i in 0..=n - r {
            points[i] = points[i].lerp(points[i + 1], u);
        }
    }
    points[0]
}
// END SOLUTION

/// `S(u, v)` of the rational Bézier surface (seed 001, (1.7)) with the
/// homogeneous control net `net` (degree `rows − 1` in `u`, `columns − 1`
/// in `v`), for `(u, v) ∈ [0, 1]²`.
///
/// Tensor-product de Casteljau (The NURBS Book, A1.5, on `Pʷ`): run the
/// curve algorithm along `v` on every row, giving one homogeneous point per
/// row, then along `u` on those; project once. (Rows then columns gives the
/// same point as columns then rows: both are `Σᵢ Σⱼ Bᵢ(u) Bⱼ(v) P_{i,j}ʷ`.)
///
/// Errors: `u` or `v` outside `[0, 1]` or NaN ([`NurbsError::OutOfDomain`]);
/// the net is valid by construction.
#[transcript::task]
pub fn rational_bezier_surface_point(
    net: &ControlNet,
    u: f64,
    v: f64,
) -> Result<DVec3, NurbsError> {
    // BEGIN SOLUTION rational_bezier: de Casteljau along v on every row, then along u on the results, project
    let u = Domain::UNIT.check(u)?;
    let v = Domain::UNIT.check(v)?;
    let along_v: Vec<DVec4> = (0..net.rows())
        .map(|i| de_casteljau(net.row(i).to_vec(), v))
        .collect();
    Ok(project(de_casteljau(along_v, u)))
    // END SOLUTION
}
