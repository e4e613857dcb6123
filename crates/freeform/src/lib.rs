//! The course library of the surface topics (07 to 10): the surfaces they
//! evaluate, what a tessellation cuts and how it joins the pieces, written
//! once for all of them.
//!
//! - [`BezierPatch`]: the tensor-product Bézier patch's control net, in the
//!   one layout every topic uses (topic 07's de Casteljau, topic 09's
//!   tessellations, topic 10's GPU buffer).
//! - [`RationalPatch`]: a Bézier patch with weights, the piece a NURBS
//!   surface splits into, with [`RationalPatch::torus`] as 16 of them
//!   (topic 09 tessellates rational patches too).
//! - [`NurbsSurfaceData`]: NURBS surfaces as data (a torus, and a vase
//!   whose interior knots are single), where the chain of topics 08 → 09
//!   → 10 starts: topic 08 splits them into [`RationalPatch`]es.
//! - [`BezierTriangle`]: the cubic Bézier triangle's ten control points,
//!   named by their exponents and stored in one order (topic 09's PN
//!   triangles, topic 10's GPU buffer).
//! - [`domain`]: the quad and triangle domains, the parameter points and
//!   counter-clockwise triangles that a tessellation places on a surface
//!   (what the primitive generator of topic 10 produces, and what topic
//!   09's PN triangles are evaluated over).
//! - [`CurvePoint`], [`SurfacePoint`], [`SurfaceSample`]: what evaluating
//!   a curve or a surface returns (a point with its tangent, with its
//!   partial derivatives, with its parameters and unit normal), and
//!   [`NORMAL_NUDGE`], where a degenerate normal is taken instead.
//! - [`trim`]: the seed's trim regions, two Bézier curves in the
//!   parameter square (topic 07 trims with them).
//! - [`stitch`]: the zipper that triangulates the strip between two
//!   polylines (the ring between a patch's inner grid and its boundary in
//!   topic 09, the rings of the primitive generator in topic 10).
#![warn(missing_docs)]

pub mod domain;
pub mod nurbs;
pub mod patch;
pub mod point;
pub mod rational;
pub mod stitch;
pub mod triangle;
pub mod trim;

pub use domain::{QuadDomain, TriangleDomain, embed};
pub use nurbs::NurbsSurfaceData;
pub use patch::{BezierPatch, PatchError};
pub use point::{CurvePoint, NORMAL_NUDGE, SurfacePoint, SurfaceSample};
pub use rational::RationalPatch;
pub use stitch::stitch;
pub use triangle::BezierTriangle;
