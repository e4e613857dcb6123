//! What the GPU scene draws: the NURBS split first where the surface is
//! one, then your passes.

use crate::stages::gpu::{GpuDrawing, GpuSetup, GpuStageReport, STAGES};
use crate::stages::{Stages, Status};
use crate::worker::Worker;

/// The worker that draws on the GPU.
pub type GpuWorker = Worker<GpuSetup, GpuDrawing>;

/// A worker drawing with `stages`.
#[must_use]
pub fn worker(stages: Stages) -> GpuWorker {
    Worker::start(move |setup: GpuSetup| draw(&setup, &stages))
}

/// Draws `setup` with your topic 10 code.
#[must_use]
pub fn draw(setup: &GpuSetup, stages: &Stages) -> GpuDrawing {
    let mut setup = *setup;
    setup.tidy();
    let stopped = |status: Status, device: &str| GpuDrawing {
        setup,
        canvas: None,
        stages: STAGES
            .iter()
            .map(|&(name, source)| GpuStageReport {
                name,
                source,
                status: status.clone(),
            })
            .collect(),
        triangles: 0,
        device: device.to_owned(),
    };
    let Some(run) = &stages.gpu.run else {
        return stopped(Status::Missing, "topic 10 is not in this build");
    };
    // A NURBS surface is split into patches by your topic 08 first; that
    // stage is listed before the GPU's.
    let Some(data) = setup.surface.nurbs() else {
        return run(&setup, None);
    };
    let (decomposed, status) = crate::stages::decompose(stages, &data);
    let mut drawing = match &decomposed {
        Some(patches) => run(&setup, Some(patches)),
        None => stopped(
            Status::NotReached,
            "nothing to draw: the surface was not split into patches",
        ),
    };
    drawing.stages.insert(
        0,
        GpuStageReport {
            name: stages.decompose.name,
            source: stages.decompose.source,
            status,
        },
    );
    drawing
}
