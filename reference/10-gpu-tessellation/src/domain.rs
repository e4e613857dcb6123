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

use freeform::stitch;
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
    // BEGIN SOLUTION primitive_generator: clamp per spacing, round up to an integer / even / odd n
    let (low, high) = match spacing {
        Spacing::Equal => (1.0, MAX_TESS_GEN_LEVEL),
        Spacing::FractionalEven => (2.0, MAX_TESS_GEN_LEVEL),
        Spacing::FractionalOdd => (1.0, MAX_TESS_GEN_LEVEL - 1.0),
    };
    let f = if level.is_nan() {
        low
    } else {
        level.clamp(low, high)
    };
    let up = f.ceil() as usize;
    let n = match spacing {
        Spacing::Equal => up,
        Spacing::FractionalEven => up + up % 2,
        Spacing::FractionalOdd => up + (1 - up % 2),
    };
    (f, n)
    // END SOLUTION
}

/// The subdivision of an edge `[0, 1]` for `level` under `spacing`: the
/// `n + 1` positions `0 = d_0 < d_1 < … < d_n = 1` (module table; the two
/// shorter fractional segments first and last). Symmetric:
/// `d_(n−i) = 1 − d_i`.
#[must_use]
#[transcript::task]
pub fn subdivide_edge(level: f64, spacing: Spacing) -> Vec<f64> {
    // BEGIN SOLUTION primitive_generator: n equal segments, or n − 2 of length 1/f and two short ones at the ends
    let (f, n) = clamp_level(level, spacing);
    let mut d: Vec<f64> = (0..=n).map(|i| i as f64 / n as f64).collect();
    if spacing != Spacing::Equal && n >= 2 {
        let short = (f - (n - 2) as f64) / (2.0 * f);
        for (i, x) in d.iter_mut().enumerate().take(n).skip(1) {
            *x = short + (i - 1) as f64 / f;
        }
    }
    for i in n / 2 + 1..n {
        d[i] = 1.0 - d[n - i];
    }
    d[n] = 1.0;
    d
    // END SOLUTION
}

