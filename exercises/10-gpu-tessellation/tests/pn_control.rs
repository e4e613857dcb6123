//! Task 6: the PN triangle built in the control stage, in WGSL, compared
//! with the construction of seed 001 §4.1 computed here in f64 (the same
//! construction as topic 09's `pn_triangle`).

mod common;

use glam::{DVec3, Vec3};
use gpu::Gpu;
use gpu_tessellation::passes::{FlatTriangle, run_pn_control};
use gpu_tessellation::patch::BezierTriangle;
use gpu_tessellation::wgsl::{self, Piece};
use proptest::prelude::*;

/// Largest difference of a control point from the f64 construction (points
/// in `[-1, 1]³`: a few f32 rounding steps).
const TOLERANCE: f64 = 1e-5;

/// The names of the ten points in `BezierTriangle::points` order.
const NAMES: [&str; 10] = [
    "b300", "b210", "b201", "b120", "b111", "b102", "b030", "b021", "b012", "b003",
];

/// The sheet's construction in f64: corners, the thirds of the edges moved
/// onto the tangent planes at their nearer corner, the centre E + (E − V)/2.
fn construction(t: &FlatTriangle) -> BezierTriangle {
    let [p1, p2, p3] = t.corners.map(Vec3::as_dvec3);
    let [n1, n2, n3] = t.normals.map(|n| n.as_dvec3().normalize());
    let third = |pi: DVec3, pj: DVec3, ni: DVec3| (2.0 * pi + pj - (pj - pi).dot(ni) * ni) / 3.0;
    let (b210, b120) = (third(p1, p2, n1), third(p2, p1, n2));
    let (b021, b012) = (third(p2, p3, n2), third(p3, p2, n3));
    let (b102, b201) = (third(p3, p1, n3), third(p1, p3, n1));
    let e = (b210 + b120 + b021 + b012 + b102 + b201) / 6.0;
    let v = (p1 + p2 + p3) / 3.0;
    BezierTriangle {
        b300: p1,
        b030: p2,
        b003: p3,
        b210,
        b201,
        b120,
        b021,
        b102,
        b012,
        b111: e + (e - v) / 2.0,
    }
}

fn pn(gpu: &Gpu, piece: Piece, triangles: &[FlatTriangle]) -> Vec<BezierTriangle> {
    run_pn_control(gpu, piece, triangles).unwrap()
}

/// Each of the ten points of `yours` against the construction, named.
fn check(yours: &BezierTriangle, t: &FlatTriangle) -> Result<(), TestCaseError> {
    let expected = construction(t);
    for (k, (y, e)) in yours.points().iter().zip(expected.points()).enumerate() {
        prop_assert!(
            y.distance(e) <= TOLERANCE,
            "the PN triangle of corners {:?} and normals {:?}: {} is {y}, the construction \
             gives {e} ({})",
            t.corners,
            t.normals,
            NAMES[k],
            match NAMES[k] {
                "b300" | "b030" | "b003" => "a corner is its vertex",
                "b111" =>
                    "the centre is E + (E − V)/2, E the mean of the six edge points, V of the corners",
                _ =>
                    "an edge point is (2 Pi + Pj − ((Pj − Pi)·Ni) Ni)/3, next to Pi, with Ni normalised",
            }
        );
    }
    Ok(())
}

/// The triangle of task 3's PN test: three vertices, three normals
/// leaning out of the plane.
fn leaning() -> FlatTriangle {
    FlatTriangle {
        corners: [
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(1.0, 0.0, 0.2),
            Vec3::new(0.0, 1.0, 0.1),
        ],
        normals: [
            Vec3::new(-0.2, -0.2, 1.0),
            Vec3::new(0.3, 0.0, 1.0),
            Vec3::new(0.0, 0.3, 1.0),
        ],
    }
}

#[testkit::test]
fn a_triangle_with_leaning_normals_gets_the_ten_points_of_the_construction() {
    let piece = wgsl::PN.written();
    let Some(gpu) = common::gpu() else { return };
    let t = leaning();
    let yours = pn(&gpu, piece, &[t]);
    assert_eq!(yours.len(), 1, "one PN triangle per flat triangle");
    if let Err(TestCaseError::Fail(reason)) = check(&yours[0], &t) {
        panic!("{}", reason.message());
    }
    // Worked by hand: N1 = (−0.2, −0.2, 1)/1.0392; P2 − P1 = (1, 0, 0.2) is
    // already in the tangent plane at P1 (its dot with N1 is 0), so b210 is
    // the plain third; P3 − P1 = (0, 1, 0.1) is not (dot −0.0962), so b201 is
    // moved along N1. The same points as task 3's PN test.
    for (name, yours, expected) in [
        ("b210", yours[0].b210, DVec3::new(1.0 / 3.0, 0.0, 0.2 / 3.0)),
        (
            "b201",
            yours[0].b201,
            DVec3::new(-0.0061728, 0.3271605, 0.0641975),
        ),
        (
            "b111",
            yours[0].b111,
            DVec3::new(0.3524323, 0.3455516, 0.2223949),
        ),
    ] {
        assert!(
            yours.distance(expected) < 1e-6,
            "{name} of {t:?} is {yours}, worked by hand {expected}: an edge point is the \
             third of its edge next to its corner, moved along the corner's unit normal onto \
             its tangent plane; the centre is E + (E − V)/2"
        );
    }
}

