//! Given code: a pinhole camera and a z-buffered triangle rasterizer with
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

/// A pinhole camera looking from `eye` at `target`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// Where the eye is (world space).
    pub eye: DVec3,
    /// The point in the centre of the picture.
    pub target: DVec3,
    /// Which way is up in the picture.
    pub up: DVec3,
    /// The vertical field of view in degrees.
    pub fov_y_degrees: f64,
}

impl Camera {
    /// The near plane distance: geometry closer to the eye is dropped.
    pub const NEAR: f64 = 0.1;
    /// The far plane distance.
    pub const FAR: f64 = 100.0;

    /// Maps a world point to the canvas: `x, y` in pixel coordinates
    /// (the canvas spans `[−½, width − ½] × [−½, height − ½]`), `z` the depth
    /// in `[0, 1]` (0 on the near plane, OpenGL's perspective depth).
    /// `None` for a point nearer than [`Camera::NEAR`] (or behind the eye)
    /// or a non-finite result.
    ///
    /// ```text
    ///   f = normalize(target − eye),  r = normalize(f × up),  s = r × f
    ///   d = p − eye:  x = r·d, y = s·d, z = f·d (distance along the view)
    ///   ndc = (x / (z · tan(fov/2) · aspect), y / (z · tan(fov/2)))
    ///   depth = (FAR / (FAR − NEAR)) · (1 − NEAR / z)
    /// ```
    #[must_use]
    pub fn to_screen(&self, world: DVec3, width: u32, height: u32) -> Option<DVec3> {
        let aspect = f64::from(width) / f64::from(height.max(1));
        let f = (self.target - self.eye).normalize_or_zero();
        let r = f.cross(self.up).normalize_or_zero();
        let s = r.cross(f);
        let d = world - self.eye;
        let z = f.dot(d);
        // NaN fails this test too.
        if z.is_nan() || z < Self::NEAR {
            return None;
        }
        let scale = (self.fov_y_degrees.to_radians() * 0.5).tan();
        let ndc = DVec2::new(r.dot(d) / (z * scale * aspect), s.dot(d) / (z * scale));
        // OpenGL's viewport transform: NDC ±1 on the edges of the canvas.
        let pixel = canvas::ndc_to_window(ndc, width, height);
        let screen = pixel.extend(Self::FAR / (Self::FAR - Self::NEAR) * (1.0 - Self::NEAR / z));
        screen.is_finite().then_some(screen)
    }
}

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
