//! Topic 04: clipping — polygons against the six planes of the clip volume
//! in homogeneous clip space (Sutherland-Hodgman, as the TU Wien sheet
//! does it), and line segments against the viewport in 2D (Cohen-Sutherland
//! with outcodes, Liang-Barsky in the parameter). The task sheet is
//! `README.md` next to this crate.
//!
//! Each task module below is one task; `plane`, `window` and `error` are
//! given. You edit the files in `src/`: what you build, test and grade is
//! always your own code.
#![warn(missing_docs)]

/// Given: a plane of clip space as a 4-vector, `CLIP_NUDGE`.
pub mod plane;

/// Given: the 2D clip window and line segments.
pub mod window;

/// Given: why a clipping function refused its input.
pub mod error;

/// Task 1: the six planes of the clip volume, `inside` and `intersect`.
pub mod clip_planes;

/// Task 2: Sutherland-Hodgman, a polygon against one plane and against all.
pub mod sutherland_hodgman;

/// Task 3: Cohen-Sutherland line clipping with outcodes.
pub mod cohen_sutherland;

/// Task 4: Liang-Barsky line clipping in the segment's parameter.
pub mod liang_barsky;

pub use error::ClipError;
pub use plane::{CLIP_NUDGE, ClipPlane};
/// The clip-space vertex of the course library: position and colour.
pub use scene::ClipVertex;
pub use window::{ClipWindow, Segment};
