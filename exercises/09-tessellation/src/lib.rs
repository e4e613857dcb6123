//! Topic 09: tessellation of freeform surfaces on the CPU — uniform and
//! per-patch adaptive tessellation of Bézier patches, fully adaptive
//! refinement with the seed's edge tests, and PN triangles. The task sheet is `README.md` next to
//! this crate.
//!
//! Modules marked *Given* are course code you read and use; the others are
//! the tasks. You edit the task files in `src/`: what you build, test and
//! grade is always your own code.
#![warn(missing_docs)]

pub use glam::{DVec2, DVec3};

/// Given: the error type of every fallible function of this crate.
pub mod error;

/// Given: Bézier curves and tensor-product Bézier patches, evaluated through their power form.
pub mod bezier;

/// Given: a surface of several Bézier patches that meet along shared boundary curves.
pub mod patch_grid;

/// Given: the indexed triangle mesh, with OBJ and ASCII PLY output.
pub mod mesh;

/// Given: a small CPU z-buffer renderer (shaded and wireframe) for pictures.
pub mod render;

/// Task 1: uniform tessellation of a Bézier patch, n_u × n_v cells, two triangles each.
pub mod uniform;

/// Task 2: per-patch adaptive tessellation without cracks (shared boundary curves).
pub mod per_patch;

/// Task 3, part 1: the seven edge tests of the fully adaptive tessellation.
pub mod edge_tests;

/// Task 3, part 2: fully adaptive refinement with a work list and midpoint insertion.
pub mod fully_adaptive;

/// Task 4: cubic Bézier triangles and PN triangles.
pub mod bezier_triangle;
