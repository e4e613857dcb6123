//! Task 5: cubic Bézier triangles and PN triangles.

mod common;

use common::assert_picture;
use proptest::prelude::*;
use tessellation::DVec3;
use tessellation::bezier::curve;
use tessellation::bezier_triangle::{BezierTriangle, evaluate, pn_triangle, tessellate_pn};
use tessellation::error::TessError;
use tessellation::mesh::Mesh;
use tessellation::render::{Style, View};
use testkit::domains::lattice;

const EXACT: f64 = 1e-12;

/// Ten distinct, unrelated control points.
fn lumpy() -> BezierTriangle {
    let p = |x: f64, y: f64, z: f64| DVec3::new(x, y, z);
    BezierTriangle {
        b300: p(3.0, 0.0, 0.0),
        b030: p(0.0, 3.0, 0.5),
        b003: p(0.0, 0.0, -1.0),
        b210: p(2.0, 1.0, 1.0),
        b201: p(2.0, 0.0, 2.0),
        b120: p(1.0, 2.0, -1.0),
        b021: p(0.0, 2.0, 3.0),
        b102: p(1.0, 0.0, 0.5),
        b012: p(0.0, 1.0, 1.5),
        b111: p(1.0, 1.0, 4.0),
    }
}

/// The control points of the flat triangle `u P1 + v P2 + w P3`:
/// `b_ijk = (i P1 + j P2 + k P3) / 3`.
fn linear(p1: DVec3, p2: DVec3, p3: DVec3) -> BezierTriangle {
    let b = |i: f64, j: f64, k: f64| (i * p1 + j * p2 + k * p3) / 3.0;
    BezierTriangle {
        b300: b(3.0, 0.0, 0.0),
        b030: b(0.0, 3.0, 0.0),
        b003: b(0.0, 0.0, 3.0),
        b210: b(2.0, 1.0, 0.0),
        b201: b(2.0, 0.0, 1.0),
        b120: b(1.0, 2.0, 0.0),
        b021: b(0.0, 2.0, 1.0),
        b102: b(1.0, 0.0, 2.0),
        b012: b(0.0, 1.0, 2.0),
        b111: b(1.0, 1.0, 1.0),
    }
}

#[testkit::test]
fn corners_are_the_corner_control_points() {
    let t = lumpy();
    assert_eq!(evaluate(&t, [1.0, 0.0, 0.0]), t.b300);
    assert_eq!(evaluate(&t, [0.0, 1.0, 0.0]), t.b030);
    assert_eq!(evaluate(&t, [0.0, 0.0, 1.0]), t.b003);
}

#[testkit::test]
fn edges_are_cubic_bezier_curves() {
    // On w = 0: Σ b_ij0 3!/(i! j!) uⁱ vʲ, the cubic with control points
    // b030, b120, b210, b300 at parameter u; likewise the other edges.
    let t = lumpy();
    for s in [0.0, 0.2, 0.5, 0.9] {
        let w0 = curve(&[t.b030, t.b120, t.b210, t.b300], s).0;
        assert!(
            evaluate(&t, [s, 1.0 - s, 0.0]).distance(w0) < EXACT,
            "w = 0 at u = {s}"
        );
        let u0 = curve(&[t.b003, t.b012, t.b021, t.b030], s).0;
        assert!(
            evaluate(&t, [0.0, s, 1.0 - s]).distance(u0) < EXACT,
            "u = 0 at v = {s}"
        );
        let v0 = curve(&[t.b300, t.b201, t.b102, t.b003], s).0;
        assert!(
            evaluate(&t, [1.0 - s, 0.0, s]).distance(v0) < EXACT,
            "v = 0 at w = {s}"
        );
    }
}

#[testkit::test]
fn centre_weighs_b111_six_twentysevenths() {
    // At (⅓, ⅓, ⅓) every cubic term is 1/27, times 1, 3 or 6.
    let t = lumpy();
    let expected = (t.b300 + t.b030 + t.b003) / 27.0
        + (t.b210 + t.b201 + t.b120 + t.b021 + t.b102 + t.b012) * (3.0 / 27.0)
        + t.b111 * (6.0 / 27.0);
    assert!(evaluate(&t, [1.0 / 3.0; 3]).distance(expected) < EXACT);
}

