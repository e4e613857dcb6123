//! Task 2: the primitive generator (OpenGL 4.6 §11.2.2).

use std::collections::HashMap;

use glam::DVec2;
use gpu_tessellation::domain::{
    MAX_TESS_GEN_LEVEL, QuadDomain, Spacing, TriangleDomain, clamp_level, embed, quad_domain,
    subdivide_edge, triangle_domain,
};
use proptest::prelude::*;
use testkit::topology::directed_edges;

const SPACINGS: [Spacing; 3] = [
    Spacing::Equal,
    Spacing::FractionalEven,
    Spacing::FractionalOdd,
];
const EXACT: f64 = 1e-12;

fn assert_close(yours: &[f64], expected: &[f64], what: &str) {
    assert_eq!(
        yours.len(),
        expected.len(),
        "{what}: {yours:?} vs {expected:?}"
    );
    for (a, b) in yours.iter().zip(expected) {
        assert!((a - b).abs() < EXACT, "{what}: {yours:?} vs {expected:?}");
    }
}

#[testkit::test]
fn levels_are_clamped_and_rounded_per_spacing() {
    use Spacing::{Equal, FractionalEven as Even, FractionalOdd as Odd};
    let cases = [
        (Equal, 0.5, 1.0, 1),
        (Equal, 1.0, 1.0, 1),
        (Equal, 3.2, 3.2, 4),
        (Equal, 100.0, 64.0, 64),
        (Equal, f64::NAN, 1.0, 1),
        (Even, 1.0, 2.0, 2),
        (Even, 3.0, 3.0, 4),
        (Even, 4.0, 4.0, 4),
        (Even, 4.1, 4.1, 6),
        (Even, 70.0, 64.0, 64),
        (Odd, 0.2, 1.0, 1),
        (Odd, 2.0, 2.0, 3),
        (Odd, 3.0, 3.0, 3),
        (Odd, 3.5, 3.5, 5),
        (Odd, 64.0, 63.0, 63),
    ];
    for (spacing, level, f, n) in cases {
        assert_eq!(
            clamp_level(level, spacing),
            (f, n),
            "{spacing:?} level {level}"
        );
    }
    assert_eq!(MAX_TESS_GEN_LEVEL, 64.0);
}

#[testkit::test]
fn edges_are_subdivided_with_two_short_fractional_segments() {
    assert_close(
        &subdivide_edge(4.0, Spacing::Equal),
        &[0.0, 0.25, 0.5, 0.75, 1.0],
        "equal 4",
    );
    assert_close(
        &subdivide_edge(2.5, Spacing::Equal),
        &[0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0],
        "equal 2.5",
    );
    // Even, f = 3: n = 4, two segments of 1/3 and two of (3 − 2)/6 = 1/6.
    assert_close(
        &subdivide_edge(3.0, Spacing::FractionalEven),
        &[0.0, 1.0 / 6.0, 0.5, 5.0 / 6.0, 1.0],
        "even 3",
    );
    // Odd, f = 2: n = 3, one segment of 1/2 and two of (2 − 1)/4 = 1/4.
    assert_close(
        &subdivide_edge(2.0, Spacing::FractionalOdd),
        &[0.0, 0.25, 0.75, 1.0],
        "odd 2",
    );
    // At f = n the fractional spacings are equal spacing.
    assert_close(
        &subdivide_edge(5.0, Spacing::FractionalOdd),
        &subdivide_edge(5.0, Spacing::Equal),
        "odd 5",
    );
    assert_close(
        &subdivide_edge(6.0, Spacing::FractionalEven),
        &subdivide_edge(6.0, Spacing::Equal),
        "even 6",
    );
    assert_close(
        &subdivide_edge(1.0, Spacing::FractionalOdd),
        &[0.0, 1.0],
        "odd 1: not subdivided",
    );
}

