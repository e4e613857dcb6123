//! Task 3: NURBS curves and surfaces — points, derivatives, normals, grids.

mod common;

use common::{
    assert_close, circle, curve_point, nurbs_curve, nurbs_surface, point3, surface_point, torus,
    torus_distance,
};
use glam::{DMat3, DVec3, DVec4};
use nurbs::{ControlNet, KnotVector, NurbsCurve, NurbsError, NurbsSurface, homogeneous};
use proptest::prelude::*;
use testkit::image::{Tolerance, assert_image_matches};
use testkit::proptest_config;

/// Points of curves with coordinates up to 10 and weights in `[0.2, 5]`
/// agree with the definition to this.
const TOLERANCE: f64 = 1e-9;

/// Step of the central difference quotients.
const H: f64 = 1e-6;

fn projected(points: &[DVec4]) -> impl Iterator<Item = DVec3> + '_ {
    points.iter().map(|p| p.truncate() / p.w)
}

/// Whether `[u − margin, u + margin]` contains a knot.
fn near_knot(knots: &KnotVector, u: f64, margin: f64) -> bool {
    knots.knots().iter().any(|&k| (k - u).abs() <= margin)
}

#[testkit::test]
fn circle_lies_exactly_on_the_unit_circle() {
    let circle = circle();
    for k in 0..=1000 {
        let u = f64::from(k) / 1000.0;
        let p = circle.point(u).unwrap();
        assert!((p.length() - 1.0).abs() < 1e-14, "u = {u}: {p}");
    }
    // The quadrants meet at the knots: u = ¼ is (0, 1), ½ is (−1, 0).
    assert_close(DVec3::Y, circle.point(0.25).unwrap(), 1e-15, "C(¼)");
    assert_close(-DVec3::X, circle.point(0.5).unwrap(), 1e-15, "C(½)");
    assert_close(DVec3::X, circle.point(1.0).unwrap(), 1e-15, "C(1)");
}

#[testkit::test]
fn circle_tangent_is_perpendicular_to_the_radius() {
    let circle = circle();
    for k in 0..100 {
        let u = (f64::from(k) + 0.5) / 100.0;
        let d = circle.derivative(u).unwrap();
        assert!(
            d.point.dot(d.derivative).abs() < 1e-12 * d.derivative.length(),
            "u = {u}: {d:?}"
        );
        // Counter-clockwise: the tangent turns left of the radius.
        assert!(d.point.cross(d.derivative).z > 0.0, "u = {u}");
    }
    // At u = 0 the quadratic arc leaves (1, 0) towards (1, 1): C′(0) =
    // p/(u_{p+1} − u_1) · (w₁/w₀) (P₁ − P₀) = 2/¼ · √2/2 · (0, 1).
    let d = circle.derivative(0.0).unwrap();
    assert_close(
        DVec3::Y * (8.0 * common::CORNER_WEIGHT),
        d.derivative,
        1e-12,
        "C′(0)",
    );
}

#[testkit::test]
fn bezier_knots_give_the_rational_bezier_curve() {
    // Bézier = B-spline on {0, …, 0, 1, …, 1}: compare with the Bernstein form.
    let points = [
        homogeneous(DVec3::new(4.0, 7.0, 11.0), 1.0),
        homogeneous(DVec3::new(6.0, 8.0, 11.0), 2.0),
        homogeneous(DVec3::new(5.0, 5.0, 5.0), 0.5),
        homogeneous(DVec3::new(9.0, 7.0, 3.0), 1.0),
    ];
    let curve = NurbsCurve::try_new(KnotVector::bezier(3).unwrap(), points.to_vec()).unwrap();
    for k in 0..=16 {
        let u = f64::from(k) / 16.0;
        let (mut num, mut den) = (DVec3::ZERO, 0.0);
        for (i, p) in points.iter().enumerate() {
            let b = common::bernstein(i, 3, u);
            num += b * p.truncate();
            den += b * p.w;
        }
        assert_close(
            num / den,
            curve.point(u).unwrap(),
            1e-12,
            &format!("u = {u}"),
        );
    }
}

#[testkit::test]
fn torus_points_lie_on_the_torus_and_normals_point_outwards() {
    let torus = torus();
    for a in 0..=24 {
        for b in 0..=24 {
            let (u, v) = (f64::from(a) / 24.0, f64::from(b) / 24.0);
            let p = torus.point(u, v).unwrap();
            assert!(
                torus_distance(p) < 1e-13,
                "S({u}, {v}) = {p} is off the torus"
            );
            // The exact normal: from the tube's centre circle to the point.
            let ring = DVec3::new(p.x, p.y, 0.0).normalize() * common::TORUS_R;
            let outward = (p - ring).normalize();
            let n = torus.normal(u, v).unwrap();
            assert!(
                (n.length() - 1.0).abs() < 1e-12,
                "|N| = {} at ({u}, {v})",
                n.length()
            );
            assert!(
                n.dot(outward).abs() > 1.0 - 1e-10,
                "N({u}, {v}) = {n}, expected ±{outward}"
            );
        }
    }
}

