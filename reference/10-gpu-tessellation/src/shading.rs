//! Task 4: shading and the wireframe (seed 000 §4.2.3, Listing 13 lines
//! 52-75: Phong with two lights and a texture; the wireframe of a
//! tessellation as in the seed's figures). The shading is WGSL, in
//! `src/shading.wgsl`; the wireframe's edges are Rust, here.

/// The edges of a triangle mesh for a wireframe drawn as a line list: every
/// edge once, as `[a, b]` with `a < b`, sorted, whichever triangles share
/// it.
///
/// A triangle with a repeated index contributes only its real edges (none
/// of the form `[a, a]`). Empty input gives no edges.
#[must_use]
#[transcript::task]
pub fn wireframe_edges(triangles: &[[u32; 3]]) -> Vec<[u32; 2]> {
    // BEGIN SOLUTION render: collect each triangle edge once as [min, max], sorted
    let mut edges: Vec<[u32; 2]> = triangles
        .iter()
        .flat_map(|&[a, b, c]| [[a, b], [b, c], [c, a]])
        .filter(|[a, b]| a != b)
        .map(|[a, b]| [a.min(b), a.max(b)])
        .collect();
    edges.sort_unstable();
    edges.dedup();
    edges
    // END SOLUTION
}
