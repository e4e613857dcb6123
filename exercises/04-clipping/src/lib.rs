//! Topic 04: clipping — polygons against the six planes of the clip volume
//! in homogeneous clip space (Sutherland-Hodgman, as the TU Wien sheet
//! does it), and line segments against the viewport in 2D (Cohen-Sutherland
//! with outcodes, Liang-Barsky in the parameter). The task sheet is
//! `README.md` next to this crate.
//!
//! Each task module below is one task; `plane`, `window` and `error` are
//! given. You edit the files in `src/`; with the `reference` feature the
//! tutor's solutions in `reference/04-clipping/src/` are compiled instead,
//! against the very same tests. (Unused-variable warnings are silenced in
//! your files until you fill them in.)
#![warn(missing_docs)]

/// Given: a plane of clip space as a 4-vector, `CLIP_NUDGE`.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/04-clipping/src/plane.rs"
)]
pub mod plane;

/// Given: the 2D clip window and line segments.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/04-clipping/src/window.rs"
)]
pub mod window;

/// Given: why a clipping function refused its input.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/04-clipping/src/error.rs"
)]
pub mod error;

/// Task 1: the six planes of the clip volume, `inside` and `intersect`.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/04-clipping/src/clip_planes.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod clip_planes;

/// Task 2: Sutherland-Hodgman, a polygon against one plane and against all.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/04-clipping/src/sutherland_hodgman.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod sutherland_hodgman;

/// Task 3: Cohen-Sutherland line clipping with outcodes.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/04-clipping/src/cohen_sutherland.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod cohen_sutherland;

/// Task 4: Liang-Barsky line clipping in the segment's parameter.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/04-clipping/src/liang_barsky.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod liang_barsky;

pub use error::ClipError;
pub use plane::{CLIP_NUDGE, ClipPlane};
/// The clip-space vertex of the course library: position and colour.
pub use scene::ClipVertex;
pub use window::{ClipWindow, Segment};
