//! The primitive generator: the fixed-function stage between the
//! tessellation control and evaluation shaders, which turns tessellation
//! levels into domain points and triangles (OpenGL 4.6 §11.2.2; seed 001
//! §3 "Primitivni generator", seed 000 §4.1).
//!
//! This module is given: wgpu has no tessellator, so it is done here on the
//! CPU and its output is uploaded as a buffer that the evaluation pass reads.
//!
//! # Terms
//! - A **level** `f` says into how many segments an edge is cut. The
//!   **spacing** turns it into a whole number `n` of segments:
//!
//!   | spacing           | `f` clamped to | `n`                        |
//!   |-------------------|----------------|----------------------------|
//!   | `equal`           | `[1, 64]`      | `⌈f⌉`                      |
//!   | `fractional_odd`  | `[1, 63]`      | the odd integer `≥ f`      |
//!   | `fractional_even` | `[2, 64]`      | the even integer `≥ f`     |
//!
//!   With equal spacing all `n` segments are `1/n` long. With fractional
//!   spacing `n − 2` segments are `1/f` long and two shorter ones of
//!   `(1 − (n − 2)/f) / 2` share the rest, placed symmetrically; the GL
//!   leaves their place to the implementation, here they sit next to the
//!   centre of the edge (`l l s [l] s l l` for odd `n`, `l l s s l l` for
//!   even `n`), so that new vertices grow out of the centre as `f` rises.
//! - **Outer levels** cut the edges of the domain; **inner levels** cut its
//!   interior into concentric rings. The ring between the outer edge and the
//!   first inner ring is stitched with triangles (its triangulation is left
//!   to the implementation by the GL; here a merge along the edge).
//!
//! ```text
//!  quads: (u, v) in [0,1]²           triangles: (u, v, w), u + v + w = 1
//!   v                                          W (0,0,1)
//!   1 +----outer[3]----+                       /\
//!     |    inner[0]    |              outer[1]/  \outer[0]
//!  o[0]  inner[1]     o[2]                   /    \
//!     |                |                    /______\
//!   0 +----outer[1]----+ u          (1,0,0) U outer[2] V (0,1,0)
//!     0                1
//! ```
//!
//! Triangles are counter-clockwise in the domain (`ccw`: in `(u, v)` for
//! quads, in the plane `U → V → W` for triangles). A patch with an outer
//! level `≤ 0` or NaN is discarded (no points, no triangles), as in the GL.

use glam::{DVec2, Vec3};

/// The largest tessellation level (`GL_MAX_TESS_GEN_LEVEL`'s minimum).
pub const MAX_TESS_LEVEL: f32 = 64.0;

/// How a level becomes a number of segments (GLSL `equal_spacing`,
/// `fractional_odd_spacing`, `fractional_even_spacing`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Spacing {
    /// `n = ⌈f⌉` segments of equal length.
    #[default]
    Equal,
    /// `n` odd; `n − 2` segments of `1/f` and two shorter ones.
    FractionalOdd,
    /// `n` even; `n − 2` segments of `1/f` and two shorter ones.
    FractionalEven,
}

/// Levels of a quad patch (GLSL `gl_TessLevelOuter[0..4]`, `gl_TessLevelInner[0..2]`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuadLevels {
    /// Edges `u = 0`, `v = 0`, `u = 1`, `v = 1`.
    pub outer: [f32; 4],
    /// Interior cuts along `u` and along `v`.
    pub inner: [f32; 2],
}

impl QuadLevels {
    /// All six levels equal to `level` (the seed's TCS, Listing 1).
    #[must_use]
    pub const fn uniform(level: f32) -> Self {
        Self {
            outer: [level; 4],
            inner: [level; 2],
        }
    }
}

/// Levels of a triangle patch (`gl_TessLevelOuter[0..3]`, `gl_TessLevelInner[0]`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleLevels {
    /// Edges `u = 0` (V–W), `v = 0` (W–U), `w = 0` (U–V).
    pub outer: [f32; 3],
    /// The interior rings.
    pub inner: f32,
}

impl TriangleLevels {
    /// All four levels equal to `level` (seed 001: outer level = inner level).
    #[must_use]
    pub const fn uniform(level: f32) -> Self {
        Self {
            outer: [level; 3],
            inner: level,
        }
    }
}

