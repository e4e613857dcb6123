//! Task 1: Bernstein polynomials, binomial coefficients and the Bernstein
//! form of a curve (seed 000, §2.2–2.3).

mod common;

use bezier::bernstein::{bernstein, bernstein_basis, bernstein_curve, binomial};
use bezier::{BezierError, MAX_DEGREE};
use common::Counted;
use glam::{DVec2, DVec3};
use proptest::prelude::*;

#[testkit::test]
fn binomial_matches_pascals_triangle_up_to_the_degree_limit() {
    for n in 0..=MAX_DEGREE {
        for i in 0..=n {
            assert_eq!(
                binomial(n, i),
                Ok(common::pascal(n, i) as f64),
                "binomial({n}, {i}) is C({n}, {i}) of Pascal's triangle, exact in f64 up to \
                 MAX_DEGREE (a running product c · (n − k) / (k + 1) stays integral)"
            );
        }
    }
}

#[testkit::test]
fn cubic_basis_is_the_seeds_weight_functions() {
    // Seed eq. (2): (1 − t)³, 3t(1 − t)², 3t²(1 − t), t³.
    for k in 0..=16 {
        let t = f64::from(k) / 16.0; // dyadic: every product below is exact
        let s = 1.0 - t;
        let expected = [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t];
        assert_eq!(
            bernstein_basis(3, t).unwrap(),
            expected,
            "bernstein_basis(3, {t}) is the seed's eq. (2), [(1 − t)³, 3t(1 − t)², 3t²(1 − t), \
             t³], exactly at a dyadic t"
        );
    }
}

#[testkit::test]
fn known_values_and_the_ends() {
    for (i, n, t, expected, by_hand) in [
        (1, 2, 0.5, 0.5, "2 · ½ · ½"),
        (0, 3, 0.5, 0.125, "(½)³"),
        (2, 4, 0.5, 6.0 / 16.0, "6 · (½)⁴"),
        (0, 0, 0.3, 1.0, "C(0, 0) · t⁰ · (1 − t)⁰, with 0⁰ = 1"),
    ] {
        assert_eq!(
            bernstein(i, n, t),
            Ok(expected),
            "bernstein({i}, {n}, {t}) = C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ = {by_hand}"
        );
    }
    for n in 0..=6 {
        for i in 0..=n {
            let at_0 = if i == 0 { 1.0 } else { 0.0 };
            let at_1 = if i == n { 1.0 } else { 0.0 };
            assert_eq!(
                bernstein(i, n, 0.0),
                Ok(at_0),
                "bernstein({i}, {n}, 0): at t = 0 only B_0,n is 1 (tⁱ = 0 for i > 0, and 0⁰ = 1)"
            );
            assert_eq!(
                bernstein(i, n, 1.0),
                Ok(at_1),
                "bernstein({i}, {n}, 1): at t = 1 only B_n,n is 1 ((1 − t)ⁿ⁻ⁱ = 0 for i < n, \
                 and 0⁰ = 1)"
            );
        }
    }
}

#[testkit::test]
fn the_seeds_one_minus_i_would_be_wrong() {
    // Eq. (3) as printed, C(n,i) tⁱ (1 − i)ⁿ⁻ⁱ, gives B_{0,2}(0.5) = 1 and
    // B_{1,2}(0.5) = 0; the basis with (1 − t) gives ¼ and ½.
    assert_eq!(
        bernstein(0, 2, 0.5),
        Ok(0.25),
        "bernstein(0, 2, ½) = C(2, 0) · (1 − t)² = ¼; the seed's printed (1 − i)ⁿ⁻ⁱ would give 1"
    );
    assert_eq!(
        bernstein(1, 2, 0.5),
        Ok(0.5),
        "bernstein(1, 2, ½) = C(2, 1) · t · (1 − t) = ½; the seed's printed (1 − i)ⁿ⁻ⁱ would \
         give 0"
    );
}

