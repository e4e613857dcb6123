//! Task 1: Bernstein polynomials, rational Bézier curves and surfaces.

mod common;

use approx::assert_relative_eq;
use common::{CORNER_WEIGHT, assert_close, bezier_patch_point, point3, quarter_circle, weight};
use glam::{DMat3, DVec3, DVec4};
use nurbs::rational_bezier::{bernstein, rational_bezier_point, rational_bezier_surface_point};
use nurbs::{ControlNet, NurbsError, homogeneous};
use proptest::prelude::*;
use testkit::proptest_config;

/// Evaluations of sums of a handful of `f64` products agree to this.
const TOLERANCE: f64 = 1e-9;

fn projected(points: &[DVec4]) -> impl Iterator<Item = DVec3> + '_ {
    points.iter().map(|p| p.truncate() / p.w)
}

/// The rational Bézier curve by its definition (seed 001, (1.4)).
fn curve_by_definition(points: &[DVec4], u: f64) -> DVec3 {
    let n = points.len() - 1;
    let (mut num, mut den) = (DVec3::ZERO, 0.0);
    for (i, p) in points.iter().enumerate() {
        let b = common::bernstein(i, n, u);
        num += b * p.truncate(); // p.xyz is already w·P
        den += b * p.w;
    }
    num / den
}

#[testkit::test]
fn bernstein_has_the_known_values() {
    // B_{1,2}(½) = 2·½·½, B_{0,3}(¼) = (¾)³, B_{2,4}(½) = 6/16.
    assert_relative_eq!(bernstein(2, 1, 0.5), 0.5, max_relative = 1e-15);
    assert_relative_eq!(bernstein(3, 0, 0.25), 27.0 / 64.0, max_relative = 1e-15);
    assert_relative_eq!(bernstein(4, 2, 0.5), 6.0 / 16.0, max_relative = 1e-15);
    assert_relative_eq!(
        bernstein(5, 3, 0.3),
        10.0 * 0.027 * 0.49,
        max_relative = 1e-14
    );
    // 0⁰ = 1 at the ends; other functions vanish there.
    assert_eq!(bernstein(3, 0, 0.0), 1.0);
    assert_eq!(bernstein(3, 3, 1.0), 1.0);
    assert_eq!(bernstein(3, 1, 0.0), 0.0);
    assert_eq!(bernstein(3, 2, 1.0), 0.0);
    // i > n: no such polynomial.
    assert_eq!(bernstein(2, 3, 0.5), 0.0);
}

#[testkit::test]
fn quarter_circle_lies_exactly_on_the_unit_circle() {
    let points = quarter_circle();
    for k in 0..=1000 {
        let u = f64::from(k) / 1000.0;
        let p = rational_bezier_point(&points, u).unwrap();
        assert!(
            (p.length() - 1.0).abs() < 1e-14,
            "u = {u}: |C(u)| = {}",
            p.length()
        );
        assert_eq!(p.z, 0.0);
    }
    // The middle of the arc is the point at 45°.
    let mid = rational_bezier_point(&points, 0.5).unwrap();
    let expected = DVec3::new(CORNER_WEIGHT, CORNER_WEIGHT, 0.0);
    assert_close(expected, mid, 1e-15, "C(½)");
}

#[testkit::test]
fn the_ends_are_the_first_and_last_control_points() {
    // Seed 001 after Example 1.1.2: P_0 = C(0) and P_n = C(1) (the seed
    // writes P_1 = C(1) for the quadratic, a typo for P_2).
    let points = [
        homogeneous(DVec3::new(0.0, 0.0, 0.0), 1.0),
        homogeneous(DVec3::new(10.0, 15.0, 0.0), 3.0),
        homogeneous(DVec3::new(20.0, 0.0, 0.0), 0.5),
    ];
    assert_close(
        DVec3::ZERO,
        rational_bezier_point(&points, 0.0).unwrap(),
        0.0,
        "C(0)",
    );
    assert_close(
        DVec3::new(20.0, 0.0, 0.0),
        rational_bezier_point(&points, 1.0).unwrap(),
        1e-15,
        "C(1)",
    );
}

