//! The curve scene's panel and drawing area.

use eframe::egui;
use egui::Color32;

use super::draw::{self as curves, CurveKind, CurveSetup};
use super::state::CurvesScene;
use crate::widgets::{
    DEFINITION, EMPTY, HANDLE, LEVELS, ONLY_YOURS, nearest, notice_room, slow_notice, stage_label,
    unit_to_screen,
};

impl CurvesScene {
    /// The panel: Bézier or NURBS, the points, `t` or the degree and
    /// weights, your stage.
    pub(crate) fn controls(&mut self, ui: &mut egui::Ui) {
        ui.heading("Your curve");
        ui.horizontal(|ui| {
            ui.radio_value(&mut self.setup.kind, CurveKind::Bezier, "Bézier (07)");
            ui.radio_value(&mut self.setup.kind, CurveKind::Nurbs, "NURBS (08)");
        });
        ui.label(match self.setup.kind {
            CurveKind::Bezier => {
                "Your de Casteljau draws the curve and the construction of one point; drag the control points. Beside it, the curve of the definition (the Bernstein sum)."
            }
            CurveKind::Nurbs => {
                "Your NurbsCurve::point draws the curve over the clamped uniform knot vector, with its points at the knots; drag the control points, set the degree and the weights. Beside it, the curve of the definition (the Cox–de Boor sum)."
            }
        });
        ui.separator();
        let mut count = self.setup.points.len();
        ui.add(
            egui::Slider::new(&mut count, curves::MIN_POINTS..=curves::MAX_POINTS)
                .text("control points"),
        );
        if count != self.setup.points.len() {
            self.setup.set_count(count);
        }
        match self.setup.kind {
            CurveKind::Bezier => {
                ui.add(egui::Slider::new(&mut self.setup.t, 0.0..=1.0).text("t"));
                ui.checkbox(&mut self.construction, "Construction at t");
            }
            CurveKind::Nurbs => {
                let highest = self.setup.points.len() - 1;
                ui.add(egui::Slider::new(&mut self.setup.degree, 1..=highest).text("degree"));
                self.setup.weights.resize(self.setup.points.len(), 1.0);
                for (k, w) in self.setup.weights.iter_mut().enumerate() {
                    ui.add(
                        egui::Slider::new(w, curves::WEIGHTS)
                            .logarithmic(true)
                            .text(format!("w{k}")),
                    );
                }
            }
        }
        ui.checkbox(&mut self.definition, "The definition's curve");
        if ui.button("Reset").clicked() {
            let kind = self.setup.kind;
            self.setup = CurveSetup {
                kind,
                ..CurveSetup::default()
            };
        }
        ui.separator();
        ui.heading("Your stage");
        let stages = crate::stages::Stages::default();
        let Some(drawing) = &self.live.drawing else {
            ui.label("drawing …");
            return;
        };
        let (name, source) = match drawing.setup.kind {
            CurveKind::Bezier => (stages.curve.name, stages.curve.source),
            CurveKind::Nurbs => (stages.nurbs.name, stages.nurbs.source),
        };
        stage_label(ui, name, source, &drawing.status);
        if let Some(deviation) = drawing.deviation {
            ui.label(format!(
                "largest distance from the definition: {deviation:.1e}"
            ));
        }
        if drawing.setup.kind == CurveKind::Bezier
            && let Some(point) = drawing.levels.last().filter(|l| l.len() == 1).map(|l| l[0])
        {
            ui.label(format!(
                "C({:.2}) = ({:.4}, {:.4})",
                drawing.setup.t, point.x, point.y
            ));
        }
        if drawing.setup.kind == CurveKind::Nurbs {
            let knots: Vec<String> = drawing
                .setup
                .knots()
                .iter()
                .map(|k| format!("{k:.2}"))
                .collect();
            ui.label(format!("knots: {}", knots.join(" ")));
        }
    }

    /// The unit square: the control polygon, your curve, the definition's
    /// and the construction; the points to drag.
    pub(crate) fn picture(&mut self, ui: &mut egui::Ui) {
        let slow = self.live.worker.slow_for();
        let available = ui.available_size() - egui::vec2(0.0, notice_room(ui));
        let side = available.x.min(available.y).max(100.0);
        let (response, painter) = ui.allocate_painter(egui::vec2(side, side), egui::Sense::drag());
        let area = response.rect.shrink(side * 0.04);
        self.area = Some(area);
        let to_unit = |s: egui::Pos2| {
            glam::DVec2::new(
                f64::from((s.x - area.left()) / area.width()),
                f64::from((area.bottom() - s.y) / area.height()),
            )
        };
        if response.drag_started()
            && let Some(at) = response.interact_pointer_pos()
        {
            let at = to_unit(at);
            self.dragging = nearest(self.setup.points.iter().map(|p| p.distance(at)), 0.05);
        }
        if let (Some(k), Some(at)) = (self.dragging, response.interact_pointer_pos())
            && response.dragged()
            && let Some(p) = self.setup.points.get_mut(k)
        {
            *p = to_unit(at).clamp(glam::DVec2::ZERO, glam::DVec2::ONE);
        }
        if response.drag_stopped() {
            self.dragging = None;
        }
        painter.rect_filled(response.rect, 0.0, EMPTY);
        let screen = |p: glam::DVec2| unit_to_screen(area, p);
        let polyline = |points: &[glam::DVec2], stroke: egui::Stroke| {
            if points.len() >= 2 {
                painter.add(egui::Shape::line(
                    points.iter().map(|&p| screen(p)).collect(),
                    stroke,
                ));
            }
        };
        // The control polygon, as it is now (also while a drag waits for
        // its drawing).
        polyline(&self.setup.points, egui::Stroke::new(1.5, Color32::GRAY));
        if let Some(drawing) = &self.live.drawing {
            if self.definition {
                polyline(&drawing.expected, egui::Stroke::new(5.0, DEFINITION));
            }
            polyline(&drawing.yours, egui::Stroke::new(2.0, Color32::WHITE));
            for &p in &drawing.knot_points {
                painter.circle_filled(screen(p), 4.5, LEVELS[1]);
            }
            if self.construction && drawing.setup.kind == CurveKind::Bezier {
                for (k, level) in drawing.levels.iter().enumerate().skip(1) {
                    let colour = LEVELS[(k - 1) % LEVELS.len()];
                    polyline(level, egui::Stroke::new(1.5, colour));
                    for &p in level {
                        painter.circle_filled(screen(p), 3.5, colour);
                    }
                }
                if let Some(&[point]) = drawing.levels.last().map(Vec::as_slice)
                    && drawing.levels.len() == drawing.setup.points.len()
                {
                    painter.circle_filled(screen(point), 6.0, ONLY_YOURS);
                }
            }
        }
        for (k, &p) in self.setup.points.iter().enumerate() {
            let centre = screen(p);
            painter.circle_filled(centre, 9.0, HANDLE);
            painter.text(
                centre,
                egui::Align2::CENTER_CENTER,
                k.to_string(),
                egui::FontId::proportional(11.0),
                Color32::BLACK,
            );
        }
        slow_notice(ui, "Your de Casteljau has been drawing", slow);
    }
}
