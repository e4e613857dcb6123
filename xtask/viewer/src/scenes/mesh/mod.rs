//! The pipeline scene, drawn by your stages: seed 004's program (§3.1)
//! around your code.
//!
//! ```text
//!  mesh ─▶ clip space ─▶ [your clipping] ─▶ ÷ w, viewport ─▶ [your lines or fill] ─▶ [your depth test] ─▶ picture
//!          (given)                           (given)
//! ```
//!
//! The transforms and the perspective divide are the course's
//! (`scene::Pipeline`); every stage in brackets is yours. A stage at
//! `todo!()` or that panics draws nothing and is named in the frame's
//! report; the other stages still run.

mod draw;
#[cfg(feature = "window")]
mod state;
#[cfg(feature = "window")]
mod ui;

pub use draw::*;
#[cfg(feature = "window")]
pub(crate) use state::MeshScene;
