//! Given code: a pinhole camera (`scene`'s) and a z-buffered triangle rasterizer with
//! interpolated attributes — the fixed-function part of the pipeline that
//! the render task (and the test pictures) drive. Topic 03 teaches how it
//! works; here it is a tool.
//!
//! Convention (see `canvas`): pixel centres at integer coordinates, y up.
//! The pixels of a triangle are those `scene::raster::cover` finds: a
//! pixel belongs to a triangle when its centre is inside or on an edge (no
//! fill rule: a pixel on a shared edge is visited twice, and the depth
//! test keeps one). Depth test LESS; fragments outside depth `[0, 1]` are
//! dropped (near/far clipping per fragment).

use canvas::{Canvas, Pixel, Rgba};
use glam::{DVec2, DVec3};

/// A pinhole camera looking from `eye` at `target`, projecting with the
/// course pipeline's conventions (`scene::Camera`, the course library's).
pub use scene::Camera;

/// A triangle corner after projection, with the attributes to interpolate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RasterVertex {
    /// Pixel coordinates `x, y` and depth `z` (from [`Camera::to_screen`]).
    pub screen: DVec3,
    /// The surface parameters.
    pub uv: DVec2,
    /// The world position.
    pub world: DVec3,
    /// The (unit) normal.
    pub normal: DVec3,
}

/// What the rasterizer hands the shading function for one pixel: the
/// attributes interpolated linearly in screen space with barycentric
/// weights (not perspective-correct; with a fine tessellation the error is
/// a small fraction of a triangle). The normal is interpolated, not
/// renormalised.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fragment {
    /// The pixel.
    pub pixel: Pixel,
    /// Depth in `[0, 1]`.
    pub depth: f64,
    /// Interpolated surface parameters.
    pub uv: DVec2,
    /// Interpolated world position.
    pub world: DVec3,
    /// Interpolated normal (not unit length).
    pub normal: DVec3,
}

/// Rasterizes one triangle into `canvas` with a depth test: for every
/// covered pixel whose depth is less than the stored one, `shade` is
/// called; `Some(colour)` writes colour and depth, `None` discards the
/// fragment (the shader's `discard`: nothing is written).
///
/// The covered pixels and their barycentric weights are the course's one
/// given triangle rasterizer's, `scene::raster::cover` (centres on an edge
/// included); this function interpolates the attributes and tests depth.
/// Triangles with a non-finite or zero-area screen footprint draw nothing.
pub fn rasterize_triangle(
    canvas: &mut Canvas,
    vertices: [RasterVertex; 3],
    mut shade: impl FnMut(&Fragment) -> Option<Rgba>,
) {
    let corners = vertices.map(|v| v.screen.truncate());
    let viewport = canvas.viewport();
    scene::raster::cover(corners, viewport, |pixel, w| {
        let mix3 = |f: fn(&RasterVertex) -> DVec3| {
            f(&vertices[0]) * w[0] + f(&vertices[1]) * w[1] + f(&vertices[2]) * w[2]
        };
        let depth = mix3(|v| v.screen).z;
        let stored = canvas.depth(pixel).map_or(f64::NEG_INFINITY, f64::from);
        if !(0.0..=1.0).contains(&depth) || depth >= stored {
            return;
        }
        let fragment = Fragment {
            pixel,
            depth,
            uv: mix3(|v| v.uv.extend(0.0)).truncate(),
            world: mix3(|v| v.world),
            normal: mix3(|v| v.normal),
        };
        if let Some(colour) = shade(&fragment) {
            canvas.set(pixel, colour);
            canvas.set_depth(pixel, depth as f32);
        }
    });
}
