//! Task 3: tensor-product Bézier surfaces — de Casteljau in u then v and v
//! then u, partial derivatives, the unit normal (seed 000, §2.4–2.5,
//! Listings 4–6).

mod common;

use bezier::surface::{evaluate_u_then_v, evaluate_v_then_u, normal, partial_derivatives};
use bezier::{BezierError, BezierPatch, PatchError};
use glam::{DMat3, DVec2, DVec3};
use proptest::prelude::*;

fn uv(u: f64, v: f64) -> DVec2 {
    DVec2::new(u, v)
}

/// A bilinear-in-the-grid 3 × 2 net in the plane z = 0 with P_{i,j} = (i, 2 j, 0).
fn plane_net() -> BezierPatch {
    let mut points = Vec::new();
    for i in 0..3 {
        for j in 0..2 {
            points.push(DVec3::new(f64::from(i), 2.0 * f64::from(j), 0.0));
        }
    }
    BezierPatch::try_new(2, 1, points).unwrap()
}

#[testkit::test]
fn a_plane_grid_reproduces_its_parameters() {
    // P(u, v) = (2u, 2v, 0): Bernstein linear precision in both directions.
    let net = plane_net();
    for (u, v) in [(0.0, 0.0), (0.25, 0.5), (1.0, 0.75), (0.5, 1.0)] {
        let expected = DVec3::new(2.0 * u, 2.0 * v, 0.0);
        let at = format!("({u}, {v}) on the plane net P_i,j = (i, 2j, 0)");
        let yours = evaluate_u_then_v(&net, uv(u, v)).unwrap();
        assert!(
            yours.abs_diff_eq(expected, 1e-15),
            "evaluate_u_then_v at {at}: linear precision gives P(u, v) = (2u, 2v, 0) = \
             {expected}, yours {yours}"
        );
        let yours = evaluate_v_then_u(&net, uv(u, v)).unwrap();
        assert!(
            yours.abs_diff_eq(expected, 1e-15),
            "evaluate_v_then_u at {at}: linear precision gives P(u, v) = (2u, 2v, 0) = \
             {expected}, yours {yours}"
        );
        let p = partial_derivatives(&net, uv(u, v)).unwrap();
        assert!(
            p.position.abs_diff_eq(expected, 1e-15),
            "partial_derivatives at {at}: position {expected}, yours {}",
            p.position
        );
        assert!(
            p.du.abs_diff_eq(DVec3::new(2.0, 0.0, 0.0), 1e-15),
            "partial_derivatives at {at}: ∂P/∂u = (2, 0, 0), yours {}",
            p.du
        );
        assert!(
            p.dv.abs_diff_eq(DVec3::new(0.0, 2.0, 0.0), 1e-15),
            "partial_derivatives at {at}: ∂P/∂v = (0, 2, 0), yours {}",
            p.dv
        );
        let n = normal(&net, uv(u, v)).unwrap();
        assert!(
            n.abs_diff_eq(DVec3::Z, 1e-15),
            "normal at {at}: ∂P/∂u × ∂P/∂v normalised is +z, yours {n}"
        );
    }
}

#[testkit::test]
fn corners_are_the_corner_control_points() {
    let net = BezierPatch::seed_hill();
    for (u, v, i, j) in [
        (0.0, 0.0, 0, 0),
        (1.0, 0.0, 3, 0),
        (0.0, 1.0, 0, 3),
        (1.0, 1.0, 3, 3),
    ] {
        assert_eq!(
            evaluate_u_then_v(&net, uv(u, v)),
            Ok(net.control_point(i, j)),
            "evaluate_u_then_v(seed hill, ({u}, {v})): a corner of the patch is the corner \
             control point P_{i},{j}, exactly"
        );
        assert_eq!(
            evaluate_v_then_u(&net, uv(u, v)),
            Ok(net.control_point(i, j)),
            "evaluate_v_then_u(seed hill, ({u}, {v})): a corner of the patch is the corner \
             control point P_{i},{j}, exactly"
        );
    }
}

