//! Topic 08: NURBS — rational Bézier curves and surfaces, the B-spline
//! basis by Cox-de Boor with the knot span search, NURBS curves and
//! surfaces with derivatives and normals, and knot insertion with the
//! decomposition of a surface into Bézier patches. The task sheet is
//! `README.md` next to this crate.
//!
//! `knots` and `net` are given (read them first: they fix the conventions,
//! homogeneous points `Pʷ = (w·P, w)` and nets with rows along `u`). Each
//! other module is one task. You edit the files in `src/`: what you build,
//! test and grade is always your own code.
#![warn(missing_docs)]

/// Given: knot vectors, their domain, and the errors of this crate.
pub mod knots;

/// Given: homogeneous points, control nets, curve and surface types.
pub mod net;

/// Task 1: Bernstein polynomials, rational Bézier curves and surfaces.
pub mod rational_bezier;

/// Task 2: the B-spline basis — Cox-de Boor, span search, A2.2 and A2.3.
pub mod basis;

/// Task 3: NURBS curves and surfaces — points, derivatives, normals, grids.
pub mod nurbs;

/// Task 4: knot insertion (Boehm) and Bézier decomposition of surfaces.
pub mod knot_insertion;

pub use freeform::RationalPatch;
pub use knots::{Breakpoint, Domain, KnotVector, MAX_GRID_POINTS, NurbsError};
pub use net::{
    ControlNet, CurvePoint, NurbsCurve, NurbsSurface, SurfacePoint, homogeneous, project,
};
