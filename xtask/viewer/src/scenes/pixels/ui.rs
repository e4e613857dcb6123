//! The pixel playground's panel and magnified grid.

use eframe::egui;
use egui::{Color32, RichText};

use super::draw::{Cell, Primitive, Setup};
use super::state::PixelsScene;
use crate::widgets::{
    EMPTY, HANDLE, IDEAL, INK, ONLY_EXPECTED, ONLY_YOURS, colour32, nearest, notice_room,
    slow_notice, stage_label,
};

impl PixelsScene {
    /// The panel: the primitive, the grid's size, your stage and the
    /// stepping through your pixels.
    pub(crate) fn controls(&mut self, ui: &mut egui::Ui) {
        ui.heading("Your pixels");
        ui.label("Your code draws one primitive; drag its handles. Beside it, the pixels of the course's definition, which the tests compare with.");
        ui.separator();
        egui::ComboBox::from_label("Primitive")
            .selected_text(self.setup.primitive.label())
            .show_ui(ui, |ui| {
                for primitive in Primitive::ALL {
                    ui.selectable_value(&mut self.setup.primitive, primitive, primitive.label());
                }
            });
        ui.add(egui::Slider::new(&mut self.setup.size, Setup::SIZES).text("pixels across"));
        ui.separator();
        ui.label("# in both, + only yours, - only expected (the tests' legend)");
        let Some(drawing) = &self.live.drawing else {
            ui.label("drawing …");
            return;
        };
        let (name, source) = drawing.stage;
        stage_label(ui, name, source, &drawing.status);
        ui.label(drawing.summary());
        ui.separator();
        let count = drawing.yours.len();
        ui.label(format!(
            "Step through your {count} pixels, in the order you plotted them"
        ));
        let mut shown = self.steps.unwrap_or(count);
        ui.horizontal(|ui| {
            if ui.button("Back").clicked() {
                shown = shown.saturating_sub(1);
            }
            if ui.button("Next").clicked() {
                shown = (shown + 1).min(count);
            }
            if ui.button("All").clicked() {
                shown = count;
            }
        });
        ui.add(egui::Slider::new(&mut shown, 0..=count).text("pixels shown"));
        self.steps = (shown < count).then_some(shown);
        if let Some(step) = shown.checked_sub(1).and_then(|k| drawing.yours.get(k)) {
            ui.label(RichText::new(format!("pixel {shown} of {count}")).strong());
            ui.label(&step.note);
        }
    }

    /// The magnified grid: your pixels, the definition's, the ideal
    /// primitive and its handles.
    pub(crate) fn picture(&mut self, ui: &mut egui::Ui) {
        let slow = self.live.worker.slow_for();
        let n = self.setup.size;
        let available = ui.available_size() - egui::vec2(0.0, notice_room(ui));
        let cell = (available.x.min(available.y) / n as f32).floor().max(4.0);
        let (response, painter) = ui.allocate_painter(
            egui::vec2(cell * n as f32, cell * n as f32),
            egui::Sense::drag(),
        );
        let origin = response.rect.left_top();
        self.grid = Some((origin, cell));
        let top = n as f32 - 0.5;
        let to_screen = |p: glam::Vec2| {
            egui::pos2(origin.x + (p.x + 0.5) * cell, origin.y + (top - p.y) * cell)
        };
        let to_grid = |s: egui::Pos2| {
            glam::Vec2::new((s.x - origin.x) / cell - 0.5, top - (s.y - origin.y) / cell)
        };
        let setup = &self.setup;
        let handles = setup.primitive.handles();
        if response.drag_started()
            && let Some(at) = response.interact_pointer_pos()
        {
            let at = to_grid(at);
            self.dragging = nearest(
                (0..handles).map(|k| f64::from(setup.handles[k].distance(at))),
                1.0,
            );
        }
        if let (Some(k), Some(at)) = (self.dragging, response.interact_pointer_pos())
            && response.dragged()
        {
            self.setup.move_handle(k, to_grid(at));
        }
        if response.drag_stopped() {
            self.dragging = None;
        }
        let setup = &self.setup;
        let painter = &painter;
        let font = egui::FontId::monospace(cell * 0.6);
        if let Some(drawing) = &self.live.drawing {
            let shown = self.steps.unwrap_or(drawing.yours.len());
            let colours: std::collections::HashMap<canvas::Pixel, Color32> = drawing
                .yours
                .iter()
                .take(shown)
                .filter_map(|s| Some((s.pixel, s.colour.map(colour32)?)))
                .collect();
            // The legend's mark on a cell: a frame and its symbol.
            let mark = |rect: egui::Rect, width: f32, colour: Color32, symbol: &str| {
                painter.rect_stroke(
                    rect.shrink(1.5),
                    0.0,
                    egui::Stroke::new(width, colour),
                    egui::StrokeKind::Inside,
                );
                painter.text(
                    rect.center(),
                    egui::Align2::CENTER_CENTER,
                    symbol,
                    font.clone(),
                    colour,
                );
            };
            for (p, how) in drawing.cells(shown) {
                let rect =
                    egui::Rect::from_center_size(to_screen(p.centre()), egui::vec2(cell, cell));
                let ink = colours.get(&p).copied().unwrap_or(INK);
                match how {
                    Cell::Both => {
                        painter.rect_filled(rect.shrink(1.0), 0.0, ink);
                    }
                    Cell::OnlyYours => {
                        painter.rect_filled(rect.shrink(1.0), 0.0, ink);
                        mark(rect, 3.0, ONLY_YOURS, "+");
                    }
                    Cell::OnlyExpected => mark(rect, 2.0, ONLY_EXPECTED, "-"),
                    Cell::Empty => {
                        painter.rect_filled(rect.shrink(1.0), 0.0, EMPTY);
                    }
                }
            }
            if let Some(step) = shown.checked_sub(1).and_then(|k| drawing.yours.get(k))
                && shown < drawing.yours.len()
            {
                let rect = egui::Rect::from_center_size(
                    to_screen(step.pixel.centre()),
                    egui::vec2(cell, cell),
                );
                painter.rect_stroke(
                    rect,
                    0.0,
                    egui::Stroke::new(3.0, Color32::YELLOW),
                    egui::StrokeKind::Outside,
                );
            }
        }
        // The ideal primitive over the pixels.
        let ideal = egui::Stroke::new(2.0, IDEAL);
        let h = setup.handles;
        match setup.primitive {
            Primitive::DdaLine | Primitive::MidpointLine | Primitive::WuLine => {
                painter.line_segment([to_screen(h[0]), to_screen(h[1])], ideal);
            }
            Primitive::Circle => {
                painter.circle_stroke(to_screen(h[0]), setup.radius() as f32 * cell, ideal);
            }
            Primitive::Triangle => {
                let points: Vec<egui::Pos2> = h.iter().map(|&p| to_screen(p)).collect();
                painter.add(egui::Shape::closed_line(points, ideal));
            }
        }
        for (k, handle) in h.iter().take(handles).enumerate() {
            let centre = to_screen(*handle);
            painter.circle_filled(centre, (cell * 0.3).max(4.0), HANDLE);
            painter.text(
                centre,
                egui::Align2::CENTER_CENTER,
                k.to_string(),
                egui::FontId::proportional((cell * 0.35).max(8.0)),
                Color32::BLACK,
            );
        }
        slow_notice(ui, "Your code has been drawing", slow);
    }
}
