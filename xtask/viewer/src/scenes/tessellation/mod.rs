//! The tessellation scene (topic 09): a surface of Bézier or rational
//! patches cut into triangles by your uniform, per-patch or fully
//! adaptive tessellation — seed 001's program, in which the user chooses
//! the surface, the method and its level, tolerance or edge test and
//! looks at the triangles. The picture is drawn by topic 09's given
//! renderer (course code for looking at meshes); the triangles are yours.

mod draw;
#[cfg(feature = "window")]
mod state;
#[cfg(feature = "window")]
mod ui;

pub use crate::stages::tessellate::{
    Look, MAX_DEPTH, MAX_LEVEL, Method, Surface, TessSetup, Tessellated, Test,
};
pub use draw::*;
#[cfg(feature = "window")]
pub(crate) use state::TessellationScene;