#[testkit::test]
fn the_seed_hill_at_its_centre() {
    // Inner points at height ½, the rest at 0: P(½, ½).y = ½ · (B₁₃ + B₂₃)(½)² = ½ · (¾)².
    let net = BezierPatch::seed_hill();
    let centre = evaluate_u_then_v(&net, uv(0.5, 0.5)).unwrap();
    assert!(
        centre.abs_diff_eq(DVec3::new(0.0, 0.5 * 0.75 * 0.75, 0.0), 1e-15),
        "evaluate_u_then_v(seed hill, (½, ½)) = (0, ½ · (¾)², 0) = (0, 0.28125, 0), the inner \
         points at height ½; yours {centre}"
    );
    // By symmetry the top of the hill is flat and the normal points up.
    let n = normal(&net, uv(0.5, 0.5)).unwrap();
    assert!(
        n.abs_diff_eq(DVec3::Y, 1e-15),
        "normal(seed hill, (½, ½)): the top is flat and ∂P/∂u × ∂P/∂v points up (u along +x, v \
         along −z), (0, 1, 0); yours {n}"
    );
}

/// ```text
///   v ↑  P01=P11=P21  (the top edge collapsed to the apex (1, 2, 0))
///     │     /  |  \
///     │  P00  P10  P20   → u
/// ```
fn collapsed_net() -> BezierPatch {
    let apex = DVec3::new(1.0, 2.0, 0.0);
    let mut points = Vec::new();
    for i in 0..3 {
        points.push(DVec3::new(f64::from(i), 0.0, 0.0));
        points.push(apex);
    }
    BezierPatch::try_new(2, 1, points).unwrap()
}

#[testkit::test]
fn normal_at_a_collapsed_edge_falls_back_to_its_limit() {
    // The patch is a flat triangle in z = 0, so every normal is +Z; at the
    // apex ∂P/∂u = 0 and the cross product vanishes.
    let net = collapsed_net();
    let p = partial_derivatives(&net, uv(0.0, 1.0)).unwrap();
    assert_eq!(
        p.du,
        DVec3::ZERO,
        "partial_derivatives at (0, 1): the top edge is collapsed to the apex, so ∂P/∂u = 0 there"
    );
    for at in [uv(0.0, 1.0), uv(0.5, 1.0), uv(1.0, 1.0), uv(0.3, 0.2)] {
        let n = normal(&net, at).unwrap();
        assert!(
            n.abs_diff_eq(DVec3::Z, 1e-9),
            "normal at {at} of the flat triangle in z = 0: +z everywhere; where ∂u × ∂v \
             vanishes, retry once moved by NORMAL_NUDGE towards (½, ½); yours {n}"
        );
    }
}

#[testkit::test]
fn a_net_collapsed_to_a_line_has_no_normal() {
    let points = (0..4).map(|k| DVec3::new(f64::from(k), 0.0, 0.0)).collect();
    let net = BezierPatch::try_new(1, 1, points).unwrap();
    assert_eq!(
        normal(&net, uv(0.5, 0.5)),
        Err(BezierError::DegenerateNormal { u: 0.5, v: 0.5 }),
        "normal of a net collapsed to a line: ∂u × ∂v vanishes at (½, ½) and at the nudged \
         point too, so DegenerateNormal at the (u, v) asked for"
    );
}

