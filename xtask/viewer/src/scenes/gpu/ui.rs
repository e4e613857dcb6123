//! The GPU scene's panel and picture.

use eframe::egui;
use egui::RichText;

use super::state::GpuScene;
use crate::stages::gpu::{self as gpu_scene, GpuSetup};
use crate::widgets::{magnified, orbit, slow_notice, stage_label, texture, trim_controls};

impl GpuScene {
    /// The panel: the surface, the levels and spacing, the trim, the
    /// camera and your stages; `show_timing` says whether the device shows.
    pub(crate) fn controls(&mut self, ui: &mut egui::Ui, show_timing: bool) {
        ui.heading("Your GPU passes");
        ui.label(
            "Patches tessellated and drawn on the GPU by your topic 10 code: control pass, primitive generator, evaluation pass, shading, trimming and wireframe.",
        );
        ui.separator();
        let setup = &mut self.setup;
        egui::ComboBox::from_label("Surface")
            .selected_text(setup.surface.label())
            .show_ui(ui, |ui| {
                for surface in gpu_scene::GpuSurface::ALL {
                    ui.selectable_value(&mut setup.surface, surface, surface.label());
                }
            });
        ui.horizontal(|ui| {
            ui.radio_value(
                &mut setup.levels,
                gpu_scene::Levels::Uniform,
                "Uniform levels",
            );
            ui.radio_value(&mut setup.levels, gpu_scene::Levels::Adaptive, "Adaptive");
        });
        match setup.levels {
            gpu_scene::Levels::Uniform => {
                ui.add(egui::Slider::new(&mut setup.level, 1.0..=64.0).text("level"));
            }
            gpu_scene::Levels::Adaptive => {
                ui.add(
                    egui::Slider::new(&mut setup.pixels_per_segment, 2.0..=100.0)
                        .text("pixels per segment"),
                );
            }
        }
        ui.horizontal(|ui| {
            ui.radio_value(&mut setup.spacing, gpu_scene::Spacing::Equal, "equal");
            ui.radio_value(
                &mut setup.spacing,
                gpu_scene::Spacing::FractionalEven,
                "fractional even",
            );
            ui.radio_value(
                &mut setup.spacing,
                gpu_scene::Spacing::FractionalOdd,
                "fractional odd",
            );
        });
        ui.separator();
        trim_controls(ui, &mut setup.trim);
        ui.separator();
        ui.checkbox(&mut setup.wireframe, "Wireframe");
        ui.label("Camera (or drag the picture; scroll to zoom)");
        ui.add(egui::Slider::new(&mut setup.yaw, -180.0..=180.0).text("around"));
        ui.add(egui::Slider::new(&mut setup.pitch, -89.0..=89.0).text("above"));
        ui.add(egui::Slider::new(&mut setup.distance, 0.8..=10.0).text("distance"));
        if ui.button("Reset").clicked() {
            *setup = GpuSetup::default();
        }
        ui.separator();
        ui.heading("Your stages");
        let Some(drawing) = &self.live.drawing else {
            ui.label("drawing on the GPU …");
            return;
        };
        for stage in &drawing.stages {
            stage_label(ui, stage.name, stage.source, &stage.status);
        }
        if drawing.canvas.is_some() {
            ui.label(format!("{} triangles", drawing.triangles));
        }
        if show_timing {
            ui.label(RichText::new(format!("device: {}", drawing.device)).small());
        }
    }

    /// The picture your passes drew.
    pub(crate) fn picture(&mut self, ui: &mut egui::Ui) {
        let slow = self.live.worker.slow_for();
        let Some(canvas) = self.live.drawing.as_ref().and_then(|d| d.canvas.as_ref()) else {
            ui.label(match &self.live.drawing {
                None => "drawing on the GPU …",
                Some(_) => "nothing drawn: a stage it needs did not run (see the panel)",
            });
            slow_notice(ui, "Your GPU passes have been running", slow);
            return;
        };
        if self.live.textures.is_empty() {
            self.live.textures = vec![texture(ui, "gpu", canvas)];
        }
        let response = magnified(ui, &self.live.textures[0], 0.0);
        let (around, above, zoom) = orbit(ui, &response);
        let setup = &mut self.setup;
        setup.yaw = (setup.yaw + around).clamp(-180.0, 180.0);
        setup.pitch = (setup.pitch + above).clamp(-89.0, 89.0);
        setup.distance = (setup.distance * zoom).clamp(0.8, 10.0);
        slow_notice(ui, "Your GPU passes have been running", slow);
    }
}
