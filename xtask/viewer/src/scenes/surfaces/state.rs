//! The surface scene's state in the window: the set-up and the drawing on screen.

use std::time::Duration;

use eframe::egui;

use super::draw::{SurfaceDrawing, SurfaceSetup, worker};
use crate::live::Live;
use crate::stages::Stages;

/// The surface scene in the window.
pub(crate) struct SurfacesScene {
    pub(crate) setup: SurfaceSetup,
    pub(crate) live: Live<SurfaceSetup, SurfaceDrawing>,
}

impl SurfacesScene {
    /// The scene drawing with `stages`.
    pub(crate) fn new(stages: Stages) -> Self {
        Self {
            setup: SurfaceSetup::default(),
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
