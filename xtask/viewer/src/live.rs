//! A scene's live drawing in the window: asked of a [`Worker`] when its
//! set-up changes, taken when it arrives, and shown as textures made the
//! first time it shows. Every scene keeps one; the window never waits for
//! a drawing (except where a test asks it to, [`Live::wait`]).

use std::time::Duration;

use eframe::egui;
use egui::TextureHandle;

use crate::worker::Worker;

/// A drawing done by a worker: what was last asked for (`K`, the request
/// `J` itself unless the scene names its requests otherwise), the
/// drawing `R` on screen and its pictures on the GPU.
pub(crate) struct Live<J, R, K = J> {
    /// The worker that draws.
    pub(crate) worker: Worker<J, R>,
    /// What was last asked for.
    asked: Option<K>,
    /// The drawing on screen, if one arrived.
    pub(crate) drawing: Option<R>,
    /// The drawing's pictures as textures, made when first shown.
    pub(crate) textures: Vec<TextureHandle>,
}

impl<J: Send + 'static, R: Send + 'static, K: Clone + PartialEq> Live<J, R, K> {
    /// Nothing asked for yet, nothing drawn.
    pub(crate) fn new(worker: Worker<J, R>) -> Self {
        Self {
            worker,
            asked: None,
            drawing: None,
            textures: Vec::new(),
        }
    }

    /// Asks for the drawing `job` makes unless `key` is what was last
    /// asked for; whether it asked.
    pub(crate) fn ask(&mut self, key: &K, job: impl FnOnce() -> J) -> bool {
        if self.asked.as_ref() == Some(key) {
            return false;
        }
        self.worker.request(job());
        self.asked = Some(key.clone());
        true
    }

    fn arrived(&mut self, drawing: R) {
        self.drawing = Some(drawing);
        self.textures.clear();
    }

    /// Takes the newest drawing, if one arrived (whether one did); asks the
    /// window to look again soon while one is being drawn.
    pub(crate) fn poll(&mut self, ui: &egui::Ui) -> bool {
        let arrived = match self.worker.poll() {
            Some(drawing) => {
                self.arrived(drawing);
                true
            }
            None => false,
        };
        if self.worker.busy_for().is_some() {
            ui.ctx().request_repaint_after(Duration::from_millis(100));
        }
        arrived
    }

    /// Waits for the drawing asked for, at most `limit` (for tests);
    /// whether it arrived.
    pub(crate) fn wait(&mut self, limit: Duration) -> bool {
        match self.worker.wait(limit) {
            Some(drawing) => {
                self.arrived(drawing);
                true
            }
            None => self.worker.busy_for().is_none(),
        }
    }
}

impl<J: Clone + PartialEq + Send + 'static, R: Send + 'static> Live<J, R> {
    /// Asks for the drawing of `setup` unless it is what was last asked
    /// for; whether it asked.
    pub(crate) fn ask_for(&mut self, setup: &J) -> bool {
        self.ask(setup, || setup.clone())
    }
}
