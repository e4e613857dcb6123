//! Domains: the parameter points of a tessellation and the triangles
//! between them, for the two domain shapes of OpenGL's tessellator (seed
//! 001 §3.2; OpenGL 4.6 §11.2.2).
//!
//! ```text
//!  quads: (u, v) in [0,1]²            triangles: [u, v, w], u + v + w = 1,
//!   v                                 drawn by embed():
//!   1 +----------------+                        (0,1,0)
//!     |                |                          /\
//!     |                |                         /  \
//!     |                |                        /    \
//!   0 +----------------+ u              (0,0,1) ------ (1,0,0)
//!     0                1
//! ```
//!
//! Triangles are index triples into `points`, counter-clockwise: in
//! `(u, v)` for quads, in the [`embed`]ding for triangles (`layout(ccw)`).

use glam::DVec2;

/// The quad domain: points `(u, v)` in `[0, 1]²` and triangles.
#[transcript::evidence]
#[derive(Clone, Debug, Default, PartialEq)]
pub struct QuadDomain {
    /// Domain points `(u, v)`, each once.
    pub points: Vec<DVec2>,
    /// Counter-clockwise triangles in `(u, v)`.
    pub triangles: Vec<[u32; 3]>,
}

/// The triangle domain: barycentric points `[u, v, w]` and triangles.
#[transcript::evidence]
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TriangleDomain {
    /// Domain points `[u, v, w]`, `u + v + w = 1`, each once.
    pub points: Vec<[f64; 3]>,
    /// Counter-clockwise triangles in the embedding of [`embed`].
    pub triangles: Vec<[u32; 3]>,
}

/// The plane position of a barycentric point in the equilateral triangle
/// with `(1,0,0)` at `(1, 0)`, `(0,1,0)` at `(½, √3/2)` and `(0,0,1)` at the
/// origin (area `√3/4`).
#[must_use]
pub fn embed([u, v, _]: [f64; 3]) -> DVec2 {
    DVec2::new(u + 0.5 * v, 0.5 * 3.0_f64.sqrt() * v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn corners_embed_as_drawn() {
        assert_eq!(embed([1.0, 0.0, 0.0]), DVec2::new(1.0, 0.0));
        assert_eq!(embed([0.0, 0.0, 1.0]), DVec2::ZERO);
        let top = embed([0.0, 1.0, 0.0]);
        assert!((top - DVec2::new(0.5, 0.75_f64.sqrt())).length() < 1e-15);
    }
}