#[testkit::test]
fn invalid_input_is_a_clear_error() {
    let net = BezierPatch::seed_hill();
    for bad in [
        uv(f64::NAN, 0.5),
        uv(0.5, -0.1),
        uv(1.5, 0.5),
        uv(0.5, f64::INFINITY),
    ] {
        let rule = format!("{bad} is NaN or outside [0, 1]²: an error, never an extrapolation");
        let yours = evaluate_u_then_v(&net, bad);
        assert!(
            matches!(yours, Err(BezierError::ParameterOutOfRange { .. })),
            "evaluate_u_then_v: {rule}, ParameterOutOfRange; yours {yours:?}"
        );
        let yours = evaluate_v_then_u(&net, bad);
        assert!(yours.is_err(), "evaluate_v_then_u: {rule}; yours {yours:?}");
        let yours = partial_derivatives(&net, bad);
        assert!(
            yours.is_err(),
            "partial_derivatives: {rule}; yours {yours:?}"
        );
        let yours = normal(&net, bad);
        assert!(yours.is_err(), "normal: {rule}; yours {yours:?}");
    }
    // The patch checks itself (given code): these nets never reach your functions.
    assert!(
        matches!(
            BezierPatch::try_new(1, 1, vec![DVec3::ZERO; 3]),
            Err(PatchError::Shape {
                expected: 4,
                found: 3,
                ..
            })
        ),
        "BezierPatch::try_new(1, 1, 3 points): a 1 × 1 net needs 4 points"
    );
    assert!(
        matches!(
            BezierPatch::try_new(33, 0, vec![DVec3::ZERO; 34]),
            Err(PatchError::DegreeTooHigh { degree: 33, .. })
        ),
        "BezierPatch::try_new(33, 0, …): degree 33 is above MAX_DEGREE"
    );
    let mut points = vec![DVec3::ZERO; 4];
    points[2].y = f64::NAN;
    assert_eq!(
        BezierPatch::try_new(1, 1, points),
        Err(PatchError::NonFinite { index: 2 }),
        "BezierPatch::try_new with a NaN in point 2 names it"
    );
}

/// A net of degree 24 in u whose points swing between ±1000: the power form
/// `Σ a_k uᵏ` of its curves has coefficients near `C(24, k) · 2ᵏ · 1000`
/// that cancel to a value near 1000, and loses all its digits doing so;
/// de Casteljau only ever takes convex combinations of the points and
/// stays within rounding of the definition.
///
/// ```text
///   x ↑  P0    P2    P4   …  P24          (every column j the same swing,
///     │                                    shifted in y and z)
///     │     P1    P3    …  P23
/// ```
fn swinging_net() -> BezierPatch {
    BezierPatch::from_fn(24, 2, |i, j| {
        let swing = if i % 2 == 0 { 1000.0 } else { -1000.0 };
        let (i, j) = (i as f64, j as f64);
        DVec3::new(swing + 3.0 * i, 10.0 * j - 0.5 * swing, i * j)
    })
    .unwrap()
}

#[testkit::test]
fn de_casteljau_stays_on_the_surface_of_a_swinging_net_of_degree_24() {
    let net = swinging_net();
    for (u, v) in [
        (0.1, 0.3),
        (0.37, 0.5),
        (0.5, 0.9),
        (0.77, 0.2),
        (0.9, 0.65),
    ] {
        let expected = common::surface_def(&net, uv(u, v));
        for (order, got) in [
            ("evaluate_u_then_v", evaluate_u_then_v(&net, uv(u, v))),
            ("evaluate_v_then_u", evaluate_v_then_u(&net, uv(u, v))),
            (
                "partial_derivatives' position",
                partial_derivatives(&net, uv(u, v)).map(|p| p.position),
            ),
        ] {
            let got = got.unwrap();
            assert!(
                got.abs_diff_eq(expected, 1e-9),
                "{order} at ({u}, {v}) gives {got}, the definition {expected}: off by {:e} \
                 (de Casteljau's convex combinations stay within 1e-9 of it; the power \
                 form with Horner's rule loses its digits at this degree)",
                (got - expected).length()
            );
        }
    }
}

/// The net with u and v swapped: `P'_{j,i} = P_{i,j}`.
fn transposed(net: &BezierPatch) -> BezierPatch {
    BezierPatch::from_fn(net.degree_v(), net.degree_u(), |j, i| {
        net.control_point(i, j)
    })
    .unwrap()
}

