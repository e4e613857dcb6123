//! Task 4: trimming in (u, v) — interval, circle, ellipse (seed 000,
//! §3.1, Listing 7) and Newton trimming with quadratic and cubic Bézier
//! curves, single and nested (§3.2, Listings 8–12), with the seed's
//! iteration and epsilon figures (§5.2).

mod common;

use bezier::Trim;
use bezier::newton_trim::{
    NestedNewtonTrim, NewtonSettings, NewtonTrim, between_crossings, newton,
};
use bezier::simple_trim::{CircleTrim, EllipseTrim, IntervalTrim};
use glam::DVec2;
use proptest::prelude::*;

fn uv(u: f64, v: f64) -> DVec2 {
    DVec2::new(u, v)
}

// ---------------------------------------------------------------------------
// Exact regions of the test trims. The control points' u are evenly spaced,
// so C_u(t) = u₀ + (u_n − u₀) t is linear and the region is known in closed
// form: between v_lower(t) and v_upper(t) at t = (u − u₀) / (u_n − u₀).

/// The seed's quadratic example (Fig. 11): ends (0.2, 0.5), (0.8, 0.5),
/// upper control (0.5, 0.9), lower control (0.5, 0.1).
///
/// ```text
///   v_upper(t) = 0.5 + 0.8 t (1 − t),  v_lower(t) = 0.5 − 0.8 t (1 − t)
/// ```
const QUADRATIC: [DVec2; 4] = freeform::trim::QUADRATIC_REGION;

/// Inside the quadratic region, by its closed form (boundary excluded).
fn in_quadratic(p: DVec2) -> bool {
    let t = (p.x - 0.2) / 0.6;
    (0.0..=1.0).contains(&t) && (p.y - 0.5).abs() < 0.8 * t * (1.0 - t)
}

/// The seed's cubic region (Fig. 24): ends (0.1, 0.5), (0.9, 0.5); upper
/// controls (0.3667, 0.95), (0.6333, 0.75); lower controls (0.3667, 0.2),
/// (0.6333, 0.05).
const CUBIC: [DVec2; 6] = freeform::trim::CUBIC_REGION;

/// Inside the cubic region, by eq. (2) in v along the linear u.
fn in_cubic(p: DVec2) -> bool {
    let t = (p.x - 0.1) / 0.8;
    if !(0.0..=1.0).contains(&t) {
        return false;
    }
    let s = 1.0 - t;
    let cubic = |a: f64, b: f64, c: f64, d: f64| {
        a * s * s * s + 3.0 * b * t * s * s + 3.0 * c * t * t * s + d * t * t * t
    };
    let upper = cubic(0.5, 0.95, 0.75, 0.5);
    let lower = cubic(0.5, 0.2, 0.05, 0.5);
    p.y < upper && p.y > lower
}

/// The inner region of the nested example: `|v − 0.5| < 0.4 t (1 − t)`.
const INNER: [DVec2; 4] = freeform::trim::INNER_REGION;

fn in_inner(p: DVec2) -> bool {
    let t = (p.x - 0.35) / 0.3;
    (0.0..=1.0).contains(&t) && (p.y - 0.5).abs() < 0.4 * t * (1.0 - t)
}

/// Counts the samples of a `size²` grid where `trim` and `exact` differ,
/// leaving out those within `margin` (in v) of the exact boundary.
fn misclassified(
    size: usize,
    margin: f64,
    trim: &dyn Trim,
    exact: impl Fn(DVec2) -> bool,
) -> usize {
    let mut wrong = 0;
    for row in 0..size {
        for col in 0..size {
            let p = DVec2::new(col as f64 + 0.5, row as f64 + 0.5) / size as f64;
            let near = exact(p + DVec2::new(0.0, margin)) != exact(p)
                || exact(p - DVec2::new(0.0, margin)) != exact(p)
                || exact(p + DVec2::new(margin, 0.0)) != exact(p)
                || exact(p - DVec2::new(margin, 0.0)) != exact(p);
            if !near && trim.trims(p) != exact(p) {
                wrong += 1;
            }
        }
    }
    wrong
}

// ---------------------------------------------------------------------------
// Simple trims.