#[testkit::test]
fn flat_triangle_with_face_normals_stays_flat() {
    // Normals equal to the face normal: every w_ij is 0, the edge points
    // are the thirds, E = V and b111 = V: the linear control points.
    let (p1, p2, p3) = (
        DVec3::new(0.0, 0.0, 1.0),
        DVec3::new(3.0, 0.0, 1.0),
        DVec3::new(1.0, 2.0, 1.0),
    );
    let pn = pn_triangle([p1, p2, p3], [DVec3::Z * 5.0; 3]).unwrap();
    let expected = linear(p1, p2, p3);
    for (a, b) in [
        (pn.geometry.b210, expected.b210),
        (pn.geometry.b012, expected.b012),
        (pn.geometry.b111, expected.b111),
        (pn.geometry.b102, expected.b102),
    ] {
        assert!(a.distance(b) < EXACT, "{a} vs {b}");
    }
    assert_eq!(pn.normals, [DVec3::Z; 3], "normals are normalised");
}

#[testkit::test]
fn pn_triangle_interpolates_vertices_and_normals() {
    let positions = [
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(0.0, 1.0, 0.0),
        DVec3::new(0.0, 0.0, 1.0),
    ];
    let pn = pn_triangle(positions, positions).unwrap();
    let mesh = tessellate_pn(&pn, &lattice(6));
    let domain = lattice(6);
    for (k, b) in domain.points.iter().enumerate() {
        for corner in 0..3 {
            if b[corner] == 1.0 {
                assert!(
                    mesh.positions[k].distance(positions[corner]) < EXACT,
                    "vertex {corner}"
                );
                assert!(
                    mesh.normals[k].distance(positions[corner]) < EXACT,
                    "normal {corner}"
                );
            }
        }
        let expected_normal =
            (b[0] * positions[0] + b[1] * positions[1] + b[2] * positions[2]).normalize();
        assert!(
            mesh.normals[k].distance(expected_normal) < EXACT,
            "normals are interpolated linearly"
        );
        assert_eq!(mesh.uvs[k].to_array(), [b[0], b[1]]);
    }
    assert_eq!(mesh.triangles, domain.triangles);
}

#[testkit::test]
fn pn_octant_bulges_towards_the_sphere() {
    // The octant of the unit sphere from its three axis points with their
    // normals. By hand: on the edge Y–Z, w = (Z − Y)·Y = −1, so the edge
    // points are Y + Z/3 and Z + Y/3, and the edge's midpoint is
    // (0, 5/8, 5/8), at 5√2/8 = 0.884 from the centre. The six edge points
    // average E = (4/9, 4/9, 4/9), V = (1/3, 1/3, 1/3), so b111 = (½, ½, ½)
    // and the centre is B(⅓, ⅓, ⅓) = (4/9, 4/9, 4/9), at 4√3/9 = 0.770 —
    // the flat triangle's centre is at 1/√3 = 0.577.
    let positions = [DVec3::X, DVec3::Y, DVec3::Z];
    let pn = pn_triangle(positions, positions).unwrap();
    let g = pn.geometry;
    assert!(
        g.b021.distance(DVec3::new(0.0, 1.0, 1.0 / 3.0)) < EXACT,
        "{}",
        g.b021
    );
    assert!(g.b111.distance(DVec3::splat(0.5)) < EXACT, "{}", g.b111);
    assert!(evaluate(&g, [0.0, 0.5, 0.5]).distance(DVec3::new(0.0, 0.625, 0.625)) < EXACT);
    assert!(evaluate(&g, [1.0 / 3.0; 3]).distance(DVec3::splat(4.0 / 9.0)) < EXACT);
    // Everywhere at least as far out as the flat triangle, never outside the sphere.
    let domain = lattice(12);
    let mesh = tessellate_pn(&pn, &domain);
    for (p, b) in mesh.positions.iter().zip(&domain.points) {
        let flat = b[0] * DVec3::X + b[1] * DVec3::Y + b[2] * DVec3::Z;
        assert!(
            p.length() >= flat.length() - EXACT && p.length() <= 1.0 + EXACT,
            "{p} at {b:?}"
        );
    }
}

