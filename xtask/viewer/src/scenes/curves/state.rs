//! The curve scene's state in the window: the set-up, the drawing on
//! screen, the point being dragged and what shows.

use std::time::Duration;

use eframe::egui;

use super::draw::{CurveDrawing, CurveSetup, worker};
use crate::live::Live;
use crate::stages::Stages;
use crate::widgets::unit_to_screen;

/// The curve scene in the window.
pub(crate) struct CurvesScene {
    pub(crate) setup: CurveSetup,
    pub(crate) live: Live<CurveSetup, CurveDrawing>,
    /// The control point being dragged.
    pub(crate) dragging: Option<usize>,
    /// Where the unit square was last drawn on screen.
    pub(crate) area: Option<egui::Rect>,
    /// Whether the construction at `t` shows.
    pub(crate) construction: bool,
    /// Whether the definition's curve shows.
    pub(crate) definition: bool,
}

impl CurvesScene {
    /// The scene drawing with `stages`.
    pub(crate) fn new(stages: Stages) -> Self {
        Self {
            setup: CurveSetup::default(),
            live: Live::new(worker(stages)),
            dragging: None,
            area: None,
            construction: true,
            definition: true,
        }
    }

    /// Asks for the drawing if the set-up changed.
    pub(crate) fn ask(&mut self) {
        self.setup.tidy();
        self.live.ask_for(&self.setup);
    }

    /// Asks for the drawing and takes it when it arrives.
    pub(crate) fn update(&mut self, ui: &egui::Ui) {
        self.ask();
        self.live.poll(ui);
    }

    /// Asks for the drawing and waits for it, at most `limit`; whether it
    /// arrived.
    pub(crate) fn wait(&mut self, limit: Duration) -> bool {
        self.ask();
        self.live.wait(limit)
    }

    /// Where control point `k` shows on screen, once the scene has been
    /// drawn.
    pub(crate) fn point_on_screen(&self, k: usize) -> Option<egui::Pos2> {
        let area = self.area?;
        let p = *self.setup.points.get(k)?;
        Some(unit_to_screen(area, p))
    }
}
