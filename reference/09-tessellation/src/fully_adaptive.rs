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

use std::collections::HashMap;

use crate::bezier::{Evaluate, SurfaceSample};
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
    // BEGIN SOLUTION fully_adaptive: the seed's work list, a generation at a time, edges decided once
    initial.validate()?;
    test.validate()?;
    if max_depth > MAX_DEPTH {
        return Err(TessError::Resolution(max_depth as usize));
    }
    if !initial.uvs.iter().all(|uv| uv.is_finite()) {
        return Err(TessError::NonFinite {
            what: "a parameter of the initial mesh",
        });
    }
    let mut mesh = initial.clone();
    let mut levels: HashMap<(u32, u32), u32> = HashMap::new();
    for tri in &initial.triangles {
        for (a, b) in edges(*tri) {
            levels.insert(key(a, b), 0);
        }
    }
    // Per edge: `None` = keep, `Some(m)` = split at vertex `m`.
    let mut decided: HashMap<(u32, u32), Option<u32>> = HashMap::new();
    let mut done: Vec<[u32; 3]> = Vec::new();
    let mut pending: Vec<[u32; 3]> = initial.triangles.clone();
    while !pending.is_empty() {
        let adjacency = Adjacency::new(&mesh, done.iter().chain(&pending));
        let mut new_vertices: Vec<((u32, u32), SurfaceSample)> = Vec::new();
        let mut this_round: HashMap<(u32, u32), bool> = HashMap::new();
        for tri in &pending {
            for (a, b) in edges(*tri) {
                let k = key(a, b);
                if decided.contains_key(&k) || this_round.contains_key(&k) {
                    continue;
                }
                let level = levels.get(&k).copied().unwrap_or(0);
                let mid = patch.sample((mesh.uvs[a as usize] + mesh.uvs[b as usize]) / 2.0);
                let split = level < max_depth
                    && adjacency.context(&mesh, a, b, mid, |edge| test.must_split(edge));
                this_round.insert(k, split);
                if split {
                    new_vertices.push((k, mid));
                }
            }
        }
        for (k, split) in this_round {
            if !split {
                decided.insert(k, None);
            }
        }
        for (k, mid) in new_vertices {
            decided.insert(k, Some(mesh.push_vertex(mid)));
        }
        let mut next = Vec::new();
        for tri in pending {
            let splits = edges(tri).map(|(a, b)| decided[&key(a, b)]);
            let count = splits.iter().flatten().count();
            if count == 0 {
                done.push(tri);
                continue;
            }
            let level = edges(tri)
                .map(|(a, b)| levels[&key(a, b)])
                .into_iter()
                .max()
                .unwrap_or(0)
                + 1;
            let children = subdivide(&mesh, tri, splits);
            for child in &children {
                for (a, b) in edges(*child) {
                    levels.entry(key(a, b)).or_insert(level);
                }
            }
            next.extend(children);
            if done.len() + next.len() > MAX_TRIANGLES {
                return Err(TessError::Resolution(MAX_TRIANGLES));
            }
        }
        pending = next;
    }
    mesh.triangles = done;
    Ok(mesh)
    // END SOLUTION
}

// BEGIN SOLUTION
/// The edges `(a, b), (b, c), (c, a)` of a triangle.
fn edges([a, b, c]: [u32; 3]) -> [(u32, u32); 3] {
    [(a, b), (b, c), (c, a)]
}

/// The key of an undirected edge.
fn key(a: u32, b: u32) -> (u32, u32) {
    (a.min(b), a.max(b))
}

/// The children of `tri` for its split edges (`splits[k]` = the midpoint of
/// edge `k`, if split), by the patterns of Figure 2.6.
fn subdivide(mesh: &Mesh, tri: [u32; 3], splits: [Option<u32>; 3]) -> Vec<[u32; 3]> {
    let count = splits.iter().flatten().count();
    // Rotate so that the pattern is canonical: with one split edge it is
    // edge 0 (a, b); with two, the unsplit edge is edge 2 (c, a).
    let rotation = (0..3)
        .find(|&r| match count {
            1 => splits[r].is_some(),
            2 => splits[(r + 2) % 3].is_none(),
            _ => true,
        })
        .unwrap_or(0);
    let [a, b, c] = [
        tri[rotation],
        tri[(rotation + 1) % 3],
        tri[(rotation + 2) % 3],
    ];
    let m = [
        splits[rotation],
        splits[(rotation + 1) % 3],
        splits[(rotation + 2) % 3],
    ];
    match (count, m) {
        (1, [Some(m0), _, _]) => vec![[a, m0, c], [m0, b, c]],
        (2, [Some(m0), Some(m1), None]) => {
            let uv = |i: u32| mesh.uvs[i as usize];
            let diagonal = |p: u32, q: u32| uv(p).distance(uv(q));
            if diagonal(a, m1) <= diagonal(m0, c) {
                vec![[m0, b, m1], [a, m0, m1], [a, m1, c]]
            } else {
                vec![[m0, b, m1], [a, m0, c], [m0, m1, c]]
            }
        }
        (3, [Some(m0), Some(m1), Some(m2)]) => {
            vec![[a, m0, m2], [m0, b, m1], [m2, m1, c], [m0, m1, m2]]
        }
        _ => vec![tri],
    }
}

/// The connectivity of the mesh at the start of a generation.
struct Adjacency {
    /// Per undirected edge, the vertices opposite it.
    opposite: HashMap<(u32, u32), Vec<u32>>,
    /// Per vertex, the vertices joined to it by an edge (sorted, unique).
    neighbours: Vec<Vec<u32>>,
}

impl Adjacency {
    fn new<'a>(mesh: &Mesh, triangles: impl Iterator<Item = &'a [u32; 3]>) -> Self {
        let mut opposite: HashMap<(u32, u32), Vec<u32>> = HashMap::new();
        let mut neighbours = vec![Vec::new(); mesh.vertex_count()];
        for &[a, b, c] in triangles {
            for (p, q, r) in [(a, b, c), (b, c, a), (c, a, b)] {
                opposite.entry(key(p, q)).or_default().push(r);
                neighbours[p as usize].push(q);
                neighbours[q as usize].push(p);
            }
        }
        for list in &mut neighbours {
            list.sort_unstable();
            list.dedup();
        }
        Self {
            opposite,
            neighbours,
        }
    }

    /// Builds the context of edge `(a, b)` and hands it to `decide`.
    fn context(
        &self,
        mesh: &Mesh,
        a: u32,
        b: u32,
        mid: SurfaceSample,
        decide: impl Fn(&EdgeContext) -> bool,
    ) -> bool {
        let points = |ids: &[u32]| ids.iter().map(|&i| mesh.vertex(i)).collect::<Vec<_>>();
        let empty = Vec::new();
        let opposite = points(self.opposite.get(&key(a, b)).unwrap_or(&empty));
        let (n1, n2) = (&self.neighbours[a as usize], &self.neighbours[b as usize]);
        let mut ring: Vec<u32> = [a, b].iter().chain(n1).chain(n2).copied().collect();
        ring.sort_unstable();
        ring.dedup();
        decide(&EdgeContext {
            v1: mesh.vertex(a),
            v2: mesh.vertex(b),
            mid,
            opposite: &opposite,
            ring: &points(&ring),
            neighbours1: &points(n1),
            neighbours2: &points(n2),
        })
    }
}

// END SOLUTION
