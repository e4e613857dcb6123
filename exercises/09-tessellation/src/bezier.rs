//! Bézier curves and tensor-product Bézier patches, evaluated through their
//! power form (seed 001 §1.1, Definitions 1.1.1 and 1.1.4 with all weights
//! `w_ij = 1`; the surface normal is the seed's equation (1.18)).
//!
//! The patch is the course library's [`BezierPatch`] (`freeform`): degree
//! `p × q`, control points `P_ij`, `i` along `u`, `j` along `v`, stored row
//! by row with `j` running fastest, so row `i` is a curve in `v`. This
//! module adds what the tessellations need of it ([`Evaluate`]):
//!
//! ```text
//!   S(u, v) = Σ_i Σ_j B_i,p(u) B_j,q(v) P_ij = Σ_i B_i,p(u) R_i(v),
//!   R_i(v)  = Σ_j B_j,q(v) P_ij                (row i, a curve in v)
//!   N(u, v) = (S_u × S_v) / |S_u × S_v|
//! ```
//!
//! A patch is a curve of curves: each row evaluated at `v` gives the
//! control points `R_i(v)` of the curve in `u` through `S(u, v)`, and the
//! rows' derivatives `R_i'(v)` those of the curve through `S_v`.
//!
//! A rational patch ([`RationalPatch`], the piece a NURBS surface splits
//! into) is the quotient of two such patches, `S = A / W` (see
//! `freeform::rational`); its tangents follow by the quotient rule:
//!
//! ```text
//!   S_u = (A_u − S·W_u) / W,    S_v = (A_v − S·W_v) / W
//! ```
//!
//! Every tessellation of this crate takes any surface that can
//! [`Evaluate`], polynomial or rational.

use glam::{DVec2, DVec3};

pub use freeform::{BezierPatch, RationalPatch};

/// The largest number of cells or segments per direction any function of
/// this crate accepts or produces: bounds memory and time on hostile input.
pub const MAX_RESOLUTION: usize = 1024;

/// Where the normal is degenerate (`|S_u × S_v|` below this, e.g. at a
/// corner where two control-polygon edges are parallel), it is taken a
/// little inside the patch instead, see [`Evaluate::normal`].
pub const DEGENERATE_NORMAL: f64 = 1e-12;

/// How far towards the centre of the parameter square a degenerate normal
/// is evaluated instead (the course library's `freeform::NORMAL_NUDGE`):
/// the fraction of the way there, small enough to be the limit for any
/// picture.
pub use freeform::NORMAL_NUDGE;

/// A point of a surface with what the tessellations need: its parameters,
/// its position and its unit normal (the course library's record,
/// `freeform::SurfaceSample`; [`Evaluate::sample`] makes one).
pub use freeform::SurfaceSample;

/// The power form of a Bézier curve of degree `n = points.len() − 1`: the
/// coefficients `a_k` of `C(t) = Σ_k a_k tᵏ`, which are the forward
/// differences of the control points, `a_k = C(n, k) · Δᵏ P_0`
/// (`Δ P_i = P_(i+1) − P_i`). Converting once and evaluating with Horner's
/// rule ([`horner`]) is cheap for a curve or patch evaluated at many
/// points. It is not de Casteljau's algorithm, which topic 07 teaches and
/// which is the stabler of the two at high degrees; the tessellations here
/// use degrees up to 16 (tested below), where `f64` keeps the error far
/// below what any tessellation shows.
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

/// Evaluation of a patch through the power form of its rows and of the
/// curves they make (module documentation): a patch is a curve of curves.
pub trait Evaluate {
    /// `S(u, v)` and the tangents `S_u`, `S_v`.
    #[must_use]
    fn derivatives(&self, uv: DVec2) -> [DVec3; 3];

    /// `S(u, v)`.
    #[must_use]
    fn position(&self, uv: DVec2) -> DVec3 {
        self.derivatives(uv)[0]
    }

    /// The unit normal `(S_u × S_v) / |S_u × S_v|`. Where the cross product
    /// is shorter than [`DEGENERATE_NORMAL`] (a degenerate corner or edge)
    /// the normal is taken at a point [`NORMAL_NUDGE`] closer to the centre
    /// `(½, ½)`: the limit seen from inside. Zero only if that fails too.
    #[must_use]
    fn normal(&self, uv: DVec2) -> DVec3 {
        let [_, du, dv] = self.derivatives(uv);
        unit_normal(self, uv, du, dv)
    }

