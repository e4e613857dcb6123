//! Turning a framebuffer into a picture: a colour per primitive, shaded
//! by the surface normal (Lambert, one light from the viewer's upper
//! left), background dark grey. Faces seen from inside — the back faces a
//! difference shows — are shaded with the normal turned towards the
//! viewer and drawn darker, so the walls of a drilled hole stand out.
//!
//! This module is given: you use it, you do not edit it.

use canvas::{Canvas, Pixel, Rgba};
use glam::Vec3;

use crate::primitive::Primitive;
use crate::raster::{Face, Framebuffer};

/// One colour per primitive index (repeating).
pub const PALETTE: [Rgba; 6] = [
    Rgba::rgb(0.90, 0.35, 0.25),
    Rgba::rgb(0.30, 0.60, 0.90),
    Rgba::rgb(0.35, 0.80, 0.40),
    Rgba::rgb(0.95, 0.80, 0.30),
    Rgba::rgb(0.70, 0.45, 0.90),
    Rgba::rgb(0.30, 0.85, 0.85),
];

/// The background.
pub const BACKGROUND: Rgba = Rgba::rgb(0.12, 0.12, 0.14);

/// Light that reaches every surface.
pub const AMBIENT: f32 = 0.25;

/// How much darker back faces are drawn.
pub const BACK_FACE_DIMMING: f32 = 0.7;

/// The shaded picture of `frame` (same size; y up as in `canvas`).
#[must_use]
pub fn shade(frame: &Framebuffer, primitives: &[Primitive]) -> Canvas {
    let camera = *frame.camera();
    let mut canvas = Canvas::new(camera.width(), camera.height());
    canvas.clear(BACKGROUND);
    // Towards the light, in camera terms: from the viewer, up and left.
    let towards_light = (camera.ray(Pixel::new(0, 0)).direction * -1.0
        + 0.5
            * (camera.ray(Pixel::new(0, 1)).origin - camera.ray(Pixel::new(0, 0)).origin)
                .normalize_or(Vec3::Y)
        - 0.5
            * (camera.ray(Pixel::new(1, 0)).origin - camera.ray(Pixel::new(0, 0)).origin)
                .normalize_or(Vec3::X))
    .normalize();
    for p in camera.pixels() {
        let (Some(surface), Some(depth)) = (frame.surface(p), frame.depth(p)) else {
            continue;
        };
        let Some(primitive) = primitives.get(surface.primitive) else {
            continue;
        };
        let ray = camera.ray(p);
        let mut normal = primitive.normal_at(ray.at(depth));
        if normal.dot(ray.direction) > 0.0 {
            normal = -normal;
        }
        let mut light = AMBIENT + (1.0 - AMBIENT) * normal.dot(towards_light).max(0.0);
        if surface.face == Face::Back {
            light *= BACK_FACE_DIMMING;
        }
        let base = PALETTE[surface.primitive % PALETTE.len()];
        canvas.set(p, Rgba::rgb(base.r * light, base.g * light, base.b * light));
    }
    canvas
}

/// Pixels of background between panels of [`side_by_side`].
pub const PANEL_GAP: u32 = 4;

/// The pictures next to each other, left to right, bottoms aligned.
#[must_use]
pub fn side_by_side(panels: &[Canvas]) -> Canvas {
    let width = panels.iter().map(Canvas::width).sum::<u32>()
        + PANEL_GAP * (panels.len().saturating_sub(1) as u32);
    let height = panels.iter().map(Canvas::height).max().unwrap_or(0);
    let mut out = Canvas::new(width, height);
    out.clear(Rgba::BLACK);
    let mut x0 = 0;
    for panel in panels {
        for (p, colour) in panel.enumerate() {
            out.set(Pixel::new(p.x + x0, p.y), colour);
        }
        x0 += (panel.width() + PANEL_GAP) as i32;
    }
    out
}
