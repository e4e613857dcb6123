//! The surface scene's state in the window: the set-up and the drawing on screen
//! ([`SetupScene`]).

use super::draw::{SurfaceDrawing, SurfaceSetup, worker};
use crate::live::{Setup, SetupScene};
use crate::stages::Stages;

/// The surface scene in the window.
pub(crate) type SurfacesScene = SetupScene<SurfaceSetup, SurfaceDrawing>;

impl SurfacesScene {
    /// The scene drawing with `stages`.
    pub(crate) fn new(stages: Stages) -> Self {
        Self::with_worker(worker(stages))
    }
}

impl Setup for SurfaceSetup {
    fn tidy(&mut self) {
        SurfaceSetup::tidy(self);
    }
}