#[testkit::test]
fn v_then_u_is_u_then_v_of_the_transposed_net() {
    // Reducing the columns of a net at u and then the results at v is
    // reducing the rows of its transpose at u (its second parameter) and
    // then the results at v: the very same interpolations in the very same
    // order, so the same bits. The two orders themselves differ in their
    // last bits here, which is how a v then u that is not one shows.
    let net = BezierPatch::from_fn(3, 2, |i, j| {
        let (i, j) = (i as f64, j as f64);
        DVec3::new(
            0.1 * i + 0.7 * j,
            (1.3 * i * j).sin(),
            0.3 * i * i - 0.2 * j,
        )
    })
    .unwrap();
    let flipped = transposed(&net);
    for (u, v) in [(0.1, 0.7), (0.3, 0.3), (0.77, 0.41), (0.9, 0.05)] {
        let u_then_v = evaluate_u_then_v(&net, uv(u, v)).unwrap();
        let v_then_u = evaluate_v_then_u(&net, uv(u, v)).unwrap();
        let expected = common::surface_def(&net, uv(u, v));
        for (order, got) in [("u then v", u_then_v), ("v then u", v_then_u)] {
            assert!(
                got.abs_diff_eq(expected, 1e-12),
                "{order} at ({u}, {v}): {got}, the definition gives {expected}"
            );
        }
        assert_eq!(
            evaluate_v_then_u(&flipped, uv(v, u)).unwrap(),
            u_then_v,
            "evaluate_v_then_u of the transposed net at ({v}, {u}) is evaluate_u_then_v at ({u}, {v}), bit for bit (use one de Casteljau helper for both orders)"
        );
        assert_eq!(
            evaluate_u_then_v(&flipped, uv(v, u)).unwrap(),
            v_then_u,
            "evaluate_u_then_v of the transposed net at ({v}, {u}) is evaluate_v_then_u at ({u}, {v}), bit for bit (use one de Casteljau helper for both orders)"
        );
    }
}

fn nets() -> impl Strategy<Value = BezierPatch> {
    (1..=5_usize, 1..=5_usize).prop_flat_map(|(n_u, n_v)| {
        prop::collection::vec(
            (-10.0..10.0_f64, -10.0..10.0_f64, -10.0..10.0_f64)
                .prop_map(|(x, y, z)| DVec3::new(x, y, z)),
            n_u * n_v,
        )
        .prop_map(move |points| BezierPatch::try_new(n_u - 1, n_v - 1, points).unwrap())
    })
}

