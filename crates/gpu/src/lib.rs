//! The course GPU library: a headless [`wgpu`] device, offscreen colour and
//! depth targets, and readback into a [`canvas::Canvas`].
//!
//! - [`Gpu`]: an adapter and its device, preferring real hardware and
//!   falling back to a software adapter (Mesa's lavapipe on Linux);
//!   [`Gpu::for_tests`] turns "no adapter" into a clear skip line, or into
//!   a failure where [`GPU_REQUIRED_VAR`] is set (CI sets it);
//! - [`OffscreenTarget`]: an `Rgba8Unorm` colour texture and a `Depth32Float`
//!   depth texture to render into without a window;
//! - [`read_buffer`] and [`OffscreenTarget::read_colour`]: copies back to the
//!   CPU, with the row padding `wgpu` requires removed and the rows flipped
//!   into the canvas convention (row 0 at the bottom, y up).
//!
//! Only the crates that need a GPU depend on this one, so `wgpu` is compiled
//! nowhere else.
#![warn(missing_docs)]

mod device;
mod readback;
mod target;

pub use device::{GPU_REQUIRED_VAR, Gpu, GpuError};
pub use readback::{padded_bytes_per_row, read_buffer};
pub use target::{COLOUR_FORMAT, DEPTH_FORMAT, OffscreenTarget};

/// Re-exported so that users of this crate name the same `wgpu` version.
pub use wgpu;
