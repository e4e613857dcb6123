//! Topic 07: Bézier curves and surfaces — Bernstein polynomials, the de
//! Casteljau algorithm, tensor-product surfaces with their normals,
//! trimming in the parameter square (interval, circle, ellipse, Newton
//! trimming with Bézier curves, and a general point-in-region test), and a
//! lit CPU render. The task sheet is `README.md` next to this crate.
//!
//! Each task module below is one task (the given modules are library code
//! you read and use). You edit the files in `src/`; with the `reference`
//! feature the tutor's solutions in `reference/07-bezier/src/` are compiled
//! instead, against the very same tests. (Unused-variable warnings are
//! silenced in your files until you fill them in.)
#![warn(missing_docs)]

/// Given: the error type, `MAX_DEGREE`, the point trait and the `Trim` trait.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/07-bezier/src/basics.rs"
)]
pub mod basics;

/// Given: the control net of a tensor-product surface.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/07-bezier/src/control_net.rs"
)]
pub mod control_net;

/// Given: a pinhole camera and a z-buffered triangle rasterizer.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/07-bezier/src/zbuffer.rs"
)]
pub mod zbuffer;

/// Task 1: Bernstein polynomials, binomial coefficients, the Bernstein form.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/07-bezier/src/bernstein.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod bernstein;

/// Task 2: de Casteljau evaluation, splitting, the tangent from the penultimate step.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/07-bezier/src/de_casteljau.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod de_casteljau;

/// Task 3: tensor-product surfaces, partial derivatives, the unit normal.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/07-bezier/src/surface.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod surface;

/// Task 4a: trimming by interval, circle and ellipse.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/07-bezier/src/simple_trim.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod simple_trim;

/// Task 4b: trimming with Bézier curves by the Newton method, single and nested.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/07-bezier/src/newton_trim.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod newton_trim;

/// Task 5: point in a region of closed Bézier loops by ray-crossing parity.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/07-bezier/src/ray_parity.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod ray_parity;

/// Task 6: a CPU render of a trimmed surface, Phong with two lights, wireframe.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/07-bezier/src/render.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod render;

pub use basics::{BezierError, ControlPoint, MAX_DEGREE, Trim};
pub use control_net::ControlNet;
