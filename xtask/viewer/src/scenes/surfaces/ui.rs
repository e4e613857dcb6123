//! The surface scene's panel and picture.

use eframe::egui;

use super::draw::{self as surfaces, SurfaceSetup};
use super::state::SurfacesScene;
use crate::stages::Stages;
use crate::widgets::{magnified, orbit, slow_notice, stage_label, texture, trim_controls};

impl SurfacesScene {
    /// The panel: the control points' heights, the trim, the level, the
    /// camera and your stages.
    pub(crate) fn controls(&mut self, ui: &mut egui::Ui) {
        ui.heading("Your trimmed surface");
        ui.label(
            "The seed's hill, a bicubic Bézier patch whose control points you raise and lower: evaluated by your surface code, trimmed by your trim and tessellated, rasterized and lit by your render_surface.",
        );
        ui.separator();
        let setup = &mut self.setup;
        ui.label("Control points: their heights (u to the right, v up)");
        egui::Grid::new("control net").show(ui, |ui| {
            for j in (0..4).rev() {
                for i in 0..4 {
                    ui.add(
                        egui::DragValue::new(&mut setup.heights[i][j])
                            .speed(0.01)
                            .range(surfaces::HEIGHTS)
                            .prefix(format!("P{i}{j} ")),
                    );
                }
                ui.end_row();
            }
        });
        ui.separator();
        trim_controls(ui, &mut setup.trim);
        ui.separator();
        ui.add(
            egui::Slider::new(&mut setup.level, 1..=surfaces::MAX_LEVEL).text("tessellation level"),
        );
        ui.checkbox(&mut setup.wireframe, "Wireframe");
        ui.label("Camera (or drag the picture; scroll to zoom)");
        ui.add(egui::Slider::new(&mut setup.yaw, -180.0..=180.0).text("around"));
        ui.add(egui::Slider::new(&mut setup.pitch, -89.0..=89.0).text("above"));
        ui.add(egui::Slider::new(&mut setup.distance, 0.8..=8.0).text("distance"));
        if ui.button("Reset").clicked() {
            *setup = SurfaceSetup::default();
        }
        ui.separator();
        ui.heading("Your stages");
        let Some(drawing) = &self.live.drawing else {
            ui.label("drawing …");
            return;
        };
        let stages = Stages::default();
        let trim_source = drawing.setup.trim.shape.source();
        for (name, source, status) in [
            (stages.surface.name, stages.surface.source, &drawing.surface),
            (stages.trim.name, trim_source, &drawing.trim),
            (
                stages.surface_render.name,
                stages.surface_render.source,
                &drawing.render,
            ),
        ] {
            stage_label(ui, name, source, status);
        }
    }

    /// The picture, and the parameter square as your trim sees it.
    pub(crate) fn picture(&mut self, ui: &mut egui::Ui) {
        let slow = self.live.worker.slow_for();
        let Some(drawing) = &self.live.drawing else {
            ui.label("drawing …");
            slow_notice(ui, "Your surface code has been drawing", slow);
            return;
        };
        if self.live.textures.is_empty() {
            self.live.textures = vec![
                texture(ui, "surface", &drawing.canvas),
                texture(ui, "parameter square", &drawing.uv_map),
            ];
        }
        let response = magnified(ui, &self.live.textures[0], 140.0);
        let (around, above, zoom) = orbit(ui, &response);
        let setup = &mut self.setup;
        setup.yaw = (setup.yaw + f64::from(around)).clamp(-180.0, 180.0);
        setup.pitch = (setup.pitch + f64::from(above)).clamp(-89.0, 89.0);
        setup.distance = (setup.distance * f64::from(zoom)).clamp(0.8, 8.0);
        ui.horizontal(|ui| {
            ui.add(egui::Image::from_texture(egui::load::SizedTexture::new(
                self.live.textures[1].id(),
                egui::vec2(128.0, 128.0),
            )));
            ui.label(
                "The parameter square as your trim sees it: dark is cut away.\nu to the right, v up.",
            );
        });
        slow_notice(ui, "Your surface code has been drawing", slow);
    }
}
