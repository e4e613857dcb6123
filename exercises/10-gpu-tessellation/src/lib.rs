//! Topic 10: GPU tessellation. wgpu has no tessellation stage, so you build
//! one from compute passes: the control stage (levels per patch), the
//! evaluation stage (de Casteljau for bicubic patches and Bézier
//! triangles), then shading (Phong, two lights, a texture, a wireframe)
//! and trimming in the fragment shader; and a PN pass's control stage,
//! which builds Bézier triangles from flat ones. The task sheet is `README.md` next
//! to this crate.
//!
//! Your code is WGSL in five `.wgsl` files and Rust in two (the primitive
//! generator and the wireframe's edges): the given modules put the WGSL
//! together with their own ([`wgsl::compose`]),
//! check it, run it on the GPU (or on a software adapter such as
//! lavapipe) and read the results back. What you build, test and grade is
//! always your own code, and a shader error names your file and line.
//!
//! ```text
//!  patches ─▶ control pass (src/control.wgsl) ─▶ levels ─▶ src/domain.rs (CPU)
//!          ─▶ evaluation pass (src/evaluation.wgsl) ─▶ vertices ─▶ render pass:
//!             src/shading.wgsl + src/trimming.wgsl + wireframe (shading.rs)
//!  flat triangles + normals ─▶ PN pass (src/pn.wgsl) ─▶ Bézier triangles ─▶ evaluation
//! ```
#![warn(missing_docs)]

/// Task 2: the primitive generator (domain points and triangles).
pub mod domain;
/// Given: the compute passes around tasks 1 and 3.
pub mod passes;
/// Given: Bézier patches and triangles, their control points as the GPU reads them.
pub mod patch;
/// Given: the render pass around tasks 4 and 5.
pub mod render;
/// Given: the WGSL around your functions.
pub mod shaders;

/// Your WGSL files (tasks 1, 3, 4, 5 and 6), compiled in, and how a pass
/// checks them.
pub mod wgsl;

/// Task 4: the wireframe's edges (and, in `src/shading.wgsl`, Phong shading).
pub mod shading;

/// Why a pass could not run.
#[derive(thiserror::Error)]
pub enum TessError {
    /// Input the passes refuse: non-finite numbers, non-positive levels,
    /// too many trim shapes, mismatched lengths.
    #[error("invalid input: {0}")]
    Invalid(String),
    /// WGSL that does not compile or validate: each error at its file and
    /// line (see [`wgsl::compose`]).
    #[error("the WGSL does not compile:\n{0}")]
    Wgsl(String),
    /// The GPU side: a pipeline wgpu refuses, a failed readback.
    #[error(transparent)]
    Gpu(#[from] gpu::GpuError),
}

/// As [`std::fmt::Display`]: `.unwrap()` on a failed pass prints the
/// message as written, each error on its own lines.
impl std::fmt::Debug for TessError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Display::fmt(self, f)
    }
}