fn unit() -> impl Strategy<Value = f64> {
    0.0..=1.0_f64
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn order_does_not_matter_and_both_equal_the_double_sum(net in nets(), u in unit(), v in unit()) {
        let a = evaluate_u_then_v(&net, uv(u, v)).unwrap();
        let b = evaluate_v_then_u(&net, uv(u, v)).unwrap();
        let expected = common::surface_def(&net, uv(u, v));
        prop_assert!(a.abs_diff_eq(b, 1e-12), "at ({}, {}) the order does not matter: evaluate_u_then_v gives {}, evaluate_v_then_u {} (to 1e-12)", u, v, a, b);
        prop_assert!(a.abs_diff_eq(expected, 1e-12), "evaluate_u_then_v at ({}, {}): the double sum Σ Σ B_i,n(u) B_j,m(v) P_i,j gives {}, yours {} (to 1e-12)", u, v, expected, a);
    }

    #[testkit::test]
    fn both_orders_are_each_others_transpose(net in nets(), u in unit(), v in unit()) {
        let flipped = transposed(&net);
        let u_then_v = evaluate_u_then_v(&net, uv(u, v)).unwrap();
        prop_assert!(u_then_v.abs_diff_eq(common::surface_def(&net, uv(u, v)), 1e-12), "evaluate_u_then_v at ({}, {}): the double sum gives {}, yours {} (to 1e-12)", u, v, common::surface_def(&net, uv(u, v)), u_then_v);
        prop_assert_eq!(evaluate_v_then_u(&flipped, uv(v, u)).unwrap(), u_then_v, "evaluate_v_then_u of the transposed net at ({}, {}) (left) is evaluate_u_then_v at ({}, {}) (right), bit for bit: one de Casteljau helper for both orders", v, u, u, v);
        prop_assert_eq!(evaluate_u_then_v(&flipped, uv(v, u)).unwrap(), evaluate_v_then_u(&net, uv(u, v)).unwrap(), "evaluate_u_then_v of the transposed net at ({}, {}) (left) is evaluate_v_then_u at ({}, {}) (right), bit for bit: one de Casteljau helper for both orders", v, u, u, v);
    }

    #[testkit::test]
    fn partial_derivatives_equal_the_differentiated_sum(net in nets(), u in unit(), v in unit()) {
        let p = partial_derivatives(&net, uv(u, v)).unwrap();
        let [du, dv] = common::surface_partials_def(&net, uv(u, v));
        prop_assert!(p.position.abs_diff_eq(common::surface_def(&net, uv(u, v)), 1e-12), "partial_derivatives at ({}, {}).position: the double sum gives {}, yours {} (to 1e-12)", u, v, common::surface_def(&net, uv(u, v)), p.position);
        prop_assert!(p.du.abs_diff_eq(du, 1e-10), "partial_derivatives at ({}, {}): ∂P/∂u, the double sum differentiated in u, is {}, yours {} (to 1e-10)", u, v, du, p.du);
        prop_assert!(p.dv.abs_diff_eq(dv, 1e-10), "partial_derivatives at ({}, {}): ∂P/∂v, the double sum differentiated in v, is {}, yours {} (to 1e-10)", u, v, dv, p.dv);
    }

    #[testkit::test]
    fn normal_is_unit_and_perpendicular_to_both_derivatives(net in nets(), u in unit(), v in unit()) {
        if let Ok(n) = normal(&net, uv(u, v)) {
            prop_assert!((n.length() - 1.0).abs() < 1e-12, "normal at ({}, {}) has unit length (to 1e-12), yours {} of length {}", u, v, n, n.length());
            let [du, dv] = common::surface_partials_def(&net, uv(u, v));
            let cross = du.cross(dv);
            if cross.length() > 1e-6 * du.length() * dv.length() {
                prop_assert!(n.abs_diff_eq(cross.normalize(), 1e-8), "normal at ({}, {}) is ∂P/∂u × ∂P/∂v normalised, {}; yours {} (to 1e-8)", u, v, cross.normalize(), n);
            }
        }
    }

    #[testkit::test]
    fn surface_points_lie_in_the_convex_hull(net in nets(), u in unit(), v in unit()) {
        let p = evaluate_u_then_v(&net, uv(u, v)).unwrap();
        let lo = net.control_points().iter().fold(DVec3::INFINITY, |m, &q| m.min(q));
        let hi = net.control_points().iter().fold(DVec3::NEG_INFINITY, |m, &q| m.max(q));
        prop_assert!(p.cmpge(lo - 1e-12).all() && p.cmple(hi + 1e-12).all(), "evaluate_u_then_v at ({}, {}) = {} lies outside the control points' bounding box {} to {} (the convex hull property)", u, v, p, lo, hi);
    }

    #[testkit::test]
    fn affine_maps_commute_with_evaluation(
        net in nets(), u in unit(), v in unit(),
        m in prop::array::uniform9(-2.0..2.0_f64),
        shift in prop::array::uniform3(-50.0..50.0_f64),
    ) {
        let a = DMat3::from_cols_array(&m);
        let b = DVec3::from_array(shift);
        let mapped = net.map(|p| a * p + b).unwrap();
        let lhs = evaluate_v_then_u(&mapped, uv(u, v)).unwrap();
        let rhs = a * evaluate_v_then_u(&net, uv(u, v)).unwrap() + b;
        prop_assert!(lhs.abs_diff_eq(rhs, 1e-9), "evaluate_v_then_u at ({}, {}): the mapped net A·P + b gives {}, the mapped point A·P(u, v) + b {} (affine maps commute with evaluation, to 1e-9)", u, v, lhs, rhs);
    }
}