#[testkit::test]
fn interval_includes_its_boundary() {
    let rect = IntervalTrim::new(uv(0.25, 0.5), uv(0.75, 0.625)).unwrap();
    let what = "IntervalTrim [0.25, 0.75] × [0.5, 0.625]";
    assert!(
        rect.trims(uv(0.5, 0.55)),
        "{what}: (0.5, 0.55) lies inside, trimmed"
    );
    for on in [
        uv(0.25, 0.5),
        uv(0.75, 0.625),
        uv(0.25, 0.6),
        uv(0.5, 0.625),
    ] {
        assert!(
            rect.trims(on),
            "{what}: {on} is on the boundary: trimmed (seed: >=, <=)"
        );
    }
    for off in [uv(0.2499, 0.55), uv(0.5, 0.626), uv(0.9, 0.9)] {
        assert!(!rect.trims(off), "{what}: {off} lies outside, not trimmed");
    }
}

#[testkit::test]
fn circle_excludes_its_boundary() {
    let circle = CircleTrim::new(uv(0.5, 0.5), 0.25).unwrap();
    // distance == radius exactly: kept (seed: distance < radius).
    for (p, trimmed, why) in [
        (uv(0.5, 0.5), true, "the centre"),
        (uv(0.5, 0.7499), true, "just inside"),
        (uv(0.75, 0.5), false, "on the circle, distance = radius"),
        (uv(0.5, 0.25), false, "on the circle, distance = radius"),
        (uv(0.7, 0.7), false, "outside"),
    ] {
        assert_eq!(
            circle.trims(p),
            trimmed,
            "CircleTrim centre (0.5, 0.5), radius 0.25, at {p} ({why}): trims where \
             distance < radius, the boundary kept (seed: <)"
        );
    }
}

#[testkit::test]
fn ellipse_includes_its_boundary() {
    let ellipse = EllipseTrim::new(uv(0.5, 0.5), uv(0.25, 0.125)).unwrap();
    let what = "EllipseTrim centre (0.5, 0.5), radii (0.25, 0.125)";
    assert!(ellipse.trims(uv(0.5, 0.5)), "{what}: the centre is trimmed");
    // (u − c₁)²/a² + (v − c₂)²/b² = 1 exactly on the axes: trimmed (seed: <= 1).
    for on in [uv(0.75, 0.5), uv(0.25, 0.5), uv(0.5, 0.625), uv(0.5, 0.375)] {
        assert!(
            ellipse.trims(on),
            "{what}: {on} is on the ellipse, (u − c₁)²/a² + (v − c₂)²/b² = 1: trimmed (seed: <= \
             1)"
        );
    }
    for off in [uv(0.5, 0.63), uv(0.7, 0.6)] {
        assert!(
            !ellipse.trims(off),
            "{what}: {off} lies outside, (u − c₁)²/a² + (v − c₂)²/b² > 1: not trimmed"
        );
    }
}

