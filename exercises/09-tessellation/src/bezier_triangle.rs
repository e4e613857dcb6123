//! Cubic Bézier triangles and their construction from a flat triangle's
//! vertices and normals: curved point-normal (PN) triangles (seed 001
//! §4.1, equation (4.1), Figure 4.2; Vlachos, Peters, Boyd, Mitchell,
//! "Curved PN Triangles", I3D 2001).
//!
//! ```text
//!                 b030                  B(u, v, w) = Σ_{i+j+k=3} 3!/(i! j! k!) uⁱ vʲ wᵏ b_ijk
//!               ╱      ╲                  = b300 u³ + b030 v³ + b003 w³
//!           b021        b120              + 3 b210 u²v + 3 b201 u²w + 3 b120 v²u
//!          ╱     b111      ╲              + 3 b021 v²w + 3 b102 w²u + 3 b012 w²v
//!      b012                b210           + 6 b111 uvw,      u + v + w = 1
//!      ╱                      ╲
//!  b003 ─── b102 ──── b201 ─── b300
//! ```
//!
//! (The seed's evaluation shader, listing 4.6, multiplies `b300` by `w³`
//! and `b030` by `u³`: it names the barycentric coordinates in another
//! order than (4.1). This module follows (4.1): `u` belongs to `b300`.)
//!
//! **PN construction.** The corners are the vertices `P1, P2, P3`. Each
//! edge gets two points at its thirds, each moved onto the tangent plane of
//! the nearer vertex (`w_ij = (P_j − P_i) · N_i`):
//!
//! ```text
//!   b210 = (2 P1 + P2 − w12 N1) / 3      b120 = (2 P2 + P1 − w21 N2) / 3
//!   b021 = (2 P2 + P3 − w23 N2) / 3      b012 = (2 P3 + P2 − w32 N3) / 3
//!   b102 = (2 P3 + P1 − w31 N3) / 3      b201 = (2 P1 + P3 − w13 N1) / 3
//!   E = (b210 + b120 + b021 + b012 + b102 + b201) / 6,   V = (P1 + P2 + P3) / 3
//!   b111 = E + (E − V) / 2
//! ```
//!
//! Normals are interpolated linearly and normalised, as the seed's
//! evaluation shader does (`interpolate3D`); the PN paper's quadratic
//! normal patch is a refinement left out here.

#[allow(unused_imports)]
use glam::{DVec2, DVec3};

#[allow(unused_imports)]
use crate::bezier::SurfaceSample;
use crate::error::TessError;
use crate::mesh::Mesh;
pub use freeform::{BezierTriangle, TriangleDomain};

/// A PN triangle: its cubic geometry and the unit normals at its corners.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PnTriangle {
    /// The geometry.
    pub geometry: BezierTriangle,
    /// Unit normals at `P1` (`u = 1`), `P2` (`v = 1`), `P3` (`w = 1`).
    pub normals: [DVec3; 3],
}

/// `B(u, v, w)` by equation (4.1). The coordinates are used as given (the
/// caller keeps `u + v + w = 1`; other values extrapolate the polynomial).
#[must_use]
#[transcript::task]
pub fn evaluate(t: &BezierTriangle, [u, v, w]: [f64; 3]) -> DVec3 {
    // Unused until you write the body:
    let _ = (&t, &u, &v, &w);
    todo!("bezier_triangle: the ten Bernstein terms of (4.1)")
}

/// The PN triangle of the flat triangle `P1, P2, P3` with vertex normals
/// `N1, N2, N3` (normalised here), by the construction in the module
/// documentation. It passes through the three vertices, and its tangent
/// plane at each vertex is perpendicular to that vertex's normal.
///
/// # Errors
/// [`TessError::NonFinite`] for a non-finite position or normal, and for a
/// normal that cannot be normalised (zero).
#[transcript::task]
pub fn pn_triangle(positions: [DVec3; 3], normals: [DVec3; 3]) -> Result<PnTriangle, TessError> {
    // Unused until you write the body:
    let _ = (&positions, &normals);
    todo!("bezier_triangle: corners, edge thirds projected onto the tangent planes, then b111")
}

/// Tessellates a PN triangle over a triangle domain (a regular lattice, or
/// what topic 10's primitive generator makes): one vertex per domain point `[u, v, w]` at
/// `B(u, v, w)`, with the normal `normalize(u N1 + v N2 + w N3)` and the
/// parameters `(u, v)`; the domain's triangles unchanged (so a
/// counter-clockwise `P1, P2, P3` gives counter-clockwise triangles).
#[must_use]
#[transcript::task]
pub fn tessellate_pn(pn: &PnTriangle, domain: &TriangleDomain) -> Mesh {
    // Unused until you write the body:
    let _ = (&pn, &domain);
    todo!(
        "bezier_triangle: evaluate every domain point, interpolate the normals, keep the triangles"
    )
}
