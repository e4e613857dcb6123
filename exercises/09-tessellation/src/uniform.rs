//! Uniform tessellation of a Bézier patch (seed 001 §2.1, steps 1 and 2):
//! the parameter square is cut into `n_u × n_v` cells of size
//! `1/n_u × 1/n_v`, and every cell becomes two triangles.
//!
//! ```text
//!   v ▲ 8───9──10──11       vertex (i, j) has index j·(n_u + 1) + i and
//!     │ │ ╱ │ ╱ │ ╱ │       parameters (i/n_u, j/n_v); cell (i, j) is cut
//!     │ 4───5───6───7       along its diagonal from (i, j) to (i+1, j+1):
//!     │ │ ╱ │ ╱ │ ╱ │         [(i, j), (i+1, j), (i+1, j+1)]
//!     │ 0───1───2───3         [(i, j), (i+1, j+1), (i, j+1)]
//!     └──────────────▶ u    (n_u = 3, n_v = 2)
//! ```

#[allow(unused_imports)]
use glam::DVec2;

#[allow(unused_imports)]
use crate::bezier::{Evaluate, MAX_RESOLUTION};
use crate::error::TessError;
use crate::mesh::Mesh;

/// Tessellates `patch` uniformly into `n_u × n_v` cells, two triangles per
/// cell: `(n_u + 1)(n_v + 1)` vertices and `2 n_u n_v` triangles, numbered
/// and cut as in the module's diagram (vertices row by row from `v = 0`,
/// `u` running fastest; triangles cell by cell in the same order, the lower
/// right triangle first). Every vertex lies on the surface, with the
/// surface's unit normal ([`Evaluate::sample`]); triangles are
/// counter-clockwise in the `(u, v)` plane. `patch` is any surface that
/// can [`Evaluate`]: a Bézier patch, or a rational one (a piece of a NURBS
/// surface).
///
/// # Errors
/// [`TessError::Resolution`] if `n_u` or `n_v` is 0 or above
/// [`MAX_RESOLUTION`].
#[transcript::task]
pub fn tessellate_uniform(
    patch: &impl Evaluate,
    n_u: usize,
    n_v: usize,
) -> Result<Mesh, TessError> {
    // Unused until you write the body:
    let _ = (&patch, &n_u, &n_v);
    todo!("uniform: sample the (n_u+1)×(n_v+1) grid, then two triangles per cell")
}
