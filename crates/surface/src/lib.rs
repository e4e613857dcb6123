//! The course library of the surface topics (09 and 10): what a
//! tessellation cuts and how it joins the pieces, written once for both.
//!
//! - [`BezierTriangle`]: the cubic Bézier triangle's ten control points,
//!   named by their exponents and stored in one order (topic 09's PN
//!   triangles, topic 10's GPU buffer).
//! - [`domain`]: the quad and triangle domains, the parameter points and
//!   counter-clockwise triangles that a tessellation places on a surface
//!   (what the primitive generator of topic 10 produces, and what topic
//!   09's PN triangles are evaluated over).
//! - [`stitch`]: the zipper that triangulates the strip between two
//!   polylines (the ring between a patch's inner grid and its boundary in
//!   topic 09, the rings of the primitive generator in topic 10).
#![warn(missing_docs)]

pub mod domain;
pub mod stitch;
pub mod triangle;

pub use domain::{QuadDomain, TriangleDomain, embed};
pub use stitch::stitch;
pub use triangle::BezierTriangle;
