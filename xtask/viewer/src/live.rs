//! A scene's live drawing in the window: asked of a [`Worker`] when its
//! set-up changes, taken when it arrives, and shown as textures made the
//! first time it shows. Every scene keeps one; the window never waits for
//! a drawing (except where a test asks it to, [`Live::wait`]).

use std::time::{Duration, Instant};

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
        let deadline = Instant::now() + limit;
        // The drawing that arrives may be of an older request, after which
        // the newest goes to the worker: that one is waited for too.
        while self.worker.busy_for().is_some() {
            let left = deadline.saturating_duration_since(Instant::now());
            match self.worker.wait(left) {
                Some(drawing) => self.arrived(drawing),
                None => return false,
            }
        }
        true
    }
}

impl<J: Clone + PartialEq + Send + 'static, R: Send + 'static> Live<J, R> {
    /// Asks for the drawing of `setup` unless it is what was last asked
    /// for; whether it asked.
    pub(crate) fn ask_for(&mut self, setup: &J) -> bool {
        self.ask(setup, || setup.clone())
    }
}

/// A set-up a scene's panel edits: kept drawable before its drawing is
/// asked for.
pub(crate) trait Setup: Clone + PartialEq + Send + 'static {
    /// Every number in range and finite.
    fn tidy(&mut self);
}

/// A scene drawn from one set-up: the set-up its panel edits and the
/// drawing of it on screen.
pub(crate) struct SetupScene<S, R> {
    pub(crate) setup: S,
    pub(crate) live: Live<S, R>,
}

impl<S: Setup + Default, R: Send + 'static> SetupScene<S, R> {
    /// The default set-up, drawn by `worker`.
    pub(crate) fn with_worker(worker: Worker<S, R>) -> Self {
        Self {
            setup: S::default(),
            live: Live::new(worker),
        }
    }
}

impl<S: Setup, R: Send + 'static> LiveScene for SetupScene<S, R> {
    type Job = S;
    type Drawing = R;
    type Key = S;

    fn ask(&mut self) {
        self.setup.tidy();
        self.live.ask_for(&self.setup);
    }

    fn live(&mut self) -> &mut Live<S, R> {
        &mut self.live
    }
}

/// A scene drawn live: it says what to ask for; asking, taking the drawing
/// when it arrives and waiting for it (in tests) are the same for all.
pub(crate) trait LiveScene {
    /// What the worker draws from.
    type Job: Send + 'static;
    /// What it draws.
    type Drawing: Send + 'static;
    /// What names a request (see [`Live`]).
    type Key: Clone + PartialEq;

    /// Asks for the drawing of what is set now, unless it was asked for
    /// last.
    fn ask(&mut self);

    /// The scene's live drawing.
    fn live(&mut self) -> &mut Live<Self::Job, Self::Drawing, Self::Key>;

    /// Asks for the drawing and takes it when it arrives; whether it
    /// arrived.
    fn update(&mut self, ui: &egui::Ui) -> bool {
        self.ask();
        self.live().poll(ui)
    }

    /// Asks for the drawing and waits for it, at most `limit`; whether it
    /// arrived.
    fn wait(&mut self, limit: Duration) -> bool {
        self.ask();
        self.live().wait(limit)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn waiting_takes_the_drawing_of_the_newest_request() {
        let worker = Worker::start(|job: u32| {
            std::thread::sleep(Duration::from_millis(50));
            job
        });
        let mut live: Live<u32, u32> = Live::new(worker);
        live.ask_for(&1);
        // Asked while the first is drawn: it follows that one.
        live.ask_for(&2);
        assert!(live.wait(Duration::from_secs(30)));
        assert_eq!(live.drawing, Some(2));
        // Nothing asked: nothing to wait for.
        assert!(live.wait(Duration::ZERO));
    }
}