/// The primitive generator's output for one patch.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Domain {
    /// Domain points: `(u, v, 0)` for quads, barycentric `(u, v, w)` for
    /// triangles (what GLSL calls `gl_TessCoord`).
    pub points: Vec<Vec3>,
    /// Counter-clockwise triangles as indices into `points`.
    pub triangles: Vec<[u32; 3]>,
}

/// The number of segments a level gives under a spacing, `None` for a level
/// that discards the patch (`≤ 0` or NaN); `+∞` is clamped like any level.
#[must_use]
pub fn segment_count(level: f32, spacing: Spacing) -> Option<u32> {
    clamped_level(level, spacing).map(|(_, n)| n)
}

/// The clamped level and its segment count.
fn clamped_level(level: f32, spacing: Spacing) -> Option<(f64, u32)> {
    if level.is_nan() || level <= 0.0 {
        return None;
    }
    let f = f64::from(level);
    Some(match spacing {
        Spacing::Equal => {
            let f = f.clamp(1.0, f64::from(MAX_TESS_LEVEL));
            (f, f.ceil() as u32)
        }
        Spacing::FractionalOdd => {
            let f = f.clamp(1.0, f64::from(MAX_TESS_LEVEL) - 1.0);
            let n = f.ceil() as u32;
            (f, if n.is_multiple_of(2) { n + 1 } else { n })
        }
        Spacing::FractionalEven => {
            let f = f.clamp(2.0, f64::from(MAX_TESS_LEVEL));
            let n = f.ceil() as u32;
            (f, if n.is_multiple_of(2) { n } else { n + 1 })
        }
    })
}

/// The `n + 1` cut positions of an edge, from 0 to 1 (both included),
/// for a level under a spacing; `None` if the level discards the patch.
///
/// The positions are symmetric: `t[n − i] = 1 − t[i]` exactly, so an edge
/// shared by two patches that run along it in opposite directions is cut at
/// the same points.
#[must_use]
pub fn edge_cuts(level: f32, spacing: Spacing) -> Option<Vec<f32>> {
    let (f, n) = clamped_level(level, spacing)?;
    Some(cuts(f, n, spacing))
}

fn cuts(f: f64, n: u32, spacing: Spacing) -> Vec<f32> {
    let lengths: Vec<f64> = if spacing == Spacing::Equal || n == 1 {
        vec![1.0 / f64::from(n); n as usize]
    } else {
        let long = 1.0 / f;
        let short = (1.0 - f64::from(n - 2) * long) / 2.0;
        // Long segments on each side of the centre group.
        let side = if n.is_multiple_of(2) {
            (n - 2) / 2
        } else {
            (n - 3) / 2
        } as usize;
        let mut v = vec![long; side];
        v.push(short);
        if !n.is_multiple_of(2) {
            v.push(long);
        }
        v.push(short);
        v.extend(std::iter::repeat_n(long, side));
        v
    };
    let n = lengths.len();
    let mut t = vec![0.0_f32; n + 1];
    // Prefix sums from the left for the first half, mirrored for the second.
    // Rounded to multiples of 2⁻²⁴, so that `1 − t` is exact in f32 and
    // mirroring twice gives `t` back: `t[n − i] = 1 − t[i]` for every i.
    const GRID: f64 = (1 << 24) as f64;
    let mut sum = 0.0_f64;
    for i in 0..=n / 2 {
        t[i] = ((sum * GRID).round() / GRID) as f32;
        sum += lengths[i.min(n - 1)];
    }
    if n.is_multiple_of(2) {
        t[n / 2] = 0.5;
    }
    for i in 0..=n / 2 {
        t[n - i] = 1.0 - t[i];
    }
    t
}

/// The segment count of an inner level, with the GL's rule that an inner
/// level of one becomes `1 + ε` (2 segments, 3 for odd spacing) unless the
/// whole patch is a single primitive.
fn inner_count(level: f32, spacing: Spacing) -> (f64, u32) {
    // An inner level is never a reason to discard: NaN or ≤ 0 count as 1.
    let level = if level.is_nan() || level <= 0.0 {
        1.0
    } else {
        level
    };
    match clamped_level(level, spacing) {
        Some((_, 1)) => {
            let n = if spacing == Spacing::FractionalOdd {
                3
            } else {
                2
            };
            // `1 + ε` clamped: cut like a level of exactly `1 + ε`, which for
            // fractional spacing gives two near-empty short segments.
            let f = 1.0 + f64::from(f32::EPSILON);
            (if spacing == Spacing::Equal { 2.0 } else { f }, n)
        }
        Some(pair) => pair,
        None => unreachable!("levels ≤ 0 and NaN were replaced by 1"),
    }
}

