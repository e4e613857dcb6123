//! A CPU render of a trimmed Bézier surface: tessellation into a grid of
//! triangles (what the seed's TCS/TES do, §4.1), per-fragment trimming
//! (the fragment shader's `discard`, §4.2.3), Phong shading with the
//! seed's two lights (Listing 13) and a wireframe overlay (Fig. 21, 26).
//!
//! ```text
//!   (u, v) grid ──surface──▶ positions, normals ──camera──▶ screen triangles
//!        ──rasterize (z-buffer)──▶ fragments ──trim? discard──▶ Phong ──▶ canvas
//! ```

use canvas::{Canvas, Rgba};
use glam::{DVec2, DVec3};

use crate::basics::{BezierError, Trim};
use crate::zbuffer::{Camera, Fragment, RasterVertex, rasterize_triangle};

/// The ambient colour (Listing 13: `ambientColor = vec3(0.1)`).
pub const AMBIENT: DVec3 = DVec3::splat(0.1);
/// The specular colour (Listing 13: white).
pub const SPECULAR: DVec3 = DVec3::ONE;
/// The Phong exponent (Listing 13: `pow(…, 150)`).
pub const SHININESS: f64 = 150.0;
/// The two point lights, above and below (Listing 13), in world space.
pub const LIGHTS: [DVec3; 2] = [DVec3::new(0.0, 10.0, 0.0), DVec3::new(0.0, -10.0, 0.0)];
/// The highest tessellation level (OpenGL's guaranteed
/// `GL_MAX_TESS_GEN_LEVEL`).
pub const MAX_TESS_LEVEL: u32 = 64;
/// Checker cells per side of the parameter square: the texture that
/// stands in for the seed's brick texture.
pub const CHECKER_CELLS: f64 = 8.0;
/// Half the width of a wireframe line, in grid cells of the tessellation.
pub const WIREFRAME_HALF_WIDTH: f64 = 0.06;
/// The colour of the wireframe overlay.
pub const WIREFRAME_COLOUR: Rgba = Rgba::rgb(0.05, 0.05, 0.1);

/// A point of the surface with its parameters and unit normal (the course
/// library's record, `freeform::SurfaceSample`): what [`render_surface`]
/// asks of the surface at each grid point.
pub use freeform::SurfaceSample;

/// How to render.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderSettings {
    /// The camera.
    pub camera: Camera,
    /// Grid cells per side of the parameter square (the seed's
    /// `tessLevel`, all inner and outer levels equal), `1 ..= MAX_TESS_LEVEL`.
    pub tess_level: u32,
    /// Draw the tessellation grid over the shaded surface.
    pub wireframe: bool,
    /// The colour of pixels the surface does not cover.
    pub background: Rgba,
}

/// The diffuse colour at `uv`: a checkerboard of [`CHECKER_CELLS`]² cells
/// in two warm tones (given: the stand-in for the seed's texture).
#[must_use]
pub fn checker(uv: DVec2) -> DVec3 {
    let cell = (uv * CHECKER_CELLS).floor();
    if (cell.x + cell.y).rem_euclid(2.0) < 1.0 {
        DVec3::new(0.75, 0.35, 0.2)
    } else {
        DVec3::new(0.9, 0.8, 0.6)
    }
}

/// Phong shading with the seed's two lights (Listing 13):
///
/// ```text
///   l_k = normalize(LIGHTS[k] − position)     e = normalize(eye − position)
///   r_k = reflect(−l_k, n) = 2 (n · l_k) n − l_k
///   φ_k = max(n · l_k, 0)                     ψ_k = max(r_k · e, 0)^SHININESS
///   colour = diffuse · AMBIENT + Σ_k (φ_k · diffuse + ψ_k · SPECULAR)
/// ```
///
/// `normal` must be unit length. The result is not clamped (a canvas
/// clamps when it stores it). The seed's shader works in view space with
/// the eye at the origin (`eye = normalize(−position)`); here everything
/// is in world space with the eye given.
#[must_use]
#[transcript::task]
pub fn phong(normal: DVec3, position: DVec3, eye: DVec3, diffuse: DVec3) -> DVec3 {
    // BEGIN SOLUTION render: ambient · diffuse plus, per light, φ · diffuse + ψ · specular as in Listing 13
    let e = (eye - position).normalize_or_zero();
    let mut colour = diffuse * AMBIENT;
    for light in LIGHTS {
        let l = (light - position).normalize_or_zero();
        let r = 2.0 * normal.dot(l) * normal - l;
        let phi = normal.dot(l).max(0.0);
        let psi = r.dot(e).max(0.0).powf(SHININESS);
        colour += phi * diffuse + psi * SPECULAR;
    }
    colour
    // END SOLUTION
}

