//! A small CPU renderer for looking at meshes: orthographic view, z-buffer,
//! Gouraud-free per-pixel Lambert shading of the interpolated normal, and a
//! wireframe drawn with hidden lines removed. It is course code for the
//! pictures of this topic, not a task; the rasterization topics teach how
//! each of its steps is done properly.
//!
//! Conventions: the canvas's (pixel centres at integers, y up); the
//! triangles' pixels are those of the course's given rasterizer,
//! `scene::raster::cover` (centres on an edge included). The surfaces of
//! this topic stand on the xy plane with z up, as the seed draws them; the
//! renderer stands them in the course's world, whose up is y
//! ([`STAND_UP`]), and looks at them with a camera turned as every camera
//! of the course ([`scene::turn`]); the mesh is scaled so that its picture
//! fills [`FILL`](crate::render::FILL) of the smaller canvas side.

use canvas::{Canvas, Pixel, Rgba};
use glam::{DMat3, DVec2, DVec3};

use crate::mesh::Mesh;

/// The part of the canvas the larger side of the turned mesh's bounding rectangle fills.
pub const FILL: f64 = 0.9;
/// Light direction in view space (towards the light), normalised at use.
pub const LIGHT: DVec3 = DVec3::new(-0.4, 0.5, 1.0);
/// Ambient light, added to the diffuse term.
pub const AMBIENT: f64 = 0.15;
/// Wire pixels are drawn unless they lie further than this (a fraction of
/// the mesh's bounding radius) behind the surface: hides lines behind the
/// surface, keeps those on it.
pub const WIRE_DEPTH_BIAS: f64 = 1e-2;
/// The surface colour.
pub const SURFACE: Rgba = Rgba::rgb(0.55, 0.7, 0.95);
/// The wire colour.
pub const WIRE: Rgba = Rgba::rgb(0.1, 0.1, 0.2);
/// The background colour.
pub const BACKGROUND: Rgba = Rgba::WHITE;

/// What to draw.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Style {
    /// Lambert-shaded surface.
    Shaded,
    /// Visible edges only, on the background.
    Wireframe,
    /// Shaded surface with its visible edges on top.
    ShadedWireframe,
}

/// The turn from the topic's z-up surfaces to the course's y-up world:
/// a quarter turn about x, `(x, y, z) ↦ (x, z, −y)`.
pub const STAND_UP: DMat3 = DMat3::from_cols(DVec3::X, DVec3::NEG_Z, DVec3::Y);

/// Where the mesh is seen from: the camera's turn ([`scene::turn`],
/// radians), its orbit about the mesh's middle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    /// Around the world's up axis (the surface's z).
    pub yaw: f64,
    /// The camera's tilt (negative: it looks down on the surface).
    pub pitch: f64,
}

/// Renders `mesh` into a new `width × height` canvas. Triangles with a
/// non-finite vertex are skipped; an empty mesh gives the background.
#[must_use]
pub fn render(mesh: &Mesh, view: View, style: Style, width: u32, height: u32) -> Canvas {
    let mut canvas = Canvas::new(width, height);
    canvas.clear(BACKGROUND);
    let (w, h) = (canvas.width() as usize, canvas.height() as usize);
    // World to camera: stood up, then the camera's turn undone.
    let rotation = scene::turn(view.yaw, view.pitch).transpose() * STAND_UP;
    let finite: Vec<DVec3> = mesh
        .positions
        .iter()
        .copied()
        .filter(|p| p.is_finite())
        .collect();
    if finite.is_empty() || w == 0 || h == 0 {
        return canvas;
    }
    // Fit the turned mesh's bounding rectangle into the canvas.
    let turned: Vec<DVec3> = finite.iter().map(|&p| rotation * p).collect();
    let (lo, hi) = turned.iter().fold((turned[0], turned[0]), |(lo, hi), &p| {
        (lo.min(p), hi.max(p))
    });
    let centre = (lo + hi) / 2.0;
    let extent = (hi - lo).truncate().max_element().max(f64::MIN_POSITIVE);
    let radius = (hi - lo).length() / 2.0;
    let scale = FILL * w.min(h) as f64 / extent;
    let screen_centre = DVec2::new((w as f64 - 1.0) / 2.0, (h as f64 - 1.0) / 2.0);
    // Screen x, y in pixels; z grows towards the viewer.
    let project = |p: DVec3| {
        let q = rotation * p - centre;
        DVec3::new(
            screen_centre.x + scale * q.x,
            screen_centre.y + scale * q.y,
            q.z,
        )
    };
    let screen: Vec<DVec3> = mesh.positions.iter().map(|&p| project(p)).collect();
    let normals: Vec<DVec3> = mesh.normals.iter().map(|&n| rotation * n).collect();
    let light = LIGHT.normalize();
    let mut depth = vec![f64::NEG_INFINITY; w * h];
    let mut shade = vec![None; w * h];
    for tri in &mesh.triangles {
        let Some([a, b, c]) = fetch(&screen, *tri) else {
            continue;
        };
        let [na, nb, nc] = fetch(&normals, *tri).unwrap_or([DVec3::Z; 3]);
        let corners = [a, b, c].map(DVec3::truncate);
        scene::raster::cover(corners, canvas.viewport(), |pixel, [wa, wb, wc]| {
            let z = wa * a.z + wb * b.z + wc * c.z;
            let k = pixel.y as usize * w + pixel.x as usize;
            if z > depth[k] {
                depth[k] = z;
                let n = (wa * na + wb * nb + wc * nc).normalize_or_zero();
                shade[k] = Some(AMBIENT + (1.0 - AMBIENT) * n.dot(light).abs());
            }
        });
    }
    if style != Style::Wireframe {
        for (k, s) in shade.iter().enumerate() {
            if let Some(s) = s {
                let s = *s as f32;
                let colour = Rgba::rgb(SURFACE.r * s, SURFACE.g * s, SURFACE.b * s);
                canvas.set(Pixel::new((k % w) as i32, (k / w) as i32), colour);
            }
        }
    }
    if style != Style::Shaded {
        for tri in &mesh.triangles {
            let Some(corners) = fetch(&screen, *tri) else {
                continue;
            };
            for e in 0..3 {
                wire(
                    &mut canvas,
                    &depth,
                    w,
                    WIRE_DEPTH_BIAS * radius,
                    corners[e],
                    corners[(e + 1) % 3],
                );
            }
        }
    }
    canvas
}

/// The three entries of `list` a triangle names, if all exist and are finite.
fn fetch(list: &[DVec3], tri: [u32; 3]) -> Option<[DVec3; 3]> {
    let get = |i: u32| list.get(i as usize).copied().filter(|p| p.is_finite());
    Some([get(tri[0])?, get(tri[1])?, get(tri[2])?])
}

/// A DDA line from `a` to `b`, drawn where it is not behind the surface.
fn wire(canvas: &mut Canvas, depth: &[f64], w: usize, bias: f64, a: DVec3, b: DVec3) {
    let h = depth.len() / w;
    let steps = (b.x - a.x).abs().max((b.y - a.y).abs()).ceil().min(1e5) as usize;
    for s in 0..=steps {
        let t = if steps == 0 {
            0.0
        } else {
            s as f64 / steps as f64
        };
        let p = a.lerp(b, t);
        let (x, y) = (p.x.round(), p.y.round());
        if x < 0.0 || y < 0.0 || x >= w as f64 || y >= h as f64 {
            continue;
        }
        let k = y as usize * w + x as usize;
        if p.z + bias >= depth[k] {
            canvas.set(Pixel::new(x as i32, y as i32), WIRE);
        }
    }
}
