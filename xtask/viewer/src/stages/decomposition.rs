//! The first link of the NURBS chain: a surface split into rational
//! Bézier patches by your topic 08.

use super::{Stages, Status, guarded};

/// A NURBS surface split into rational Bézier patches, laid out as topic
/// 09's `PatchGrid` lays them: patch `(row, col)` at `row · cols + col`,
/// `col` the span along `u` and `row` the span along `v`.
#[derive(Clone, Debug, PartialEq)]
pub struct Decomposed {
    /// Spans along `v`.
    pub rows: usize,
    /// Spans along `u`.
    pub cols: usize,
    /// The patches.
    pub patches: Vec<freeform::RationalPatch>,
}

impl Decomposed {
    /// The grid of `patches` in topic 08's order (by `u` span, then `v`
    /// span: patch `(a, b)` at `a · spans_v + b`) for a surface of
    /// `spans_u × spans_v` spans.
    ///
    /// # Errors
    /// Not `spans_u · spans_v` patches.
    pub fn from_u_major(
        (spans_u, spans_v): (usize, usize),
        patches: Vec<freeform::RationalPatch>,
    ) -> Result<Self, String> {
        if patches.len() != spans_u * spans_v {
            return Err(format!(
                "{} patches for {spans_u} × {spans_v} spans",
                patches.len()
            ));
        }
        let patches = (0..spans_v)
            .flat_map(|b| (0..spans_u).map(move |a| a * spans_v + b))
            .map(|k| patches[k].clone())
            .collect();
        Ok(Self {
            rows: spans_v,
            cols: spans_u,
            patches,
        })
    }
}

/// The patches of `data` split by `stages`' decomposition, and how that
/// fared: the first link of the chain.
#[must_use]
pub fn decompose(
    stages: &Stages,
    data: &freeform::NurbsSurfaceData,
) -> (Option<Decomposed>, Status) {
    let Some(run) = &stages.decompose.run else {
        return (None, Status::Missing);
    };
    let mut status = Status::Unused;
    match guarded(&mut status, || run(data)) {
        Some(Ok(patches)) => (Some(patches), status),
        Some(Err(error)) => (None, Status::Failed(error)),
        None => (None, status),
    }
}
