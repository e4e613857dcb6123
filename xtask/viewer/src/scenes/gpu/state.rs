//! The GPU scene's state in the window: the set-up and the drawing on screen
//! ([`SetupScene`]).

use super::draw::worker;
use crate::live::{Setup, SetupScene};
use crate::stages::Stages;
use crate::stages::gpu::{GpuDrawing, GpuSetup};

/// The GPU scene in the window.
pub(crate) type GpuScene = SetupScene<GpuSetup, GpuDrawing>;

impl GpuScene {
    /// The scene drawing with `stages`.
    pub(crate) fn new(stages: Stages) -> Self {
        Self::with_worker(worker(stages))
    }
}

impl Setup for GpuSetup {
    fn tidy(&mut self) {
        GpuSetup::tidy(self);
    }
}
