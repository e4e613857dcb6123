//! Task 2: the B-spline basis — Cox-de Boor, span search, A2.2, A2.3.

mod common;

use approx::assert_relative_eq;
use common::knot_vector;
use nurbs::basis::{basis_funs, cox_de_boor, ders_basis_funs, find_span};
use nurbs::{KnotVector, NurbsError};
use proptest::prelude::*;
use testkit::proptest_config;

/// Sums of a few products of values in `[0, 1]` agree to this.
const TOLERANCE: f64 = 1e-12;

/// The NURBS Book, Example 2.3: `U = {0,0,0,1,2,3,4,4,5,5,5}`, `p = 2`.
fn book_knots() -> KnotVector {
    KnotVector::try_new(
        2,
        vec![0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 4.0, 5.0, 5.0, 5.0],
    )
    .unwrap()
}

#[testkit::test]
fn book_example_has_the_known_values() {
    // At u = 5/2 (span [2, 3), s = 4): N_{2,2} = 1/8, N_{3,2} = 6/8,
    // N_{4,2} = 1/8; all others 0 (The NURBS Book, Ex. 2.3).
    //
    //   0 0 0   1   2 ─•─ 3   4 4   5 5 5
    //                 5/2
    let knots = book_knots();
    let u = 2.5;
    assert_eq!(find_span(&knots, u), Ok(4));
    let values = basis_funs(&knots, 4, u).unwrap();
    assert_eq!(values.len(), 3);
    for (value, expected) in values.iter().zip([1.0 / 8.0, 6.0 / 8.0, 1.0 / 8.0]) {
        assert_relative_eq!(*value, expected, max_relative = 1e-15);
    }
    for (i, expected) in [
        (2, 1.0 / 8.0),
        (3, 6.0 / 8.0),
        (4, 1.0 / 8.0),
        (1, 0.0),
        (5, 0.0),
    ] {
        assert_relative_eq!(cox_de_boor(&knots, i, 2, u), expected, max_relative = 1e-15);
    }
    // Lower degrees from the same recursion: N_{4,0}(5/2) = 1,
    // N_{3,1}(5/2) = N_{4,1}(5/2) = ½.
    assert_eq!(cox_de_boor(&knots, 4, 0, u), 1.0);
    assert_relative_eq!(cox_de_boor(&knots, 3, 1, u), 0.5, max_relative = 1e-15);
    assert_relative_eq!(cox_de_boor(&knots, 4, 1, u), 0.5, max_relative = 1e-15);
    // The derivatives there (Ex. 2.4): N′_{2,2} = −½, N′_{3,2} = 0, N′_{4,2} = ½.
    let ders = ders_basis_funs(&knots, 4, u, 2).unwrap();
    for (value, expected) in ders[1].iter().zip([-0.5, 0.0, 0.5]) {
        assert_relative_eq!(*value, expected, epsilon = 1e-15);
    }
    // Second derivatives of quadratic pieces: 2/((u_{i+2}−u_i)(…)) sums;
    // on [2, 3) with unit spacing they are 1, −2, 1.
    for (value, expected) in ders[2].iter().zip([1.0, -2.0, 1.0]) {
        assert_relative_eq!(*value, expected, epsilon = 1e-14);
    }
}

#[testkit::test]
fn the_recursion_uses_degree_p_minus_one() {
    // With the seed's (1.9) read literally (N_{i,p} on the right), the
    // hat function N_{0,1} on U = {0, 1, 2} could not be ½ at u = ½.
    let knots = KnotVector::try_new(1, vec![0.0, 1.0, 2.0, 3.0]).unwrap();
    assert_relative_eq!(cox_de_boor(&knots, 0, 1, 0.5), 0.5, max_relative = 1e-15);
    assert_relative_eq!(cox_de_boor(&knots, 0, 1, 1.5), 0.5, max_relative = 1e-15);
    assert_eq!(cox_de_boor(&knots, 0, 1, 2.5), 0.0);
}

#[testkit::test]
fn steps_are_half_open_except_at_the_domain_end() {
    // Seed (1.8) closes the step: at the interior knot 1 two degree-0
    // functions would be 1. Half-open: exactly one.
    let knots = KnotVector::try_new(1, vec![0.0, 0.0, 1.0, 2.0, 2.0]).unwrap();
    assert_eq!(cox_de_boor(&knots, 1, 0, 1.0), 0.0);
    assert_eq!(cox_de_boor(&knots, 2, 0, 1.0), 1.0);
    // At the domain's end the last step is closed, so the basis sums to 1.
    assert_eq!(cox_de_boor(&knots, 2, 0, 2.0), 1.0);
    let sum: f64 = (0..3).map(|i| cox_de_boor(&knots, i, 1, 2.0)).sum();
    assert_relative_eq!(sum, 1.0, max_relative = 1e-15);
    assert_eq!(find_span(&knots, 1.0), Ok(2));
    assert_eq!(find_span(&knots, 2.0), Ok(2));
    assert_eq!(find_span(&knots, 0.0), Ok(1));
}