#[testkit::test]
fn nan_is_never_trimmed_and_bad_shapes_are_errors() {
    let nan = uv(f64::NAN, 0.5);
    let rule = "a NaN uv is never trimmed";
    assert!(
        !IntervalTrim::new(uv(0.0, 0.0), uv(1.0, 1.0))
            .unwrap()
            .trims(nan),
        "IntervalTrim [0, 1]², {nan}: {rule}"
    );
    assert!(
        !CircleTrim::new(uv(0.5, 0.5), 1.0).unwrap().trims(nan),
        "CircleTrim centre (0.5, 0.5), radius 1, {nan}: {rule}"
    );
    assert!(
        !EllipseTrim::new(uv(0.5, 0.5), uv(1.0, 1.0))
            .unwrap()
            .trims(nan),
        "EllipseTrim centre (0.5, 0.5), radii (1, 1), {nan}: {rule}"
    );
    assert!(
        !NewtonTrim::quadratic(QUADRATIC)
            .unwrap()
            .trims(uv(0.5, f64::NAN)),
        "NewtonTrim::quadratic(QUADRATIC), (0.5, NaN): {rule}"
    );
    // The same shapes trim their centres.
    let centre = uv(0.5, 0.5);
    assert!(
        IntervalTrim::new(uv(0.0, 0.0), uv(1.0, 1.0))
            .unwrap()
            .trims(centre),
        "IntervalTrim [0, 1]² trims its centre (0.5, 0.5)"
    );
    assert!(
        CircleTrim::new(centre, 1.0).unwrap().trims(centre),
        "CircleTrim centre (0.5, 0.5), radius 1, trims its centre"
    );
    assert!(
        EllipseTrim::new(centre, uv(1.0, 1.0))
            .unwrap()
            .trims(centre),
        "EllipseTrim centre (0.5, 0.5), radii (1, 1), trims its centre"
    );
    assert!(
        NewtonTrim::quadratic(QUADRATIC).unwrap().trims(centre),
        "NewtonTrim::quadratic(QUADRATIC) trims (0.5, 0.5), between the crossings of both arches"
    );
    for (refused, what) in [
        (
            IntervalTrim::new(uv(0.5, 0.0), uv(0.4, 1.0)).is_err(),
            "IntervalTrim with min.u > max.u",
        ),
        (
            IntervalTrim::new(uv(f64::NAN, 0.0), uv(0.4, 1.0)).is_err(),
            "IntervalTrim with a NaN corner",
        ),
        (
            CircleTrim::new(uv(0.5, 0.5), -0.1).is_err(),
            "CircleTrim of radius −0.1",
        ),
        (
            CircleTrim::new(uv(0.5, 0.5), f64::NAN).is_err(),
            "CircleTrim of radius NaN",
        ),
        (
            EllipseTrim::new(uv(0.5, 0.5), uv(0.0, 0.1)).is_err(),
            "EllipseTrim with a radius 0",
        ),
        (
            EllipseTrim::new(uv(0.5, 0.5), uv(f64::INFINITY, 0.1)).is_err(),
            "EllipseTrim with an infinite radius",
        ),
    ] {
        assert!(refused, "{what} is an error (the given constructor)");
    }
    // Newton trims: 3 or 4 points, shared end points, finite.
    let [a, b, c, d] = QUADRATIC;
    for (refused, what) in [
        (
            NewtonTrim::new(vec![a, c], vec![a, d, c]).is_err(),
            "an upper curve of 2 points",
        ),
        (
            NewtonTrim::new(vec![a, b, c], vec![a, d, c + DVec2::X]).is_err(),
            "curves with different end points",
        ),
        (
            NewtonTrim::new(vec![a, b, c], vec![a, d * f64::NAN, c]).is_err(),
            "a NaN control point",
        ),
        (
            NewtonTrim::new(vec![a, b, b, b, c], vec![a, d, c]).is_err(),
            "an upper curve of 5 points",
        ),
    ] {
        assert!(
            refused,
            "NewtonTrim::new with {what} is an error: 3 or 4 points each, shared end points, \
             finite (the given constructor)"
        );
    }
}

