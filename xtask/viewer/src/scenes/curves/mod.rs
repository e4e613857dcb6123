//! The curve scene (topics 07 and 08): a curve whose control points you
//! drag, drawn by your code at [`SAMPLES`]` + 1` parameters, beside the
//! curve of its definition (`testkit::oracles`) and how far yours lies
//! from it.
//!
//! - A Bézier curve (07), drawn by your `de_casteljau`, with the
//!   construction of one point `C(t)` (seed 000, Abbildung 6): every level
//!   of the scheme, each of its points found by your `de_casteljau` on the
//!   control points it depends on (`b_i^k(t)` is the curve of
//!   `P_i … P_{i+k}` at `t`); the definition is the Bernstein sum.
//! - A NURBS curve (08) of the degree and weights you choose over the
//!   clamped uniform knot vector, drawn by your `NurbsCurve::point`, with
//!   the points at its knots; the definition is the Cox–de Boor sum.
//!
//! Points live in the unit square `[0, 1]²`, y up.

mod draw;
#[cfg(feature = "window")]
mod state;
#[cfg(feature = "window")]
mod ui;

pub use draw::*;
#[cfg(feature = "window")]
pub(crate) use state::CurvesScene;