/// Renders the surface into `canvas` (cleared to `settings.background`
/// first): sample `surface` on the `(L + 1)²` grid `uv = (i/L, j/L)`,
/// `L = tess_level`; two triangles per grid cell; rasterize with the depth
/// test; per fragment, clamp the interpolated uv to `[0, 1]²`, discard it
/// where `trim.trims(uv)`, otherwise shade it with [`phong`] using the
/// renormalised interpolated normal, the camera's eye and [`checker`] as
/// diffuse colour; with `wireframe`, fragments within
/// [`WIREFRAME_HALF_WIDTH`] grid cells of a grid line get
/// [`WIREFRAME_COLOUR`] instead.
///
/// Triangles with a corner behind the camera are skipped.
///
/// # Errors
/// [`BezierError::InvalidSetting`] for a tessellation level outside
/// `1 ..= MAX_TESS_LEVEL`; the first error of `surface`. Nothing is drawn
/// then.
#[transcript::task]
pub fn render_surface(
    canvas: &mut Canvas,
    surface: impl Fn(DVec2) -> Result<SurfaceSample, BezierError>,
    trim: &dyn Trim,
    settings: &RenderSettings,
) -> Result<(), BezierError> {
    // BEGIN SOLUTION render: check the level; sample the grid; project; two triangles per cell; discard trimmed, shade the rest
    let level = settings.tess_level;
    if !(1..=MAX_TESS_LEVEL).contains(&level) {
        return Err(BezierError::InvalidSetting(
            "tess_level must be in 1 ..= 64",
        ));
    }
    let l = f64::from(level);
    let n = level as usize + 1;
    let mut grid = Vec::with_capacity(n * n);
    for i in 0..n {
        for j in 0..n {
            let uv = DVec2::new(i as f64 / l, j as f64 / l);
            let sample = surface(uv)?;
            let screen =
                settings
                    .camera
                    .to_screen(sample.position, canvas.width(), canvas.height());
            grid.push(screen.map(|screen| RasterVertex {
                screen,
                uv,
                world: sample.position,
                normal: sample.normal,
            }));
        }
    }
    canvas.clear(settings.background);
    let shade = |f: &Fragment| {
        let uv = f.uv.clamp(DVec2::ZERO, DVec2::ONE);
        if trim.trims(uv) {
            return None;
        }
        if settings.wireframe {
            let cell = uv * l;
            let off_line = (cell - cell.round()).abs();
            if off_line.min_element() < WIREFRAME_HALF_WIDTH {
                return Some(WIREFRAME_COLOUR);
            }
        }
        let c = phong(
            f.normal.normalize_or_zero(),
            f.world,
            settings.camera.eye,
            checker(uv),
        );
        Some(Rgba::rgb(c.x as f32, c.y as f32, c.z as f32))
    };
    let at = |i: usize, j: usize| grid[i * n + j];
    for i in 0..level as usize {
        for j in 0..level as usize {
            let corners = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)];
            for [p, q, r] in [[0, 1, 2], [0, 2, 3]] {
                if let (Some(a), Some(b), Some(c)) = (corners[p], corners[q], corners[r]) {
                    rasterize_triangle(canvas, [a, b, c], &shade);
                }
            }
        }
    }
    Ok(())
    // END SOLUTION
}