    /// Position and normal at `(u, v)`.
    #[must_use]
    fn sample(&self, uv: DVec2) -> SurfaceSample {
        let [position, du, dv] = self.derivatives(uv);
        SurfaceSample {
            uv,
            position,
            normal: unit_normal(self, uv, du, dv),
        }
    }
}

/// The normal from the tangents at `uv`, with the fallback of
/// [`Evaluate::normal`].
fn unit_normal<S: Evaluate + ?Sized>(surface: &S, uv: DVec2, du: DVec3, dv: DVec3) -> DVec3 {
    let n = du.cross(dv);
    if n.length() > DEGENERATE_NORMAL {
        return n.normalize();
    }
    let inside = uv + (DVec2::splat(0.5) - uv) * NORMAL_NUDGE;
    let [_, du, dv] = surface.derivatives(inside);
    du.cross(dv).normalize_or_zero()
}

impl Evaluate for BezierPatch {
    /// Each row `i` at `v` gives `R_i(v)` and `R_i'(v)`; the curve of the
    /// `R_i` at `u` gives `S` and `S_u`, the curve of the `R_i'` gives `S_v`.
    fn derivatives(&self, uv: DVec2) -> [DVec3; 3] {
        let (across, across_dv): (Vec<DVec3>, Vec<DVec3>) = (0..=self.degree_u())
            .map(|i| curve(self.row(i), uv.y))
            .unzip();
        let (position, du) = curve(&across, uv.x);
        let (dv, _) = curve(&across_dv, uv.x);
        [position, du, dv]
    }
}

impl Evaluate for RationalPatch {
    /// `S = A / W`, its tangents by the quotient rule (module
    /// documentation); `A` and `W` evaluated as polynomial patches.
    fn derivatives(&self, uv: DVec2) -> [DVec3; 3] {
        let [a, a_u, a_v] = self.numerator().derivatives(uv);
        let [w, w_u, w_v] = self.denominator().derivatives(uv).map(|d| d.x);
        let s = a / w;
        [s, (a_u - s * w_u) / w, (a_v - s * w_v) / w]
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
    fn the_power_form_is_the_bernstein_form_up_to_degree_16() {
        for n in 0..=16 {
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
            let across: Vec<DVec3> = (0..=3).map(|i| by_definition(patch.row(i), v)).collect();
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

    #[test]
    fn a_rational_torus_is_evaluated_on_the_torus_with_its_tangents() {
        let (major, minor) = (2.0, 0.6);
        for patch in RationalPatch::torus(major, minor) {
            for (u, v) in [(0.0, 0.0), (0.25, 0.7), (0.5, 0.5), (0.9, 0.1), (1.0, 1.0)] {
                let uv = DVec2::new(u, v);
                let [s, s_u, s_v] = patch.derivatives(uv);
                let off = ((s.x.hypot(s.y) - major).hypot(s.z) - minor).abs();
                assert!(off < 1e-12, "{s} is {off} off the torus");
                // The normal points away from the tube's centre line.
                let centre = major * DVec3::new(s.x, s.y, 0.0).normalize();
                let radial = (s - centre).normalize();
                let normal = patch.normal(uv);
                assert!(
                    (normal.dot(radial) - 1.0).abs() < 1e-9,
                    "normal {normal}, radial {radial}"
                );
                // The tangents against central differences.
                let h = 1e-6;
                for (tangent, step) in [(s_u, DVec2::X * h), (s_v, DVec2::Y * h)] {
                    let (a, b) = (
                        patch.position((uv - step).max(DVec2::ZERO)),
                        patch.position((uv + step).min(DVec2::ONE)),
                    );
                    let width =
                        ((uv + step).min(DVec2::ONE) - (uv - step).max(DVec2::ZERO)).length();
                    let difference = (b - a) / width;
                    assert!(
                        (tangent - difference).length() < 1e-5 * difference.length().max(1.0),
                        "tangent {tangent} against {difference}"
                    );
                }
            }
        }
    }
}