#[testkit::test]
fn zero_or_non_finite_input_is_an_error() {
    let positions = [DVec3::X, DVec3::Y, DVec3::Z];
    let zero = [DVec3::X, DVec3::ZERO, DVec3::Z];
    assert!(matches!(
        pn_triangle(positions, zero),
        Err(TessError::NonFinite { .. })
    ));
    let nan = [DVec3::X, DVec3::new(f64::NAN, 0.0, 0.0), DVec3::Z];
    assert!(matches!(
        pn_triangle(nan, positions),
        Err(TessError::NonFinite { .. })
    ));
    assert!(matches!(
        pn_triangle(positions, nan),
        Err(TessError::NonFinite { .. })
    ));
}

#[testkit::test]
fn pn_sphere_matches_the_reference_image() {
    // The octahedron's eight faces as PN triangles with normals = positions.
    let axes = [DVec3::X, DVec3::Y, -DVec3::X, -DVec3::Y];
    let domain = lattice(8);
    let mut sphere = Mesh::new();
    for k in 0..4 {
        for pole in [DVec3::Z, -DVec3::Z] {
            let (a, b) = (axes[k], axes[(k + 1) % 4]);
            let corners = if pole.z > 0.0 {
                [a, b, pole]
            } else {
                [b, a, pole]
            };
            let part = tessellate_pn(&pn_triangle(corners, corners).unwrap(), &domain);
            let offset = sphere.vertex_count() as u32;
            sphere.positions.extend(&part.positions);
            sphere.normals.extend(&part.normals);
            sphere.uvs.extend(&part.uvs);
            sphere
                .triangles
                .extend(part.triangles.iter().map(|t| t.map(|i| i + offset)));
        }
    }
    let view = View {
        yaw: -0.4,
        pitch: -0.47,
    };
    assert_picture(
        "bezier_triangle_pn_sphere",
        &sphere,
        view,
        Style::ShadedWireframe,
    );
}

fn point() -> impl Strategy<Value = DVec3> {
    (-5.0f64..5.0, -5.0f64..5.0, -5.0f64..5.0).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn unit() -> impl Strategy<Value = DVec3> {
    point()
        .prop_filter("non-zero", |p| p.length() > 0.1)
        .prop_map(DVec3::normalize)
}

fn barycentric() -> impl Strategy<Value = [f64; 3]> {
    (0.0f64..1.0, 0.0f64..1.0).prop_map(|(a, b)| {
        let (u, v) = if a + b > 1.0 {
            (1.0 - a, 1.0 - b)
        } else {
            (a, b)
        };
        [u, v, 1.0 - u - v]
    })
}

proptest! {
    #![proptest_config(testkit::strategies::proptest_config())]

    #[testkit::test]
    fn linear_control_points_give_the_flat_triangle(p1 in point(), p2 in point(), p3 in point(), b in barycentric()) {
        let flat = b[0] * p1 + b[1] * p2 + b[2] * p3;
        prop_assert!(evaluate(&linear(p1, p2, p3), b).distance(flat) < 1e-9);
    }

    #[testkit::test]
    fn equal_control_points_give_a_constant(p in point(), b in barycentric()) {
        let t = BezierTriangle { b300: p, b030: p, b003: p, b210: p, b201: p, b120: p, b021: p, b102: p, b012: p, b111: p };
        prop_assert!(evaluate(&t, b).distance(p) < 1e-9, "the Bernstein weights sum to 1");
    }

    #[testkit::test]
    fn pn_tangent_planes_are_perpendicular_to_the_normals(p in [point(), point(), point()], n in [unit(), unit(), unit()]) {
        let g = pn_triangle(p, n).unwrap().geometry;
        // The edge control points next to a vertex span its tangent plane.
        for (corner, normal, a, b) in [(g.b300, n[0], g.b210, g.b201), (g.b030, n[1], g.b120, g.b021), (g.b003, n[2], g.b102, g.b012)] {
            prop_assert!((a - corner).dot(normal).abs() < 1e-9);
            prop_assert!((b - corner).dot(normal).abs() < 1e-9);
        }
        prop_assert_eq!((g.b300, g.b030, g.b003), (p[0], p[1], p[2]));
    }
}
