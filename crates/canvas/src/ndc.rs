//! The viewport transform: from normalised device coordinates (NDC, the
//! result of the perspective divide) to the pixel coordinates of the
//! convention above, and to depth.
//!
//! NDC run from −1 to +1 on each axis, y up like the canvas. Where ±1
//! lands is a choice, and the course meets two:
//!
//! ```text
//!   canvas 4 pixels wide:  |  0  |  1  |  2  |  3  |      (centres at integers)
//!                       −0.5                       3.5
//!   ndc_to_pixel:            −1 ···················· +1   ±1 on the outer pixel centres
//!   ndc_to_window:        −1 ·························· +1  ±1 on the canvas edges
//! ```
//!
//! - [`ndc_to_pixel`], the course's CPU pipeline (`scene`): ±1 on the
//!   centres of the outermost pixels, so that a polygon clipped to the
//!   clip volume never rounds to a pixel off the canvas and its edges on
//!   the border are drawn.
//! - [`ndc_to_window`], OpenGL's `glViewport(0, 0, w, h)` and wgpu's
//!   viewport, written in this course's pixel convention: ±1 on the edges
//!   of the canvas. The GPU rasterizes with it, so CPU code that must
//!   agree with a GPU (or measure lengths in the GPU's pixels) uses it.
//!
//! Depth maps the same way in both: [`ndc_depth`].

use glam::{DVec2, Vec2};

/// NDC `(x, y)` to pixel coordinates with ±1 on the centres of the
/// outermost pixels:
///
/// ```text
///   x_p = (x + 1) / 2 · (width − 1),   y_p = (y + 1) / 2 · (height − 1)
/// ```
///
/// An empty canvas (`width` or `height` 0) maps every point to 0 on that
/// axis. Non-finite input gives non-finite output.
#[must_use]
pub fn ndc_to_pixel(ndc: Vec2, width: u32, height: u32) -> Vec2 {
    let size = Vec2::new(width as f32, height as f32) - 1.0;
    (ndc + 1.0) * 0.5 * size.max(Vec2::ZERO)
}

/// NDC `(x, y)` to pixel coordinates with ±1 on the edges of the canvas,
/// as the GPU's viewport transform puts them (its pixel centres at
/// `+½`, ours at integers, hence the `− ½`):
///
/// ```text
///   x_p = (x + 1) / 2 · width − ½,     y_p = (y + 1) / 2 · height − ½
/// ```
///
/// Lengths in the GPU's pixels are differences of two mapped points
/// (`NDC · size / 2`). Non-finite input gives non-finite output.
#[must_use]
pub fn ndc_to_window(ndc: DVec2, width: u32, height: u32) -> DVec2 {
    DVec2::new(
        (ndc.x + 1.0) * 0.5 * f64::from(width) - 0.5,
        (ndc.y + 1.0) * 0.5 * f64::from(height) - 0.5,
    )
}

/// NDC depth `z ∈ [−1, 1]` (OpenGL's clip volume) to the depth buffer's
/// `[0, 1]`: `d = (z + 1) / 2`, the near plane at 0, the far plane at 1.
#[must_use]
pub fn ndc_depth(z: f32) -> f32 {
    (z + 1.0) * 0.5
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ndc_to_pixel_puts_the_corners_on_the_outer_pixel_centres() {
        assert_eq!(ndc_to_pixel(Vec2::new(-1.0, -1.0), 4, 3), Vec2::ZERO);
        assert_eq!(ndc_to_pixel(Vec2::new(1.0, 1.0), 4, 3), Vec2::new(3.0, 2.0));
        assert_eq!(ndc_to_pixel(Vec2::ZERO, 5, 5), Vec2::new(2.0, 2.0));
        assert_eq!(ndc_to_pixel(Vec2::ONE, 0, 0), Vec2::ZERO);
    }

    #[test]
    fn ndc_to_window_puts_the_corners_on_the_canvas_edges() {
        assert_eq!(
            ndc_to_window(DVec2::new(-1.0, -1.0), 4, 3),
            DVec2::new(-0.5, -0.5)
        );
        assert_eq!(
            ndc_to_window(DVec2::new(1.0, 1.0), 4, 3),
            DVec2::new(3.5, 2.5)
        );
        // The GPU's pixel centre (0.5, 0.5) of the first pixel is ours (0, 0).
        assert_eq!(ndc_to_window(DVec2::new(-0.75, -0.75), 4, 4), DVec2::ZERO);
    }

    #[test]
    fn depth_runs_from_the_near_to_the_far_plane() {
        assert_eq!(ndc_depth(-1.0), 0.0);
        assert_eq!(ndc_depth(1.0), 1.0);
        assert_eq!(ndc_depth(0.0), 0.5);
    }
}
