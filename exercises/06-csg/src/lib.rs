//! Topic 06: image-based CSG — classifying points against CSG trees,
//! normalizing trees to a sum of products with Goldfeather's nine rules,
//! pruning with bounding boxes, and drawing the result with a depth and a
//! stencil buffer: Goldfeather's parity test and its layered variant,
//! checked against a ray caster. The task sheet is `README.md` next to
//! this crate.
//!
//! The modules marked "given" are course code you read and use; each task
//! module is yours. You edit the task files in `src/`: what you build, test
//! and grade is always your own code.
#![warn(missing_docs)]

pub use glam::Vec3;

/// Given: the convex primitives (cuboid, sphere, cylinder), their bounds and spans along a ray.
pub mod primitive;

/// Given: CSG trees, products and literals, the validated `Scene` and `Model`, errors.
pub mod csg;

/// Given: the camera and the framebuffer (depth, 8-bit stencil, surfaces) with OpenGL's tests and operations.
pub mod raster;

/// Given: the ground truth, a ray caster on interval sets.
pub mod raycast;

/// Given: pictures from framebuffers.
pub mod shade;

/// Task 1: point classification against primitives and trees.
pub mod classify;

/// Task 2: normalization to a sum of products with the nine rules.
pub mod normalize;

/// Task 3: bounding-box pruning of a sum of products.
pub mod prune;

/// Task 4: Goldfeather rendering with the parity test.
pub mod goldfeather;

/// Task 5: layered Goldfeather, depth complexity and layer extraction.
pub mod layered;

/// Task 6: affine transformations at the nodes of a CSG tree.
pub mod transforms;
