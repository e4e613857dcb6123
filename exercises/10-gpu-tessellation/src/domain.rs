//! Task 2: the primitive generator, the fixed-function stage between the
//! tessellation control and evaluation shaders, which turns tessellation
//! levels into domain points and triangles (seed 001 §3.2 "Primitivni
//! generator", seed 000 §4.1; OpenGL 4.6 core specification §11.2.2,
//! "Tessellation Primitive Generation", and the same rules in Vulkan's
//! "Tessellator Spacing", "Triangle Tessellation", "Quad Tessellation").
//! wgpu has no tessellator, so it is a pure function here, on the CPU: the
//! given passes upload its points for your evaluation stage.
//!
//! **Levels and spacing.** A level `f` is clamped and rounded to a segment
//! count `n` (maximum level [`MAX_TESS_GEN_LEVEL`] = 64):
//!
//! | spacing            | clamp to | round up to        | segments                          |
//! |--------------------|----------|--------------------|-----------------------------------|
//! | `equal_spacing`    | [1, 64]  | an integer         | `n` equal                         |
//! | `fractional_even`  | [2, 64]  | an even integer    | `n − 2` of length `1/f`, 2 shorter |
//! | `fractional_odd`   | [1, 63]  | an odd integer     | `n − 2` of length `1/f`, 2 shorter |
//!
//! The two shorter segments have the length `(f − (n − 2)) / (2f)` each, so
//! all `n` add up to 1: equal to the others when `n = f`, shrinking to 0 as
//! `n − f` approaches 2, as the specification demands. Where they lie is
//! implementation-dependent ("placed symmetrically on opposite sides");
//! here they are the first and the last segment of the edge.
//!
//! **Triangles** (`u + v + w = 1`, embedded with `(1,0,0)` bottom right,
//! `(0,1,0)` at the top, `(0,0,1)` bottom left): the inner level `n` makes
//! `⌊n/2⌋` concentric triangles inside the outer one (the last a single
//! point when `n` is even). The corner of ring `k` is where the lines
//! perpendicular to a corner's two edges through their `k`-th subdivision
//! points meet; in barycentrics, with `d_k` the `k`-th point of the inner
//! subdivision of `[0, 1]`,
//!
//! ```text
//!   corner_k = centroid + (1 − 2 d_k) (corner − centroid)
//! ```
//!
//! and ring `k`'s edges carry the perpendicular projections of the points
//! `d_k … d_(n−k)`: `n − 2k` segments. (The seed's Figure 3.4 is captioned
//! "Inner Tess = 3" where its text speaks of an inner level of 2; with 2
//! the only inner triangle is the centre point, with 3 it is a triangle.) The outer triangle's edges are
//! subdivided by the outer levels instead (`outer[0]`: `u = 0`, left;
//! `outer[1]`: `v = 0`, bottom; `outer[2]`: `w = 0`, right).
//!
//! **Quads**: the inner levels subdivide `u` (`inner[0]`) and `v`
//! (`inner[1]`) into `m_u × m_v`; the rectangle of points `(u_i, v_j)`,
//! `0 < i < m_u`, `0 < j < m_v`, is cut into two triangles per cell; the
//! outer edges are subdivided by `outer[0]` (`u = 0`), `outer[1]` (`v = 0`),
//! `outer[2]` (`u = 1`), `outer[3]` (`v = 1`).
//!
//! The strips between rings are filled "in an implementation-dependent
//! manner" (the specification fixes only the vertices and that the
//! triangles tile the domain): here by the zipper of [`freeform::stitch`] (given).
//! All triangles are counter-clockwise (`layout(ccw)`).

#[allow(unused_imports)]
use freeform::stitch;
#[allow(unused_imports)]
use glam::DVec2;

pub use freeform::domain::{QuadDomain, TriangleDomain, embed};

/// `GL_MAX_TESS_GEN_LEVEL`: the largest level (64 is the minimum every
/// implementation must support and what this generator uses).
pub const MAX_TESS_GEN_LEVEL: f64 = 64.0;

