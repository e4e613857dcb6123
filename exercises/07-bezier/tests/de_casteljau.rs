//! Task 2: the de Casteljau algorithm — evaluation, splitting, and the
//! derivative from the penultimate step (seed 000, §2.5, Listing 4).

mod common;

use bezier::de_casteljau::{de_casteljau, point_and_derivative, split};
use bezier::{BezierError, MAX_DEGREE};
use common::Counted;
use glam::{DMat2, DVec2, DVec3};
use proptest::prelude::*;

fn p2(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

/// Seed Fig. 6: four control points, t = ½.
///
/// ```text
///   P1 ●───────● P2
///     /  ·───·  \        P(½) = (P0 + 3 P1 + 3 P2 + P3) / 8
///    /  /  ●  \  \
///   P0           P3
/// ```
#[testkit::test]
fn seed_figure_6_at_one_half() {
    let p = [p2(0.0, 0.0), p2(1.0, 2.0), p2(3.0, 2.0), p2(4.0, 0.0)];
    let expected = (p[0] + p[1] * 3.0 + p[2] * 3.0 + p[3]) / 8.0;
    assert_eq!(
        de_casteljau(&p, 0.5),
        Ok(expected),
        "de_casteljau((0, 0), (1, 2), (3, 2), (4, 0); ½) is (P0 + 3 P1 + 3 P2 + P3) / 8 \
         (seed Fig. 6)"
    );
    assert_eq!(expected, p2(2.0, 1.5), "the test's own P(½) by hand");
    // The penultimate step is b0² = (1.25, 1.5), b1² = (2.75, 1.5), so the
    // tangent at ½ is horizontal: P'(½) = 3 (b1² − b0²) = (4.5, 0), which is
    // also 3 (¼ (P1 − P0) + ½ (P2 − P1) + ¼ (P3 − P2)).
    let cp = point_and_derivative(&p, 0.5).unwrap();
    assert_eq!(
        cp.point,
        p2(2.0, 1.5),
        "point_and_derivative(Fig. 6; ½).point is P(½) = (2, 1.5)"
    );
    assert_eq!(
        cp.derivative,
        p2(4.5, 0.0),
        "point_and_derivative(Fig. 6; ½).derivative is n (b1² − b0²) = 3 ((2.75, 1.5) − (1.25, \
         1.5)) = (4.5, 0), from the penultimate step"
    );
}

#[testkit::test]
fn evaluation_interpolates_neighbours_level_by_level() {
    for degree in 1..=8_usize {
        let points: Vec<Counted> = (0..=degree)
            .map(|i| Counted(i as f64 * 0.7 - (i * i) as f64 * 0.1))
            .collect();
        let plain: Vec<f64> = points.iter().map(|p| p.0).collect();
        let (point, scalings) = common::scalings(|| de_casteljau(&points, 0.3).unwrap());
        let multiplications = scalings.len();
        let interpolations = degree * (degree + 1) / 2;
        assert!(
            multiplications >= interpolations,
            "degree {degree}: {multiplications} multiplications of points, but de Casteljau's \
             triangle has {interpolations} interpolations of neighbours (is this the Bernstein sum?)"
        );
        let expected = de_casteljau(&plain, 0.3).unwrap();
        assert!(
            (point.0 - expected).abs() < 1e-12,
            "degree {degree}: de_casteljau(…, 0.3) on the counting points gives {}, on the same \
             points as f64 {expected}",
            point.0
        );
    }
}

#[testkit::test]
fn ends_and_end_tangents_are_exact() {
    let p = [
        p2(1.0, 1.0),
        p2(2.0, 5.0),
        p2(6.0, 4.0),
        p2(7.0, -1.0),
        p2(9.0, 0.5),
    ];
    let n = 4.0;
    assert_eq!(
        de_casteljau(&p, 0.0),
        Ok(p[0]),
        "de_casteljau(quartic, 0) is the first control point, exactly"
    );
    assert_eq!(
        de_casteljau(&p, 1.0),
        Ok(p[4]),
        "de_casteljau(quartic, 1) is the last control point, exactly"
    );
    // The end tangents point at the neighbouring control points (seed §2.2).
    assert_eq!(
        point_and_derivative(&p, 0.0).unwrap().derivative,
        (p[1] - p[0]) * n,
        "point_and_derivative(quartic, 0).derivative is n (P1 − P0), exactly"
    );
    assert_eq!(
        point_and_derivative(&p, 1.0).unwrap().derivative,
        (p[4] - p[3]) * n,
        "point_and_derivative(quartic, 1).derivative is n (P4 − P3), exactly"
    );
}

#[testkit::test]
fn degree_zero_and_one() {
    let single = [p2(3.0, 4.0)];
    assert_eq!(
        de_casteljau(&single, 0.7),
        Ok(single[0]),
        "de_casteljau of one point (degree 0) is that point"
    );
    assert_eq!(
        point_and_derivative(&single, 0.7).unwrap().derivative,
        DVec2::ZERO,
        "a curve of degree 0 is constant: its derivative is 0"
    );
    let line = [p2(0.0, 0.0), p2(4.0, 8.0)];
    assert_eq!(
        de_casteljau(&line, 0.25),
        Ok(p2(1.0, 2.0)),
        "de_casteljau((0, 0), (4, 8); ¼) = ¾ P0 + ¼ P1"
    );
    assert_eq!(
        point_and_derivative(&line, 0.25).unwrap().derivative,
        p2(4.0, 8.0),
        "the derivative of a line (degree 1) is 1 · (P1 − P0)"
    );
    let s = split(&line, 0.25).unwrap();
    assert_eq!(
        s.left,
        vec![p2(0.0, 0.0), p2(1.0, 2.0)],
        "split((0, 0), (4, 8); ¼).left is b_0⁰, b_0¹ = P0, P(¼)"
    );
    assert_eq!(
        s.right,
        vec![p2(1.0, 2.0), p2(4.0, 8.0)],
        "split((0, 0), (4, 8); ¼).right is b_0¹, b_1⁰ = P(¼), P1"
    );
}

#[testkit::test]
fn split_of_a_quadratic_at_one_half() {
    // ```text
    //        P1 (2, 4)
    //      a (1, 2)  b (3, 2)       left  = P0, a, m
    //   P0       m (2, 2)     P2     right = m, b, P2
    // ```
    let p = [p2(0.0, 0.0), p2(2.0, 4.0), p2(4.0, 0.0)];
    let s = split(&p, 0.5).unwrap();
    assert_eq!(
        s.left,
        vec![p2(0.0, 0.0), p2(1.0, 2.0), p2(2.0, 2.0)],
        "split((0, 0), (2, 4), (4, 0); ½).left is the triangle's first entries b_0⁰, b_0¹, b_0² \
         = P0, a, m"
    );
    assert_eq!(
        s.right,
        vec![p2(2.0, 2.0), p2(3.0, 2.0), p2(4.0, 0.0)],
        "split((0, 0), (2, 4), (4, 0); ½).right is the triangle's last entries b_0², b_1¹, b_2⁰ \
         = m, b, P2"
    );
}

#[testkit::test]
fn high_degree_works_and_too_high_is_an_error() {
    let top: Vec<f64> = (0..=MAX_DEGREE).map(|i| i as f64).collect();
    // Σ B_{i,n}(t) · i = n t: linear precision at the highest degree.
    let v = de_casteljau(&top, 0.5).unwrap();
    assert!(
        (v - MAX_DEGREE as f64 * 0.5).abs() < 1e-12,
        "de_casteljau(0, 1, …, {MAX_DEGREE}; ½): Σ B_i,n(t) · i = n t = {}, yours {v}",
        MAX_DEGREE as f64 * 0.5
    );
    let mut over = top.clone();
    over.push(0.0);
    assert_eq!(
        de_casteljau(&over, 0.5),
        Err(BezierError::DegreeTooHigh {
            degree: MAX_DEGREE + 1,
            max: MAX_DEGREE
        }),
        "{} points are degree {}, above MAX_DEGREE: DegreeTooHigh",
        MAX_DEGREE + 2,
        MAX_DEGREE + 1
    );
}

#[testkit::test]
fn invalid_input_is_a_clear_error() {
    let p = [p2(0.0, 0.0), p2(1.0, 1.0)];
    assert_eq!(
        de_casteljau::<DVec2>(&[], 0.5),
        Err(BezierError::Empty),
        "de_casteljau of no points is Empty"
    );
    let yours = split::<DVec3>(&[], 0.5);
    assert!(
        yours.is_err(),
        "split of no points is an error, yours {yours:?}"
    );
    let yours = point_and_derivative::<f64>(&[], 0.5);
    assert!(
        yours.is_err(),
        "point_and_derivative of no points is an error, yours {yours:?}"
    );
    for t in [f64::NAN, -1e-9, 1.0 + 1e-9, f64::INFINITY] {
        let err = Err(BezierError::ParameterOutOfRange {
            name: "t",
            value: t,
        });
        let rule = format!("t = {t} is NaN or outside [0, 1]: an error, never an extrapolation");
        if !t.is_nan() {
            assert_eq!(
                de_casteljau(&p, t),
                err,
                "de_casteljau(…, {t}): {rule}, ParameterOutOfRange naming \"t\" and its value"
            );
        }
        let yours = de_casteljau(&p, t);
        assert!(
            yours.is_err(),
            "de_casteljau(…, {t}): {rule}; yours {yours:?}"
        );
        let yours = split(&p, t);
        assert!(yours.is_err(), "split(…, {t}): {rule}; yours {yours:?}");
        let yours = point_and_derivative(&p, t);
        assert!(
            yours.is_err(),
            "point_and_derivative(…, {t}): {rule}; yours {yours:?}"
        );
    }
    let bad = [p2(0.0, 0.0), p2(f64::INFINITY, 1.0), p2(f64::NAN, 0.0)];
    assert_eq!(
        de_casteljau(&bad, 0.5),
        Err(BezierError::NonFinitePoint { index: 1 }),
        "de_casteljau((0, 0), (∞, 1), (NaN, 0); ½): NonFinitePoint naming the first bad point, 1"
    );
    let yours = split(&bad, 0.5);
    assert!(
        yours.is_err(),
        "split((0, 0), (∞, 1), (NaN, 0); ½): a non-finite point is an error, yours {yours:?}"
    );
}

fn points3(max_len: usize) -> impl Strategy<Value = Vec<DVec3>> {
    prop::collection::vec(
        (-50.0..50.0_f64, -50.0..50.0_f64, -50.0..50.0_f64)
            .prop_map(|(x, y, z)| DVec3::new(x, y, z)),
        1..=max_len,
    )
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn de_casteljau_equals_the_bernstein_form(points in points3(14), t in 0.0..=1.0_f64) {
        let p = de_casteljau(&points, t).unwrap();
        prop_assert!(p.abs_diff_eq(common::curve3(&points, t), 1e-9), "de_casteljau(…, {}) of degree {}: the Bernstein form Σ B_i,n(t) P_i gives {}, yours {} (to 1e-9)", t, points.len() - 1, common::curve3(&points, t), p);
    }

    #[testkit::test]
    fn derivative_equals_the_hodograph(points in points3(10), t in 0.0..=1.0_f64) {
        let cp = point_and_derivative(&points, t).unwrap();
        prop_assert!(cp.point.abs_diff_eq(common::curve3(&points, t), 1e-9), "point_and_derivative(…, {}).point: the Bernstein form gives {}, yours {} (to 1e-9)", t, common::curve3(&points, t), cp.point);
        prop_assert!(cp.derivative.abs_diff_eq(common::derivative3(&points, t), 1e-8),
            "point_and_derivative(…, {}).derivative of degree {}: the hodograph n Σ B_i,n−1(t) (P_i+1 − P_i) gives {}, yours {} (to 1e-8)", t, points.len() - 1, common::derivative3(&points, t), cp.derivative);
    }

    #[testkit::test]
    fn split_halves_trace_the_same_curve(points in points3(8), t in 0.0..=1.0_f64, s in 0.0..=1.0_f64) {
        let halves = split(&points, t).unwrap();
        let n = points.len();
        prop_assert_eq!(halves.left.len(), n, "split(…, {}): each half has as many control points as the curve, {}", t, n);
        prop_assert_eq!(halves.right.len(), n, "split(…, {}): each half has as many control points as the curve, {}", t, n);
        prop_assert_eq!(halves.left[0], points[0], "split(…, {}): the left half starts at P0", t);
        prop_assert_eq!(halves.right[n - 1], points[n - 1], "split(…, {}): the right half ends at Pn", t);
        prop_assert_eq!(halves.left[n - 1], halves.right[0], "split(…, {}): the left half ends where the right one starts, at P(t) = b_0ⁿ", t);
        let on_left = common::curve3(&halves.left, s);
        let on_right = common::curve3(&halves.right, s);
        prop_assert!(on_left.abs_diff_eq(common::curve3(&points, s * t), 1e-8), "split(…, {}): the left half at {} is the curve at s·t = {}, {}; yours {} (to 1e-8)", t, s, s * t, common::curve3(&points, s * t), on_left);
        prop_assert!(on_right.abs_diff_eq(common::curve3(&points, t + s * (1.0 - t)), 1e-8), "split(…, {}): the right half at {} is the curve at t + s(1 − t) = {}, {}; yours {} (to 1e-8)", t, s, t + s * (1.0 - t), common::curve3(&points, t + s * (1.0 - t)), on_right);
    }

    #[testkit::test]
    fn affine_maps_commute_with_evaluation(
        points in prop::collection::vec((-10.0..10.0_f64, -10.0..10.0_f64), 1..10),
        t in 0.0..=1.0_f64,
        m in (-3.0..3.0_f64, -3.0..3.0_f64, -3.0..3.0_f64, -3.0..3.0_f64),
        shift in (-100.0..100.0_f64, -100.0..100.0_f64),
    ) {
        let a = DMat2::from_cols_array(&[m.0, m.1, m.2, m.3]);
        let b = DVec2::new(shift.0, shift.1);
        let points: Vec<DVec2> = points.into_iter().map(|(x, y)| DVec2::new(x, y)).collect();
        let mapped: Vec<DVec2> = points.iter().map(|&p| a * p + b).collect();
        let lhs = de_casteljau(&mapped, t).unwrap();
        let rhs = a * de_casteljau(&points, t).unwrap() + b;
        prop_assert!(lhs.abs_diff_eq(rhs, 1e-9), "de_casteljau(…, {}): evaluating the mapped points A·P_i + b gives {}, mapping the point A·P(t) + b gives {} (affine maps commute with evaluation, to 1e-9)", t, lhs, rhs);
    }

    #[testkit::test]
    fn points_lie_in_the_convex_hull(
        points in prop::collection::vec((-100.0..100.0_f64, -100.0..100.0_f64), 1..16),
        t in 0.0..=1.0_f64,
    ) {
        let points: Vec<DVec2> = points.into_iter().map(|(x, y)| DVec2::new(x, y)).collect();
        let p = de_casteljau(&points, t).unwrap();
        for k in 0..32 {
            let a = f64::from(k) * std::f64::consts::TAU / 32.0;
            let d = DVec2::new(a.cos(), a.sin());
            let reach = points.iter().map(|q| q.dot(d)).fold(f64::NEG_INFINITY, f64::max);
            prop_assert!(p.dot(d) <= reach + 1e-9, "de_casteljau(…, {}) = {} lies outside the control points' convex hull: along {} it reaches {}, the points only {}", t, p, d, p.dot(d), reach);
        }
    }

    #[testkit::test]
    fn hostile_input_never_panics(
        x in testkit::strategies::hostile_f32(),
        t in testkit::strategies::hostile_f32(),
    ) {
        let points = [DVec2::new(f64::from(x), 0.0), DVec2::new(1.0, f64::from(x))];
        let t = f64::from(t);
        let result = de_casteljau(&points, t);
        let valid = f64::from(x).is_finite() && (0.0..=1.0).contains(&t);
        prop_assert_eq!(result.is_ok(), valid, "de_casteljau(({}, 0), (1, {}); {}) = {:?}: Ok exactly when the points are finite and t is in [0, 1], an error otherwise, never a panic", x, x, t, result);
        prop_assert_eq!(split(&points, t).is_ok(), valid, "split(({}, 0), (1, {}); {}): Ok exactly when the points are finite and t is in [0, 1], an error otherwise", x, x, t);
    }
}