#[testkit::test]
fn quadratic_and_cubic_curves_follow_seed_equations_1_and_2() {
    let p = [
        DVec2::new(0.0, 0.0),
        DVec2::new(1.0, 2.0),
        DVec2::new(3.0, 2.0),
        DVec2::new(4.0, 0.0),
    ];
    for k in 0..=8 {
        let t = f64::from(k) / 8.0;
        let s = 1.0 - t;
        let quadratic = p[0] * (s * s) + p[1] * (2.0 * t * s) + p[2] * (t * t);
        let cubic = p[0] * (s * s * s)
            + p[1] * (3.0 * t * s * s)
            + p[2] * (3.0 * t * t * s)
            + p[3] * (t * t * t);
        let yours = bernstein_curve(&p[..3], t).unwrap();
        assert!(
            yours.abs_diff_eq(quadratic, 1e-14),
            "bernstein_curve((0, 0), (1, 2), (3, 2); {t}) is eq. (1), (1 − t)² P0 + 2t(1 − t) P1 \
             + t² P2 = {quadratic}; yours {yours}"
        );
        let yours = bernstein_curve(&p, t).unwrap();
        assert!(
            yours.abs_diff_eq(cubic, 1e-14),
            "bernstein_curve((0, 0), (1, 2), (3, 2), (4, 0); {t}) is eq. (2), Σ B_i,3(t) P_i = \
             {cubic}; yours {yours}"
        );
    }
    // The curve passes through its end points exactly.
    assert_eq!(
        bernstein_curve(&p, 0.0),
        Ok(p[0]),
        "bernstein_curve(…, 0) is the first control point, exactly"
    );
    assert_eq!(
        bernstein_curve(&p, 1.0),
        Ok(p[3]),
        "bernstein_curve(…, 1) is the last control point, exactly"
    );
}

#[testkit::test]
fn scalar_curves_work_too() {
    // Σ B_{i,n}(t) · i/n = t: the Bernstein form reproduces linear functions.
    let points: Vec<f64> = (0..=7).map(|i| f64::from(i) / 7.0).collect();
    for k in 0..=10 {
        let t = f64::from(k) / 10.0;
        let p = bernstein_curve(&points, t).unwrap();
        assert!(
            (p - t).abs() < 1e-14,
            "bernstein_curve(0, 1/7, 2/7, …, 1; {t}): Σ B_i,7(t) · i/7 = t (the Bernstein form \
             reproduces linear functions); yours {p}"
        );
    }
}

#[testkit::test]
fn the_curve_scales_each_control_point_once_by_its_polynomial() {
    for degree in 1..=8_usize {
        let points: Vec<Counted> = (0..=degree)
            .map(|i| Counted(1.0 + i as f64 * 0.7 - (i * i) as f64 * 0.1))
            .collect();
        let t = 0.3;
        let (point, scalings) = common::scalings(|| bernstein_curve(&points, t).unwrap());
        let described: Vec<String> = scalings
            .iter()
            .map(|(p, s)| format!("{p:.3} · {s:.5}"))
            .collect();
        assert_eq!(
            scalings.len(),
            degree + 1,
            "degree {degree}: the Bernstein form Σ B_i,n(t) · P_i multiplies each of the {} \
             control points once, yours multiplies points {} times ({}): is this de \
             Casteljau or another evaluation?",
            degree + 1,
            scalings.len(),
            described.join(", ")
        );
        for (i, p) in points.iter().enumerate() {
            let expected = common::bernstein_def(i, degree, t);
            let found = scalings
                .iter()
                .any(|&(q, s)| q == p.0 && (s - expected).abs() < 1e-12);
            assert!(
                found,
                "degree {degree}: P_{i} = {} is never multiplied by B_{i},{degree}({t}) = {expected} \
                 (your multiplications: {})",
                p.0,
                described.join(", ")
            );
        }
        let expected: f64 = (0..=degree)
            .map(|i| points[i].0 * common::bernstein_def(i, degree, t))
            .sum();
        assert!(
            (point.0 - expected).abs() < 1e-12,
            "degree {degree}: bernstein_curve(…, {t}) is Σ B_i,n(t) · P_i = {expected}, yours {}",
            point.0
        );
    }
}

