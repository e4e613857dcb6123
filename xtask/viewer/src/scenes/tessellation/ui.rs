//! The tessellation scene's panel and picture.

use eframe::egui;

use super::state::TessellationScene;
use crate::stages::tessellate::{self as tess, TessSetup};
use crate::stages::{Stages, Status};
use crate::widgets::{magnified, orbit, slow_notice, stage_label, texture};

impl TessellationScene {
    /// The panel: the surface, the method and its parameters, the look,
    /// the view and your stage.
    pub(crate) fn controls(&mut self, ui: &mut egui::Ui) {
        ui.heading("Your tessellation");
        ui.label(
            "A surface of Bézier or rational patches cut into triangles by your topic 09 code, drawn by the topic's given renderer.",
        );
        ui.separator();
        let setup = &mut self.setup;
        egui::ComboBox::from_label("Surface")
            .selected_text(setup.surface.label())
            .show_ui(ui, |ui| {
                for surface in tess::Surface::ALL {
                    ui.selectable_value(&mut setup.surface, surface, surface.label());
                }
            });
        ui.horizontal(|ui| {
            for method in tess::Method::ALL {
                ui.radio_value(&mut setup.method, method, method.label());
            }
        });
        match setup.method {
            tess::Method::Uniform => {
                ui.add(
                    egui::Slider::new(&mut setup.level, 1..=tess::MAX_LEVEL).text("cells per side"),
                );
            }
            tess::Method::PerPatch => {
                ui.add(
                    egui::Slider::new(&mut setup.tolerance, 1e-4..=0.1)
                        .logarithmic(true)
                        .text("chord tolerance"),
                );
            }
            tess::Method::FullyAdaptive => {
                ui.add(
                    egui::Slider::new(&mut setup.level, 1..=tess::MAX_LEVEL)
                        .text("start: cells per side"),
                );
                let before = setup.test;
                egui::ComboBox::from_label("Edge test")
                    .selected_text(setup.test.label())
                    .show_ui(ui, |ui| {
                        for test in tess::Test::ALL {
                            ui.selectable_value(&mut setup.test, test, test.label());
                        }
                    });
                if setup.test != before {
                    setup.thresholds = setup.test.default_thresholds();
                }
                ui.add(
                    egui::Slider::new(&mut setup.thresholds[0], 1e-3..=1.0)
                        .logarithmic(true)
                        .text("threshold"),
                );
                if setup.test == tess::Test::OneEdgeComplementary {
                    ui.add(
                        egui::Slider::new(&mut setup.thresholds[1], 1e-3..=1.0)
                            .logarithmic(true)
                            .text("t2"),
                    );
                }
                ui.add(
                    egui::Slider::new(&mut setup.depth, 0..=tess::MAX_DEPTH).text("most halvings"),
                );
            }
        }
        ui.separator();
        ui.horizontal(|ui| {
            ui.radio_value(&mut setup.look, tess::Look::Shaded, "Shaded");
            ui.radio_value(&mut setup.look, tess::Look::Wireframe, "Wireframe");
            ui.radio_value(&mut setup.look, tess::Look::Both, "Both");
        });
        ui.label("View (or drag the picture)");
        ui.add(egui::Slider::new(&mut setup.yaw, -180.0..=180.0).text("around"));
        ui.add(egui::Slider::new(&mut setup.pitch, -89.0..=89.0).text("above"));
        if ui.button("Reset").clicked() {
            *setup = TessSetup::default();
        }
        ui.separator();
        ui.heading("Your stage");
        let Some(drawing) = &self.live.drawing else {
            ui.label("drawing …");
            return;
        };
        let named = Stages::default();
        if drawing.decomposition != Status::Unused {
            let stage = &named.decompose;
            stage_label(ui, stage.name, stage.source, &drawing.decomposition);
        }
        stage_label(
            ui,
            named.tessellate.name,
            drawing.setup.method.source(),
            &drawing.status,
        );
        if let Some(result) = &drawing.result {
            ui.label(format!(
                "{} vertices, {} triangles",
                result.vertices, result.triangles
            ));
        }
    }

    /// The triangles, drawn by topic 09's renderer.
    pub(crate) fn picture(&mut self, ui: &mut egui::Ui) {
        let slow = self.live.worker.slow_for();
        let Some(result) = self.live.drawing.as_ref().and_then(|d| d.result.as_ref()) else {
            ui.label(match &self.live.drawing {
                None => "tessellating …",
                Some(_) => "no triangles: your stage did not make a mesh (see the panel)",
            });
            slow_notice(ui, "Your tessellation has been running", slow);
            return;
        };
        if self.live.textures.is_empty() {
            self.live.textures = vec![texture(ui, "tessellation", &result.canvas)];
        }
        let response = magnified(ui, &self.live.textures[0], 0.0);
        // Turn and tilt; the renderer fits the mesh, so no zoom.
        let (around, above, _) = orbit(ui, &response);
        let setup = &mut self.setup;
        setup.yaw = (setup.yaw + f64::from(around)).clamp(-180.0, 180.0);
        setup.pitch = (setup.pitch + f64::from(above)).clamp(-89.0, 89.0);
        slow_notice(ui, "Your tessellation has been running", slow);
    }
}
