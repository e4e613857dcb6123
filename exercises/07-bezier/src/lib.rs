//! Topic 07: Bézier curves and surfaces — Bernstein polynomials, the de
//! Casteljau algorithm, tensor-product surfaces with their normals,
//! trimming in the parameter square (interval, circle, ellipse, Newton
//! trimming with Bézier curves, and a general point-in-region test), and a
//! lit CPU render. The task sheet is `README.md` next to this crate.
//!
//! Each task module below is one task (the given modules are library code
//! you read and use). You edit the files in `src/`: what you build, test
//! and grade is always your own code.
#![warn(missing_docs)]

/// Given: the error type, `MAX_DEGREE`, the point trait and the `Trim` trait.
pub mod basics;

/// Given: a pinhole camera and a z-buffered triangle rasterizer.
pub mod zbuffer;

/// Task 1: Bernstein polynomials, binomial coefficients, the Bernstein form.
pub mod bernstein;

/// Task 2: de Casteljau evaluation, splitting, the tangent from the penultimate step.
pub mod de_casteljau;

/// Task 3: tensor-product surfaces, partial derivatives, the unit normal.
pub mod surface;

/// Task 4a: trimming by interval, circle and ellipse.
pub mod simple_trim;

/// Task 4b: trimming with Bézier curves by the Newton method, single and nested.
pub mod newton_trim;

/// Task 5: point in a region of closed Bézier loops by ray-crossing parity.
pub mod ray_parity;

/// Task 6: a CPU render of a trimmed surface, Phong with two lights, wireframe.
pub mod render;

pub use basics::{BezierError, ControlPoint, MAX_DEGREE, Trim};
pub use freeform::{BezierPatch, PatchError};