/// Adds triangles between two polylines running side by side in the same
/// direction, `outer` and `inner` (indices into `points`), with
/// parameters `t_outer`, `t_inner` along that direction: a merge that
/// always advances along the polyline whose next point comes first.
fn stitch(
    domain: &mut Domain,
    outer: &[u32],
    t_outer: &[f32],
    inner: &[u32],
    t_inner: &[f32],
    to_plane: impl Fn(Vec3) -> DVec2,
) {
    let (mut i, mut j) = (0, 0);
    while i + 1 < outer.len() || j + 1 < inner.len() {
        let advance_outer =
            j + 1 == inner.len() || (i + 1 < outer.len() && t_outer[i + 1] <= t_inner[j + 1]);
        let triangle = if advance_outer {
            i += 1;
            [outer[i - 1], outer[i], inner[j]]
        } else {
            j += 1;
            [outer[i], inner[j], inner[j - 1]]
        };
        push_ccw(domain, triangle, &to_plane);
    }
}

/// Pushes a triangle, swapping two corners if it is clockwise in the plane.
fn push_ccw(domain: &mut Domain, [a, b, c]: [u32; 3], to_plane: impl Fn(Vec3) -> DVec2) {
    let p = |k: u32| to_plane(domain.points[k as usize]);
    let (pa, pb, pc) = (p(a), p(b), p(c));
    let area2 = (pb - pa).perp_dot(pc - pa);
    domain
        .triangles
        .push(if area2 < 0.0 { [a, c, b] } else { [a, b, c] });
}

fn add_point(domain: &mut Domain, p: Vec3) -> u32 {
    domain.points.push(p);
    (domain.points.len() - 1) as u32
}

/// One side of the quad ring: its outer level's index, its two corners
/// (point indices), whether u runs along it, and the inner grid cells
/// `(row, column)` facing it.
type Side = (usize, u32, u32, bool, Vec<(usize, usize)>);

/// The quad domain `[0,1]²` for the given levels (GLSL `layout(quads)`).
#[must_use]
pub fn quad_domain(levels: QuadLevels, spacing: Spacing) -> Domain {
    let Some(outer) = levels
        .outer
        .iter()
        .map(|&l| edge_cuts(l, spacing))
        .collect::<Option<Vec<_>>>()
    else {
        return Domain::default();
    };
    let plane = |p: Vec3| DVec2::new(f64::from(p.x), f64::from(p.y));
    let mut domain = Domain::default();
    let all_one = outer.iter().all(|c| c.len() == 2)
        && levels
            .inner
            .iter()
            .all(|&l| segment_count(l, spacing).is_none_or(|n| n == 1));
    if all_one && spacing != Spacing::FractionalEven {
        // The GL's exception: all levels one give the quad as two triangles.
        for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            add_point(&mut domain, Vec3::new(u, v, 0.0));
        }
        domain.triangles = vec![[0, 1, 2], [0, 2, 3]];
        return domain;
    }
    let (fu, nu) = inner_count(levels.inner[0], spacing);
    let (fv, nv) = inner_count(levels.inner[1], spacing);
    let (us, vs) = (cuts(fu, nu, spacing), cuts(fv, nv, spacing));
    // The inner grid: columns 1..nu-1, rows 1..nv-1 (a single column or row
    // when there are 2 segments).
    let (cols, rows) = ((nu - 1) as usize, (nv - 1) as usize);
    let mut grid = vec![0_u32; cols * rows];
    for r in 0..rows {
        for c in 0..cols {
            grid[r * cols + c] = add_point(&mut domain, Vec3::new(us[c + 1], vs[r + 1], 0.0));
        }
    }
    for r in 0..rows.saturating_sub(1) {
        for c in 0..cols.saturating_sub(1) {
            let (a, b) = (grid[r * cols + c], grid[r * cols + c + 1]);
            let (d, e) = (grid[(r + 1) * cols + c], grid[(r + 1) * cols + c + 1]);
            push_ccw(&mut domain, [a, b, e], plane);
            push_ccw(&mut domain, [a, e, d], plane);
        }
    }
    let corners: Vec<u32> = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
        .iter()
        .map(|&(u, v)| add_point(&mut domain, Vec3::new(u, v, 0.0)))
        .collect();
    // Each side: its outer level, its corners, which coordinate runs along
    // it, and the inner grid's side running the same way.
    let column = |c: usize| (0..rows).map(move |r| (r, c));
    let row = |r: usize| (0..cols).map(move |c| (r, c));
    let sides: [Side; 4] = [
        (1, corners[0], corners[1], true, row(0).collect()),
        (2, corners[1], corners[2], false, column(cols - 1).collect()),
        (3, corners[3], corners[2], true, row(rows - 1).collect()),
        (0, corners[0], corners[3], false, column(0).collect()),
    ];
    for (level, from, to, along_u, inner_cells) in sides {
        let cuts = &outer[level];
        let fixed = domain.points[from as usize];
        let mut line = vec![from];
        for &t in &cuts[1..cuts.len() - 1] {
            let p = if along_u {
                Vec3::new(t, fixed.y, 0.0)
            } else {
                Vec3::new(fixed.x, t, 0.0)
            };
            line.push(add_point(&mut domain, p));
        }
        line.push(to);
        let inner: Vec<u32> = inner_cells
            .iter()
            .map(|&(r, c)| grid[r * cols + c])
            .collect();
        let t_inner: Vec<f32> = inner_cells
            .iter()
            .map(|&(r, c)| if along_u { us[c + 1] } else { vs[r + 1] })
            .collect();
        stitch(&mut domain, &line, cuts, &inner, &t_inner, plane);
    }
    domain
}

