//! Topic 05: buffers — the z-buffer with OpenGL's depth functions, depth
//! along a scanline, the painter's algorithm, polygon offset for
//! hidden-line drawing, the stencil buffer, double buffering and the
//! accumulation buffer. The task sheet is `README.md` next to this crate.
//!
//! Each task module below is one task. You edit the files in `src/`; with
//! the `reference` feature the tutor's solutions in
//! `reference/05-buffers/src/` are compiled instead, against the very same
//! tests. `raster` is given code that the tasks use to make fragments.
//! (Unused-variable warnings are silenced in your files until you fill
//! them in.)
#![warn(missing_docs)]

/// Given code (not a task): a triangle and a line rasterizer that emit fragments with depth.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/05-buffers/src/raster.rs"
)]
pub mod raster;

/// Task 1: the z-buffer with OpenGL's eight depth functions, clear value and depth range.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/05-buffers/src/zbuffer.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod zbuffer;

/// Task 2: depth along a scanline, by edge interpolation and incrementally from the plane equation.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/05-buffers/src/scanline_depth.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod scanline_depth;

/// Task 3: the painter's algorithm, and where it fails.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/05-buffers/src/painter.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod painter;

/// Task 4: polygon offset for hidden-line drawing without stitching.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/05-buffers/src/polygon_offset.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod polygon_offset;

/// Task 5: the stencil test, the eight stencil operations and the write mask.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/05-buffers/src/stencil.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod stencil;

/// Task 6: double buffering and jittered accumulation for scene antialiasing.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/05-buffers/src/accumulation.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod accumulation;