#[testkit::test]
fn invalid_input_is_a_clear_error() {
    let too_high = MAX_DEGREE + 1;
    assert_eq!(
        binomial(3, 4),
        Err(BezierError::IndexAboveDegree { i: 4, n: 3 }),
        "binomial(3, 4): i > n is IndexAboveDegree"
    );
    assert_eq!(
        binomial(too_high, 1),
        Err(BezierError::DegreeTooHigh {
            degree: too_high,
            max: MAX_DEGREE
        }),
        "binomial({too_high}, 1): a degree above MAX_DEGREE = {MAX_DEGREE} is DegreeTooHigh"
    );
    let yours = bernstein(4, 3, 0.5);
    assert!(
        matches!(yours, Err(BezierError::IndexAboveDegree { .. })),
        "bernstein(4, 3, 0.5): i > n is IndexAboveDegree, yours {yours:?}"
    );
    let yours = bernstein(0, too_high, 0.5);
    assert!(
        matches!(yours, Err(BezierError::DegreeTooHigh { .. })),
        "bernstein(0, {too_high}, 0.5): a degree above MAX_DEGREE is DegreeTooHigh, yours \
         {yours:?}"
    );
    for t in [f64::NAN, -0.1, 1.1, f64::INFINITY, f64::NEG_INFINITY] {
        let yours = bernstein(1, 3, t);
        assert!(
            matches!(
                yours,
                Err(BezierError::ParameterOutOfRange { name: "t", .. })
            ),
            "bernstein(1, 3, {t}): a t that is NaN or outside [0, 1] is ParameterOutOfRange \
             naming \"t\", yours {yours:?}"
        );
        let yours = bernstein_basis(3, t);
        assert!(
            yours.is_err(),
            "bernstein_basis(3, {t}): a t that is NaN or outside [0, 1] is an error, yours \
             {yours:?}"
        );
    }
    assert_eq!(
        bernstein_curve::<DVec2>(&[], 0.5),
        Err(BezierError::Empty),
        "bernstein_curve of no points is Empty"
    );
    let nan = [DVec3::ZERO, DVec3::new(0.0, f64::NAN, 0.0)];
    assert_eq!(
        bernstein_curve(&nan, 0.5),
        Err(BezierError::NonFinitePoint { index: 1 }),
        "bernstein_curve with a NaN in point 1 is NonFinitePoint naming it"
    );
    let long = vec![DVec2::ONE; MAX_DEGREE + 2];
    let yours = bernstein_curve(&long, 0.5);
    assert!(
        matches!(yours, Err(BezierError::DegreeTooHigh { .. })),
        "bernstein_curve of {} points (degree {}) is DegreeTooHigh, yours {yours:?}",
        MAX_DEGREE + 2,
        MAX_DEGREE + 1
    );
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn basis_is_non_negative_and_sums_to_one(n in 0..=MAX_DEGREE, t in 0.0..=1.0_f64) {
        let basis = bernstein_basis(n, t).unwrap();
        prop_assert_eq!(basis.len(), n + 1, "bernstein_basis({}, {}): n + 1 polynomials B_0,n … B_n,n", n, t);
        prop_assert!(basis.iter().all(|&b| b >= 0.0), "bernstein_basis({}, {}): every B_i,n(t) ≥ 0 on [0, 1], yours {:?}", n, t, basis);
        let sum: f64 = basis.iter().sum();
        prop_assert!((sum - 1.0).abs() < 1e-12, "bernstein_basis({}, {}): the basis sums to 1 (partition of unity, to 1e-12), yours to {}", n, t, sum);
    }

    #[testkit::test]
    fn bernstein_matches_its_definition(n in 0..=MAX_DEGREE, i in 0..=MAX_DEGREE, t in 0.0..=1.0_f64) {
        prop_assume!(i <= n);
        let b = bernstein(i, n, t).unwrap();
        let expected = common::bernstein_def(i, n, t);
        prop_assert!((b - expected).abs() <= 1e-12 * expected.max(1e-300).max(1.0), "bernstein({}, {}, {}) = C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ = {}, yours {}", i, n, t, expected, b);
    }

    #[testkit::test]
    fn curve_points_lie_in_the_convex_hull(
        points in prop::collection::vec((-100.0..100.0_f64, -100.0..100.0_f64), 1..12),
        t in 0.0..=1.0_f64,
    ) {
        let points: Vec<DVec2> = points.into_iter().map(|(x, y)| DVec2::new(x, y)).collect();
        let p = bernstein_curve(&points, t).unwrap();
        // Support test: no direction sees the point beyond every control point.
        for k in 0..32 {
            let a = f64::from(k) * std::f64::consts::TAU / 32.0;
            let d = DVec2::new(a.cos(), a.sin());
            let reach = points.iter().map(|q| q.dot(d)).fold(f64::NEG_INFINITY, f64::max);
            prop_assert!(p.dot(d) <= reach + 1e-9, "bernstein_curve(…, {}) = {} lies outside the control points' convex hull: along {} it reaches {}, the points only {}", t, p, d, p.dot(d), reach);
        }
    }
}