/// Levels that the specification treats as `1 + ε` (an inner level of 1
/// when some other level is above 1).
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
    // BEGIN SOLUTION primitive_generator: outer edges by the outer levels, inner grid by the inner levels, zip the ring
    let mut domain = QuadDomain::default();
    if outer.iter().any(|&l| l.is_nan() || l <= 0.0) {
        return domain;
    }
    let corners = [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
    domain.points.extend(corners);
    let all_one = inner
        .iter()
        .chain(&outer)
        .all(|&l| clamp_level(l, spacing).1 == 1);
    if all_one {
        domain.triangles = vec![[0, 1, 2], [0, 2, 3]];
        return domain;
    }
    let raise = |l: f64| {
        if clamp_level(l, spacing).1 == 1 {
            ONE_PLUS_EPSILON
        } else {
            l
        }
    };
    let us = subdivide_edge(raise(inner[0]), spacing);
    let vs = subdivide_edge(raise(inner[1]), spacing);
    let (m_u, m_v) = (us.len() - 1, vs.len() - 1);
    // Outer edges, counter-clockwise: v = 0 (outer[1]), u = 1 (outer[2]),
    // v = 1 (outer[3]), u = 0 (outer[0]); keys run along each side.
    let sides = [
        (0, 1, outer[1]),
        (1, 2, outer[2]),
        (2, 3, outer[3]),
        (3, 0, outer[0]),
    ];
    let mut outer_paths = Vec::new();
    for (from, to, level) in sides {
        let d = subdivide_edge(level, spacing);
        let mut ids = vec![from as u32];
        for &t in &d[1..d.len() - 1] {
            ids.push(domain.points.len() as u32);
            domain.points.push(corners[from].lerp(corners[to], t));
        }
        ids.push(to as u32);
        outer_paths.push((ids, d));
    }
    let first = domain.points.len() as u32;
    for &v in &vs[1..m_v] {
        for &u in &us[1..m_u] {
            domain.points.push(DVec2::new(u, v));
        }
    }
    let at = |i: usize, j: usize| first + ((j - 1) * (m_u - 1) + (i - 1)) as u32;
    for j in 1..m_v - 1 {
        for i in 1..m_u - 1 {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            domain.triangles.push([a, b, c]);
            domain.triangles.push([a, c, d]);
        }
    }
    let flip = |ts: &[f64]| ts.iter().map(|t| 1.0 - t).collect::<Vec<_>>();
    let row: Vec<f64> = us[1..m_u].to_vec();
    let column: Vec<f64> = vs[1..m_v].to_vec();
    let inner_paths = [
        ((1..m_u).map(|i| at(i, 1)).collect::<Vec<_>>(), row.clone()),
        ((1..m_v).map(|j| at(m_u - 1, j)).collect(), column.clone()),
        (
            (1..m_u).rev().map(|i| at(i, m_v - 1)).collect(),
            flip(&row).into_iter().rev().collect(),
        ),
        (
            (1..m_v).rev().map(|j| at(1, j)).collect(),
            flip(&column).into_iter().rev().collect(),
        ),
    ];
    for ((outer_ids, outer_keys), (inner_ids, inner_keys)) in outer_paths.iter().zip(&inner_paths) {
        stitch(
            outer_ids,
            outer_keys,
            inner_ids,
            inner_keys,
            &mut domain.triangles,
        );
    }
    domain
    // END SOLUTION
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
    // BEGIN SOLUTION primitive_generator: concentric rings from the inner level, outer edges by the outer levels, zip
    let mut domain = TriangleDomain::default();
    if outer.iter().any(|&l| l.is_nan() || l <= 0.0) {
        return domain;
    }
    // Corners counter-clockwise: bottom left, bottom right, top.
    let corners = [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let all_one = std::iter::once(&inner)
        .chain(&outer)
        .all(|&l| clamp_level(l, spacing).1 == 1);
    if all_one {
        domain.points.extend(corners);
        domain.triangles.push([0, 1, 2]);
        return domain;
    }
    let inner = if clamp_level(inner, spacing).1 == 1 {
        ONE_PLUS_EPSILON
    } else {
        inner
    };
    let d = subdivide_edge(inner, spacing);
    let n = d.len() - 1;
    // Sides counter-clockwise: v = 0 (outer[1]), w = 0 (outer[2]), u = 0 (outer[0]).
    let side_levels = [outer[1], outer[2], outer[0]];
    let lerp = |a: [f64; 3], b: [f64; 3], t: f64| [0, 1, 2].map(|k| a[k] + (b[k] - a[k]) * t);
    let centroid = [1.0 / 3.0; 3];
    // Each ring: per side, the vertex ids from its start corner to its end
    // corner, and their keys along the side.
    let mut rings: Vec<Vec<(Vec<u32>, Vec<f64>)>> = Vec::new();
    for k in 0..=n / 2 {
        let segments = n - 2 * k;
        if segments == 0 {
            let id = domain.points.len() as u32;
            domain.points.push(centroid);
            rings.push(vec![(vec![id], vec![0.5]); 3]);
            break;
        }
        let scale = if k == 0 { 1.0 } else { 1.0 - 2.0 * d[k] };
        let ring_corners = corners.map(|c| lerp(centroid, c, scale));
        let corner_ids: Vec<u32> = (0..3)
            .map(|s| {
                domain.points.push(ring_corners[s]);
                (domain.points.len() - 1) as u32
            })
            .collect();
        let mut sides = Vec::new();
        for s in 0..3 {
            let (from, to) = (ring_corners[s], ring_corners[(s + 1) % 3]);
            let positions: Vec<f64> = if k == 0 {
                subdivide_edge(side_levels[s], spacing)
            } else {
                d[k..=n - k]
                    .iter()
                    .map(|&x| (x - d[k]) / (1.0 - 2.0 * d[k]))
                    .collect()
            };
            let mut ids = vec![corner_ids[s]];
            for &t in &positions[1..positions.len() - 1] {
                ids.push(domain.points.len() as u32);
                domain.points.push(lerp(from, to, t));
            }
            ids.push(corner_ids[(s + 1) % 3]);
            sides.push((ids, Vec::new()));
        }
        if segments == 1 {
            domain
                .triangles
                .push([corner_ids[0], corner_ids[1], corner_ids[2]]);
        }
        rings.push(sides);
    }
    // Keys: the position along the outer side's direction in the plane.
    for pair in 0..rings.len().saturating_sub(1) {
        for s in 0..3 {
            let (start, end) = (embed(corners[s]), embed(corners[(s + 1) % 3]));
            let direction = (end - start).normalize();
            let keys = |ids: &[u32]| {
                ids.iter()
                    .map(|&i| (embed(domain.points[i as usize]) - start).dot(direction))
                    .collect::<Vec<_>>()
            };
            let (outer_ids, _) = &rings[pair][s];
            let (inner_ids, _) = &rings[pair + 1][s];
            let (outer_keys, inner_keys) = (keys(outer_ids), keys(inner_ids));
            stitch(
                outer_ids,
                &outer_keys,
                inner_ids,
                &inner_keys,
                &mut domain.triangles,
            );
        }
    }
    domain
    // END SOLUTION
}