#[testkit::test]
fn clamped_bezier_knots_give_the_bernstein_basis() {
    // U = {0, …, 0, 1, …, 1}: N_{i,p} = B_{i,p} (seed 001, §1.2).
    for p in 1..=6 {
        let knots = KnotVector::bezier(p).unwrap();
        for k in 0..=10 {
            let u = f64::from(k) / 10.0;
            let span = find_span(&knots, u).unwrap();
            assert_eq!(span, p, "a Bézier curve has a single span");
            let values = basis_funs(&knots, span, u).unwrap();
            for (i, &value) in values.iter().enumerate() {
                let expected = common::bernstein(i, p, u);
                assert!(
                    (value - expected).abs() < TOLERANCE,
                    "p = {p}, i = {i}, u = {u}"
                );
                let recursive = cox_de_boor(&knots, i, p, u);
                assert!(
                    (recursive - expected).abs() < TOLERANCE,
                    "p = {p}, i = {i}, u = {u}"
                );
            }
        }
    }
}

#[testkit::test]
fn unclamped_uniform_knots_give_the_uniform_cubic_b_spline() {
    // U = {0, 1, …, 7}, p = 3, domain [3, 4]: at the span's start the
    // uniform cubic B-spline weights are 1/6, 4/6, 1/6, 0.
    let knots = KnotVector::uniform(3, 4).unwrap();
    assert_eq!(knots.domain().start, 3.0);
    assert_eq!(knots.domain().end, 4.0);
    let values = basis_funs(&knots, find_span(&knots, 3.0).unwrap(), 3.0).unwrap();
    assert_eq!(
        values.len(),
        4,
        "p + 1 = 4 basis functions are non-zero on a span"
    );
    for (value, expected) in values.iter().zip([1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0, 0.0]) {
        assert_relative_eq!(*value, expected, epsilon = 1e-15);
    }
}

#[testkit::test]
fn invalid_knots_parameters_and_spans_are_errors() {
    // The knot vector checks (given code) that every task relies on.
    assert_eq!(
        KnotVector::try_new(0, vec![0.0, 1.0]),
        Err(NurbsError::DegreeZero)
    );
    assert!(matches!(
        KnotVector::try_new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0]),
        Err(NurbsError::TooFewKnots {
            needed: 6,
            got: 5,
            ..
        })
    ));
    assert!(matches!(
        KnotVector::try_new(1, vec![0.0, 0.0, 0.5, 0.4, 1.0, 1.0]),
        Err(NurbsError::DecreasingKnots { index: 3, .. })
    ));
    assert!(matches!(
        KnotVector::try_new(1, vec![0.0, 0.0, f64::NAN, 1.0, 1.0]),
        Err(NurbsError::NonFiniteKnot { index: 2, .. })
    ));
    assert!(matches!(
        KnotVector::try_new(2, vec![0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0]),
        Err(NurbsError::MultiplicityTooHigh {
            multiplicity: 3,
            ..
        })
    ));
    assert!(matches!(
        KnotVector::try_new(1, vec![0.0, 0.0, 0.0, 1.0, 1.0]),
        Err(NurbsError::EmptyEndSpan { .. })
    ));
    assert!(matches!(
        KnotVector::clamped_uniform(3, 3),
        Err(NurbsError::TooFewKnots { .. })
    ));
    let clamped = KnotVector::clamped_uniform(2, 5).unwrap();
    assert_eq!(
        clamped.knots(),
        &[0.0, 0.0, 0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0, 1.0, 1.0]
    );
    assert!(clamped.is_clamped());
    assert!(!KnotVector::uniform(2, 5).unwrap().is_clamped());
    // Parameters and spans (your code).
    let knots = book_knots();
    for u in [-0.1, 5.0 + 1e-9, f64::NAN, f64::NEG_INFINITY] {
        assert!(
            matches!(find_span(&knots, u), Err(NurbsError::OutOfDomain { .. })),
            "u = {u}"
        );
    }
    // Spans of the domain are p ..= n = 2 ..= 7.
    for span in [0, 1, 8, 100] {
        assert!(
            matches!(
                basis_funs(&knots, span, 2.5),
                Err(NurbsError::BadSpan { .. })
            ),
            "span {span}"
        );
    }
    assert!(matches!(
        basis_funs(&knots, 4, 3.5),
        Err(NurbsError::OutOfDomain { .. })
    ));
    assert!(matches!(
        basis_funs(&knots, 4, f64::NAN),
        Err(NurbsError::OutOfDomain { .. })
    ));
    assert!(matches!(
        ders_basis_funs(&knots, 1, 0.5, 1),
        Err(NurbsError::BadSpan { .. })
    ));
    // Out of range for the recursion: zero, not a panic.
    assert_eq!(cox_de_boor(&knots, 9, 2, 2.5), 0.0);
    assert_eq!(cox_de_boor(&knots, 3, 2, f64::NAN), 0.0);
}

