//! `cargo xtask view`: your own pipeline on screen.
//!
//! The seeds are built around programs in which the student's code draws
//! the pictures: seed 004's framework (§3.1) loads a PLY mesh, switches
//! between rasterization modes and saves the result. This is that program
//! for this course: the course transforms the mesh; your clipping, lines,
//! fill and depth test draw it ([`stages`]). A stage at `todo!()` or that
//! panics is named with its message, never replaced by a solution, and
//! the rest of the frame still draws; your code runs off the UI thread
//! ([`worker`]), so a slow or looping stage does not freeze the window.
//!
//! ```text
//! cargo xtask view                      # the window, with your stages
//! cargo xtask view --screenshot a.png   # one picture, no window
//! ```

#[cfg(feature = "window")]
pub mod app;
pub mod camera;
#[cfg(feature = "window")]
mod live;
pub mod meshes;
pub mod scenes;
pub mod stages;
#[cfg(feature = "window")]
mod widgets;
pub mod worker;

#[cfg(feature = "window")]
pub use app::{Scene, ViewerApp};
pub use scenes::mesh::{Frame, Settings, render};
pub use stages::{Stages, Status};
