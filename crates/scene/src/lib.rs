//! The pipeline around the exercises: meshes from PLY files, glam model /
//! view / projection transforms, homogeneous clip space, the perspective
//! divide, the viewport transform and a small rasterizer to draw the result.
//!
//! It follows the graphics pipeline of the TU Wien "Rasterisierung" sheet
//! (section 2 and the framework of section 3): a mesh is transformed into
//! clip space, clipped there (that is the `04-clipping` exercise; this crate
//! only offers a crude stand-in, [`discard_outside`]), divided by `w`,
//! mapped to pixels and rasterized.
//!
//! ```text
//!  Mesh ──model──▶ world ──view──▶ eye ──projection──▶ clip space
//!                                                          │ (clip here)
//!  Canvas ◀──raster── pixels ◀──viewport── NDC ◀──÷ w──────┘
//! ```
//!
//! # Conventions
//! - glam's: column vectors, column-major matrices, right-handed eye space
//!   looking down −z, OpenGL clip space. The clip volume is
//!   `−w ≤ x, y, z ≤ w`, i.e. the cube `[−1, 1]³` after the divide (the
//!   sheet's "cube of side length 2 centred at the origin").
//! - Depth: NDC `z = −1` (the near plane) becomes canvas depth 0, `z = +1`
//!   (the far plane) depth 1, as with OpenGL's default `glDepthRange(0, 1)`.
//! - Cameras: the world's up is +y, and a camera turned by angles is
//!   turned by [`turn`] (yaw about +y after a pitch about its own x axis);
//!   [`Pipeline::for_mesh`]'s fixed camera for the shipped meshes (`f32`),
//!   and [`Camera`], a pinhole camera for `f64` world points with the same
//!   view and projection (the surface topics' renders).
//! - Pixels: the canvas convention (centres at integers, y up); NDC `−1` and
//!   `+1` map to the centres of the outermost pixels (see [`Pipeline::screen`]).
#![warn(missing_docs)]

pub mod camera;
mod clip_vertex;
pub mod data;
mod mesh;
pub mod pipeline;
pub mod ply;
pub mod raster;

pub use camera::{Camera, turn};
pub use clip_vertex::ClipVertex;
pub use mesh::Mesh;
pub use pipeline::{Mode, Pipeline, discard_outside, inside_view_volume};
pub use ply::PlyError;

/// Re-exported so that users of the pipeline need no direct glam dependency.
pub use glam::{Mat4, Vec3, Vec4};
