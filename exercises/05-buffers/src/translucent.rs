//! Translucent surfaces and the z-buffer (seed 002, §6.2 "Z-Buffer-
//! Algorithmus", its problems: "Transparente Oberflächen werden nicht
//! korrekt berücksichtigt").
//!
//! Convention (see `canvas`): pixel centres at integers, y up; depth 0 is
//! nearest, the depth plane starts at [`canvas::DEPTH_CLEAR`]. Triangles
//! are drawn with the given [`crate::raster::fill_triangle`].
//!
//! The z-buffer keeps one surface per pixel, the nearest, and forgets the
//! rest: right for opaque surfaces, whose order does not matter, wrong for
//! a translucent one, through which the surfaces behind it must still be
//! seen. Drawn in any order with depth writes, a near translucent triangle
//! drawn first hides a far one drawn later (its fragments fail the depth
//! test); without depth writes, the far one is blended *over* the near
//! one. Blending is not commutative: `over` must go from back to front.
//! The usual mend, and this task's: opaque surfaces first with the
//! z-buffer, then the translucent ones pre-sorted by depth, farthest first,
//! tested against the depth plane (an opaque surface in front hides them)
//! but never writing it.
//!
//! ```text
//!   eye ──▶   red 50 %  (near)     blue 50 %  (far)     grey (opaque)
//!   back to front:  grey, then blue over it, then red over that
//!   unsorted, red first with depth writes:  blue fails the depth test
//! ```
//!
//! The sort is by whole triangles, so it is right for triangles that do
//! not overlap in depth; two translucent triangles that pass through each
//! other are still blended in one order at every pixel (the painter's
//! problem again; order-independent transparency is beyond this task).

#[allow(unused_imports)]
use canvas::{Canvas, Vertex, Viewport};

#[allow(unused_imports)]
use crate::raster::fill_triangle;

/// The sort key of a translucent triangle: the depth of its centroid,
/// `(d₀ + d₁ + d₂) / 3` in `f32`, summed in that order. `None` when a depth
/// is NaN or infinite.
#[must_use]
#[transcript::task]
pub fn centroid_depth(triangle: &[Vertex; 3]) -> Option<f32> {
    // Unused until you write the body:
    let _ = &triangle;
    todo!("translucent: (d0 + d1 + d2) / 3 in f32, None if a depth is not finite")
}

/// Draws a scene with translucent surfaces onto `canvas` (its colour and
/// depth planes as they are; a cleared canvas is the usual start):
///
/// 1. **Opaque** triangles in the given order, with the z-buffer: a
///    fragment passes when its depth is *less* than the stored one; then
///    its depth is stored and its colour overwrites the pixel.
/// 2. **Translucent** triangles, farthest first by [`centroid_depth`]
///    (equal keys keep their input order; a triangle with a NaN or
///    infinite depth is left out): a fragment passes the same test against
///    the depth plane, then its colour is blended over the pixel with
///    [`Canvas::blend`] at coverage 1 (its own alpha, interpolated from
///    the vertices, says how much of it shows). Its depth is **not**
///    stored: a translucent surface hides nothing.
///
/// Only pixels inside the canvas are drawn.
#[transcript::task]
pub fn draw_with_translucency(
    canvas: &mut Canvas,
    opaque: &[[Vertex; 3]],
    translucent: &[[Vertex; 3]],
) {
    // Unused until you write the body:
    let _ = (&canvas, &opaque, &translucent);
    todo!(
        "translucent: opaque with depth test LESS and depth write; then translucent sorted stably by centroid depth, farthest first, depth test LESS, blended, no depth write"
    )
}