#[testkit::test]
fn unit_weights_give_the_polynomial_bezier_curve() {
    // Seed 001, Example 1.1.2: C(u) = (1−u)² P0 + 2u(1−u) P1 + u² P2.
    let (p0, p1, p2) = (DVec3::ZERO, DVec3::new(10.0, 15.0, 0.0), DVec3::X * 20.0);
    let points = [p0, p1, p2].map(|p| homogeneous(p, 1.0));
    for u in [0.1, 0.25, 0.5, 0.9] {
        let expected = (1.0 - u) * (1.0 - u) * p0 + 2.0 * u * (1.0 - u) * p1 + u * u * p2;
        assert_close(
            expected,
            rational_bezier_point(&points, u).unwrap(),
            1e-12,
            "quadratic",
        );
    }
}

#[testkit::test]
fn bilinear_patch_interpolates_its_corners() {
    //  P01 ── P11        degree (1, 1), unit weights: the bilinear patch
    //   │      │         S(u, v) = (1−u)(1−v) P00 + (1−u) v P01
    //  P00 ── P10                 + u (1−v) P10 + u v P11
    let corners = [
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(0.0, 2.0, 1.0),
        DVec3::new(3.0, 0.0, -1.0),
        DVec3::new(3.0, 2.0, 5.0),
    ];
    let net = ControlNet::try_new(2, 2, corners.map(|c| homogeneous(c, 1.0)).to_vec()).unwrap();
    for (u, v) in [(0.0, 0.0), (0.3, 0.8), (1.0, 0.5), (0.5, 0.5)] {
        let expected = (1.0 - u) * (1.0 - v) * corners[0]
            + (1.0 - u) * v * corners[1]
            + u * (1.0 - v) * corners[2]
            + u * v * corners[3];
        assert_close(
            expected,
            rational_bezier_surface_point(&net, u, v).unwrap(),
            1e-12,
            &format!("S({u}, {v})"),
        );
    }
}

#[testkit::test]
fn extruded_quarter_circle_is_a_quarter_cylinder() {
    // Rows along u: the quarter circle; columns along v: z = 0 and z = 2.
    let mut points = Vec::new();
    for p in quarter_circle() {
        for z in [0.0, 2.0] {
            points.push(DVec4::new(p.x, p.y, z * p.w, p.w));
        }
    }
    let net = ControlNet::try_new(3, 2, points).unwrap();
    for k in 0..=20 {
        let u = f64::from(k) / 20.0;
        let s = rational_bezier_surface_point(&net, u, 0.75).unwrap();
        assert!((s.x.hypot(s.y) - 1.0).abs() < 1e-14, "u = {u}: {s}");
        assert!((s.z - 1.5).abs() < 1e-14, "u = {u}: {s}");
    }
}

#[testkit::test]
fn invalid_input_is_an_error() {
    let good = quarter_circle();
    assert_eq!(
        rational_bezier_point(&[], 0.5),
        Err(NurbsError::NoControlPoints)
    );
    for weight in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let mut points = good;
        points[1] = DVec4::new(1.0, 1.0, 0.0, weight);
        assert!(
            matches!(
                rational_bezier_point(&points, 0.5),
                Err(NurbsError::BadWeight { index: 1, .. })
            ),
            "weight {weight}"
        );
    }
    let mut points = good;
    points[2].x = f64::NAN;
    assert_eq!(
        rational_bezier_point(&points, 0.5),
        Err(NurbsError::NonFinitePoint { index: 2 })
    );
    for u in [-0.1, 1.0 + 1e-12, f64::NAN, f64::INFINITY] {
        assert!(
            matches!(
                rational_bezier_point(&good, u),
                Err(NurbsError::OutOfDomain { .. })
            ),
            "u = {u}"
        );
    }
    let net = ControlNet::try_new(3, 1, good.to_vec()).unwrap();
    assert!(matches!(
        rational_bezier_surface_point(&net, 0.5, 1.5),
        Err(NurbsError::OutOfDomain { .. })
    ));
    assert!(matches!(
        rational_bezier_surface_point(&net, f64::NAN, 0.5),
        Err(NurbsError::OutOfDomain { .. })
    ));
}

fn weighted_points(max: usize) -> impl Strategy<Value = Vec<DVec4>> {
    prop::collection::vec(
        (point3(), weight()).prop_map(|(p, w)| homogeneous(p, w)),
        1..=max,
    )
}

