//! The curve scene's state in the window: the set-up, the drawing on
//! screen, the point being dragged and what shows.

use eframe::egui;

use super::draw::{CurveDrawing, CurveSetup, worker};
use crate::live::{Live, LiveScene};
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

    /// Where control point `k` shows on screen, once the scene has been
    /// drawn.
    pub(crate) fn point_on_screen(&self, k: usize) -> Option<egui::Pos2> {
        let area = self.area?;
        let p = *self.setup.points.get(k)?;
        Some(unit_to_screen(area, p))
    }
}

impl LiveScene for CurvesScene {
    type Job = CurveSetup;
    type Drawing = CurveDrawing;
    type Key = CurveSetup;

    fn ask(&mut self) {
        self.setup.tidy();
        self.live.ask_for(&self.setup);
    }

    fn live(&mut self) -> &mut Live<CurveSetup, CurveDrawing> {
        &mut self.live
    }
}
