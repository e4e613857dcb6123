//! The pipeline scene's panel and picture: the mesh, the switches, your
//! stages, and your clipped polygons outlined.

use canvas::Canvas;
use eframe::egui;
use egui::{Color32, RichText};
use scene::Mode;

use super::draw::Settings;
use super::state::MeshScene;
use crate::stages::Status;
use crate::widgets::{magnified, orbit, slow_notice, stage_label, texture};

impl MeshScene {
    /// The panel: the mesh, the switches, the camera, saving, your stages.
    /// `not_compiling` names the topics left out of the build;
    /// `show_timing` says whether the frame's time shows.
    pub(crate) fn controls(
        &mut self,
        ui: &mut egui::Ui,
        not_compiling: &[String],
        show_timing: bool,
    ) {
        ui.heading("Your pipeline");
        ui.label(
            "The mesh, transformed by the course; clipped, drawn and depth-tested by your code.",
        );
        ui.separator();
        let current = self.meshes[self.selected].name.clone();
        egui::ComboBox::from_label("Mesh")
            .selected_text(current)
            .show_ui(ui, |ui| {
                for (index, entry) in self.meshes.iter().enumerate() {
                    ui.selectable_value(&mut self.selected, index, &entry.name);
                }
            });
        ui.horizontal(|ui| {
            let label = ui.label("PLY file");
            ui.add(egui::TextEdit::singleline(&mut self.open_path).hint_text("path/to/mesh.ply"))
                .labelled_by(label.id);
            if ui.button("Open").clicked() {
                let path = self.open_path.clone();
                self.open(&path);
            }
        });
        ui.separator();
        ui.horizontal(|ui| {
            ui.radio_value(&mut self.settings.mode, Mode::Line, "Wireframe");
            ui.radio_value(&mut self.settings.mode, Mode::Fill, "Filled");
        });
        ui.checkbox(&mut self.settings.clip, "Clipping");
        ui.checkbox(
            &mut self.outline_clipped,
            "Outline your clipped polygons (drawn by the window, not by your lines)",
        )
        .on_hover_text(
            "Topic 04 on its own: the polygons your Sutherland–Hodgman returns, \
             outlined in yellow with the window's vector shapes. Shown by itself \
             when your lines or fill draw nothing yet.",
        );
        ui.checkbox(&mut self.settings.depth_test, "Depth test");
        ui.separator();
        ui.label("Camera (or drag the picture; scroll to zoom)");
        ui.add(egui::Slider::new(&mut self.settings.yaw, -180.0..=180.0).text("around"));
        ui.add(egui::Slider::new(&mut self.settings.pitch, -89.0..=89.0).text("above"));
        ui.add(egui::Slider::new(&mut self.settings.distance, 1.0..=12.0).text("distance"));
        egui::ComboBox::from_label("Pixels")
            .selected_text(format!("{0} × {0}", self.settings.width))
            .show_ui(ui, |ui| {
                for size in [100, 200, 400, 800] {
                    if ui
                        .selectable_label(self.settings.width == size, format!("{size} × {size}"))
                        .clicked()
                    {
                        self.settings.width = size;
                        self.settings.height = size;
                    }
                }
            });
        if ui.button("Reset camera").clicked() {
            let defaults = Settings::default();
            self.settings.yaw = defaults.yaw;
            self.settings.pitch = defaults.pitch;
            self.settings.distance = defaults.distance;
        }
        ui.separator();
        ui.horizontal(|ui| {
            let label = ui.label("Save as");
            ui.add(egui::TextEdit::singleline(&mut self.save_path))
                .labelled_by(label.id);
            if ui.button("Save PNG").clicked() {
                let path = self.save_path.clone();
                self.save(&path);
            }
        });
        if let Some(message) = &self.message {
            ui.label(message);
        }
        ui.separator();
        self.stage_list(ui, not_compiling, show_timing);
    }

    fn stage_list(&self, ui: &mut egui::Ui, not_compiling: &[String], show_timing: bool) {
        ui.heading("Your stages");
        if !not_compiling.is_empty() {
            ui.label(
                RichText::new(format!(
                    "Not compiling, so left out: {}",
                    not_compiling.join(", ")
                ))
                .color(Color32::LIGHT_RED),
            );
        }
        let Some(frame) = &self.live.drawing else {
            ui.label("drawing the first frame …");
            return;
        };
        for stage in &frame.stages {
            stage_label(ui, stage.name, stage.source, &stage.status);
        }
        let (total, drawn) = frame.polygons;
        let timing = self
            .live
            .worker
            .last_frame_time()
            .filter(|_| show_timing)
            .map_or_else(String::new, |t| {
                format!(" in {:.0} ms", t.as_secs_f64() * 1e3)
            });
        ui.label(format!("{drawn} of {total} polygons drawn{timing}"));
    }

    /// The picture, your clipped polygons outlined where asked for.
    pub(crate) fn picture(&mut self, ui: &mut egui::Ui) {
        let slow = self.live.worker.slow_for();
        let Some(frame) = &self.live.drawing else {
            ui.label("drawing …");
            slow_notice(ui, "Your stages have been drawing this frame", slow);
            return;
        };
        if self.live.textures.is_empty() {
            self.live.textures = vec![texture(ui, "picture", &frame.canvas)];
        }
        let texture = self.live.textures[0].clone();
        let response = magnified(ui, &texture, 0.0);
        // Topic 04 without topics 01 and 03: your clipped polygons as
        // outlines, when asked for or when nothing else draws them.
        let drew = frame.stages[1..=2].iter().any(|s| s.status == Status::Ok);
        if !frame.clipped.is_empty() && (self.outline_clipped || !drew) {
            outline_polygons(ui, response.rect, &frame.canvas, &frame.clipped);
            ui.label(
                RichText::new(
                    "Yellow: your clipped polygons, outlined by the window (not by your lines)",
                )
                .color(OUTLINE),
            );
        }
        let (around, above, zoom) = orbit(ui, &response);
        let settings = &mut self.settings;
        settings.yaw = (settings.yaw + around).clamp(-180.0, 180.0);
        settings.pitch = (settings.pitch + above).clamp(-89.0, 89.0);
        settings.distance = (settings.distance * zoom).clamp(1.0, 12.0);
        slow_notice(ui, "Your stages have been drawing this frame", slow);
    }
}

/// The colour of the clipped polygons' outlines.
const OUTLINE: Color32 = Color32::from_rgb(255, 215, 0);

/// Draws `polygons` (pixel coordinates of `canvas`, `y` up) as closed
/// outlines over the picture shown in `rect`, with egui's vector shapes.
fn outline_polygons(ui: &egui::Ui, rect: egui::Rect, canvas: &Canvas, polygons: &[Vec<[f32; 2]>]) {
    let (w, h) = (canvas.width() as f32, canvas.height() as f32);
    let scale = egui::vec2(rect.width() / w, rect.height() / h);
    let to_screen = |[x, y]: [f32; 2]| {
        egui::pos2(
            rect.left() + (x + 0.5) * scale.x,
            rect.top() + (h - y - 0.5) * scale.y,
        )
    };
    let painter = ui.painter_at(rect);
    for polygon in polygons {
        let points: Vec<egui::Pos2> = polygon.iter().map(|&p| to_screen(p)).collect();
        painter.add(egui::Shape::closed_line(
            points,
            egui::Stroke::new(1.0, OUTLINE),
        ));
    }
}