#[testkit::test]
fn levels_of_one_give_a_single_quad_or_triangle() {
    for spacing in [Spacing::Equal, Spacing::FractionalOdd] {
        let quad = quad_domain([1.0, 0.7], [1.0, 0.5, 1.0, 1.0], spacing);
        assert_eq!(quad.points, [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y]);
        assert_eq!(quad.triangles, [[0, 1, 2], [0, 2, 3]]);
        let tri = triangle_domain(1.0, [1.0, 1.0, 0.9], spacing);
        assert_eq!(
            tri.points,
            [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
        );
        assert_eq!(tri.triangles, [[0, 1, 2]]);
    }
}

#[testkit::test]
fn non_positive_or_nan_outer_levels_discard_the_patch() {
    for spacing in SPACINGS {
        for bad in [0.0, -1.0, f64::NAN] {
            assert_eq!(
                quad_domain([3.0, 3.0], [3.0, bad, 3.0, 3.0], spacing),
                QuadDomain::default()
            );
            assert_eq!(
                triangle_domain(3.0, [3.0, 3.0, bad], spacing),
                TriangleDomain::default()
            );
        }
        // With every level positive, the same patches are generated.
        assert_ne!(
            quad_domain([3.0, 3.0], [3.0; 4], spacing),
            QuadDomain::default()
        );
        assert_ne!(
            triangle_domain(3.0, [3.0; 3], spacing),
            TriangleDomain::default()
        );
    }
}

#[testkit::test]
fn equal_quads_of_level_three_are_the_regular_grid() {
    // 4 × 4 points; 9 cells; the ring 4 sides × (3 + 1) triangles + 2 inside.
    let quad = quad_domain([3.0, 3.0], [3.0; 4], Spacing::Equal);
    assert_eq!((quad.points.len(), quad.triangles.len()), (16, 18));
    for i in 0..4 {
        for j in 0..4 {
            let p = DVec2::new(i as f64 / 3.0, j as f64 / 3.0);
            assert!(
                quad.points.iter().any(|q| q.distance(p) < EXACT),
                "missing {p}"
            );
        }
    }
}

#[testkit::test]
fn inner_levels_subdivide_u_and_v_of_the_quad() {
    // inner[0] = 2 cuts u in halves, inner[1] = 4 cuts v in quarters: the
    // inner grid is the column u = ½ at v = ¼, ½, ¾.
    let quad = quad_domain([2.0, 4.0], [1.0; 4], Spacing::Equal);
    let mut inside: Vec<(f64, f64)> = quad
        .points
        .iter()
        .filter(|p| p.x > 0.0 && p.x < 1.0 && p.y > 0.0 && p.y < 1.0)
        .map(|p| (p.x, p.y))
        .collect();
    inside.sort_by(|a, b| a.partial_cmp(b).unwrap());
    assert_eq!(inside, [(0.5, 0.25), (0.5, 0.5), (0.5, 0.75)]);
}

#[testkit::test]
fn triangle_of_inner_level_two_has_a_centre_point() {
    // ⌊2/2⌋ = 1 concentric triangle, degenerate to the centroid.
    let tri = triangle_domain(2.0, [1.0; 3], Spacing::Equal);
    assert_eq!((tri.points.len(), tri.triangles.len()), (4, 3));
    assert!(
        tri.points
            .iter()
            .any(|p| p.iter().all(|&x| (x - 1.0 / 3.0).abs() < EXACT))
    );
}

/// The corner of ring `k` by the specification's construction, computed in
/// the plane: the intersection of the perpendiculars to the two edges at
/// a corner, through their points at distance `d` from it.
fn ring_corner(corner: DVec2, towards1: DVec2, towards2: DVec2, d: f64) -> DVec2 {
    let (e1, e2) = (
        (towards1 - corner).normalize(),
        (towards2 - corner).normalize(),
    );
    let side = (towards1 - corner).length();
    // Solve x·e1 = d·side, x·e2 = d·side for x (relative to the corner).
    let det = e1.x * e2.y - e1.y * e2.x;
    let c = d * side;
    corner + DVec2::new(c * e2.y - e1.y * c, e1.x * c - c * e2.x) / det
}

#[testkit::test]
fn inner_triangles_follow_the_perpendicular_construction() {
    // Inner level 5, equal: rings at d = 1/5 (3 segments per edge) and
    // d = 2/5 (1 segment: the innermost triangle).
    let tri = triangle_domain(5.0, [5.0; 3], Spacing::Equal);
    let plane: Vec<DVec2> = tri.points.iter().map(|&b| embed(b)).collect();
    let (a, b, c) = (
        embed([0.0, 0.0, 1.0]),
        embed([1.0, 0.0, 0.0]),
        embed([0.0, 1.0, 0.0]),
    );
    for d in [0.2, 0.4] {
        for (corner, p, q) in [(a, b, c), (b, c, a), (c, a, b)] {
            let expected = ring_corner(corner, p, q, d);
            assert!(
                plane.iter().any(|x| x.distance(expected) < 1e-12),
                "no ring corner at {expected} (d = {d})"
            );
        }
    }
    // 15 outer points, 3·3 on ring 1, 3 on ring 2: 27 points; by Euler's
    // formula for a triangulated disc, T = 2V − B − 2 = 54 − 15 − 2 = 37.
    assert_eq!((tri.points.len(), tri.triangles.len()), (27, 37));
}

#[testkit::test]
fn inner_level_three_makes_corners_at_five_ninths() {
    // Barycentric corner of the single inner triangle: (1 − 4d/3, 2d/3, 2d/3), d = 1/3.
    let tri = triangle_domain(3.0, [1.0; 3], Spacing::Equal);
    for k in 0..3 {
        let mut expected = [2.0 / 9.0; 3];
        expected[k] = 5.0 / 9.0;
        assert!(
            tri.points
                .iter()
                .any(|p| p.iter().zip(&expected).all(|(a, b)| (a - b).abs() < EXACT)),
            "missing {expected:?}"
        );
    }
}

#[testkit::test]
fn fractional_odd_inner_level_one_puts_inner_corners_on_the_edges() {
    // Inner 1 with an outer level above 1 counts as 1 + ε: 3 segments
    // whose two short ones have length ε/2 — the inner corners lie on the
    // outer corners, as the specification warns.
    let tri = triangle_domain(1.0, [2.0, 1.0, 1.0], Spacing::FractionalOdd);
    let inner_corners = tri
        .points
        .iter()
        .filter(|p| p.iter().filter(|&&x| x < 1e-9).count() == 2)
        .count();
    assert_eq!(
        inner_corners, 6,
        "3 outer and 3 inner corners at the triangle's corners: {:?}",
        tri.points
    );
}

/// Triangles of a triangle domain with every level `n` and equal
/// spacing, from the structure of §11.2.2.1: `⌊n/2⌋` rings, the ring whose
/// outer side has `m` segments holding `3·(m + m − 2)` triangles, and for
/// odd `n` one triangle in the middle. That is `6k²` for `n = 2k` and
/// `6k(k + 1) + 1` for `n = 2k + 1`.
fn triangles_at_level(n: u32) -> usize {
    let k = (n / 2) as usize;
    if n.is_multiple_of(2) {
        6 * k * k
    } else {
        6 * k * (k + 1) + 1
    }
}

/// Seed 001 §4.2 tessellates a cube (12 triangles) and a monkey head (968)
/// with every level equal and reports the totals: 444, 1800 and 46812
/// triangles for the cube at levels 5, 9 and 50; 968 and 35816 for the
/// monkey at levels 1 and 5. Levels 1 and 5 follow from equal spacing
/// (1 and 37 triangles per triangle); 1800 = 12 · 150 and 46812 = 12 · 3901
/// do not (equal spacing gives 1452 and 45000): they are the counts of
/// fractional-even spacing at 9 (rounded up to 10) and fractional-odd at
/// 50 (rounded up to 51).
#[testkit::test]
fn the_seeds_object_counts_follow_from_the_triangles_per_level() {
    let count = |level: f64, spacing| triangle_domain(level, [level; 3], spacing).triangles.len();
    for n in 1..=64 {
        assert_eq!(
            count(f64::from(n), Spacing::Equal),
            triangles_at_level(n),
            "a triangle domain with every level {n}, equal spacing"
        );
    }
    assert_eq!(12 * count(5.0, Spacing::Equal), 444, "the cube at level 5");
    assert_eq!(
        968 * count(1.0, Spacing::Equal),
        968,
        "the monkey at level 1"
    );
    assert_eq!(
        968 * count(5.0, Spacing::Equal),
        35816,
        "the monkey at level 5"
    );
    assert_eq!(
        12 * count(9.0, Spacing::Equal),
        1452,
        "the cube at level 9, equal spacing"
    );
    assert_eq!(
        12 * count(9.0, Spacing::FractionalEven),
        1800,
        "the seed's cube at level 9: fractional-even spacing rounds 9 up to 10"
    );
    assert_eq!(
        12 * count(50.0, Spacing::Equal),
        45000,
        "the cube at level 50, equal spacing"
    );
    assert_eq!(
        12 * count(50.0, Spacing::FractionalOdd),
        46812,
        "the seed's cube at level 50: fractional-odd spacing rounds 50 up to 51"
    );
}

/// Checks that a domain tiles its shape: every triangle counter-clockwise
/// (zero area allowed only where the specification puts vertices on top
/// of each other), areas summing to `area`, every edge shared by two
/// triangles in opposite directions or on the boundary once, and
/// `boundary` boundary edges, and (if `distinct`) no point twice. Panics
/// with the first problem.
fn assert_tiles(
    points: &[DVec2],
    triangles: &[[u32; 3]],
    area: f64,
    boundary: usize,
    distinct: bool,
    on_boundary: impl Fn(DVec2) -> bool,
) {
    let mut total = 0.0;
    for &[a, b, c] in triangles {
        let (pa, pb, pc) = (points[a as usize], points[b as usize], points[c as usize]);
        let signed = (pb - pa).perp_dot(pc - pa) / 2.0;
        assert!(signed > -1e-15, "triangle {:?} is clockwise", [a, b, c]);
        total += signed;
    }
    assert!(
        (total - area).abs() < 1e-9,
        "areas sum to {total}, not {area}"
    );
    let edges = directed_edges(triangles);
    let mut outer = 0;
    for (&(a, b), &n) in &edges {
        assert_eq!(n, 1, "edge {a}→{b} twice in one direction");
        if !edges.contains_key(&(b, a)) {
            let (pa, pb) = (points[a as usize], points[b as usize]);
            assert!(
                on_boundary(pa) && on_boundary(pb) && on_boundary((pa + pb) / 2.0),
                "open edge {pa}–{pb} inside"
            );
            outer += 1;
        }
    }
    assert_eq!(outer, boundary, "boundary edges");
    if !distinct {
        return;
    }
    let mut seen: HashMap<(i64, i64), usize> = HashMap::new();
    for p in points {
        *seen
            .entry(((p.x * 1e12).round() as i64, (p.y * 1e12).round() as i64))
            .or_default() += 1;
    }
    assert!(
        seen.values().all(|&n| n == 1),
        "a domain point occurs twice"
    );
}

fn level() -> impl Strategy<Value = f64> {
    prop_oneof![1 => Just(1.0), 1 => (1u32..=12).prop_map(f64::from), 3 => 0.5f64..16.0, 1 => 60.0f64..70.0]
}

fn spacing() -> impl Strategy<Value = Spacing> {
    prop_oneof![
        Just(Spacing::Equal),
        Just(Spacing::FractionalEven),
        Just(Spacing::FractionalOdd)
    ]
}

proptest! {
    #![proptest_config(testkit::strategies::proptest_config())]

    #[testkit::test]
    fn edge_subdivision_is_monotone_and_symmetric(level in level(), spacing in spacing()) {
        let d = subdivide_edge(level, spacing);
        let (f, n) = clamp_level(level, spacing);
        prop_assert_eq!(d.len(), n + 1);
        prop_assert!(d[0] == 0.0 && d[n] == 1.0);
        for i in 0..=n {
            prop_assert!((d[i] + d[n - i] - 1.0).abs() < EXACT, "symmetric");
            if i < n { prop_assert!(d[i + 1] >= d[i]); }
        }
        if spacing != Spacing::Equal && n >= 2 {
            // n − 2 segments of 1/f and two equal shorter ones.
            let mut lengths: Vec<f64> = d.windows(2).map(|w| w[1] - w[0]).collect();
            lengths.sort_by(f64::total_cmp);
            prop_assert!((lengths[0] - lengths[1]).abs() < EXACT);
            prop_assert!(lengths[0] <= 1.0 / f + EXACT);
            for l in &lengths[2..] { prop_assert!((l - 1.0 / f).abs() < EXACT); }
        }
    }

    #[testkit::test]
    fn quad_domain_tiles_the_unit_square(inner in [level(), level()], outer in [level(), level(), level(), level()], spacing in spacing()) {
        let quad = quad_domain(inner, outer, spacing);
        let counts = outer.map(|l| clamp_level(l, spacing).1);
        let on_boundary = |p: DVec2| p.x.abs() < EXACT || p.y.abs() < EXACT || (p.x - 1.0).abs() < EXACT || (p.y - 1.0).abs() < EXACT;
        // Fractional odd spacing at an inner level of 1 + ε puts inner
        // points within ε of the edges (the specification says so).
        let stacked = spacing == Spacing::FractionalOdd && inner.iter().any(|&l| clamp_level(l, spacing).1 == 1);
        assert_tiles(&quad.points, &quad.triangles, 1.0, counts.iter().sum(), !stacked, on_boundary);
        // Euler for a triangulated disc: T = 2V − B − 2.
        prop_assert_eq!(quad.triangles.len(), 2 * quad.points.len() - counts.iter().sum::<usize>() - 2);
        // The u = 0 edge carries outer[0]'s subdivision (v values), and so on.
        let edge = |select: &dyn Fn(DVec2) -> Option<f64>| {
            let mut ts: Vec<f64> = quad.points.iter().filter_map(|&p| select(p)).collect();
            ts.sort_by(f64::total_cmp);
            ts
        };
        let near = |x: f64, y: f64| (x - y).abs() < EXACT;
        if stacked {
            return Ok(());
        }
        // The inner grid: (u_i, v_j) from the subdivisions of inner[0] and
        // inner[1] (a level of 1 counting as 1 + ε, i.e. 2 segments).
        let all_one = inner.iter().chain(&outer).all(|&l| clamp_level(l, spacing).1 == 1);
        if !all_one {
            let raised = |l: f64| subdivide_edge(if clamp_level(l, spacing).1 == 1 { 2.0 } else { l }, spacing);
            let (us, vs) = (raised(inner[0]), raised(inner[1]));
            let inside: Vec<DVec2> = quad.points.iter().copied().filter(|&p| !on_boundary(p)).collect();
            prop_assert_eq!(inside.len(), (us.len() - 2) * (vs.len() - 2));
            for &v in &vs[1..vs.len() - 1] {
                for &u in &us[1..us.len() - 1] {
                    let p = DVec2::new(u, v);
                    prop_assert!(inside.iter().any(|q| q.distance(p) < EXACT), "no inner point at {}", p);
                }
            }
        }
        assert_close(&edge(&|p| near(p.x, 0.0).then_some(p.y)), &subdivide_edge(outer[0], spacing), "u = 0");
        assert_close(&edge(&|p| near(p.y, 0.0).then_some(p.x)), &subdivide_edge(outer[1], spacing), "v = 0");
        assert_close(&edge(&|p| near(p.x, 1.0).then_some(p.y)), &subdivide_edge(outer[2], spacing), "u = 1");
        assert_close(&edge(&|p| near(p.y, 1.0).then_some(p.x)), &subdivide_edge(outer[3], spacing), "v = 1");
    }

    #[testkit::test]
    fn triangle_domain_tiles_the_triangle(inner in level(), outer in [level(), level(), level()], spacing in spacing()) {
        let tri = triangle_domain(inner, outer, spacing);
        for p in &tri.points {
            prop_assert!((p[0] + p[1] + p[2] - 1.0).abs() < EXACT && p.iter().all(|&x| x > -EXACT), "{:?}", p);
        }
        let counts = outer.map(|l| clamp_level(l, spacing).1);
        let plane: Vec<DVec2> = tri.points.iter().map(|&b| embed(b)).collect();
        // A point is on the boundary when one barycentric coordinate is 0.
        let on_boundary = |p: DVec2| {
            let v = p.y / (0.5 * 3.0f64.sqrt());
            let u = p.x - 0.5 * v;
            u.abs() < 1e-9 || v.abs() < 1e-9 || (1.0 - u - v).abs() < 1e-9
        };
        // Fractional odd at 1 + ε stacks points within ε of each other.
        let stacked = spacing == Spacing::FractionalOdd && clamp_level(inner, spacing).1 == 1;
        assert_tiles(&plane, &tri.triangles, 3.0f64.sqrt() / 4.0, counts.iter().sum(), !stacked, on_boundary);
        prop_assert_eq!(tri.triangles.len(), 2 * tri.points.len() - counts.iter().sum::<usize>() - 2);
        // The edges carry the outer levels' subdivisions: u = 0 (outer[0]) from w = 1 to v = 1, …
        let edge = |k: usize, t: usize| {
            let mut ts: Vec<f64> = tri.points.iter().filter(|p| p[k].abs() < 1e-15).map(|p| p[t]).collect();
            ts.sort_by(f64::total_cmp);
            ts.dedup_by(|a, b| (*a - *b).abs() < 1e-15);
            ts
        };
        if !stacked {
            assert_close(&edge(0, 1), &subdivide_edge(outer[0], spacing), "u = 0");
            assert_close(&edge(1, 0), &subdivide_edge(outer[1], spacing), "v = 0");
            assert_close(&edge(2, 1), &subdivide_edge(outer[2], spacing), "w = 0");
        }
        // The perpendicular construction for every spacing: ring k's side
        // parallel to v = 0 lies at height d_k/√3 in the plane and carries
        // the points straight above d_k … d_(n−k) of the inner
        // subdivision (an inner level of 1 counting as 1 + ε, 2 segments).
        let all_one = clamp_level(inner, spacing).1 == 1 && counts.iter().all(|&c| c == 1);
        if !stacked && !all_one {
            let d = subdivide_edge(if clamp_level(inner, spacing).1 == 1 { 2.0 } else { inner }, spacing);
            let n = d.len() - 1;
            for k in 1..=n / 2 {
                for &x in &d[k..=n - k] {
                    let expected = DVec2::new(x, d[k] / 3.0f64.sqrt());
                    prop_assert!(plane.iter().any(|p| p.distance(expected) < 1e-9), "no point of ring {} at {}", k, expected);
                }
            }
        }
        // ⌊n/2⌋ concentric triangles: count the distinct distances of the
        // inner ring corners from the centroid (equal spacing only).
        if spacing == Spacing::Equal && !(clamp_level(inner, spacing).1 == 1 && counts.iter().all(|&c| c == 1)) {
            let n = clamp_level(inner, spacing).1.max(2);
            let mut rings: Vec<i64> = tri.points.iter()
                .filter(|p| p.iter().filter(|&&x| (x - p[1]).abs() < 1e-12).count() >= 2 && p[0] > p[1] + 1e-12)
                .map(|p| ((p[0] - 1.0 / 3.0) * 1e9).round() as i64)
                .collect();
            rings.sort_unstable();
            rings.dedup();
            // The corners towards (1, 0, 0) of every ring, the outer one included.
            prop_assert_eq!(rings.len(), 1 + (n - 1) / 2);
        }
    }
}
