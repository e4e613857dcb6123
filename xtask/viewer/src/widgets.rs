//! What the scenes share: magnified pictures, orbiting, stage labels,
//! notices, the trim controls and the colours.

use canvas::Canvas;
use eframe::egui;
use egui::{Color32, RichText, TextureHandle, TextureOptions};

use crate::stages::Status;
use crate::stages::trim::{TrimSetup, TrimShape};

/// The room kept below a picture or the pixel grid for [`slow_notice`]:
/// the picture is laid out the same whether the notice shows or not, so
/// that it never moves under the pointer (a handle being dragged stays
/// where it was grabbed).
pub(crate) fn notice_room(ui: &egui::Ui) -> f32 {
    3.0 * ui.text_style_height(&egui::TextStyle::Body)
}

/// Below the picture: that the student's code has been drawing for long,
/// perhaps in an endless loop, and that the window still answers.
pub(crate) fn slow_notice(ui: &mut egui::Ui, what: &str, busy: Option<std::time::Duration>) {
    if let Some(busy) = busy {
        ui.label(
            RichText::new(format!(
                "{what} for {:.1} s: an endless loop? \
                 The window stays usable; fix the loop and restart the viewer.",
                busy.as_secs_f64()
            ))
            .color(Color32::YELLOW),
        );
    }
}

/// A picture at the largest whole-pixel magnification that fits (every
/// pixel a sharp square), `reserve` points kept free below it, sensing
/// drags (to orbit the camera).
pub(crate) fn magnified(
    ui: &mut egui::Ui,
    texture: &TextureHandle,
    reserve: f32,
) -> egui::Response {
    let [w, h] = texture.size().map(|s| s.max(1) as f32);
    let available = ui.available_size() - egui::vec2(0.0, notice_room(ui) + reserve);
    let scale = (available.x / w).min(available.y / h);
    let scale = if scale >= 1.0 { scale.floor() } else { scale };
    ui.add(
        egui::Image::from_texture(egui::load::SizedTexture::new(
            texture.id(),
            egui::vec2(w * scale, h * scale),
        ))
        .sense(egui::Sense::drag()),
    )
}

/// How a drag over a picture and the scroll wheel move an orbiting
/// camera: degrees around and above (half a degree a point, the picture
/// following the pointer), and the factor for its distance.
pub(crate) fn orbit(ui: &egui::Ui, response: &egui::Response) -> (f32, f32, f32) {
    let delta = if response.dragged() {
        response.drag_delta()
    } else {
        egui::Vec2::ZERO
    };
    let scroll = if response.hovered() {
        ui.input(|i| i.smooth_scroll_delta.y)
    } else {
        0.0
    };
    (-delta.x * 0.5, delta.y * 0.5, 1.0 - scroll * 0.002)
}

/// A canvas as a texture, drawn without smoothing.
pub(crate) fn texture(ui: &egui::Ui, name: &str, canvas: &Canvas) -> TextureHandle {
    ui.ctx()
        .load_texture(name, colour_image(canvas), TextureOptions::NEAREST)
}

/// One stage in a panel: `name: status` in the status's colour, its
/// source below.
pub(crate) fn stage_label(ui: &mut egui::Ui, name: &str, source: &str, status: &Status) {
    ui.label(RichText::new(format!("{name}: {}", status.describe())).color(status_colour(status)));
    ui.label(RichText::new(source).small().weak());
}