/// The triangle domain for the given levels (GLSL `layout(triangles)`).
///
/// Inner rings follow the GL's construction (seed 001 §3): ring `k`'s corner
/// near `U` is where the perpendiculars through the `k`-th inner cuts of the
/// two edges at `U` meet, `lerp(U, centre, 2·t_k)`, and its edges carry the
/// inner cuts `t_k ..= t_(n−k)`. `⌊n/2⌋` rings; the last is a point (even
/// `n`) or a triangle (odd `n`).
#[must_use]
pub fn triangle_domain(levels: TriangleLevels, spacing: Spacing) -> Domain {
    let Some(outer) = levels
        .outer
        .iter()
        .map(|&l| edge_cuts(l, spacing))
        .collect::<Option<Vec<_>>>()
    else {
        return Domain::default();
    };
    const CORNERS: [Vec3; 3] = [Vec3::X, Vec3::Y, Vec3::Z];
    // Side s runs from corner `SIDES[s].0` to `SIDES[s].1`; its outer level
    // is `outer[SIDES[s].2]`. Sides U→V, V→W, W→U (counter-clockwise).
    const SIDES: [(usize, usize, usize); 3] = [(0, 1, 2), (1, 2, 0), (2, 0, 1)];
    // The plane of the triangle, with U → V → W counter-clockwise.
    let plane = |p: Vec3| {
        let (v, w) = (f64::from(p.y), f64::from(p.z));
        DVec2::new(v + 0.5 * w, w * 3.0_f64.sqrt() / 2.0)
    };
    let mut domain = Domain::default();
    let inner_level_one = segment_count(levels.inner, spacing).is_none_or(|n| n == 1);
    if inner_level_one && outer.iter().all(|c| c.len() == 2) {
        for corner in CORNERS {
            add_point(&mut domain, corner);
        }
        domain.triangles = vec![[0, 1, 2]];
        return domain;
    }
    let (f, n) = inner_count(levels.inner, spacing);
    let t = cuts(f, n, spacing);
    let centre = Vec3::splat(1.0 / 3.0);
    let ring_corner = |k: usize, c: usize| CORNERS[c].lerp(centre, 2.0 * t[k]);
    // Points of ring k on side s: from its start corner to its end corner
    // (both included) with their parameters along the side; ring 0 uses
    // the outer levels.
    let corner_ids: Vec<u32> = CORNERS.iter().map(|&c| add_point(&mut domain, c)).collect();
    let mut previous: Vec<(Vec<u32>, Vec<f32>)> = SIDES
        .iter()
        .map(|&(a, b, level)| {
            let cuts = &outer[level];
            let mut ids = vec![corner_ids[a]];
            for &s in &cuts[1..cuts.len() - 1] {
                ids.push(add_point(&mut domain, CORNERS[a].lerp(CORNERS[b], s)));
            }
            ids.push(corner_ids[b]);
            (ids, cuts.clone())
        })
        .collect();
    let rings = (n / 2) as usize;
    for k in 1..=rings {
        let segments = n as usize - 2 * k;
        // A ring of no segments is the centre point, shared by all sides.
        let corners: Vec<u32> = if segments == 0 {
            vec![add_point(&mut domain, centre); 3]
        } else {
            (0..3)
                .map(|c| add_point(&mut domain, ring_corner(k, c)))
                .collect()
        };
        let mut current = Vec::with_capacity(3);
        for &(a, b, _) in &SIDES {
            let (pa, pb) = (ring_corner(k, a), ring_corner(k, b));
            let params: Vec<f32> = t[k..=n as usize - k].to_vec();
            let mut ids = vec![corners[a]];
            if segments > 0 {
                for &s in &params[1..segments] {
                    let along = (s - t[k]) / (t[n as usize - k] - t[k]);
                    ids.push(add_point(&mut domain, pa.lerp(pb, along)));
                }
                ids.push(corners[b]);
            }
            current.push((ids, params));
        }
        for (side, (inner_ids, inner_t)) in current.iter().enumerate() {
            let (outer_ids, outer_t) = &previous[side];
            stitch(&mut domain, outer_ids, outer_t, inner_ids, inner_t, plane);
        }
        if segments == 1 {
            push_ccw(&mut domain, [corners[0], corners[1], corners[2]], plane);
        }
        previous = current;
    }
    domain
}

