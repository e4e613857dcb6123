//! What the tessellation scene draws: your triangles and how your stages
//! fared.

use crate::stages::tessellate::{Look, Method, Surface, TessSetup, Tessellated};
use crate::stages::{Stages, Status, guarded};
use crate::worker::Worker;

/// What the scene shows.
#[derive(Clone, Debug, PartialEq)]
pub struct TessDrawing {
    /// What was drawn.
    pub setup: TessSetup,
    /// The mesh and its picture, when your code made one.
    pub result: Option<Tessellated>,
    /// How your tessellation fared.
    pub status: Status,
    /// How your topic 08 split the surface into patches, for a NURBS
    /// surface ([`Status::Unused`] for the others).
    pub decomposition: Status,
}

/// The chain picture of the grade report's "Your pipeline" section (`cargo
/// xtask grade` draws it with your stages, beside `xtask/viewer/expected/`):
/// the vase split by your topic 08 and tessellated by your topic 09.
pub const REPORT_CHAIN: (&str, Surface) = ("nurbs-chain-vase.png", Surface::Vase);

/// The set-up of a chain picture: `surface` uniform at four cells a
/// side per patch, shaded with its edges, `size` pixels square.
#[must_use]
pub fn chain_setup(surface: Surface, size: u32) -> TessSetup {
    TessSetup {
        surface,
        method: Method::Uniform,
        level: 4,
        look: Look::Both,
        size,
        ..TessSetup::default()
    }
}

/// The worker that tessellates.
pub type TessWorker = Worker<TessSetup, TessDrawing>;

/// A worker tessellating with `stages`.
#[must_use]
pub fn worker(stages: Stages) -> TessWorker {
    Worker::start(move |setup: TessSetup| draw(&setup, &stages))
}

/// Tessellates and draws `setup` with your code.
#[must_use]
pub fn draw(setup: &TessSetup, stages: &Stages) -> TessDrawing {
    let mut setup = *setup;
    setup.tidy();
    let (decomposed, decomposition) = match setup.surface.nurbs() {
        Some(data) => crate::stages::decompose(stages, &data),
        None => (None, Status::Unused),
    };
    let Some(run) = &stages.tessellate.run else {
        return TessDrawing {
            setup,
            result: None,
            status: Status::Missing,
            decomposition,
        };
    };
    let mut status = Status::Unused;
    if setup.surface.nurbs().is_some() && decomposed.is_none() {
        return TessDrawing {
            setup,
            result: None,
            status: Status::NotReached,
            decomposition,
        };
    }
    let result = match guarded(&mut status, || run(&setup, decomposed.as_ref())) {
        Some(Ok(result)) => Some(result),
        Some(Err(error)) => {
            status = Status::Failed(error);
            None
        }
        None => None,
    };
    TessDrawing {
        setup,
        result,
        status,
        decomposition,
    }
}
