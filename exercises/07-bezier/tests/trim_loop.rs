//! Task 5: point in a region bounded by closed loops of Bézier curves, of
//! any degree and orientation, by ray-crossing parity — beyond seed 000,
//! whose Newton trimming needs the end points on one horizontal line
//! (§5.2, Fig. 28).

use bezier::BezierError;
use bezier::Trim;
use bezier::ray_parity::{TrimLoop, TrimRegion, crossing_parity};
use glam::{DMat2, DVec2};
use proptest::prelude::*;

fn p(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

/// The parabola y = x² for x ∈ [−1, 1] is exactly the quadratic Bézier
/// (−1, 1), (0, −1), (1, 1): x = 2t − 1, y = (2t − 1)². Closed by the line
/// back from (1, 1) to (−1, 1), it bounds x² < y < 1.
///
/// ```text
///   (−1,1) ●─────────────● (1,1)
///           \           /
///            '-.     .-'
///               '-●-'        (0, 0); control point (0, −1)
/// ```
fn parabola_loop() -> Vec<Vec<DVec2>> {
    vec![
        vec![p(-1.0, 1.0), p(0.0, -1.0), p(1.0, 1.0)],
        vec![p(1.0, 1.0), p(-1.0, 1.0)],
    ]
}

fn in_parabola(q: DVec2) -> bool {
    q.x * q.x < q.y && q.y < 1.0
}

/// Distance of `q` from the parabola region's boundary is at least `margin`
/// (checked on a dense sampling of the boundary).
fn far_from_parabola(q: DVec2, margin: f64) -> bool {
    let near_line = (q.y - 1.0).abs() < margin && q.x.abs() < 1.0 + margin;
    let near_curve = (0..=2000).any(|k| {
        let x = -1.0 + f64::from(k) / 1000.0;
        q.distance(p(x, x * x)) < margin
    });
    !near_line && !near_curve
}

fn region(loops: Vec<Vec<Vec<DVec2>>>) -> TrimRegion {
    TrimRegion::new(
        loops
            .into_iter()
            .map(|l| TrimLoop::new(l).unwrap())
            .collect(),
    )
}

#[testkit::test]
fn a_segment_is_crossed_once_from_its_left() {
    let segment = [p(0.0, -1.0), p(0.0, 1.0)];
    for (a, crossed, why) in [
        (
            p(-1.0, 0.0),
            true,
            "the segment crosses the ray at u = 0 > −1",
        ),
        (
            p(1.0, 0.0),
            false,
            "the segment lies left of the ray's start",
        ),
        (
            p(-1.0, 2.0),
            false,
            "the segment lies below the ray's level",
        ),
    ] {
        assert_eq!(
            crossing_parity(&segment, a),
            crossed,
            "crossing_parity((0, −1) → (0, 1), {a}): {why}; the ray a + x·(1, 0), x > 0, is \
             crossed where the curve changes side (v ≥ a.v above) at u > a.u"
        );
    }
}

#[testkit::test]
fn end_points_on_the_ray_follow_the_half_open_rule() {
    // v ≥ a.v counts as above: a segment from the ray upwards never
    // changes side; one from below up to the ray does.
    //
    //   ●  (1, 1)
    //   |
    //   ●  (1, 0) ← ray from (0, 0) →
    //   |
    //   ●  (1, −1)
    let a = p(0.0, 0.0);
    let rule = "a point with v ≥ a.v counts as above (the half-open rule)";
    assert!(
        !crossing_parity(&[p(1.0, 0.0), p(1.0, 1.0)], a),
        "crossing_parity((1, 0) → (1, 1), (0, 0)): {rule}, so a segment from the ray upwards \
         never changes side: not crossed"
    );
    assert!(
        crossing_parity(&[p(1.0, -1.0), p(1.0, 0.0)], a),
        "crossing_parity((1, −1) → (1, 0), (0, 0)): {rule}, so a segment from below up to the \
         ray changes side: crossed"
    );
    // Together, a path through the ray's level is crossed once.
    let up = [p(1.0, -1.0), p(1.0, 0.0)];
    let on = [p(1.0, 0.0), p(1.0, 1.0)];
    assert!(
        crossing_parity(&up, a) ^ crossing_parity(&on, a),
        "(1, −1) → (1, 0) → (1, 1) crosses the ray from (0, 0) once: exactly one of its two \
         segments counts ({rule})"
    );
    // A tangency (touching the ray from below) is no crossing.
    assert!(
        !crossing_parity(&[p(1.0, -1.0), p(2.0, 1.0), p(3.0, -1.0)], a),
        "crossing_parity((1, −1), (2, 1), (3, −1); (0, 0)): the curve touches the ray's level \
         from below and goes back, ending on the side it started: not crossed"
    );
}

#[testkit::test]
fn the_parabola_is_crossed_twice_or_once() {
    let parabola = &parabola_loop()[0];
    // Ray at y = ¼ meets y = x² at x = ±½.
    for (a, crossed, why) in [
        (
            p(-2.0, 0.25),
            false,
            "the ray crosses it twice, at x = −½ and ½",
        ),
        (p(0.0, 0.25), true, "the ray crosses it once, at x = ½"),
        (
            p(0.6, 0.25),
            false,
            "both crossings lie behind the ray's start",
        ),
    ] {
        assert_eq!(
            crossing_parity(parabola, a),
            crossed,
            "crossing_parity(the parabola y = x², {a}): {why}; the parity is odd exactly for \
             one crossing"
        );
    }
}

#[testkit::test]
fn parabola_region_is_exact() {
    let r = region(vec![parabola_loop()]);
    for (q, inside) in [
        (p(0.0, 0.5), true),
        (p(0.0, -0.01), false),
        (p(0.7, 0.5), true),
        (p(0.71, 0.5), false), // √½ ≈ 0.7071
        (p(0.0, 1.01), false),
        (p(-0.99, 0.99), true),
        (p(5.0, 0.5), false),
    ] {
        assert_eq!(
            r.contains(q),
            inside,
            "the region x² < y < 1, contains({q}): an odd number of crossings of the ray from it \
             (√½ ≈ 0.7071)"
        );
        assert_eq!(
            r.trims(q),
            inside,
            "the region x² < y < 1, trims({q}): a TrimRegion trims what it contains"
        );
    }
}

#[testkit::test]
fn a_loop_inside_a_loop_is_a_hole() {
    // A square with the parabola region, shrunk, as a hole, and a
    // square island inside that.
    let square = |c: DVec2, h: f64| {
        let k = [c + p(-h, -h), c + p(h, -h), c + p(h, h), c + p(-h, h)];
        (0..4)
            .map(|i| vec![k[i], k[(i + 1) % 4]])
            .collect::<Vec<_>>()
    };
    let hole: Vec<Vec<DVec2>> = parabola_loop()
        .into_iter()
        .map(|c| c.into_iter().map(|q| q * 0.5).collect())
        .collect();
    let r = region(vec![
        square(p(0.0, 0.2), 2.0),
        hole,
        square(p(0.0, 0.3), 0.05),
    ]);
    let rule = "a square with the shrunk parabola as a hole and a small square island in that: \
                loops in loops alternate (even-odd rule)";
    assert!(
        r.contains(p(1.5, 0.0)),
        "{rule}; (1.5, 0) lies in the square, outside the hole: inside"
    );
    assert!(!r.contains(p(0.0, 0.4)), "{rule}; (0, 0.4) is in the hole");
    assert!(r.contains(p(0.0, 0.3)), "{rule}; (0, 0.3) is on the island");
    assert!(
        !r.contains(p(3.0, 0.0)),
        "{rule}; (3, 0) is outside the square"
    );
}

#[testkit::test]
fn end_points_at_different_heights_are_fine() {
    // The seed's Fig. 28 case: an arch from (0.2, 0.4) to (0.8, 0.6). Its
    // u is linear in t, so the exact region is known: between the
    // straight chord v = 0.4 + (u − 0.2)/3 and the arch above it.
    let arch = vec![p(0.2, 0.4), p(0.5, 0.9), p(0.8, 0.6)];
    let chord = vec![p(0.8, 0.6), p(0.2, 0.4)];
    let r = region(vec![vec![arch, chord]]);
    for row in 0..50 {
        for col in 0..50 {
            let q = (p(f64::from(col), f64::from(row)) + 0.5) / 50.0;
            let t = (q.x - 0.2) / 0.6;
            let s = 1.0 - t;
            let top = 0.4 * s * s + 2.0 * 0.9 * t * s + 0.6 * t * t;
            let bottom = 0.4 + t * 0.2;
            let inside = (0.0..=1.0).contains(&t) && q.y > bottom && q.y < top;
            let margin = (q.y - top).abs().min((q.y - bottom).abs());
            if margin > 1e-9 {
                assert_eq!(
                    r.contains(q),
                    inside,
                    "the arch (0.2, 0.4), (0.5, 0.9), (0.8, 0.6) closed by its chord, contains({q}): \
                     inside exactly between the chord v = {bottom} and the arch v = {top} here"
                );
            }
        }
    }
}

#[testkit::test]
fn points_on_the_boundary_terminate() {
    let r = region(vec![parabola_loop()]);
    for q in [
        p(0.0, 0.0),
        p(1.0, 1.0),
        p(-1.0, 1.0),
        p(0.5, 0.25),
        p(0.3, 1.0),
    ] {
        let _either_way = r.contains(q);
    }
    // Off the boundary, the answers are clear.
    assert!(
        r.contains(p(0.0, 0.5)) && !r.contains(p(0.0, 2.0)),
        "the region x² < y < 1 contains (0, 0.5) and not (0, 2), yours {} and {}",
        r.contains(p(0.0, 0.5)),
        r.contains(p(0.0, 2.0))
    );
    // A curve of the highest degree through the point.
    let wiggle: Vec<DVec2> = (0..=bezier::MAX_DEGREE)
        .map(|i| p(i as f64, if i % 2 == 0 { 1.0 } else { -1.0 }))
        .collect();
    let _either_way = crossing_parity(&wiggle, p(16.0, 0.0));
}

#[testkit::test]
fn invalid_loops_are_clear_errors_and_nan_is_outside() {
    assert_eq!(
        TrimLoop::new(vec![]),
        Err(BezierError::Empty),
        "TrimLoop::new of no curves is Empty (the given constructor)"
    );
    assert_eq!(
        TrimLoop::new(vec![vec![]]),
        Err(BezierError::Empty),
        "TrimLoop::new of a curve without points is Empty"
    );
    let open = vec![
        vec![p(0.0, 0.0), p(1.0, 0.0)],
        vec![p(1.0, 0.5), p(0.0, 0.0)],
    ];
    assert_eq!(
        TrimLoop::new(open),
        Err(BezierError::LoopNotClosed {
            curve: 1,
            previous: 0
        }),
        "TrimLoop::new: curve 1 starts at (1, 0.5), not where curve 0 ends: LoopNotClosed"
    );
    let nan = vec![vec![p(0.0, 0.0), p(f64::NAN, 0.0), p(0.0, 0.0)]];
    assert_eq!(
        TrimLoop::new(nan),
        Err(BezierError::NonFinitePoint { index: 1 }),
        "TrimLoop::new with a NaN in point 1: NonFinitePoint naming it"
    );
    let long = vec![vec![p(0.0, 0.0); bezier::MAX_DEGREE + 2]];
    assert!(
        matches!(TrimLoop::new(long), Err(BezierError::DegreeTooHigh { .. })),
        "TrimLoop::new with a curve of MAX_DEGREE + 2 points: DegreeTooHigh"
    );
    let r = region(vec![parabola_loop()]);
    for q in [
        p(f64::NAN, 0.5),
        p(0.0, f64::NAN),
        p(f64::INFINITY, 0.5),
        p(0.0, f64::NEG_INFINITY),
    ] {
        assert!(
            !r.contains(q),
            "the region x² < y < 1, contains({q}): a point with a NaN or infinite coordinate is \
             outside"
        );
    }
    assert!(
        r.contains(p(0.0, 0.5)),
        "(0, 0.5) lies inside the parabola's loop"
    );
    assert!(
        !TrimRegion::new(vec![]).contains(p(0.0, 0.5)),
        "a region of no loops contains nothing"
    );
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn parabola_region_matches_its_formula(x in -1.5..1.5_f64, y in -0.5..1.5_f64) {
        let q = p(x, y);
        prop_assume!(far_from_parabola(q, 1e-6));
        prop_assert_eq!(region(vec![parabola_loop()]).contains(q), in_parabola(q), "the region x² < y < 1, contains({}) (left: yours, right: the formula)", q);
    }

    #[testkit::test]
    fn rotation_translation_and_orientation_do_not_matter(
        x in -1.5..1.5_f64, y in -0.5..1.5_f64,
        angle in 0.0..std::f64::consts::TAU,
        shift in (-10.0..10.0_f64, -10.0..10.0_f64),
        reversed: bool,
    ) {
        let q = p(x, y);
        prop_assume!(far_from_parabola(q, 1e-6));
        let rotation = DMat2::from_angle(angle);
        let map = |v: DVec2| rotation * v + p(shift.0, shift.1);
        let mut curves: Vec<Vec<DVec2>> = parabola_loop()
            .into_iter()
            .map(|c| c.into_iter().map(map).collect())
            .collect();
        if reversed {
            curves.reverse();
            for c in &mut curves {
                c.reverse();
            }
        }
        prop_assert_eq!(region(vec![curves]).contains(map(q)), in_parabola(q), "the region x² < y < 1 turned by {} rad, moved by ({}, {}){}: contains({}), the image of {} (left: yours, right: the formula at {}); rotation, translation and orientation do not matter", angle, shift.0, shift.1, if reversed { ", curves reversed" } else { "" }, map(q), q, q);
    }
}

#[testkit::test]
fn hostile_curves_never_hang_or_panic() {
    let a = p(0.0, 0.0);
    let rule = "a curve or point that is empty or not finite is never crossed";
    assert!(
        !crossing_parity(&[], a),
        "crossing_parity(no points, (0, 0)): {rule}"
    );
    assert!(
        !crossing_parity(&[p(f64::NAN, 1.0), p(1.0, -1.0)], a),
        "crossing_parity((NaN, 1) → (1, −1), (0, 0)): {rule}"
    );
    assert!(
        !crossing_parity(&[p(1.0, 1.0), p(1.0, -1.0)], p(f64::NAN, 0.0)),
        "crossing_parity((1, 1) → (1, −1), (NaN, 0)): {rule}"
    );
    assert!(
        !crossing_parity(&[p(-f64::MAX, 1.0), p(f64::MAX, -1.0)], p(f64::MAX, 0.0)),
        "crossing_parity((−MAX, 1) → (MAX, −1), (MAX, 0)): the segment crosses the level at \
         u = 0, behind the ray's start at u = f64::MAX: not crossed"
    );
    // Huge but finite: halving never overflows.
    let huge = [
        p(-f64::MAX, -f64::MAX),
        p(f64::MAX, f64::MAX),
        p(f64::MAX, -f64::MAX),
    ];
    let _either_way = crossing_parity(&huge, a);
    // An ordinary segment across the ray is crossed.
    assert!(
        crossing_parity(&[p(1.0, 1.0), p(1.0, -1.0)], a),
        "crossing_parity((1, 1) → (1, −1), (0, 0)): an ordinary segment across the ray is crossed"
    );
}
