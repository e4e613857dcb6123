//! The tessellation scene's state in the window: the set-up and the drawing on screen.

use std::time::Duration;

use eframe::egui;

use super::draw::{TessDrawing, worker};
use crate::live::Live;
use crate::stages::Stages;
use crate::stages::tessellate::TessSetup;

/// The tessellation scene in the window.
pub(crate) struct TessellationScene {
    pub(crate) setup: TessSetup,
    pub(crate) live: Live<TessSetup, TessDrawing>,
}

impl TessellationScene {
    /// The scene drawing with `stages`.
    pub(crate) fn new(stages: Stages) -> Self {
        Self {
            setup: TessSetup::default(),
            live: Live::new(worker(stages)),
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
}