#[testkit::test]
fn with_the_face_normal_everywhere_the_triangle_stays_flat() {
    let piece = wgsl::PN.written();
    let Some(gpu) = common::gpu() else { return };
    // Every edge already lies in every tangent plane: the edge points are
    // the plain thirds, E = V and the centre is the centroid.
    let corners = [
        Vec3::new(-0.5, -0.25, 0.5),
        Vec3::new(0.75, 0.0, 0.5),
        Vec3::new(0.0, 0.5, 0.5),
    ];
    let t = FlatTriangle {
        corners,
        normals: [Vec3::new(0.0, 0.0, 2.0); 3],
    };
    let yours = pn(&gpu, piece, &[t]);
    let [p1, p2, p3] = corners.map(Vec3::as_dvec3);
    let flat =
        BezierTriangle::from_fn(|i, j, k| (i as f64 * p1 + j as f64 * p2 + k as f64 * p3) / 3.0);
    for (k, (y, e)) in yours[0].points().iter().zip(flat.points()).enumerate() {
        assert!(
            y.distance(e) <= TOLERANCE,
            "a flat triangle whose normals are all its face normal (of length 2: normalise \
             it) stays flat: {} is {y}, the flat triangle's point is {e}",
            NAMES[k]
        );
    }
}

/// A random triangle in `[-1, 1]³` whose vertex normals lean from its face
/// normal by up to about 45°.
fn flat_triangle() -> impl Strategy<Value = FlatTriangle> {
    (
        prop::array::uniform3(common::point()),
        prop::array::uniform3(common::point()),
    )
        .prop_filter_map("a degenerate triangle", |(corners, lean)| {
            let face = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
            (face.length() > 0.05).then(|| FlatTriangle {
                corners,
                normals: lean.map(|l| face.normalize() + 0.7 * l),
            })
        })
        .prop_filter("a normal too short", |t| {
            t.normals.iter().all(|n| n.length() > 0.1)
        })
}

proptest! {
    // Each case builds a pipeline: a dozen cases of up to eight triangles.
    #![proptest_config(ProptestConfig { cases: 12, ..testkit::proptest_config() })]

    #[testkit::test]
    fn random_flat_triangles_match_the_construction(
        triangles in prop::collection::vec(flat_triangle(), 1..8),
    ) {
        let piece = wgsl::PN.written();
        let Some(gpu) = common::gpu() else { return Ok(()) };
        let yours = pn(&gpu, piece, &triangles);
        prop_assert_eq!(yours.len(), triangles.len(), "one PN triangle per flat triangle");
        for (y, t) in yours.iter().zip(&triangles) {
            check(y, t)?;
        }
    }

    #[testkit::test]
    fn each_corners_edge_points_lie_in_its_tangent_plane(
        triangles in prop::collection::vec(flat_triangle(), 1..8),
    ) {
        let piece = wgsl::PN.written();
        let Some(gpu) = common::gpu() else { return Ok(()) };
        for (yours, t) in pn(&gpu, piece, &triangles).into_iter().zip(triangles) {
            corners_and_tangent_planes(&yours, &t)?;
        }
    }
}

/// The corners of `yours` are `t`'s vertices and each edge point lies in
/// the tangent plane at its corner.
fn corners_and_tangent_planes(
    yours: &BezierTriangle,
    t: &FlatTriangle,
) -> Result<(), TestCaseError> {
    let [p1, p2, p3] = t.corners.map(Vec3::as_dvec3);
    let [n1, n2, n3] = t.normals.map(|n| n.as_dvec3().normalize());
    for (name, corner, point, normal) in [
        ("b210", p1, yours.b210, n1),
        ("b201", p1, yours.b201, n1),
        ("b120", p2, yours.b120, n2),
        ("b021", p2, yours.b021, n2),
        ("b102", p3, yours.b102, n3),
        ("b012", p3, yours.b012, n3),
    ] {
        let off = (point - corner).dot(normal);
        prop_assert!(
            off.abs() <= TOLERANCE,
            "{} = {} lies {} off the tangent plane at its corner {} (normal {}): the \
             surface's tangent plane at a vertex must be perpendicular to the vertex \
             normal, so each edge point is moved onto it",
            name,
            point,
            off,
            corner,
            normal
        );
    }
    for (name, corner, point) in [
        ("b300", p1, yours.b300),
        ("b030", p2, yours.b030),
        ("b003", p3, yours.b003),
    ] {
        prop_assert!(
            point.distance(corner) <= TOLERANCE,
            "{} is {}, the vertex {}: the PN triangle passes through its corners",
            name,
            point,
            corner
        );
    }
    Ok(())
}
