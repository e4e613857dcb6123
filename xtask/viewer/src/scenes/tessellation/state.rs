//! The tessellation scene's state in the window: the set-up and the drawing on screen
//! ([`SetupScene`]).

use super::draw::{TessDrawing, worker};
use crate::live::{Setup, SetupScene};
use crate::stages::Stages;
use crate::stages::tessellate::TessSetup;

/// The tessellation scene in the window.
pub(crate) type TessellationScene = SetupScene<TessSetup, TessDrawing>;

impl TessellationScene {
    /// The scene drawing with `stages`.
    pub(crate) fn new(stages: Stages) -> Self {
        Self::with_worker(worker(stages))
    }
}

impl Setup for TessSetup {
    fn tidy(&mut self) {
        TessSetup::tidy(self);
    }
}
