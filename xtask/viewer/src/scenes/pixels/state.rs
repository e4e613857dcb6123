//! The pixel playground's state in the window: the set-up, the drawing on
//! screen, the stepping and the handle being dragged.

use eframe::egui;

use super::draw::{Drawing, Primitive, Setup, worker};
use crate::live::{Live, LiveScene};
use crate::stages::Stages;

/// The pixel playground in the window.
pub(crate) struct PixelsScene {
    pub(crate) setup: Setup,
    pub(crate) live: Live<Setup, Drawing>,
    /// How many of your pixels show (stepping through them); `None`: all.
    pub(crate) steps: Option<usize>,
    /// The handle being dragged.
    pub(crate) dragging: Option<usize>,
    /// Each primitive's handles, kept while another one is shown.
    handles: [[glam::Vec2; 3]; 5],
    /// The primitive whose handles `setup` holds.
    primitive: Primitive,
    /// Where the grid was last drawn: its top-left corner and the size of
    /// a cell on screen.
    pub(crate) grid: Option<(egui::Pos2, f32)>,
}

impl PixelsScene {
    /// The playground drawing with `stages`.
    pub(crate) fn new(stages: Stages) -> Self {
        Self {
            setup: Setup::default(),
            live: Live::new(worker(stages)),
            steps: None,
            dragging: None,
            handles: Primitive::ALL.map(Primitive::first_handles),
            primitive: Primitive::DdaLine,
            grid: None,
        }
    }

    /// Where handle `k` shows on screen, once the grid has been drawn.
    pub(crate) fn handle_on_screen(&self, k: usize) -> Option<egui::Pos2> {
        let (origin, cell) = self.grid?;
        let p = *self.setup.handles.get(k)?;
        let top = self.setup.size as f32 - 0.5;
        Some(egui::pos2(
            origin.x + (p.x + 0.5) * cell,
            origin.y + (top - p.y) * cell,
        ))
    }
}

impl LiveScene for PixelsScene {
    type Job = Setup;
    type Drawing = Drawing;
    type Key = Setup;

    /// Asks for the drawing if the set-up changed.
    fn ask(&mut self) {
        let index = |p: Primitive| Primitive::ALL.iter().position(|q| *q == p).unwrap_or(0);
        if self.setup.primitive != self.primitive {
            // Each primitive keeps its own handles.
            self.handles[index(self.primitive)] = self.setup.handles;
            self.setup.handles = self.handles[index(self.setup.primitive)];
            self.primitive = self.setup.primitive;
        }
        self.setup.tidy();
        if self.live.ask_for(&self.setup) {
            // A new drawing shows all its pixels.
            self.steps = None;
        }
    }

    fn live(&mut self) -> &mut Live<Setup, Drawing> {
        &mut self.live
    }

    /// Asks for the drawing and takes it when it arrives; a drawing with
    /// fewer pixels shows no more steps than it has.
    fn update(&mut self, ui: &egui::Ui) -> bool {
        self.ask();
        let arrived = self.live.poll(ui);
        if arrived && let Some(drawing) = &self.live.drawing {
            let count = drawing.yours.len();
            self.steps = self.steps.map(|s| s.min(count));
        }
        arrived
    }
}