#[testkit::test]
fn several_simple_shapes_in_one_square() {
    // Seed Fig. 20: square, rectangle, circle and ellipse in one surface.
    let square = IntervalTrim::new(uv(0.1, 0.6), uv(0.35, 0.85)).unwrap();
    let rect = IntervalTrim::new(uv(0.55, 0.7), uv(0.9, 0.85)).unwrap();
    let circle = CircleTrim::new(uv(0.25, 0.25), 0.15).unwrap();
    let ellipse = EllipseTrim::new(uv(0.7, 0.3), uv(0.2, 0.1)).unwrap();
    let shapes: [&dyn Trim; 4] = [&square, &rect, &circle, &ellipse];
    let art = common::ascii_trim(20, |p| shapes.iter().any(|s| s.trims(p)));
    let expected = common::ascii_trim(20, |p| {
        let square = (0.1..=0.35).contains(&p.x) && (0.6..=0.85).contains(&p.y);
        let rect = (0.55..=0.9).contains(&p.x) && (0.7..=0.85).contains(&p.y);
        let circle = (p - uv(0.25, 0.25)).length_squared() < 0.15 * 0.15;
        let e = (p - uv(0.7, 0.3)) / uv(0.2, 0.1);
        square || rect || circle || e.length_squared() <= 1.0
    });
    assert_eq!(
        art, expected,
        "seed Fig. 20, '#' trimmed: the square and rectangle include their boundary (≤), the \
         circle excludes it (<), the ellipse includes it (≤ 1); left: yours, right: by the \
         formulas"
    );
    insta::assert_snapshot!(art);
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn an_ellipse_with_equal_radii_is_the_circle_off_its_boundary(
        c in (0.0..1.0_f64, 0.0..1.0_f64), r in 0.01..0.5_f64, p in (0.0..1.0_f64, 0.0..1.0_f64),
    ) {
        let (c, p) = (uv(c.0, c.1), uv(p.0, p.1));
        prop_assume!(((p - c).length() - r).abs() > 1e-9);
        let circle = CircleTrim::new(c, r).unwrap();
        let ellipse = EllipseTrim::new(c, DVec2::splat(r)).unwrap();
        prop_assert_eq!(circle.trims(p), (p - c).length() < r, "the circle trims |uv − centre| < radius at {}", p);
        prop_assert_eq!(circle.trims(p), ellipse.trims(p), "at {} off the boundary, EllipseTrim with radii ({}, {}) (right) is CircleTrim of radius {} (left), both centred at {}", p, r, r, r, c);
    }

    #[testkit::test]
    fn interval_is_the_product_of_two_intervals(
        a in (0.0..1.0_f64, 0.0..1.0_f64), b in (0.0..1.0_f64, 0.0..1.0_f64), p in (0.0..1.0_f64, 0.0..1.0_f64),
    ) {
        let (min, max) = (uv(a.0.min(b.0), a.1.min(b.1)), uv(a.0.max(b.0), a.1.max(b.1)));
        let rect = IntervalTrim::new(min, max).unwrap();
        let inside = min.x <= p.0 && p.0 <= max.x && min.y <= p.1 && p.1 <= max.y;
        prop_assert_eq!(rect.trims(uv(p.0, p.1)), inside, "IntervalTrim {} to {} at ({}, {}): trims exactly min ≤ u ≤ max in u and in v, boundary included (right: that rule)", min, max, p.0, p.1);
    }
}

// ---------------------------------------------------------------------------
// Newton's method.

#[testkit::test]
fn newton_finds_the_square_root_of_two() {
    // x² − 2 from 1: 1.5, 1.41667, 1.414216, 1.41421356237469 with steps
    // h = −0.5, 0.0833, 0.00245, 2.1e-6: the fourth is below ε = 0.001.
    let root = newton(|x| x * x - 2.0, |x| 2.0 * x, 1.0, NewtonSettings::default());
    let call = "newton(x² − 2, 2x, from 1, 10 iterations, ε = 0.001)";
    assert!(
        root.converged,
        "{call}: the fourth step h = 2.1e-6 is below ε, so it converged; yours {root:?}"
    );
    assert_eq!(
        root.iterations, 4,
        "{call}: steps h = −0.5, 0.0833, 0.00245, 2.1e-6, and it returns right after the first \
         with |h| < ε: 4 iterations"
    );
    assert!(
        (root.t - 2.0_f64.sqrt()).abs() < 1e-11,
        "{call}: t = √2 = 1.41421356237…, to 1e-11, yours {}",
        root.t
    );
    // With ε = 0.1 the second step (0.0833) already stops it at 17/12.
    let coarse = NewtonSettings {
        max_iterations: 10,
        epsilon: 0.1,
    };
    let root = newton(|x| x * x - 2.0, |x| 2.0 * x, 1.0, coarse);
    let call = "newton(x² − 2, 2x, from 1, ε = 0.1)";
    assert_eq!(
        root.iterations, 2,
        "{call}: the second step, h = 0.0833 < 0.1, stops it: 2 iterations"
    );
    assert!(
        (root.t - 17.0 / 12.0).abs() < 1e-15,
        "{call}: after two steps t = 17/12, the point the step below ε led to; yours {}",
        root.t
    );
}

