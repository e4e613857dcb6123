//! A small library rasterizer for the pipeline: triangles by edge
//! functions and lines as one-pixel-wide bands of two triangles, with
//! colour and depth interpolation and a depth test. [`cover`], the
//! triangles' pixels with their barycentric weights, is the one triangle
//! rasterizer of the course's given code: topic 05's fragments (which add
//! the top-left rule), topic 07's z-buffer, topic 09's renderer and
//! topic 08's test pictures draw with it.
//!
//! This is not student work: the exercise topics write their own, and
//! `cargo xtask view` draws the pipeline with those. It is kept small and
//! plain, and unlike any task (no line algorithm, no fill rule for shared
//! edges, no fixed point), so that it draws the pictures of topic 04's
//! tests without answering a task.
//!
//! Pixel convention: the canvas's (centres at integers, y up, rounding half
//! away from zero). Depth test: a fragment is written only where its depth
//! is *less* than the stored one (OpenGL's `GL_LESS`); NaN depth never
//! passes. Input with a coordinate that is not finite or beyond
//! ±[`canvas::MAX_COORD`] is not drawn; the work per primitive is bounded by
//! the canvas size, however long the primitive.

mod band;
mod edge_function;

pub use band::{band, draw_line};
pub use edge_function::{cover, fill_triangle};

use canvas::{Canvas, Fragment, Vertex, within_limits};

/// Writes the fragment if it passes the depth test `depth < stored`
/// (`GL_LESS`); ignored off the canvas.
pub fn depth_test(canvas: &mut Canvas, fragment: Fragment) {
    if canvas
        .depth(fragment.pixel)
        .is_some_and(|stored| fragment.depth < stored)
    {
        canvas.plot(fragment);
    }
}

/// Whether a vertex's position can be rasterized: finite and within
/// ±[`canvas::MAX_COORD`].
fn drawable(v: &Vertex) -> bool {
    within_limits(v.position.x) && within_limits(v.position.y)
}