#[testkit::test]
fn grid_matches_points_on_the_torus() {
    let torus = torus();
    let (nu, nv) = (7, 5);
    let grid = torus.sample_grid(nu, nv).unwrap();
    assert_eq!(grid.len(), nu * nv);
    for i in 0..nu {
        for j in 0..nv {
            let (u, v) = (i as f64 / 6.0, j as f64 / 4.0);
            assert_close(
                surface_point(&torus, u, v),
                grid[i * nv + j],
                1e-12,
                &format!("grid ({i}, {j})"),
            );
        }
    }
}

#[testkit::test]
fn invalid_input_is_an_error() {
    let circle = circle();
    for u in [-0.5, 1.0 + 1e-12, f64::NAN, f64::INFINITY] {
        assert!(
            matches!(circle.point(u), Err(NurbsError::OutOfDomain { .. })),
            "u = {u}"
        );
        assert!(
            matches!(circle.derivative(u), Err(NurbsError::OutOfDomain { .. })),
            "u = {u}"
        );
    }
    let torus = torus();
    for (u, v) in [(0.5, -0.1), (1.5, 0.5), (f64::NAN, 0.5), (0.5, f64::NAN)] {
        assert!(matches!(
            torus.point(u, v),
            Err(NurbsError::OutOfDomain { .. })
        ));
        assert!(matches!(
            torus.derivatives(u, v),
            Err(NurbsError::OutOfDomain { .. })
        ));
        assert!(matches!(
            torus.normal(u, v),
            Err(NurbsError::OutOfDomain { .. })
        ));
    }
    for (nu, nv) in [(0, 5), (1, 5), (5, 1), (usize::MAX, 2), (1 << 14, 1 << 14)] {
        assert!(
            matches!(torus.sample_grid(nu, nv), Err(NurbsError::BadGrid { .. })),
            "{nu} × {nv}"
        );
    }
}

#[testkit::test]
fn collapsed_edge_has_no_normal() {
    // A bilinear patch whose row u = 0 is a single point (a triangle):
    // S_v = 0 there, so S_u × S_v = 0.
    //
    //   apex ●────● apex        row 0 (u = 0): both corners at the apex
    //         ╲  ╱
    //   P10 ●────● P11          row 1 (u = 1)
    let apex = DVec3::new(0.0, 1.0, 0.0);
    let points = [
        apex,
        apex,
        DVec3::new(-1.0, 0.0, 0.0),
        DVec3::new(1.0, 0.0, 0.0),
    ];
    let net = ControlNet::try_new(2, 2, points.map(|p| homogeneous(p, 1.0)).to_vec()).unwrap();
    let knots = KnotVector::bezier(1).unwrap();
    let surface = NurbsSurface::try_new(knots.clone(), knots, net).unwrap();
    assert!(matches!(
        surface.normal(0.0, 0.5),
        Err(NurbsError::DegenerateNormal { .. })
    ));
    // Elsewhere the normal is ±z.
    let n = surface.normal(0.5, 0.5).unwrap();
    assert!((n.z.abs() - 1.0).abs() < 1e-12, "{n}");
}

/// The torus, shaded with its normals, as the seed's figures show surfaces.
fn shaded_torus() -> canvas::Canvas {
    let torus = torus();
    let (nu, nv) = (64, 32);
    let points = torus.sample_grid(nu, nv).unwrap();
    let mut colours = Vec::with_capacity(nu * nv);
    for i in 0..nu {
        for j in 0..nv {
            let (u, v) = (i as f64 / (nu - 1) as f64, j as f64 / (nv - 1) as f64);
            colours.push(common::shade(torus.normal(u, v).unwrap()));
        }
    }
    common::render_grid(&points, &colours, nu, nv)
}

#[testkit::test]
fn shaded_torus_matches_the_reference_image() {
    let reference = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/images/nurbs_torus.png");
    assert_image_matches(
        "nurbs_torus",
        &shaded_torus(),
        reference,
        // Rounding differences may move a silhouette pixel or shift a
        // colour by a level.
        Tolerance {
            channel: 3.0 / 255.0,
            mismatched_fraction: 0.002,
        },
    );
}

