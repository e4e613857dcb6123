//! Fully adaptive tessellation (seed 001 §2.2, Figure 2.4): start from a
//! coarse mesh, test every edge, insert the parameter midpoint of each edge
//! that fails, subdivide each triangle by the pattern of its split edges,
//! and repeat on the new triangles until every edge passes.
//!
//! ```text
//!   one split edge      two split edges        three split edges
//!        c                    c                      c
//!       ╱│╲                  ╱ ╲                    ╱ ╲
//!      ╱ │ ╲                ╱   m1                m2───m1
//!     ╱  │  ╲              ╱  ╱ │ ╲              ╱ ╲ ╱ ╲
//!    a───m0──b            a───m0─┴──b           a───m0───b
//!    2 triangles          3 triangles (the      4 triangles
//!                         shorter diagonal)
//! ```
//!
//! **The work list.** The seed pops triangles from the front of a list and
//! appends their children at the back (`pop(0)`, `append`), so the list is
//! worked through one generation after another. This module does exactly
//! that, a generation at a time, and decides each edge once, the first
//! time it is met, from the mesh as it stands at the start of that
//! generation. Both triangles that share an edge therefore agree about
//! it: no T-junctions, whatever the test. (The seed's listing on page 27
//! splits only the first edge of every triangle, and its call passes a
//! vertex where the threshold `value1` belongs; the patterns of Figure 2.6
//! for one, two and three split edges are what this module implements.)
//!
//! **Termination.** Every edge has a level: 0 in the initial mesh; the
//! halves of a split edge and the edges a pattern draws inside a triangle
//! get one more than the largest level of the edges they come from. An
//! edge at `max_depth` is never split, so refinement ends.

#[allow(unused_imports)]
use std::collections::HashMap;

#[allow(unused_imports)]
use crate::bezier::{Evaluate, SurfaceSample};
#[allow(unused_imports)]
use crate::edge_tests::{EdgeContext, EdgeTest};
use crate::error::TessError;
use crate::mesh::Mesh;

/// The largest `max_depth` accepted: each level can double the triangles.
pub const MAX_DEPTH: u32 = 12;

/// The most triangles a refinement may produce; beyond it the refinement
/// stops with an error instead of filling the memory.
pub const MAX_TRIANGLES: usize = 1 << 22;

/// Refines `initial` (a mesh of `patch`, with the patch parameters in its
/// `uvs`, e.g. a uniform tessellation) until every edge passes `test` or
/// has reached level `max_depth`. Every edge of a triangle is tested once
/// ([`EdgeTest::must_split`]) with the new vertex at the parameter
/// midpoint, evaluated on `patch`; a triangle with one, two or three split
/// edges is replaced by 2, 3 or 4 triangles (the patterns in the module
/// documentation; with two split edges `a→b` (midpoint `m0`) and `b→c`
/// (`m1`), counter-clockwise, the quadrilateral `a m0 m1 c` is cut along
/// its shorter diagonal in the parameter plane, `a–m1` or `m0–c`, and on a
/// tie along `a–m1`: from the corner the unsplit edge `c→a` runs into to
/// the midpoint of the far split edge).
///
/// The result keeps the initial vertices, in order, and appends the new
/// ones; triangles keep their orientation in the parameter plane. An edge
/// is split on both of its sides or on neither, so a watertight initial
/// mesh stays watertight. `patch` is any surface that can [`Evaluate`],
/// polynomial or rational.
///
/// # Errors
/// [`TessError::Mesh`] for an invalid initial mesh,
/// [`TessError::NonFinite`] for a non-finite parameter in it,
/// [`TessError::NotPositive`] for a bad threshold,
/// [`TessError::Resolution`] for `max_depth` above [`MAX_DEPTH`], or when
/// the refinement would exceed [`MAX_TRIANGLES`].
#[transcript::task]
pub fn refine(
    patch: &impl Evaluate,
    initial: &Mesh,
    test: EdgeTest,
    max_depth: u32,
) -> Result<Mesh, TessError> {
    // Unused until you write the body:
    let _ = (&patch, &initial, &test, &max_depth);
    todo!("fully_adaptive: the seed's work list, a generation at a time, edges decided once")
}