#[testkit::test]
fn newton_stops_where_it_cannot_go_on() {
    // f' = 0 at the start: the step is not finite, nothing moves.
    let flat = newton(|x| x * x + 1.0, |x| 2.0 * x, 0.0, NewtonSettings::default());
    assert_eq!(
        (flat.t, flat.iterations, flat.converged),
        (0.0, 0, false),
        "newton(x² + 1, 2x, from 0): f'(0) = 0 makes h infinite, so it stops where it is: \
         (t, iterations, converged) = (0, 0, false)"
    );
    // No real root: the iteration runs out after max_iterations.
    let settings = NewtonSettings {
        max_iterations: 6,
        epsilon: 0.001,
    };
    let wander = newton(|x| x * x + 1.0, |x| 2.0 * x, 0.5, settings);
    assert_eq!(
        wander.iterations, 6,
        "newton(x² + 1, 2x, from 0.5, 6 iterations): no real root, so it runs out after \
         max_iterations"
    );
    assert!(
        !wander.converged,
        "newton(x² + 1, 2x, from 0.5, 6 iterations): no real root, no step below ε: not \
         converged; yours {wander:?}"
    );
    // Zero iterations return the start.
    let none = NewtonSettings {
        max_iterations: 0,
        epsilon: 0.001,
    };
    let root = newton(|x| x - 3.0, |_| 1.0, 1.0, none);
    assert_eq!(
        (root.t, root.iterations, root.converged),
        (1.0, 0, false),
        "newton(x − 3, 1, from 1, max_iterations 0): no step at all returns the start: \
         (t, iterations, converged) = (1, 0, false)"
    );
}

#[testkit::test]
fn between_the_crossings_of_one_arch() {
    // The upper arch of the seed's example, v(t) = 0.5 + 0.8 t (1 − t):
    // at v = 0.6, t (1 − t) = ⅛, so t = ½ ± √½ / 2 and u = 0.5 ± 0.3 √½ = 0.5 ± 0.2121.
    let arch = [QUADRATIC[0], QUADRATIC[1], QUADRATIC[2]];
    let s = NewtonSettings::default();
    // Above the apex (0.7) and below the end points there are no roots in [0, 1].
    for (a, inside, why) in [
        (
            uv(0.5, 0.6),
            true,
            "between the crossings at u = 0.2879 and 0.7121",
        ),
        (
            uv(0.71, 0.6),
            true,
            "just left of the right crossing, u = 0.7121",
        ),
        (
            uv(0.29, 0.6),
            true,
            "just right of the left crossing, u = 0.2879",
        ),
        (uv(0.72, 0.6), false, "right of both crossings"),
        (uv(0.28, 0.6), false, "left of both crossings"),
        (
            uv(0.5, 0.75),
            false,
            "above the apex v = 0.7: no root in [0, 1]",
        ),
        (
            uv(0.5, 0.45),
            false,
            "below the end points: no root in [0, 1]",
        ),
    ] {
        assert_eq!(
            between_crossings(&arch, a, s),
            inside,
            "between_crossings(the upper arch (0.2, 0.5), (0.5, 0.9), (0.8, 0.5), {a}), {why}: \
             inside exactly when Newton from t = 1 and from t = 0 both converge in [0, 1] and \
             x₁ = C_u(t₁) − u, x₂ = C_u(t₂) − u have opposite signs"
        );
    }
}

#[testkit::test]
fn an_arch_running_right_to_left_is_the_second_sign_case() {
    // The same arch with its control points reversed: Newton from t = 1
    // now finds the left crossing (x₁ < 0), from t = 0 the right one
    // (x₂ > 0) — seed §3.2.1's case 4, which Listing 11 does not test.
    //
    //   t₁ (from 1)        t₂ (from 0)
    //   ●──x₁──── a ────x₂──●        P_0 = (0.8, 0.5) on the right
    let reversed = [QUADRATIC[2], QUADRATIC[1], QUADRATIC[0]];
    let s = NewtonSettings::default();
    for inside in [uv(0.5, 0.6), uv(0.71, 0.6), uv(0.29, 0.6)] {
        assert!(
            between_crossings(&reversed, inside, s),
            "between_crossings(the arch reversed, from (0.8, 0.5), {inside}): between its \
             crossings, now with x₁ < 0 < x₂ (seed §3.2.1's second sign case): inside"
        );
    }
    for outside in [uv(0.72, 0.6), uv(0.28, 0.6), uv(0.5, 0.75)] {
        assert!(
            !between_crossings(&reversed, outside, s),
            "between_crossings(the arch reversed, from (0.8, 0.5), {outside}): not between its \
             crossings: outside"
        );
    }
    // A whole region given from its right end point is the same region.
    let [a, b, c, d] = QUADRATIC;
    let trim = NewtonTrim::quadratic([c, b, a, d]).unwrap();
    assert_eq!(
        misclassified(100, 0.005, &trim, in_quadratic),
        0,
        "NewtonTrim::quadratic given from its right end (c, b, a, d): the samples of a 100² grid (those farther than 0.005 from the boundary) \\
         that it puts on the wrong side of the exact region; trims(uv) is true exactly inside"
    );
}

