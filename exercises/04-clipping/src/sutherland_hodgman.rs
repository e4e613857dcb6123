//! Sutherland-Hodgman polygon clipping in homogeneous clip space: TU Wien
//! sheet "Rasterisierung" (seed 004), §5 "Clipping" (`clip.m`,
//! `clipPlane`), after I. E. Sutherland and G. W. Hodgman, "Reentrant
//! polygon clipping", CACM 17(1), 1974.
//!
//! A convex clip region is the intersection of half-spaces, so a polygon is
//! clipped against it one plane at a time: each pass walks the polygon's
//! edges `S → E` (the closing edge from the last vertex back to the first
//! included) and emits, per edge,
//!
//! ```text
//!   S inside,  E inside   →  E
//!   S inside,  E outside  →  I                  I = the edge's crossing
//!   S outside, E inside   →  I, E
//!   S outside, E outside  →  nothing
//!
//!        outside │ inside                 the output of one pass is the
//!            S ● │                        input of the next; the vertex
//!               ╲│                        count can grow by one per
//!                ◆ I                      plane, or drop to zero
//!                │╲
//!                │ ● E
//! ```
//!
//! New vertices interpolate position (and with it depth, `z / w`) and
//! colour linearly in clip space, *before* the division by `w`: there the
//! edge is still a straight line with a linear parameter.

use crate::error::ClipError;
#[allow(unused_imports)]
use crate::plane::{CLIP_NUDGE, ClipPlane, MAX_CLIP_COORD};
use scene::ClipVertex;

/// Clips a polygon against one plane: the part of it with `v · p ≤ 0`
/// (the sheet's `clipPlane`).
///
/// The polygon is closed: its edges join consecutive vertices and the last
/// vertex to the first. Walking the edges `S → E` (starting with the
/// closing edge, `S` = last vertex, `E` = first), each edge contributes as
/// in the table above: `E` when it is inside, the crossing `I` before it
/// when exactly one of `S`, `E` is inside. A vertex on the plane counts as
/// inside. `I` lies at `t = l_S / (l_S − l_E)` from `S` (signed distances
/// `l = v · p`), nudged by [`CLIP_NUDGE`](crate::plane::CLIP_NUDGE)
/// towards the inside endpoint and kept in `[0, 1]`; its colour and
/// position are `S.lerp(E, t)`. (This task is graded on its own, so write
/// the test and `t` here rather than calling task 1's `inside` and
/// `intersect`.)
///
/// A polygon entirely inside comes back unchanged, vertex for vertex and
/// starting with the same vertex; one entirely outside comes back empty.
/// Any vertex count works, even 0, 1 or 2; the result may be degenerate
/// (fewer than three vertices, repeated vertices) when the polygon only
/// touches the plane.
///
/// # Errors
///
/// [`ClipError::NonFinite`] or [`ClipError::OutOfRange`] for the first
/// vertex with a non-finite coordinate or one beyond ±[`MAX_CLIP_COORD`];
/// [`ClipError::InvalidPlane`] (index 0) for a non-finite plane.
#[transcript::task]
pub fn clip_against_plane(
    polygon: &[ClipVertex],
    plane: ClipPlane,
) -> Result<Vec<ClipVertex>, ClipError> {
    // Unused until you write the body:
    let _ = (&polygon, &plane);
    todo!(
        "sutherland_hodgman: check the input, then walk the edges S -> E from the closing edge on and emit E and/or the nudged crossing as the table says"
    )
}

/// Clips a polygon against every plane in `planes`, one pass per plane
/// (the sheet's `clip` over all six planes of the clip volume).
///
/// With the six planes of task 1 the result is the part of the polygon
/// inside `−w ≤ x, y, z ≤ w`; the tests pass their own list of planes, so
/// that this task is graded on its own. Stops early once nothing is left.
/// An empty list of planes returns the polygon unchanged.
///
/// # Errors
///
/// As [`clip_against_plane`]; [`ClipError::InvalidPlane`] names the first
/// non-finite plane.
#[transcript::task]
pub fn clip_polygon(
    polygon: &[ClipVertex],
    planes: &[ClipPlane],
) -> Result<Vec<ClipVertex>, ClipError> {
    // Unused until you write the body:
    let _ = (&polygon, &planes);
    todo!(
        "sutherland_hodgman: check the input, then clip against each plane in turn, the output of one pass being the input of the next"
    )
}
