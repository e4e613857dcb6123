//! Topic 09: tessellation of freeform surfaces on the CPU — uniform and
//! per-patch adaptive tessellation of Bézier patches, fully adaptive
//! refinement with the seed's edge tests, the OpenGL primitive generator as
//! a pure function, and PN triangles. The task sheet is `README.md` next to
//! this crate.
//!
//! Modules marked *Given* are course code you read and use; the others are
//! the tasks. You edit the task files in `src/`; with the `reference`
//! feature the tutor's solutions in `reference/09-tessellation/src/` are
//! compiled instead, against the very same tests. (Unused-variable warnings
//! are silenced in your files until you fill them in.)
#![warn(missing_docs)]

pub use glam::{DVec2, DVec3};

/// Given: the error type of every fallible function of this crate.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/09-tessellation/src/error.rs"
)]
pub mod error;

/// Given: Bézier curves and tensor-product Bézier patches, evaluated by de Casteljau.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/09-tessellation/src/bezier.rs"
)]
pub mod bezier;

/// Given: a surface of several Bézier patches that meet along shared boundary curves.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/09-tessellation/src/patch_grid.rs"
)]
pub mod patch_grid;

/// Given: the indexed triangle mesh, with OBJ and ASCII PLY output.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/09-tessellation/src/mesh.rs"
)]
pub mod mesh;

/// Given: the zipper that triangulates the strip between two polylines.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/09-tessellation/src/stitch.rs"
)]
pub mod stitch;

/// Given: a small CPU z-buffer renderer (shaded and wireframe) for pictures.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/09-tessellation/src/render.rs"
)]
pub mod render;

/// Task 1: uniform tessellation of a Bézier patch, n_u × n_v cells, two triangles each.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/09-tessellation/src/uniform.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod uniform;

/// Task 2: per-patch adaptive tessellation without cracks (shared boundary curves).
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/09-tessellation/src/per_patch.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod per_patch;

/// Task 3, part 1: the seven edge tests of the fully adaptive tessellation.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/09-tessellation/src/edge_tests.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod edge_tests;

/// Task 3, part 2: fully adaptive refinement with a work list and midpoint insertion.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/09-tessellation/src/fully_adaptive.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod fully_adaptive;

/// Task 4: the OpenGL primitive generator for the quad and triangle domains.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/09-tessellation/src/primitive_generator.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod primitive_generator;

/// Task 5: cubic Bézier triangles and PN triangles.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/09-tessellation/src/bezier_triangle.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod bezier_triangle;