#[testkit::test]
fn quadratic_newton_trim_matches_the_exact_region() {
    let trim = NewtonTrim::quadratic(QUADRATIC).unwrap();
    assert_eq!(
        misclassified(100, 0.005, &trim, in_quadratic),
        0,
        "NewtonTrim::quadratic(QUADRATIC): the samples of a 100² grid (those farther than 0.005 from the boundary) \\
         that it puts on the wrong side of the exact region; trims(uv) is true exactly inside"
    );
}

#[testkit::test]
fn cubic_newton_trim_matches_the_exact_region() {
    let trim = NewtonTrim::cubic(CUBIC).unwrap();
    assert_eq!(
        misclassified(100, 0.005, &trim, in_cubic),
        0,
        "NewtonTrim::cubic(CUBIC): the samples of a 100² grid (those farther than 0.005 from the boundary) \\
         that it puts on the wrong side of the exact region; trims(uv) is true exactly inside"
    );
}

#[testkit::test]
fn a_cubic_region_of_curves_running_right_to_left_is_the_same_region() {
    // Listing 9's curves p0 p1 p2 p3 and p0 p4 p5 p3, each reversed: every
    // inside point is now the second sign case.
    let [p0, p1, p2, p3, p4, p5] = CUBIC;
    let trim = NewtonTrim::new(vec![p3, p2, p1, p0], vec![p3, p5, p4, p0]).unwrap();
    assert_eq!(
        misclassified(100, 0.005, &trim, in_cubic),
        0,
        "NewtonTrim of CUBIC's curves each reversed: the samples of a 100² grid (those farther than 0.005 from the boundary) \\
         that it puts on the wrong side of the exact region; trims(uv) is true exactly inside"
    );
}

#[testkit::test]
fn a_nested_region_given_right_to_left_keeps_the_same_inner_region() {
    let ([a, b, c, d], [e, f, g, h]) = (QUADRATIC, INNER);
    let outer = NewtonTrim::quadratic([c, b, a, d]).unwrap();
    let inner = NewtonTrim::quadratic([g, f, e, h]).unwrap();
    let ring = NestedNewtonTrim::new(outer, inner);
    assert_eq!(
        misclassified(100, 0.005, &ring, |p| in_quadratic(p) && !in_inner(p)),
        0,
        "NestedNewtonTrim of the quadratic and the inner region, both given from the right: the samples of a 100² grid (those farther than 0.005 from the boundary) \\
         that it puts on the wrong side of the exact region; trims(uv) is true exactly inside"
    );
}

#[testkit::test]
fn nested_newton_trim_keeps_the_inner_region() {
    let outer = NewtonTrim::quadratic(QUADRATIC).unwrap();
    let inner = NewtonTrim::quadratic(INNER).unwrap();
    let ring = NestedNewtonTrim::new(outer, inner);
    assert!(
        ring.trims(uv(0.3, 0.5 + 1e-3)),
        "NestedNewtonTrim(QUADRATIC, INNER) trims (0.3, 0.501): inside the outer region, left of \
         the inner one"
    );
    assert!(
        !ring.trims(uv(0.5, 0.55)),
        "inside the inner curve the surface is drawn"
    );
    assert_eq!(
        misclassified(100, 0.005, &ring, |p| in_quadratic(p) && !in_inner(p)),
        0,
        "NestedNewtonTrim(QUADRATIC, INNER): the samples of a 100² grid (those farther than 0.005 from the boundary) \\
         that it puts on the wrong side of the exact region; trims(uv) is true exactly inside"
    );
}

