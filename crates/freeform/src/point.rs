//! What an evaluation returns: a point of a curve or a surface together
//! with what is known about the curve or surface there.
//!
//! Three records, one per question the topics ask of a surface:
//!
//! ```text
//!   CurvePoint     C(t), C′(t)                 the tangent of a curve (07, 08)
//!   SurfacePoint   S(u, v), S_u, S_v           the first derivatives (07, 08)
//!   SurfaceSample  (u, v), S(u, v), N(u, v)    what is drawn (07's render,
//!                                              09's meshes, 10's vertices)
//! ```
//!
//! The partial derivatives span the tangent plane; the unit normal is
//! their normalised cross product (seed 000 Listing 6, seed 001 equation
//! (1.18)):
//!
//! ```text
//!   N = (S_u × S_v) / |S_u × S_v|
//! ```
//!
//! It is undefined where the cross product vanishes (a corner whose edge
//! collapsed to a point, two parallel control-polygon edges at a corner).
//! There the limit of the normals nearby is taken: the normal a little
//! inside the parameter square, [`NORMAL_NUDGE`] towards its centre.
//!
//! How each record is computed is what the topics teach (de Casteljau in
//! 07, the NURBS derivatives in 08, the power form in 09, WGSL in 10):
//! only the records live here.

use glam::{DVec2, DVec3};

/// How far towards the centre `(½, ½)` of the parameter square the normal
/// is taken where it is undefined at `(u, v)` itself (module
/// documentation): a step of `1e-6` in the parameters keeps the direction
/// error near `1e-6`, far below what a picture shows, while the
/// derivatives there stay well above rounding. Topic 07 moves each
/// parameter by this much, topic 09 moves this fraction of the way to the
/// centre.
pub const NORMAL_NUDGE: f64 = 1e-6;

/// A point of a curve and its derivative there: `C(t)` and `C′(t) = dC/dt`.
/// Generic over the point type (`f64`, `DVec2`, `DVec3`, …) so that a curve
/// in the plane and one in space are evaluated alike.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurvePoint<P = DVec3> {
    /// `C(t)`.
    pub point: P,
    /// `C′(t) = dC/dt`: the tangent, not normalised (zero for a curve of
    /// degree 0, and where a curve has a cusp; normalise it where only the
    /// direction matters).
    pub derivative: P,
}

/// A point of a surface and its two partial derivatives there.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfacePoint {
    /// `S(u, v)`.
    pub position: DVec3,
    /// `S_u = ∂S/∂u (u, v)`.
    pub du: DVec3,
    /// `S_v = ∂S/∂v (u, v)`.
    pub dv: DVec3,
}

/// A point of a surface as it is drawn: the parameters it was taken at,
/// its position and its unit normal (a vertex of a tessellation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceSample {
    /// The parameters `(u, v)`: a point of the unit square for a
    /// tensor-product patch, the first two barycentric coordinates
    /// `(u, v)` of `(u, v, w)` for a Bézier triangle.
    pub uv: DVec2,
    /// `S(u, v)`.
    pub position: DVec3,
    /// The unit normal `N(u, v)`, or zero where it is undefined even a
    /// little inside (a patch degenerate everywhere near `(u, v)`).
    pub normal: DVec3,
}
