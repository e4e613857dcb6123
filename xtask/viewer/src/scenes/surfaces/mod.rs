//! The surface scene (topic 07): the seed's hill, a bicubic Bézier patch
//! whose control points you raise and lower, evaluated by your surface
//! code, trimmed by your trims and rendered by your `render_surface` — the thesis's program (seed 000 §3.1, §4), in
//! which the user chooses the trim shape, its parameters and the
//! tessellation level and looks at the result, lit or as a wireframe.
//!
//! ```text
//!   (u, v) ──your surface──▶ position, normal ──your render_surface──▶ picture
//!                              your trim ──▲ (per fragment: discard?)
//! ```
//!
//! Beside the picture, the parameter square as your trim sees it: each
//! sample cut away or kept.

mod draw;
#[cfg(feature = "window")]
mod state;
#[cfg(feature = "window")]
mod ui;

pub use crate::stages::trim::{CUBIC, INNER, QUADRATIC, TrimSetup, TrimShape};
pub use draw::*;
#[cfg(feature = "window")]
pub(crate) use state::SurfacesScene;
