//! Tensor-product Bézier surfaces by de Casteljau in u and in v, their
//! partial derivatives and unit normal (seed 000, §2.4, §2.5 and
//! Listings 4–6).
//!
//! ```text
//!   P(u, v) = Σ_i Σ_j B_{i,n}(u) · B_{j,m}(v) · P_{i,j}          (seed eq. 10)
//!           = Σ_i B_{i,n}(u) · (Σ_j B_{j,m}(v) · P_{i,j})          v first, then u
//!           = Σ_j B_{j,m}(v) · (Σ_i B_{i,n}(u) · P_{i,j})          u first, then v
//! ```
//!
//! Either way round is one-dimensional de Casteljau twice: reduce every
//! curve of the net in one direction to a point, then reduce those points
//! in the other direction. The order does not matter (the double sum can
//! be summed in either order); the seed reduces in u first.
//!
//! Every iso-parameter line `u = const` or `v = const` is a Bézier curve
//! (the seed's §2.4 says "Bézier surfaces" there, a slip), its control
//! points the reduced points of the first step.
//!
//! The penultimate step of the second reduction gives the derivative in
//! that direction: reducing in v last gives `∂P/∂v`, reducing in u last
//! gives `∂P/∂u`. The unit normal is `N = (∂P/∂u × ∂P/∂v) / |…|`
//! (Listing 6), pointing to the side from which u runs anticlockwise to v.

use glam::{DVec2, DVec3};

#[allow(unused_imports)]
use crate::basics::{BezierError, MAX_DEGREE, check_parameter};
use freeform::BezierPatch;

/// Below this ratio `|∂u × ∂v| / (|∂u| · |∂v|)` (the sine of the angle
/// between the partial derivatives) the normal is taken as undefined.
pub const NORMAL_EPSILON: f64 = 1e-10;

/// How far [`normal`] moves towards the patch centre, in u and in v, when
/// the normal at (u, v) is undefined (a collapsed edge or corner): the
/// course library's `freeform::NORMAL_NUDGE`. The normal there is the
/// limit of the normals nearby; `1e-6` keeps the direction error near
/// `1e-6` while the derivatives stay well above rounding.
pub use freeform::NORMAL_NUDGE;

/// A surface point with its two partial derivatives, `position = P(u, v)`,
/// `du = ∂P/∂u`, `dv = ∂P/∂v` (the course library's record,
/// `freeform::SurfacePoint`).
pub use freeform::SurfacePoint;

/// `P(u, v)`: reduce every column (u-curve `P_{0,j} … P_{n,j}`) at `u`,
/// then the resulting `m + 1` points at `v` — the seed's order
/// (`doubleDeCasteljau`, Listing 5).
///
/// # Errors
/// [`BezierError::ParameterOutOfRange`] for `u` or `v` NaN or outside
/// `[0, 1]` (the net itself is valid by construction).
#[transcript::task]
pub fn evaluate_u_then_v(net: &BezierPatch, uv: DVec2) -> Result<DVec3, BezierError> {
    // Unused until you write the body:
    let _ = (&net, &uv);
    todo!("surface: check u, v; de Casteljau each column at u; de Casteljau the results at v")
}

/// `P(u, v)` the other way round: reduce every row (v-curve
/// `P_{i,0} … P_{i,m}`) at `v`, then the `n + 1` points at `u`. Equal to
/// [`evaluate_u_then_v`] up to rounding.
///
/// # Errors
/// As [`evaluate_u_then_v`].
#[transcript::task]
pub fn evaluate_v_then_u(net: &BezierPatch, uv: DVec2) -> Result<DVec3, BezierError> {
    // Unused until you write the body:
    let _ = (&net, &uv);
    todo!("surface: check u, v; de Casteljau each row at v; de Casteljau the results at u")
}

/// `P(u, v)` with `∂P/∂u` and `∂P/∂v`, each derivative from the
/// penultimate de Casteljau step of the reduction done last:
///
/// ```text
///   ∂P/∂u = n · (r₁ − r₀),  r = the rows reduced at v, reduced at u to two points
///   ∂P/∂v = m · (q₁ − q₀),  q = the columns reduced at u, reduced at v to two points
/// ```
///
/// Degree 0 in a direction gives a zero derivative in it.
///
/// The seed's Listing 5 takes its second tangent from the first pass,
/// where each u-curve of the net overwrites it: it ends as the tangent of
/// the last control row's curve (`gl_in[12..15]`), not `∂P/∂u` at
/// (u, v), and `tangU`/`tangV` are named the other way round. Hence the
/// two reductions here.
///
/// # Errors
/// As [`evaluate_u_then_v`].
#[transcript::task]
pub fn partial_derivatives(net: &BezierPatch, uv: DVec2) -> Result<SurfacePoint, BezierError> {
    // Unused until you write the body:
    let _ = (&net, &uv);
    todo!(
        "surface: reduce rows at v then at u (keep n·(r1 − r0)); columns at u then at v (keep m·(q1 − q0))"
    )
}

/// The unit normal `N = (∂P/∂u × ∂P/∂v) / |∂P/∂u × ∂P/∂v|` at (u, v).
///
/// **Fallback.** Where the cross product vanishes relative to the
/// derivatives (`|∂u × ∂v| ≤ NORMAL_EPSILON · |∂u| · |∂v|`, e.g. at a
/// corner whose edge collapsed to a point, where one derivative is zero),
/// the normal is taken once more at `(u, v)` moved by [`NORMAL_NUDGE`]
/// towards the centre `(½, ½)` in each parameter: the limit of the normals
/// next to the corner. The seed (Listing 6) normalises the cross product
/// unguarded and produces NaN there.
///
/// # Errors
/// [`BezierError::ParameterOutOfRange`] as above;
/// [`BezierError::DegenerateNormal`] if the normal is undefined at the
/// nudged point too (a net collapsed to a curve or a point).
#[transcript::task]
pub fn normal(net: &BezierPatch, uv: DVec2) -> Result<DVec3, BezierError> {
    // Unused until you write the body:
    let _ = (&net, &uv);
    todo!(
        "surface: normalise ∂u × ∂v; if degenerate retry once nudged towards (½, ½); else DegenerateNormal"
    )
}

/// Checks both parameters.
#[allow(dead_code)]
fn check_uv(uv: DVec2) -> Result<(), BezierError> {
    check_parameter("u", uv.x)?;
    check_parameter("v", uv.y)
}