#[testkit::test]
fn too_few_iterations_or_a_coarse_epsilon_spoil_the_edge() {
    // Seed §5.2: one iteration cannot find the crossings; the default can.
    let trim = NewtonTrim::cubic(CUBIC).unwrap();
    let one = trim.clone().with_settings(NewtonSettings {
        max_iterations: 1,
        epsilon: 0.001,
    });
    let wrong = misclassified(100, 0.005, &one, in_cubic);
    assert!(
        wrong > 100,
        "NewtonTrim::cubic(CUBIC) with max_iterations 1: one Newton step cannot find the \
         crossings, so more than 100 of the 100² samples come out wrong; yours only {wrong}"
    );
    assert_eq!(
        misclassified(100, 0.005, &trim, in_cubic),
        0,
        "NewtonTrim::cubic(CUBIC) at the default 10 iterations and ε = 0.001: the samples of a 100² grid (those farther than 0.005 from the boundary) \\
         that it puts on the wrong side of the exact region; trims(uv) is true exactly inside"
    );
}

/// Seed §5.2 (Figs. 29–34): how many of 100² samples of the cubic region
/// come out wrong, by iteration limit and ε. The sheet shows this table.
#[testkit::test]
fn iteration_and_epsilon_table() {
    let trim = NewtonTrim::cubic(CUBIC).unwrap();
    let epsilons = [0.1, 0.01, 0.001, 0.0001];
    let mut table = String::from("iterations |  ε = 0.1  |  ε = 0.01 | ε = 0.001 | ε = 0.0001\n");
    let mut worst_at_default_epsilon = Vec::new();
    for iterations in [2, 3, 4, 5, 6, 7, 10] {
        table.push_str(&format!("{iterations:>10} |"));
        for epsilon in epsilons {
            let t = trim.clone().with_settings(NewtonSettings {
                max_iterations: iterations,
                epsilon,
            });
            let wrong = misclassified(100, 0.0, &t, in_cubic);
            if epsilon == 0.001 {
                worst_at_default_epsilon.push(wrong);
            }
            table.push_str(&format!(" {wrong:>9} |"));
        }
        table.pop();
        table.push('\n');
    }
    // More iterations never hurt at the seed's ε.
    assert!(
        worst_at_default_epsilon.windows(2).all(|w| w[1] <= w[0]),
        "at ε = 0.001 more iterations never leave more samples wrong; yours (the ε = 0.001 \
         column, by iterations 2, 3, 4, 5, 6, 7, 10): {worst_at_default_epsilon:?}\n{table}"
    );
    insta::assert_snapshot!(table);
}

/// The same cubic region at 3 and at 10 iterations, as ASCII.
#[testkit::test]
fn cubic_trim_at_three_and_ten_iterations() {
    let trim = NewtonTrim::cubic(CUBIC).unwrap();
    let three = trim.clone().with_settings(NewtonSettings {
        max_iterations: 3,
        epsilon: 0.001,
    });
    let art = format!(
        "3 iterations:\n{}\n10 iterations:\n{}",
        common::ascii_trim(32, |p| three.trims(p)),
        common::ascii_trim(32, |p| trim.trims(p))
    );
    insta::assert_snapshot!(art);
}

// ---------------------------------------------------------------------------
// The seed's figures as pictures (Figs. 15–25), drawn by test code.

fn check_figure(name: &str, trim: &dyn Trim) {
    let picture = common::trim_figure(trim);
    testkit::image::assert_image_matches(
        name,
        &picture,
        common::image_path(name),
        testkit::image::Tolerance {
            channel: 2.0 / 255.0,
            mismatched_fraction: 0.001,
        },
    );
}

#[testkit::test]
fn figure_circle() {
    check_figure("trim_circle", &CircleTrim::new(uv(0.5, 0.5), 0.2).unwrap());
}

#[testkit::test]
fn figure_rectangle() {
    check_figure(
        "trim_rectangle",
        &IntervalTrim::new(uv(0.2, 0.35), uv(0.8, 0.65)).unwrap(),
    );
}

