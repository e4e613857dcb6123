//! The surface scene's stages: your topic 07 evaluating a patch and
//! rendering it.

/// How the surface scene renders: what topic 07's `RenderSettings` holds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceView {
    /// Grid cells per side of the parameter square.
    pub level: u32,
    /// The tessellation grid over the surface.
    pub wireframe: bool,
    /// Where the camera stands (y up, 40° vertical field of view).
    pub eye: glam::DVec3,
    /// What it looks at.
    pub target: glam::DVec3,
    /// The colour where there is no surface.
    pub background: canvas::Rgba,
}

/// A patch's point and unit normal by your surface code.
#[cfg(feature = "bezier")]
pub(super) fn patch_point(
    net: &freeform::BezierPatch,
    uv: glam::DVec2,
) -> Result<(glam::DVec3, glam::DVec3), String> {
    let point = bezier::surface::partial_derivatives(net, uv).map_err(|e| e.to_string())?;
    let normal = bezier::surface::normal(net, uv).map_err(|e| e.to_string())?;
    Ok((point.position, normal))
}

/// Your `render_surface` with the viewer's surface and trim.
#[cfg(feature = "bezier")]
pub(super) fn render_surface(
    canvas: &mut canvas::Canvas,
    surface: &dyn Fn(glam::DVec2) -> Result<(glam::DVec3, glam::DVec3), String>,
    trims: &dyn Fn(glam::DVec2) -> bool,
    view: &SurfaceView,
) -> Result<(), String> {
    use bezier::render::{RenderSettings, SurfaceSample};
    /// A trim that asks the viewer's closure.
    struct Asking<'a>(&'a dyn Fn(glam::DVec2) -> bool);
    impl bezier::Trim for Asking<'_> {
        fn trims(&self, uv: glam::DVec2) -> bool {
            (self.0)(uv)
        }
    }
    let settings = RenderSettings {
        camera: bezier::zbuffer::Camera {
            eye: view.eye,
            target: view.target,
            up: glam::DVec3::Y,
            fov_y_degrees: 40.0,
        },
        tess_level: view.level,
        wireframe: view.wireframe,
        background: view.background,
    };
    // The surface's own error is the surface stage's to report; the
    // render only passes it on.
    let sample = |uv| {
        surface(uv)
            .map(|(position, normal)| SurfaceSample {
                uv,
                position,
                normal,
            })
            .map_err(|_| bezier::BezierError::Empty)
    };
    bezier::render::render_surface(canvas, sample, &Asking(trims), &settings)
        .map_err(|e| e.to_string())
}
