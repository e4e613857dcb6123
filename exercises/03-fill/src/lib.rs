//! Topic 03: fill — the axis-parallel rectangle with the slides' half-pixel
//! convention, polygons by scanlines, outline parity, edge and fence fill,
//! and triangles by edge functions with barycentric interpolation and a
//! top-left fill rule. The task sheet is `README.md`
//! next to this crate.
//!
//! Each module below is one task. You edit the files in `src/`: what you
//! build, test and grade is always your own code.
#![warn(missing_docs)]

/// Task 1: the axis-parallel rectangle, pixel centres in a half-open box.
pub mod rectangle;

/// Task 2: scanline polygon fill with an active edge table (even-odd rule).
pub mod scanline;

/// Task 3: outline parity fill, one mark per crossing and a flag per row.
pub mod parity;

/// Task 4: edge fill and fence fill by inverting pixels, with inversion counts.
pub mod edge_fence;

/// Task 5: the triangle by edge functions, with barycentric interpolation.
pub mod edge_function;

/// Task 6 (bonus): the triangle in 8 × 8 blocks, data-parallel edge functions.
pub mod blocked;

/// Task 7 (bonus): the triangle in lanes over its bounding box, edge
/// functions, coverage and interpolation as arrays (seed 004, §6.4).
pub mod vectorised;
