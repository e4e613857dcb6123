//! Topic 03: fill — the axis-parallel rectangle with the slides' half-pixel
//! convention, polygons by scanlines, outline parity, edge and fence fill,
//! and triangles by edge functions with barycentric interpolation and a
//! top-left fill rule. The task sheet is `README.md`
//! next to this crate.
//!
//! Each module below is one task. You edit the files in `src/`; with the
//! `reference` feature the tutor's solutions in `reference/03-fill/src/`
//! are compiled instead, against the very same tests. (Unused-variable
//! warnings are silenced in your files until you fill them in.)
#![warn(missing_docs)]

/// Task 1: the axis-parallel rectangle, pixel centres in a half-open box.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/03-fill/src/rectangle.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod rectangle;

/// Task 2: scanline polygon fill with an active edge table (even-odd rule).
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/03-fill/src/scanline.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod scanline;

/// Task 3: outline parity fill, one mark per crossing and a flag per row.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/03-fill/src/parity.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod parity;

/// Task 4: edge fill and fence fill by inverting pixels, with inversion counts.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/03-fill/src/edge_fence.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod edge_fence;

/// Task 5: the triangle by edge functions, with barycentric interpolation.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/03-fill/src/edge_function.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod edge_function;

/// Task 6 (bonus): the triangle in 8 × 8 blocks, data-parallel edge functions.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/03-fill/src/blocked.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod blocked;
