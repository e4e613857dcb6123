//! The GPU scene (topic 10): Bézier and rational patches tessellated and
//! drawn on the GPU by your WGSL and Rust — the seed's OpenGL program
//! (seed 000 §4, seed 001 §3) with wgpu's explicit passes in place of the
//! tessellation stages:
//!
//! ```text
//!   patches ──your control.wgsl──▶ levels ──your quad_domain──▶ (u, v) points
//!     ──your evaluation.wgsl──▶ vertices ──render: your shading.wgsl,
//!       your trimming.wgsl, your wireframe_edges──▶ picture
//! ```
//!
//! Where there is no GPU, wgpu runs on a software adapter: lavapipe (Mesa's
//! software Vulkan) on Linux, WARP (software DX12) on Windows.
//! A piece not written yet is named; the shading and the trimming have
//! given stand-ins (flat colour, nothing trimmed), the other stages do not:
//! without them nothing is drawn.

mod draw;
#[cfg(feature = "window")]
mod state;
#[cfg(feature = "window")]
mod ui;

pub use crate::stages::gpu::{
    GpuDrawing, GpuSetup, GpuStageReport, GpuSurface, Levels, STAGES, Spacing,
};
pub use draw::*;
#[cfg(feature = "window")]
pub(crate) use state::GpuScene;
