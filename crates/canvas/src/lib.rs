//! The course canvas: a raster with colour, depth and stencil planes, and the pixel
//! conventions every rasterizer in this course follows.
//!
//! # Pixel convention
//!
//! This is the one place the convention is written down; every rasterizer
//! restates it in one line together with its own tie-break rule.
//!
//! ```text
//!   y
//!   ^         pixel (2, 1) covers [1.5, 2.5] × [0.5, 1.5]
//!   2 +   ·   ·   ·   ·
//!   1 +   ·   · [■]   ·      · pixel centres, at integer coordinates
//!   0 +   ·   ·   ·   ·
//!     +---+---+---+---+--> x
//!         0   1   2   3
//! ```
//!
//! - **Pixel centres lie at integer coordinates.** Pixel `(x, y)` is the unit
//!   square `[x − ½, x + ½] × [y − ½, y + ½]`; a continuous point is sampled
//!   at the pixel whose centre is nearest.
//! - **y points up**, as in the lecture slides (E, NE, SE are the compass
//!   directions of a y-up plane). Row `y = 0` is the *bottom* row; PNG files
//!   and ASCII art are flipped so that pictures look the right way up.
//! - **Rounding is half away from zero** ([`round_half_away`]), as the TU Wien
//!   sheet's `round`: `0.5 → 1`, `−0.5 → −1`, `2.5 → 3`.
//! - **Lines include both endpoints.** Tie-breaks are the rasterizer's to
//!   state (the midpoint line takes the lower pixel of two equally near ones).
//! - **A centre exactly on an edge belongs to one of the two shapes that
//!   share the edge**, never both: the triangle fill gives it by the
//!   top-left rule, the rectangle and polygon fills by half-open ranges
//!   (left and bottom edges in, right and top edges out). Topic 03's sheet
//!   defines each precisely.
//! - **Writes outside the canvas are ignored**: rasterizers may emit pixels
//!   anywhere; [`Canvas::set`] and friends clip them silently.
//! - **Coordinates are limited to ±[`MAX_COORD`]**: beyond that an `f32`
//!   can no longer hold every pixel position, and rasterizers document
//!   what they do with such input (usually: draw nothing).
//! - **From NDC to pixels** is the viewport transform, written once in
//!   [`ndc`]: [`ndc_to_pixel`] for the course's pipeline, [`ndc_to_window`]
//!   where CPU code must agree with a GPU.
#![warn(missing_docs)]

mod ascii;
mod canvas;
mod colour;
pub mod ndc;
mod pixel;

pub use ascii::{ASCII_LEGEND, ascii_grid, ink_char};
pub use canvas::{Canvas, CanvasError, DEPTH_CLEAR, Fragment, STENCIL_BITS, STENCIL_CLEAR, Vertex};
pub use colour::Rgba;
pub use ndc::{ndc_depth, ndc_to_pixel, ndc_to_window};
pub use pixel::{MAX_COORD, Pixel, Span, Viewport, round_half_away, within_limits};

/// Re-exported so that exercise crates use the same vector types as the library.
pub use glam::{Vec2, Vec3, Vec4};