#[cfg(test)]
mod tests {
    use std::collections::BTreeMap;

    use super::*;

    const SPACINGS: [Spacing; 3] = [
        Spacing::Equal,
        Spacing::FractionalOdd,
        Spacing::FractionalEven,
    ];

    /// Twice the signed area of a triangle in the domain's plane.
    fn area2(points: [DVec2; 3]) -> f64 {
        (points[1] - points[0]).perp_dot(points[2] - points[0])
    }

    fn quad_plane(p: Vec3) -> DVec2 {
        DVec2::new(f64::from(p.x), f64::from(p.y))
    }

    fn tri_plane(p: Vec3) -> DVec2 {
        let (v, w) = (f64::from(p.y), f64::from(p.z));
        DVec2::new(v + 0.5 * w, w * 3.0_f64.sqrt() / 2.0)
    }

    /// Checks that the triangles are counter-clockwise, tile an area of
    /// `expected_area`, share every interior edge with exactly one other
    /// triangle (running the other way), and returns the boundary edges.
    fn check_tiling(d: &Domain, plane: fn(Vec3) -> DVec2, expected_area: f64) -> Vec<[u32; 2]> {
        let mut area = 0.0;
        let mut edges: BTreeMap<[u32; 2], i32> = BTreeMap::new();
        for t in &d.triangles {
            let a = area2(t.map(|k| plane(d.points[k as usize])));
            assert!(a >= 0.0, "clockwise triangle {t:?}");
            area += a / 2.0;
            for (x, y) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
                // +1 for a → b with a < b, −1 for the reverse direction.
                let (key, dir) = if x < y { ([x, y], 1) } else { ([y, x], -1) };
                *edges.entry(key).or_default() += dir * 10 + 1;
            }
        }
        assert!(
            (area - expected_area).abs() < 1e-5,
            "triangles cover {area}, expected {expected_area}"
        );
        let mut boundary = Vec::new();
        for (edge, code) in edges {
            match code {
                // Used twice in opposite directions: +11 − 9 = 2.
                2 => {}
                11 | -9 => boundary.push(edge),
                _ => panic!("edge {edge:?} is used wrongly (code {code})"),
            }
        }
        boundary
    }

    #[test]
    fn equal_spacing_cuts_edges_evenly() {
        assert_eq!(
            edge_cuts(4.0, Spacing::Equal).unwrap(),
            [0.0, 0.25, 0.5, 0.75, 1.0]
        );
        assert_eq!(edge_cuts(2.3, Spacing::Equal).unwrap().len(), 4);
        assert_eq!(segment_count(0.2, Spacing::Equal), Some(1));
        assert_eq!(segment_count(1000.0, Spacing::Equal), Some(64));
        assert_eq!(segment_count(f32::INFINITY, Spacing::Equal), Some(64));
    }

    #[test]
    fn fractional_spacing_has_two_short_segments_at_the_centre() {
        // f = 2.5, odd: n = 3, one long segment of 1/2.5 = 0.4 and two of 0.3.
        let t = edge_cuts(2.5, Spacing::FractionalOdd).unwrap();
        let expected = [0.0, 0.3, 0.7, 1.0];
        assert!(
            t.iter().zip(expected).all(|(a, b)| (a - b).abs() < 1e-6),
            "{t:?}"
        );
        // f = 5, even: n = 6, four segments of 0.2, two of 0.1 at the centre.
        let t = edge_cuts(5.0, Spacing::FractionalEven).unwrap();
        let expected = [0.0, 0.2, 0.4, 0.5, 0.6, 0.8, 1.0];
        assert!(
            t.iter().zip(expected).all(|(a, b)| (a - b).abs() < 1e-6),
            "{t:?}"
        );
        assert_eq!(segment_count(1.0, Spacing::FractionalEven), Some(2));
        assert_eq!(segment_count(64.0, Spacing::FractionalOdd), Some(63));
    }

    #[test]
    fn cuts_are_symmetric_and_increasing() {
        for spacing in SPACINGS {
            for tenth in 1..700 {
                let t = edge_cuts(tenth as f32 / 10.0, spacing).unwrap();
                let n = t.len() - 1;
                assert_eq!((t[0], t[n]), (0.0, 1.0));
                for i in 0..=n {
                    assert_eq!(t[n - i], 1.0 - t[i], "{spacing:?} {tenth}");
                }
                assert!(t.windows(2).all(|w| w[0] <= w[1]));
            }
        }
    }

    #[test]
    fn bad_outer_levels_discard_the_patch() {
        for bad in [0.0, -1.0, f32::NAN] {
            let mut q = QuadLevels::uniform(4.0);
            q.outer[2] = bad;
            assert_eq!(quad_domain(q, Spacing::Equal), Domain::default());
            let mut t = TriangleLevels::uniform(4.0);
            t.outer[1] = bad;
            assert_eq!(triangle_domain(t, Spacing::Equal), Domain::default());
        }
    }

    #[test]
    fn uniform_quads_give_two_triangles_per_cell() {
        for n in 1..=12 {
            let d = quad_domain(QuadLevels::uniform(n as f32), Spacing::Equal);
            assert_eq!(d.triangles.len(), 2 * n * n, "level {n}");
            assert_eq!(d.points.len(), (n + 1) * (n + 1), "level {n}");
        }
    }

    #[test]
    fn triangle_level_two_is_a_fan_of_six_around_the_centre() {
        let d = triangle_domain(TriangleLevels::uniform(2.0), Spacing::Equal);
        assert_eq!(d.triangles.len(), 6);
        assert_eq!(d.points.len(), 7);
        assert!(d.points.contains(&Vec3::splat(1.0 / 3.0)));
        let d = triangle_domain(TriangleLevels::uniform(1.0), Spacing::Equal);
        assert_eq!(d.triangles, [[0, 1, 2]]);
    }

    #[test]
    fn quads_tile_the_square_with_outer_edges_cut_as_asked() {
        for spacing in SPACINGS {
            for outer in [
                [1.0, 2.0, 3.0, 4.0],
                [7.5, 1.0, 2.2, 13.0],
                [64.0, 3.0, 64.0, 1.0],
            ] {
                for inner in [[1.0, 1.0], [3.0, 5.5], [9.0, 2.0]] {
                    let levels = QuadLevels { outer, inner };
                    let d = quad_domain(levels, spacing);
                    let boundary = check_tiling(&d, quad_plane, 1.0);
                    let expected: u32 = outer
                        .iter()
                        .map(|&l| segment_count(l, spacing).unwrap())
                        .sum();
                    assert_eq!(boundary.len() as u32, expected, "{levels:?} {spacing:?}");
                }
            }
        }
    }

    #[test]
    fn triangles_tile_the_triangle_with_outer_edges_cut_as_asked() {
        let full_area = 3.0_f64.sqrt() / 4.0;
        for spacing in SPACINGS {
            for outer in [[1.0, 1.0, 1.0], [4.0, 1.0, 6.0], [2.5, 9.0, 33.0]] {
                for inner in [1.0, 2.0, 3.0, 5.0, 6.5, 20.0] {
                    let levels = TriangleLevels { outer, inner };
                    let d = triangle_domain(levels, spacing);
                    let boundary = check_tiling(&d, tri_plane, full_area);
                    let expected: u32 = outer
                        .iter()
                        .map(|&l| segment_count(l, spacing).unwrap())
                        .sum();
                    assert_eq!(boundary.len() as u32, expected, "{levels:?} {spacing:?}");
                    for p in &d.points {
                        assert!((p.x + p.y + p.z - 1.0).abs() < 1e-6 && p.min_element() >= -1e-7);
                    }
                }
            }
        }
    }
}