#[testkit::test]
fn figure_ellipse() {
    check_figure(
        "trim_ellipse",
        &EllipseTrim::new(uv(0.5, 0.5), uv(0.3, 0.15)).unwrap(),
    );
}

#[testkit::test]
fn figure_quadratic_newton() {
    check_figure(
        "trim_newton_quadratic",
        &NewtonTrim::quadratic(QUADRATIC).unwrap(),
    );
}

#[testkit::test]
fn figure_cubic_newton() {
    check_figure("trim_newton_cubic", &NewtonTrim::cubic(CUBIC).unwrap());
}

#[testkit::test]
fn figure_nested_newton() {
    let outer = NewtonTrim::quadratic(QUADRATIC).unwrap();
    let inner = NewtonTrim::quadratic(INNER).unwrap();
    check_figure("trim_newton_nested", &NestedNewtonTrim::new(outer, inner));
}

#[testkit::test]
fn hostile_curves_are_never_inside() {
    let s = NewtonSettings::default();
    let rule = "a curve or point that is empty or not finite is never inside";
    assert!(
        !between_crossings(&[], uv(0.5, 0.5), s),
        "between_crossings(no points, (0.5, 0.5)): {rule}"
    );
    assert!(
        !between_crossings(&[uv(0.5, 0.5)], uv(0.5, 0.5), s),
        "between_crossings(one point, that point): a single point bounds nothing"
    );
    let nan = [QUADRATIC[0], uv(f64::NAN, 0.9), QUADRATIC[2]];
    assert!(
        !between_crossings(&nan, uv(0.5, 0.6), s),
        "between_crossings(an arch with a NaN control point, (0.5, 0.6)): {rule}"
    );
    let arch = [QUADRATIC[0], QUADRATIC[1], QUADRATIC[2]];
    assert!(
        !between_crossings(&arch, uv(f64::INFINITY, 0.6), s),
        "between_crossings(the arch, (∞, 0.6)): {rule}"
    );
    let nan_settings = NewtonSettings {
        max_iterations: 10,
        epsilon: f64::NAN,
    };
    assert!(
        !between_crossings(&arch, uv(0.5, 0.6), nan_settings),
        "between_crossings(the arch, (0.5, 0.6)) with ε = NaN: |h| < NaN never holds, Newton \
         never converges, no crossing: not inside"
    );
    // With finite settings, the same point lies under the arch.
    assert!(
        between_crossings(&arch, uv(0.5, 0.6), s),
        "between_crossings(the arch, (0.5, 0.6)) with the default settings: under the arch, \
         inside"
    );
}

/// Seed §5.2 (Figs. 29–34) as one picture of six panels, the cubic region
/// trimmed out of the hill: 3 iterations (apexes missing), 6 and 7
/// iterations at ε = 0.0001 (where this region shows the seed's 6-or-7
/// difference, see the table), then ε = 0.1, 0.01 and 0.001 at the seed's
/// 10 iterations (0.1 stops early and leaves a ragged edge).
#[testkit::test]
fn figure_iterations_and_epsilon() {
    let trim = NewtonTrim::cubic(CUBIC).unwrap();
    let settings = [
        (3, 0.001),
        (6, 0.0001),
        (7, 0.0001),
        (10, 0.1),
        (10, 0.01),
        (10, 0.001),
    ];
    let [w, h] = common::FIGURE_SIZE;
    let mut strip = canvas::Canvas::new(6 * w, h);
    for (k, (max_iterations, epsilon)) in settings.into_iter().enumerate() {
        let panel = common::trim_figure(&trim.clone().with_settings(NewtonSettings {
            max_iterations,
            epsilon,
        }));
        for (p, colour) in panel.enumerate() {
            strip.set(canvas::Pixel::new(p.x + (k as u32 * w) as i32, p.y), colour);
        }
    }
    testkit::image::assert_image_matches(
        "trim_iterations_epsilon",
        &strip,
        common::image_path("trim_iterations_epsilon"),
        testkit::image::Tolerance {
            channel: 2.0 / 255.0,
            mismatched_fraction: 0.001,
        },
    );
}