/// A parameter in the domain, often exactly on a knot.
fn parameter(knots: &KnotVector, t: f64, on_knot: Option<usize>) -> f64 {
    let domain = knots.domain();
    match on_knot {
        Some(i) => {
            let k = knots.knots();
            k[knots.degree() + i % (knots.control_points() - knots.degree() + 1)]
        }
        None => domain.lerp(t),
    }
}

proptest! {
    #![proptest_config(proptest_config())]

    #[testkit::test]
    fn span_contains_the_parameter(
        knots in knot_vector(),
        t in 0.0f64..=1.0,
        on_knot in prop::option::of(0usize..20),
    ) {
        let u = parameter(&knots, t, on_knot);
        let span = find_span(&knots, u).unwrap();
        let k = knots.knots();
        prop_assert!(span >= knots.degree() && span <= knots.last_index());
        prop_assert!(k[span] < k[span + 1], "span {span} is empty");
        if u == knots.domain().end {
            prop_assert_eq!(span, knots.last_index());
        } else {
            prop_assert!(k[span] <= u && u < k[span + 1], "u = {u} not in span {span}");
        }
    }

    #[testkit::test]
    fn basis_is_non_negative_sums_to_one_and_matches_the_definition(
        knots in knot_vector(),
        t in 0.0f64..=1.0,
        on_knot in prop::option::of(0usize..20),
    ) {
        let u = parameter(&knots, t, on_knot);
        let p = knots.degree();
        let span = find_span(&knots, u).unwrap();
        let values = basis_funs(&knots, span, u).unwrap();
        prop_assert_eq!(values.len(), p + 1);
        for (j, &value) in values.iter().enumerate() {
            prop_assert!(value >= -1e-15, "N_{{{},{p}}}({u}) = {value}", span - p + j);
        }
        let sum: f64 = values.iter().sum();
        prop_assert!((sum - 1.0).abs() < TOLERANCE, "sum {sum}");
        // Against the definition, for every basis function: those outside
        // the span must vanish.
        for i in 0..knots.control_points() {
            let expected = common::basis(&knots, i, p, u);
            let fast = if i + p >= span && i <= span { values[i + p - span] } else { 0.0 };
            prop_assert!((fast - expected).abs() < TOLERANCE, "A2.2: N_{{{i},{p}}}({u}) = {fast}, expected {expected}");
            let recursive = cox_de_boor(&knots, i, p, u);
            prop_assert!((recursive - expected).abs() < TOLERANCE, "Cox-de Boor: N_{{{i},{p}}}({u}) = {recursive}, expected {expected}");
        }
    }

    #[testkit::test]
    fn derivatives_agree_with_finite_differences(
        knots in knot_vector(),
        t in 0.0f64..=1.0,
    ) {
        // Central differences of the definition, away from knots (where the
        // derivative may jump).
        const H: f64 = 1e-6;
        let u = knots.domain().lerp(t);
        prop_assume!(knots.knots().iter().all(|&k| (k - u).abs() > 10.0 * H));
        let p = knots.degree();
        let span = find_span(&knots, u).unwrap();
        let ders = ders_basis_funs(&knots, span, u, 2).unwrap();
        prop_assert_eq!(ders.len(), 3);
        let values = basis_funs(&knots, span, u).unwrap();
        for j in 0..=p {
            prop_assert!((ders[0][j] - values[j]).abs() < TOLERANCE);
            let i = span - p + j;
            let slope = (common::basis(&knots, i, p, u + H) - common::basis(&knots, i, p, u - H)) / (2.0 * H);
            let scale = 1.0 + slope.abs();
            prop_assert!((ders[1][j] - slope).abs() < 1e-5 * scale, "N′_{{{i},{p}}}({u}) = {}, difference quotient {slope}", ders[1][j]);
        }
        // The basis sums to 1 everywhere, so its derivatives sum to 0.
        for (k, row) in ders.iter().enumerate().skip(1) {
            let sum: f64 = row.iter().sum();
            let scale: f64 = row.iter().map(|d| d.abs()).sum::<f64>() + 1.0;
            prop_assert!(sum.abs() < 1e-9 * scale, "order {k}: sum {sum}");
        }
        if p == 1 {
            prop_assert!(ders[2].iter().all(|&d| d == 0.0), "order 2 of a linear basis: {:?}", ders[2]);
        }
    }
}
