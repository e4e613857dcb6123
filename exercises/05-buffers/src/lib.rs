//! Topic 05: buffers — the z-buffer with OpenGL's depth functions, depth
//! along a scanline, the painter's algorithm, polygon offset for
//! hidden-line drawing, the stencil buffer, double buffering, the
//! accumulation buffer, stereo buffering, when a swap is shown
//! (tearing, VSYNC, triple buffering), and translucent surfaces with the
//! z-buffer. The task sheet is `README.md`
//! next to this crate.
//!
//! Each task module below is one task. You edit the files in `src/`: what
//! you build, test and grade is always your own code. `raster` is given
//! code that the tasks use to make fragments.
#![warn(missing_docs)]

/// Given code (not a task): a triangle and a line rasterizer that emit fragments with depth.
pub mod raster;

/// Task 1: the z-buffer with OpenGL's eight depth functions, clear value and depth range.
pub mod zbuffer;

/// Task 2: depth along a scanline, by edge interpolation and incrementally from the plane equation.
pub mod scanline_depth;

/// Task 3: the painter's algorithm, and where it fails.
pub mod painter;

/// Task 4: polygon offset for hidden-line drawing without stitching.
pub mod polygon_offset;

/// Task 5: the stencil test, the eight stencil operations and the write mask.
pub mod stencil;

/// Task 6: double buffering, jittered accumulation for scene antialiasing, and smoothing by alpha blending.
pub mod accumulation;

/// Task 7: stereo buffering — one camera per eye (parallel axes, asymmetric frusta) and the anaglyph.
pub mod stereo;

/// Task 8: when the back buffer is shown — tearing without VSYNC, VSYNC, triple buffering.
pub mod presentation;

/// Task 9: translucent surfaces with the z-buffer — opaque first, then the translucent ones sorted back to front, tested but not written.
pub mod translucent;