proptest! {
    #![proptest_config(proptest_config())]

    #[testkit::test]
    fn bernstein_basis_is_non_negative_and_sums_to_one(n in 0usize..=20, u in 0.0f64..=1.0) {
        let values: Vec<f64> = (0..=n).map(|i| bernstein(n, i, u)).collect();
        for (i, &b) in values.iter().enumerate() {
            prop_assert!(b >= 0.0, "B_{{{i},{n}}}({u}) = {b}");
            let expected = common::bernstein(i, n, u);
            prop_assert!((b - expected).abs() <= 1e-12, "B_{{{i},{n}}}({u}) = {b}, expected {expected}");
        }
        let sum: f64 = values.iter().sum();
        prop_assert!((sum - 1.0).abs() < 1e-12, "sum {sum}");
    }

    #[testkit::test]
    fn curve_matches_the_definition(points in weighted_points(8), u in 0.0f64..=1.0) {
        let expected = curve_by_definition(&points, u);
        let actual = rational_bezier_point(&points, u).unwrap();
        prop_assert!(expected.distance(actual) <= TOLERANCE, "{expected} vs {actual}");
    }

    #[testkit::test]
    fn curve_lies_in_the_convex_hull(points in weighted_points(8), u in 0.0f64..=1.0) {
        // Tested on the bounding box, and on the distance to the hull's
        // farthest direction: every projection onto an axis of a few
        // fixed directions stays within the control points' range.
        let c = rational_bezier_point(&points, u).unwrap();
        for dir in [DVec3::X, DVec3::Y, DVec3::Z, DVec3::new(1.0, 1.0, 1.0), DVec3::new(1.0, -2.0, 0.5)] {
            let (lo, hi) = projected(&points)
                .map(|p| p.dot(dir))
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| (lo.min(x), hi.max(x)));
            let x = c.dot(dir);
            prop_assert!(x >= lo - TOLERANCE && x <= hi + TOLERANCE, "{c} leaves the hull along {dir}");
        }
    }

    #[testkit::test]
    fn curve_is_affinely_invariant(
        points in weighted_points(6),
        u in 0.0f64..=1.0,
        matrix in prop::array::uniform9(-2.0f64..2.0),
        shift in point3(),
    ) {
        // Transform the control points (keeping their weights): the curve
        // is transformed the same way.
        let a = DMat3::from_cols_array(&matrix);
        let moved: Vec<DVec4> = points
            .iter()
            .map(|p| homogeneous(a * (p.truncate() / p.w) + shift, p.w))
            .collect();
        let expected = a * rational_bezier_point(&points, u).unwrap() + shift;
        let actual = rational_bezier_point(&moved, u).unwrap();
        prop_assert!(expected.distance(actual) <= 1e-8, "{expected} vs {actual}");
    }

    #[testkit::test]
    fn scaling_all_weights_changes_nothing(points in weighted_points(6), u in 0.0f64..=1.0, c in 0.1f64..10.0) {
        let scaled: Vec<DVec4> = points.iter().map(|&p| p * c).collect();
        let a = rational_bezier_point(&points, u).unwrap();
        let b = rational_bezier_point(&scaled, u).unwrap();
        prop_assert!(a.distance(b) <= TOLERANCE, "{a} vs {b}");
        // The curve starts at its first point (homogeneous: x, y, z over w).
        let first = points[0].truncate() / points[0].w;
        let start = rational_bezier_point(&scaled, 0.0).unwrap();
        prop_assert!(start.distance(first) <= TOLERANCE, "starts at {start}, not at {first}");
    }

    #[testkit::test]
    fn surface_matches_the_definition(
        rows in 1usize..=4,
        columns in 1usize..=4,
        seed in prop::collection::vec((point3(), weight()), 16),
        u in 0.0f64..=1.0,
        v in 0.0f64..=1.0,
    ) {
        let points = seed[..rows * columns].iter().map(|&(p, w)| homogeneous(p, w)).collect();
        let net = ControlNet::try_new(rows, columns, points).unwrap();
        let expected = bezier_patch_point(&net, u, v);
        let actual = rational_bezier_surface_point(&net, u, v).unwrap();
        prop_assert!(expected.distance(actual) <= TOLERANCE, "{expected} vs {actual}");
        prop_assert!(common::in_bounding_box(actual, projected(net.points()), TOLERANCE));
    }
}
