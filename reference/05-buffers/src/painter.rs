//! The painter's algorithm (seed 002, §6.2 "Maler-Algorithmus"): sort the
//! triangles by their distance from the eye, then draw them from the
//! farthest to the nearest, each overwriting what lies behind it.
//!
//! Convention (see `canvas`): pixel centres at integers, y up; depth 0 is
//! nearest. Triangles are drawn with the given
//! [`crate::raster::fill_triangle`] (top-left rule) and no depth test.
//!
//! The seed names its weakness: "Gegenseitige Durchdringung von
//! Objekten/Polygonen kann nicht abgebildet werden" — two triangles that
//! pass through each other are each partly in front, and no order of whole
//! triangles draws that. The z-buffer decides per pixel and gets it right.
//!
//! ```text
//!   depth ↑   A ─────────╲─────        A is behind B on the left and
//!             B ──────────╲────        in front of it on the right:
//!                        they cross    any order paints one half wrong
//! ```

use canvas::{Canvas, Vertex, Viewport};

use crate::raster::fill_triangle;

/// The sort key of a triangle: its farthest vertex depth (Newell, Newell
/// and Sancha 1972 sort by the farthest z first). `None` when a depth is
/// NaN or infinite.
#[must_use]
#[transcript::task]
pub fn farthest_depth(triangle: &[Vertex; 3]) -> Option<f32> {
    // BEGIN SOLUTION painter: the largest of the three vertex depths, None if one is not finite
    if !triangle.iter().all(|v| v.depth.is_finite()) {
        return None;
    }
    Some(triangle.iter().map(|v| v.depth).fold(f32::MIN, f32::max))
    // END SOLUTION
}

/// The drawing order of the painter's algorithm: indices into `triangles`,
/// farthest first by [`farthest_depth`]. Triangles with equal keys keep
/// their input order (a stable sort); triangles with a NaN or infinite
/// depth are left out.
#[must_use]
#[transcript::task]
pub fn painter_order(triangles: &[[Vertex; 3]]) -> Vec<usize> {
    // BEGIN SOLUTION painter: keep the triangles with a key, sort them stably by key, largest first
    let mut keyed: Vec<(usize, f32)> = triangles
        .iter()
        .enumerate()
        .filter_map(|(i, t)| farthest_depth(t).map(|key| (i, key)))
        .collect();
    keyed.sort_by(|a, b| b.1.total_cmp(&a.1));
    keyed.into_iter().map(|(i, _)| i).collect()
    // END SOLUTION
}

/// Paints `triangles` onto `canvas` in [`painter_order`]: every fragment
/// of [`fill_triangle`] (clipped to the canvas) overwrites the colour, with
/// no depth test; the depth plane is not touched.
#[transcript::task]
pub fn paint(canvas: &mut Canvas, triangles: &[[Vertex; 3]]) {
    // BEGIN SOLUTION painter: fill the triangles in painter order, each fragment overwriting the colour
    let viewport: Viewport = canvas.viewport();
    for i in painter_order(triangles) {
        fill_triangle(triangles[i], viewport, |f| canvas.set(f.pixel, f.colour));
    }
    // END SOLUTION
}
