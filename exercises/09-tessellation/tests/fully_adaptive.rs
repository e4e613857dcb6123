//! Task 3: fully adaptive refinement with the seven edge tests.

mod common;

use common::{
    POSITION_TOLERANCE, SEED_VIEW, TORUS_MAJOR, TORUS_MINOR, assert_picture,
    assert_tiles_rectangle, bernstein_surface, max_deviation, patch_from, sample_grid,
    torus_distance_and_normal, unit_plane,
};
use tessellation::bezier::{BezierPatch, Evaluate, RationalPatch, SurfaceSample};
use tessellation::edge_tests::{
    EdgeContext, EdgeTest, first_order_neighbour, local_flat, one_edge_complementary,
    one_edge_normal, two_triangle, umbrella_flat, vector_deviation_flat,
};
use tessellation::error::TessError;
use tessellation::fully_adaptive::{MAX_DEPTH, refine};
use tessellation::mesh::Mesh;
use tessellation::render::Style;
use tessellation::{DVec2, DVec3};

/// The seed's initial mesh: 25 × 25 samples, 1152 triangles.
const SEED_SAMPLES: usize = 25;
/// How deep the tests refine.
const DEPTH: u32 = 3;

/// Every test with the thresholds of the table in the task sheet.
fn tests() -> [(&'static str, EdgeTest); 7] {
    [
        ("one-edge normal", EdgeTest::OneEdgeNormal { t1: 0.2 }),
        (
            "one-edge complementary",
            EdgeTest::OneEdgeComplementary { t1: 0.2, t2: 0.3 },
        ),
        ("two-triangle", EdgeTest::TwoTriangle { t3: 0.1 }),
        (
            "first-order neighbour",
            EdgeTest::FirstOrderNeighbour { t3: 0.1 },
        ),
        (
            "vector-deviation flat",
            EdgeTest::VectorDeviationFlat { t1: 0.003 },
        ),
        ("local flat", EdgeTest::LocalFlat { t1: 0.1 }),
        ("umbrella flat", EdgeTest::UmbrellaFlat { t1: 0.95 }),
    ]
}

fn at(position: DVec3, normal: DVec3) -> SurfaceSample {
    SurfaceSample {
        uv: DVec2::ZERO,
        position,
        normal: normal.normalize(),
    }
}

fn edge<'a>(v1: SurfaceSample, v2: SurfaceSample, mid: SurfaceSample) -> EdgeContext<'a> {
    EdgeContext {
        v1,
        v2,
        mid,
        opposite: &[],
        ring: &[],
        neighbours1: &[],
        neighbours2: &[],
    }
}

// ---------------------------------------------------------------------------
// The edge tests, on hand-made edges with known answers.

#[testkit::test]
fn one_edge_normal_compares_both_ends_with_the_midpoint() {
    // |N1 − N12| = |(0, 0, 1) − (0, 0.6, 0.8)| = sqrt(0.36 + 0.04) = 0.632…
    let n12 = DVec3::new(0.0, 0.6, 0.8);
    let e = edge(
        at(DVec3::ZERO, DVec3::Z),
        at(DVec3::X, n12),
        at(DVec3::X / 2.0, n12),
    );
    assert!(one_edge_normal(&e, 0.63));
    assert!(!one_edge_normal(&e, 0.64));
    let swapped = edge(e.v2, e.v1, e.mid);
    assert!(
        one_edge_normal(&swapped, 0.63) && !one_edge_normal(&swapped, 0.64),
        "either end counts"
    );
}

#[testkit::test]
fn complementary_test_also_compares_the_end_normals() {
    // N1, N2 at ±0.5 rad from N12 = z: |N1 − N12| = 2 sin 0.25 = 0.4948,
    // |N1 − N2| = 2 sin 0.5 = 0.9589.
    let (s, c) = (0.5f64.sin(), 0.5f64.cos());
    let e = edge(
        at(DVec3::ZERO, DVec3::new(s, 0.0, c)),
        at(DVec3::X, DVec3::new(-s, 0.0, c)),
        at(DVec3::X / 2.0, DVec3::Z),
    );
    assert!(
        !one_edge_normal(&e, 0.5),
        "the midpoint is close to both ends"
    );
    assert!(
        one_edge_complementary(&e, 0.5, 0.95),
        "but the ends differ by 0.9589"
    );
    assert!(!one_edge_complementary(&e, 0.5, 0.96));
    assert!(one_edge_complementary(&e, 0.49, 10.0), "t1 still applies");
}

#[testkit::test]
fn two_triangle_test_averages_without_normalising() {
    // N1 = N2 = N12 = z, opposite normals ±x: N' = (0, 0, 2)/4, |N12 − N'| = 0.5.
    let z = |p: DVec3| at(p, DVec3::Z);
    let opposite = [at(DVec3::Y, DVec3::X), at(-DVec3::Y, -DVec3::X)];
    let mut e = edge(z(DVec3::ZERO), z(DVec3::X), z(DVec3::X / 2.0));
    e.opposite = &opposite;
    assert!(two_triangle(&e, 0.49) && !two_triangle(&e, 0.51));
    // On the boundary: N' = (1, 0, 2)/3, |N12 − N'| = sqrt(2)/3 = 0.4714.
    e.opposite = &opposite[..1];
    assert!(two_triangle(&e, 0.47) && !two_triangle(&e, 0.48));
}

#[testkit::test]
fn first_order_test_averages_the_ring() {
    // Ring normals z, z, y, −y: N'' = (0, 0, 0.5), |N12 − N''| = 0.5.
    let ring = [
        at(DVec3::ZERO, DVec3::Z),
        at(DVec3::X, DVec3::Z),
        at(DVec3::Y, DVec3::Y),
        at(-DVec3::Y, -DVec3::Y),
    ];
    let mut e = edge(ring[0], ring[1], at(DVec3::X / 2.0, DVec3::Z));
    e.ring = &ring;
    assert!(first_order_neighbour(&e, 0.49) && !first_order_neighbour(&e, 0.51));
    e.ring = &ring[..2];
    assert!(!first_order_neighbour(&e, 1e-9), "a flat ring never splits");
}

#[testkit::test]
fn vector_deviation_measures_the_angle_of_the_sub_chords() {
    //        V12 (1, 1)
    //       ╱    ╲          45° against the chord: 1 − cos 45° = 0.2929
    //   V1 ──────── V2
    let n = DVec3::Z;
    let bent = edge(
        at(DVec3::ZERO, n),
        at(2.0 * DVec3::X, n),
        at(DVec3::new(1.0, 1.0, 0.0), n),
    );
    assert!(vector_deviation_flat(&bent, 0.29) && !vector_deviation_flat(&bent, 0.30));
    let straight = edge(bent.v1, bent.v2, at(DVec3::new(1.5, 0.0, 0.0), n));
    assert!(
        !vector_deviation_flat(&straight, 1e-12),
        "a midpoint on the chord never splits"
    );
    //     V12 (0.5, 0.5)     lopsided: V1→V12 turns by 45°, V12→V2 only
    //    ╱   ╲               by 18.4° (1 − cos = 0.0513): whichever end
    //   V1 ──────── V2       comes first, the 45° sub-chord splits
    let lopsided = edge(bent.v1, bent.v2, at(DVec3::new(0.5, 0.5, 0.0), n));
    let reversed = edge(bent.v2, bent.v1, lopsided.mid);
    for e in [&lopsided, &reversed] {
        assert!(vector_deviation_flat(e, 0.29) && !vector_deviation_flat(e, 0.30));
    }
    let collapsed = edge(bent.v1, bent.v1, bent.v1);
    assert!(
        !vector_deviation_flat(&collapsed, 1e-12),
        "a zero-length edge never splits"
    );
}

#[testkit::test]
fn local_flat_test_compares_the_edge_with_the_normals() {
    // U = ±x (the edge is 2 long, U is a unit vector); |U · N1| = 0.6
    // with N1 = (0.6, 0, 0.8), and 0 with N2 = z.
    let e = edge(
        at(DVec3::ZERO, DVec3::new(0.6, 0.0, 0.8)),
        at(2.0 * DVec3::X, DVec3::Z),
        at(DVec3::X, DVec3::Z),
    );
    assert!(local_flat(&e, 0.59) && !local_flat(&e, 0.61));
    let swapped = edge(e.v2, e.v1, e.mid);
    assert!(
        local_flat(&swapped, 0.59) && !local_flat(&swapped, 0.61),
        "either end counts"
    );
    let flat = edge(at(DVec3::ZERO, DVec3::Z), at(DVec3::X, DVec3::Z), e.mid);
    assert!(!local_flat(&flat, 1e-12));
}

#[testkit::test]
fn umbrella_test_compares_the_unit_umbrella_with_the_normal() {
    // V1 at the origin with N1 = z; neighbours (±1, 0, 1): the umbrella is
    // (0, 0, 1), along the normal: |Û · N1| = 1.
    let v1 = at(DVec3::ZERO, DVec3::Z);
    let bowl = [
        at(DVec3::new(1.0, 0.0, 1.0), DVec3::Z),
        at(DVec3::new(-1.0, 0.0, 1.0), DVec3::Z),
    ];
    let mut e = edge(v1, bowl[0], at(DVec3::new(0.5, 0.0, 0.25), DVec3::Z));
    e.neighbours1 = &bowl;
    assert!(umbrella_flat(&e, 0.99));
    // In the plane: neighbours (1, 0, 0), (−1, 0, 0), (0, 1, 0) give an
    // umbrella (0, 1/3, 0), perpendicular to z.
    // V2 = (1, 0, 0) with neighbours (0, 0, 0), (2, 0, 0), (1, 1, 0) likewise.
    let plane = [
        at(DVec3::X, DVec3::Z),
        at(-DVec3::X, DVec3::Z),
        at(DVec3::Y, DVec3::Z),
    ];
    let plane2 = [
        at(DVec3::ZERO, DVec3::Z),
        at(2.0 * DVec3::X, DVec3::Z),
        at(DVec3::new(1.0, 1.0, 0.0), DVec3::Z),
    ];
    let mut e = edge(v1, at(DVec3::X, DVec3::Z), at(DVec3::X / 2.0, DVec3::Z));
    e.neighbours1 = &plane;
    e.neighbours2 = &plane2;
    assert!(!umbrella_flat(&e, 1e-12));
    e.neighbours2 = &bowl;
    assert!(
        umbrella_flat(&e, 0.7) && !umbrella_flat(&e, 0.71),
        "V2's umbrella (−1, 0, 1)/√2 counts: 0.707"
    );
    e.neighbours1 = &[];
    e.neighbours2 = &[];
    assert!(!umbrella_flat(&e, 1e-12), "no neighbours, no umbrella");
}

#[testkit::test]
fn every_test_splits_a_bent_edge_and_keeps_a_flat_one() {
    //   N1 ↖   N12 ↑   ↗ N2       bent: normals turn by ±37°, the midpoint
    //   V1 ────────── V2           sags 0.5 below the chord
    //         V12
    let (n1, n2) = (DVec3::new(-0.6, 0.0, 0.8), DVec3::new(0.6, 0.0, 0.8));
    let (v1, v2) = (at(DVec3::ZERO, n1), at(2.0 * DVec3::X, n2));
    let tangent = DVec3::new(0.8, 0.0, 0.6);
    let around1 = [at(n1 + tangent, n1), at(n1 - tangent, n1)];
    let ring = [v1, v2];
    let mut bent = edge(v1, v2, at(DVec3::new(1.0, 0.0, -0.5), DVec3::Z));
    bent.ring = &ring;
    bent.neighbours1 = &around1;
    let flat_points = [
        at(DVec3::ZERO, DVec3::Z),
        at(2.0 * DVec3::X, DVec3::Z),
        at(DVec3::Y, DVec3::Z),
        at(-DVec3::Y, DVec3::Z),
    ];
    let mut flat = edge(flat_points[0], flat_points[1], at(DVec3::X, DVec3::Z));
    flat.ring = &flat_points;
    flat.opposite = &flat_points[2..];
    flat.neighbours1 = &flat_points[1..];
    for (name, test) in tests() {
        assert!(test.must_split(&bent), "{name} keeps the bent edge");
        assert!(!test.must_split(&flat), "{name} splits the flat edge");
    }
}

// ---------------------------------------------------------------------------
// Refinement.

/// A half cylinder along v: the parabola (0, 0, 0), (1, 0, 1), (2, 0, 0)
/// in u, swept 1 along y. Normals change with u only.
fn trough() -> BezierPatch {
    patch_from(2, 1, |i, j| {
        DVec3::new(i as f64, j as f64, [0.0, 1.0, 0.0][i])
    })
}

#[testkit::test]
fn one_generation_on_a_trough_follows_the_patterns() {
    // One cell, two triangles; the one-edge test splits every edge along
    // which u changes (bottom, top, diagonal), never the sides u = 0, 1:
    //
    //   (0,1) ── m ── (1,1)        each triangle has two split edges:
    //     │  ╲        │            3 children each, 6 triangles, and
    //     │     m     │            3 new vertices (one per split edge)
    //     │        ╲  │
    //   (0,0) ── m ── (1,0)
    let patch = trough();
    let initial = sample_grid(&patch, 2);
    let mesh = refine(&patch, &initial, EdgeTest::OneEdgeNormal { t1: 0.1 }, 1).unwrap();
    assert_eq!((mesh.vertex_count(), mesh.triangle_count()), (7, 6));
    assert_eq!(
        &mesh.positions[..4],
        &initial.positions[..],
        "initial vertices first, in order"
    );
    let mut new_uvs: Vec<(f64, f64)> = mesh.uvs[4..].iter().map(|uv| (uv.x, uv.y)).collect();
    new_uvs.sort_by(|a, b| a.partial_cmp(b).unwrap());
    assert_eq!(new_uvs, [(0.5, 0.0), (0.5, 0.5), (0.5, 1.0)]);
    assert_tiles_rectangle(&mesh, 1.0, 1.0, "trough");
}

#[testkit::test]
fn depth_zero_and_flat_patches_keep_the_initial_mesh() {
    let patch = BezierPatch::seed_surface();
    let initial = sample_grid(&patch, 9);
    for (name, test) in tests() {
        assert_eq!(
            refine(&patch, &initial, test, 0).unwrap(),
            initial,
            "{name} at depth 0"
        );
    }
    let plane = unit_plane();
    let flat = sample_grid(&plane, 5);
    for (name, test) in tests() {
        assert_eq!(
            refine(&plane, &flat, test, MAX_DEPTH).unwrap(),
            flat,
            "{name} on a plane"
        );
    }
}

#[testkit::test]
fn refinement_is_watertight_on_the_surface_and_never_worse() {
    let patch = BezierPatch::seed_surface();
    let initial = sample_grid(&patch, 13);
    let surface = |uv: DVec2| bernstein_surface(&patch, uv);
    let before = max_deviation(&initial, surface);
    for (name, test) in tests() {
        let mesh = refine(&patch, &initial, test, DEPTH).unwrap();
        assert!(
            mesh.triangle_count() > initial.triangle_count(),
            "{name} refines the seed's surface"
        );
        assert_tiles_rectangle(&mesh, 1.0, 1.0, name);
        for (uv, p) in mesh.uvs.iter().zip(&mesh.positions) {
            assert!(
                p.distance(surface(*uv)) < POSITION_TOLERANCE,
                "{name}: vertex at {uv} is off the surface"
            );
        }
        let after = max_deviation(&mesh, surface);
        assert!(
            after <= before,
            "{name}: the largest deviation grew from {before} to {after}"
        );
    }
}

#[testkit::test]
fn table_of_triangle_counts() {
    // The seed's table (p. 22–27) for its surface from 1152 triangles,
    // with the course's thresholds and, for the two tests whose listing
    // gives them, the seed's own (0.02; 0.02 and 0.01); the sheet shows it.
    let patch = BezierPatch::seed_surface();
    let initial = sample_grid(&patch, SEED_SAMPLES);
    assert_eq!(initial.triangle_count(), 1152);
    let mut table = String::from("test | thresholds | triangles\n");
    table.push_str(&format!(
        "initial mesh | 25 × 25 samples | {}\n",
        initial.triangle_count()
    ));
    let seeds = [
        (
            "one-edge normal, the seed's t1",
            EdgeTest::OneEdgeNormal { t1: 0.02 },
        ),
        (
            "one-edge complementary, the seed's t1, t2",
            EdgeTest::OneEdgeComplementary { t1: 0.02, t2: 0.01 },
        ),
    ];
    let mut counts = Vec::new();
    for (name, test) in tests().into_iter().chain(seeds) {
        let mesh = refine(&patch, &initial, test, DEPTH).unwrap();
        table.push_str(&format!(
            "{name} | {:?} | {}\n",
            test.thresholds(),
            mesh.triangle_count()
        ));
        counts.push(mesh.triangle_count());
    }
    // Refinement only splits: no test ends with fewer triangles.
    for (count, (name, _)) in counts.iter().zip(tests().into_iter().chain(seeds)) {
        assert!(*count >= 1152, "{name}: {count} triangles from 1152");
    }
    // The seed's observation: the complementary test adds a condition to
    // the one-edge test, so it splits at least as much, with the course's
    // thresholds and with the seed's.
    assert!(
        counts[1] >= counts[0] && counts[8] >= counts[7],
        "the complementary test splits less than the one-edge test:\n{table}"
    );
    // Smaller thresholds split more.
    assert!(counts[7] > counts[0], "{table}");
    // Why the seed's thresholds split so much here: how far the unit
    // normal turns across half an edge of the initial mesh, the quantity
    // the one-edge test compares with t1.
    let mut turns: Vec<f64> = Vec::new();
    for t in &initial.triangles {
        for k in 0..3 {
            let (a, b) = (t[k] as usize, t[(k + 1) % 3] as usize);
            let middle = patch.sample((initial.uvs[a] + initial.uvs[b]) / 2.0).normal;
            let turn = (initial.normals[a] - middle)
                .length()
                .max((initial.normals[b] - middle).length());
            if turn.is_finite() {
                turns.push(turn);
            }
        }
    }
    turns.sort_by(f64::total_cmp);
    let above =
        |t: f64| 100.0 * turns.iter().filter(|&&x| x > t).count() as f64 / turns.len() as f64;
    table.push_str(&format!(
        "normal turn across half an edge: median {:.3}; above 0.02: {:.0} %; above 0.2: {:.0} %\n",
        turns[turns.len() / 2],
        above(0.02),
        above(0.2)
    ));
    insta::assert_snapshot!(table);
}

/// A NURBS surface refined adaptively: one of the rational patches of the
/// torus (`RationalPatch::torus`), every vertex new or old on the torus.
#[testkit::test]
fn a_rational_patch_is_refined_onto_its_surface() {
    let patch = &RationalPatch::torus(TORUS_MAJOR, TORUS_MINOR)[5];
    let initial = sample_grid(patch, 5);
    let mesh = refine(patch, &initial, EdgeTest::OneEdgeNormal { t1: 0.1 }, 3).unwrap();
    assert!(
        mesh.triangle_count() > 2 * initial.triangle_count(),
        "a quarter of a torus is curved everywhere: {} triangles from {}",
        mesh.triangle_count(),
        initial.triangle_count()
    );
    for (k, &p) in mesh.positions.iter().enumerate() {
        let (off, _) = torus_distance_and_normal(p);
        assert!(
            off < 1e-9,
            "vertex {k} at {p} is {off} off the torus: sample the new vertices on the patch"
        );
    }
}

#[testkit::test]
fn bad_input_is_an_error() {
    let patch = unit_plane();
    let initial = sample_grid(&patch, 3);
    let test = EdgeTest::OneEdgeNormal { t1: 0.1 };
    assert!(matches!(
        refine(&patch, &initial, test, MAX_DEPTH + 1),
        Err(TessError::Resolution(_))
    ));
    assert!(matches!(
        refine(&patch, &initial, EdgeTest::LocalFlat { t1: -1.0 }, 2),
        Err(TessError::NotPositive { .. })
    ));
    for (name, test) in tests() {
        assert_eq!(test.validate(), Ok(()), "{name}");
    }
    for bad in [0.0, -0.1, f64::NAN, f64::INFINITY] {
        assert!(EdgeTest::LocalFlat { t1: bad }.validate().is_err());
        assert!(
            EdgeTest::OneEdgeComplementary { t1: 0.1, t2: bad }
                .validate()
                .is_err()
        );
    }
    let mut broken = initial.clone();
    broken.triangles.push([0, 1, 99]);
    assert!(matches!(
        refine(&patch, &broken, test, 2),
        Err(TessError::Mesh(_))
    ));
    let mut hostile = initial.clone();
    hostile.uvs[4] = DVec2::new(f64::NAN, 0.5);
    assert!(matches!(
        refine(&patch, &hostile, test, 2),
        Err(TessError::NonFinite { .. })
    ));
    assert_eq!(
        refine(&patch, &Mesh::new(), test, 2),
        Ok(Mesh::new()),
        "nothing to refine"
    );
}

/// Seed 001's Slika 2.9: the seed's surface refined by the one-edge
/// complementary test (2.3), which splits where the one-edge test does
/// and also where the end normals differ by more than `t2`.
#[testkit::test]
fn adaptive_seed_surface_matches_the_reference_image() {
    let patch = BezierPatch::seed_surface();
    let mesh = refine(
        &patch,
        &sample_grid(&patch, 9),
        EdgeTest::OneEdgeComplementary { t1: 0.15, t2: 0.12 },
        4,
    )
    .unwrap();
    assert_picture(
        "fully_adaptive_seed",
        &mesh,
        SEED_VIEW,
        Style::ShadedWireframe,
    );
}