/// The trim's shape and parameters (the surface and GPU scenes).
pub(crate) fn trim_controls(ui: &mut egui::Ui, trim: &mut TrimSetup) {
    egui::ComboBox::from_label("Trim")
        .selected_text(trim.shape.label())
        .show_ui(ui, |ui| {
            for shape in TrimShape::ALL {
                ui.selectable_value(&mut trim.shape, shape, shape.label());
            }
        });
    if trim.shape != TrimShape::None {
        ui.add(egui::Slider::new(&mut trim.centre.x, 0.0..=1.0).text("centre u"));
        ui.add(egui::Slider::new(&mut trim.centre.y, 0.0..=1.0).text("centre v"));
    }
    match trim.shape {
        TrimShape::None => {}
        TrimShape::Rectangle => {
            ui.add(egui::Slider::new(&mut trim.size.x, 0.01..=0.5).text("half width"));
            ui.add(egui::Slider::new(&mut trim.size.y, 0.01..=0.5).text("half height"));
        }
        TrimShape::Circle => {
            ui.add(egui::Slider::new(&mut trim.size.x, 0.01..=0.7).text("radius"));
        }
        TrimShape::Ellipse => {
            ui.add(egui::Slider::new(&mut trim.size.x, 0.01..=0.7).text("radius in u"));
            ui.add(egui::Slider::new(&mut trim.size.y, 0.01..=0.7).text("radius in v"));
        }
        TrimShape::NewtonQuadratic | TrimShape::NewtonCubic | TrimShape::Nested => {
            ui.add(egui::Slider::new(&mut trim.scale, 0.1..=2.0).text("scale"));
            ui.add(egui::Slider::new(&mut trim.iterations, 1..=30).text("Newton steps"));
            ui.add(
                egui::Slider::new(&mut trim.epsilon, 1e-4..=0.1)
                    .logarithmic(true)
                    .text("ε"),
            );
        }
    }
}

/// The handle a drag picks up: the nearest of those at `distances` from
/// the pointer, if it is nearer than `reach`.
pub(crate) fn nearest(distances: impl Iterator<Item = f64>, reach: f64) -> Option<usize> {
    distances
        .enumerate()
        .filter(|(_, d)| *d < reach)
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(k, _)| k)
}

/// A point of the unit square on screen, in `area` (y up).
pub(crate) fn unit_to_screen(area: egui::Rect, p: glam::DVec2) -> egui::Pos2 {
    egui::pos2(
        area.left() + p.x as f32 * area.width(),
        area.bottom() - p.y as f32 * area.height(),
    )
}

/// A stage's status in its colour.
pub(crate) fn status_colour(status: &Status) -> Color32 {
    match status {
        Status::Ok => Color32::LIGHT_GREEN,
        Status::Unused | Status::NotReached | Status::Given => Color32::GRAY,
        Status::NotYet(_) => Color32::YELLOW,
        Status::Missing | Status::Panicked(_) | Status::Failed(_) => Color32::LIGHT_RED,
    }
}

/// The definition's curve, under yours.
pub(crate) const DEFINITION: Color32 = Color32::from_rgb(70, 110, 70);
/// The levels of the construction, one colour each.
pub(crate) const LEVELS: [Color32; 4] = [
    Color32::from_rgb(90, 170, 255),
    Color32::from_rgb(255, 170, 60),
    Color32::from_rgb(190, 120, 255),
    Color32::from_rgb(80, 220, 200),
];

/// A pixel you plotted (where your code gives it no colour).
pub(crate) const INK: Color32 = Color32::from_rgb(200, 200, 210);
/// A pixel of the grid nothing covers.
pub(crate) const EMPTY: Color32 = Color32::from_rgb(38, 38, 44);
/// The mark of a pixel only you plotted.
pub(crate) const ONLY_YOURS: Color32 = Color32::from_rgb(255, 60, 60);
/// The mark of a pixel only the definition has.
pub(crate) const ONLY_EXPECTED: Color32 = Color32::from_rgb(90, 170, 255);
/// The ideal primitive.
pub(crate) const IDEAL: Color32 = Color32::from_rgb(255, 220, 90);
/// The handles.
pub(crate) const HANDLE: Color32 = Color32::from_rgb(255, 255, 255);

/// A canvas colour on screen.
pub(crate) fn colour32(c: canvas::Rgba) -> Color32 {
    let [r, g, b, _] = c.to_rgba8();
    Color32::from_rgb(r, g, b)
}

/// The canvas as an egui image (y up on the canvas, y down on screen).
pub(crate) fn colour_image(canvas: &Canvas) -> egui::ColorImage {
    let image = canvas.to_image();
    egui::ColorImage::from_rgba_unmultiplied(
        [image.width() as usize, image.height() as usize],
        image.as_raw(),
    )
}