proptest! {
    #![proptest_config(proptest_config())]

    #[testkit::test]
    fn curve_matches_the_definition_and_stays_in_the_hull(curve in nurbs_curve(), t in 0.0f64..=1.0) {
        let u = curve.domain().lerp(t);
        let expected = curve_point(curve.knots(), curve.points(), u);
        let actual = curve.point(u).unwrap();
        prop_assert!(expected.distance(actual) <= TOLERANCE, "C({u}): {expected} vs {actual}");
        // Strong convex hull property: C(u) lies in the hull of the p + 1
        // control points of its span; tested on their bounding box.
        let k = curve.knots().knots();
        let span = (curve.degree()..=curve.knots().last_index())
            .rfind(|&s| k[s] <= u && k[s] < k[s + 1])
            .unwrap();
        let local = &curve.points()[span - curve.degree()..=span];
        prop_assert!(common::in_bounding_box(actual, projected(local), TOLERANCE));
    }

    #[testkit::test]
    fn curve_is_affinely_invariant(
        curve in nurbs_curve(),
        t in 0.0f64..=1.0,
        matrix in prop::array::uniform9(-2.0f64..2.0),
        shift in point3(),
    ) {
        let a = DMat3::from_cols_array(&matrix);
        let moved: Vec<DVec4> = curve
            .points()
            .iter()
            .map(|p| homogeneous(a * (p.truncate() / p.w) + shift, p.w))
            .collect();
        let moved = NurbsCurve::try_new(curve.knots().clone(), moved).unwrap();
        let u = curve.domain().lerp(t);
        let expected = a * curve.point(u).unwrap() + shift;
        let actual = moved.point(u).unwrap();
        prop_assert!(expected.distance(actual) <= 1e-8, "{expected} vs {actual}");
    }

    #[testkit::test]
    fn curve_derivative_agrees_with_finite_differences(curve in nurbs_curve(), t in 0.0f64..=1.0) {
        let u = curve.domain().lerp(t);
        prop_assume!(!near_knot(curve.knots(), u, 10.0 * H));
        let d = curve.derivative(u).unwrap();
        let expected_point = curve_point(curve.knots(), curve.points(), u);
        prop_assert!(d.point.distance(expected_point) <= TOLERANCE);
        let slope = (curve_point(curve.knots(), curve.points(), u + H)
            - curve_point(curve.knots(), curve.points(), u - H))
            / (2.0 * H);
        let scale = 1.0 + slope.length();
        prop_assert!(d.derivative.distance(slope) <= 1e-4 * scale, "C′({u}) = {}, quotient {slope}", d.derivative);
    }

    #[testkit::test]
    fn surface_matches_the_definition(surface in nurbs_surface(), s in 0.0f64..=1.0, t in 0.0f64..=1.0) {
        let (u, v) = (surface.domain_u().lerp(s), surface.domain_v().lerp(t));
        let expected = surface_point(&surface, u, v);
        let actual = surface.point(u, v).unwrap();
        prop_assert!(expected.distance(actual) <= TOLERANCE, "S({u}, {v}): {expected} vs {actual}");
        prop_assert!(common::in_bounding_box(actual, projected(surface.net().points()), TOLERANCE));
        let d = surface.derivatives(u, v).unwrap();
        prop_assert!(d.position.distance(expected) <= TOLERANCE);
    }

    #[testkit::test]
    fn surface_derivatives_agree_with_finite_differences(
        surface in nurbs_surface(),
        s in 0.0f64..=1.0,
        t in 0.0f64..=1.0,
    ) {
        let (u, v) = (surface.domain_u().lerp(s), surface.domain_v().lerp(t));
        prop_assume!(!near_knot(surface.knots_u(), u, 10.0 * H));
        prop_assume!(!near_knot(surface.knots_v(), v, 10.0 * H));
        let d = surface.derivatives(u, v).unwrap();
        let su = (surface_point(&surface, u + H, v) - surface_point(&surface, u - H, v)) / (2.0 * H);
        let sv = (surface_point(&surface, u, v + H) - surface_point(&surface, u, v - H)) / (2.0 * H);
        prop_assert!(d.du.distance(su) <= 1e-4 * (1.0 + su.length()), "S_u = {}, quotient {su}", d.du);
        prop_assert!(d.dv.distance(sv) <= 1e-4 * (1.0 + sv.length()), "S_v = {}, quotient {sv}", d.dv);
        // The normal: unit length, perpendicular to both tangents, on the
        // side of S_u × S_v.
        if let Ok(n) = surface.normal(u, v) {
            prop_assert!((n.length() - 1.0).abs() < 1e-12);
            prop_assert!(n.dot(d.du).abs() <= 1e-9 * d.du.length());
            prop_assert!(n.dot(d.dv).abs() <= 1e-9 * d.dv.length());
            prop_assert!(n.dot(d.du.cross(d.dv)) > 0.0);
        }
    }

    #[testkit::test]
    fn grid_matches_single_points(surface in nurbs_surface(), nu in 2usize..6, nv in 2usize..6) {
        let grid = surface.sample_grid(nu, nv).unwrap();
        prop_assert_eq!(grid.len(), nu * nv);
        for i in 0..nu {
            for j in 0..nv {
                let u = surface.domain_u().lerp(i as f64 / (nu - 1) as f64);
                let v = surface.domain_v().lerp(j as f64 / (nv - 1) as f64);
                let expected = surface_point(&surface, u, v);
                prop_assert!(expected.distance(grid[i * nv + j]) <= TOLERANCE, "({i}, {j})");
            }
        }
    }
}