/// The spacing of the subdivision (`layout(equal_spacing)` etc.).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Spacing {
    /// `equal_spacing`.
    #[default]
    Equal,
    /// `fractional_even_spacing`.
    FractionalEven,
    /// `fractional_odd_spacing`.
    FractionalOdd,
}

/// The clamped level `f` and segment count `n` of a level under `spacing`
/// (see the module table). NaN clamps to the lower end.
#[must_use]
#[transcript::task]
pub fn clamp_level(level: f64, spacing: Spacing) -> (f64, usize) {
    // Unused until you write the body:
    let _ = (&level, &spacing);
    todo!("primitive_generator: clamp per spacing, round up to an integer / even / odd n")
}

/// The subdivision of an edge `[0, 1]` for `level` under `spacing`: the
/// `n + 1` positions `0 = d_0 < d_1 < … < d_n = 1` (module table; the two
/// shorter fractional segments first and last). Symmetric:
/// `d_(n−i) = 1 − d_i`.
#[must_use]
#[transcript::task]
pub fn subdivide_edge(level: f64, spacing: Spacing) -> Vec<f64> {
    // Unused until you write the body:
    let _ = (&level, &spacing);
    todo!(
        "primitive_generator: n equal segments, or n − 2 of length 1/f and two short ones at the ends"
    )
}

/// Levels that the specification treats as `1 + ε` (an inner level of 1
/// when some other level is above 1).
#[allow(dead_code)]
const ONE_PLUS_EPSILON: f64 = 1.0 + f64::EPSILON;

/// The primitive generator for `layout(quads)`: domain points and
/// counter-clockwise triangles for the given inner and outer levels.
///
/// - If any outer level is `≤ 0` or NaN the patch is discarded: empty result.
/// - If both inner and all outer levels are 1 after clamping and rounding,
///   the result is the single quad: corners `(0,0), (1,0), (1,1), (0,1)`
///   as two triangles `[0, 1, 2]`, `[0, 2, 3]`.
/// - Otherwise an inner level of 1 counts as `1 + ε`.
///
/// Points come in the order: the four corners `(0,0), (1,0), (1,1),
/// (0,1)`, the inner points of the outer edges (`v = 0`, `u = 1`, `v = 1`,
/// `u = 0`, each counter-clockwise), then the inner grid row by row.
#[must_use]
#[transcript::task]
pub fn quad_domain(inner: [f64; 2], outer: [f64; 4], spacing: Spacing) -> QuadDomain {
    // Unused until you write the body:
    let _ = (&inner, &outer, &spacing);
    todo!(
        "primitive_generator: outer edges by the outer levels, inner grid by the inner levels, zip the ring"
    )
}

/// The primitive generator for `layout(triangles)`: barycentric domain
/// points and counter-clockwise triangles (in the [`embed`]ding) for the
/// inner level and the outer levels of the edges `u = 0`, `v = 0`, `w = 0`.
///
/// - If any outer level is `≤ 0` or NaN the patch is discarded: empty result.
/// - If the inner and all outer levels are 1 after clamping and rounding,
///   the result is the single triangle `(0,0,1), (1,0,0), (0,1,0)`, as
///   triangle `[0, 1, 2]`.
/// - Otherwise an inner level of 1 counts as `1 + ε` (2 segments, or 3 with
///   fractional odd spacing, whose inner corners then lie on the edges).
///
/// Points come ring by ring from the outside; each ring starts at its
/// corner towards `(0,0,1)` and runs counter-clockwise.
#[must_use]
#[transcript::task]
pub fn triangle_domain(inner: f64, outer: [f64; 3], spacing: Spacing) -> TriangleDomain {
    // Unused until you write the body:
    let _ = (&inner, &outer, &spacing);
    todo!(
        "primitive_generator: concentric rings from the inner level, outer edges by the outer levels, zip"
    )
}
