//! Topic 10: GPU tessellation. wgpu has no tessellation stage, so you build
//! one from compute passes: the control stage (levels per patch), the
//! evaluation stage (de Casteljau for bicubic patches and Bézier
//! triangles), then shading (Phong, two lights, a texture, a wireframe)
//! and trimming in the fragment shader. The task sheet is `README.md` next
//! to this crate.
//!
//! Your code is WGSL inside Rust string functions (and one Rust function);
//! the given modules paste it between their own WGSL, run it on the GPU (or
//! on a software adapter such as lavapipe) and read the results back. What
//! you build, test and grade is always your own code.
//!
//! ```text
//!  patches ─▶ control pass (task 1) ─▶ levels ─▶ domain (given, CPU)
//!          ─▶ evaluation pass (task 3) ─▶ vertices ─▶ render pass:
//!             shade (task 4) + is_trimmed (task 5) + wireframe (task 4)
//! ```
#![warn(missing_docs)]

/// Given: the primitive generator (domain points and triangles).
pub mod domain;
/// Given: the compute passes around tasks 1 and 3.
pub mod passes;
/// Given: Bézier patches and triangles, their control points as the GPU reads them.
pub mod patch;
/// Given: the render pass around tasks 4 and 5.
pub mod render;
/// Given: the WGSL around your functions.
pub mod shaders;

/// Task 1: tessellation levels per patch, uniform or adaptive (WGSL).
pub mod control;

/// Task 3: de Casteljau for bicubic patches and Bézier triangles (WGSL).
pub mod evaluation;

/// Task 4: Phong shading with two lights and a texture (WGSL), wireframe edges.
pub mod shading;

/// Task 5: trimming by rectangle, circle, ellipse and Newton (WGSL).
pub mod trimming;

/// Why a pass could not run.
#[derive(Debug, thiserror::Error)]
pub enum TessError {
    /// Input the passes refuse: non-finite numbers, non-positive levels,
    /// too many trim shapes, mismatched lengths.
    #[error("invalid input: {0}")]
    Invalid(String),
    /// The GPU side: WGSL that does not compile or validate (the message
    /// names the line), a failed readback.
    #[error(transparent)]
    Gpu(#[from] gpu::GpuError),
}
