//! Topic 06: image-based CSG — classifying points against CSG trees,
//! normalizing trees to a sum of products with Goldfeather's nine rules,
//! pruning with bounding boxes, and drawing the result with a depth and a
//! stencil buffer: Goldfeather's parity test and its layered variant,
//! checked against a ray caster. The task sheet is `README.md` next to
//! this crate.
//!
//! The modules marked "given" are course code you read and use; each
//! task module is yours. You edit the task files in `src/`; with the
//! `reference` feature the tutor's solutions in `reference/06-csg/src/`
//! are compiled instead, against the very same tests. (Unused-variable
//! warnings are silenced in your files until you fill them in.)
#![warn(missing_docs)]

pub use glam::Vec3;

/// Given: the convex primitives (cuboid, sphere, cylinder), their bounds and spans along a ray.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/06-csg/src/primitive.rs"
)]
pub mod primitive;

/// Given: CSG trees, products and literals, the validated `Scene` and `Model`, errors.
#[cfg_attr(feature = "reference", path = "../../../reference/06-csg/src/csg.rs")]
pub mod csg;

/// Given: the camera and the framebuffer (depth, 8-bit stencil, surfaces) with OpenGL's tests and operations.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/06-csg/src/raster.rs"
)]
pub mod raster;

/// Given: the ground truth, a ray caster on interval sets.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/06-csg/src/raycast.rs"
)]
pub mod raycast;

/// Given: pictures from framebuffers.
#[cfg_attr(feature = "reference", path = "../../../reference/06-csg/src/shade.rs")]
pub mod shade;

/// Task 1: point classification against primitives and trees.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/06-csg/src/classify.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod classify;

/// Task 2: normalization to a sum of products with the nine rules.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/06-csg/src/normalize.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod normalize;

/// Task 3: bounding-box pruning of a sum of products.
#[cfg_attr(feature = "reference", path = "../../../reference/06-csg/src/prune.rs")]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod prune;

/// Task 4: Goldfeather rendering with the parity test.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/06-csg/src/goldfeather.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod goldfeather;

/// Task 5: layered Goldfeather, depth complexity and layer extraction.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/06-csg/src/layered.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod layered;
