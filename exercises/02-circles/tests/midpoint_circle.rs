//! Task 1: the midpoint circle with a float decision variable.

mod common;

use canvas::{MAX_COORD, Pixel};
use circles::midpoint_circle::{circle_points, midpoint_circle};
use common::{
    HAND_CIRCLES, INK, circle_pixels, circle_row, closed_loop, collect, count, first_duplicate,
    grid_pixels, missing_mirror_image, radius_sheet, second_octant, within_limits,
};
use proptest::prelude::*;
use testkit::assert_pixels_eq;
use testkit::strategies::{hostile_pixel, pixel};

/// The pixels of `midpoint_circle(centre, radius)`, once the decisions it
/// reported are checked against the definition's (see
/// [`first_wrong_decision`]): every test of the walk checks the walk.
fn circle(centre: Pixel, radius: i32) -> Vec<Pixel> {
    let mut decided = Vec::new();
    let pixels = collect(|plot| {
        midpoint_circle(centre, radius, plot, |x, y, d| decided.push((x, y, d)));
    });
    let expected = if within_limits(centre, radius, radius) {
        decisions_by_definition(radius)
    } else {
        Vec::new()
    };
    if let Some(wrong) = first_wrong_decision(&decided, &expected) {
        panic!("midpoint_circle({centre}, {radius}): {wrong}");
    }
    pixels
}

/// A decision `midpoint_circle` reports: `(x, y, d)` before each step.
type Decision = (i32, i32, f64);

/// The decisions `midpoint_circle` reports.
fn decisions(centre: Pixel, radius: i32) -> Vec<Decision> {
    let mut reported = Vec::new();
    midpoint_circle(centre, radius, |_| {}, |x, y, d| reported.push((x, y, d)));
    reported
}

/// The decisions by the definition: at every pixel `(x, y)` of the second
/// octant with `y > x`, `F(x + 1, y − ½) = (x + 1)² + (y − ½)² − R²`,
/// computed in integers as a quarter of `4(x + 1)² + (2y − 1)² − 4R²`
/// (exact in an `f64`).
fn decisions_by_definition(radius: i32) -> Vec<Decision> {
    let r = i64::from(radius);
    second_octant(radius)
        .into_iter()
        .filter(|&(x, y)| y > x)
        .map(|(x, y)| {
            let quarters = 4 * (x + 1) * (x + 1) + (2 * y - 1) * (2 * y - 1) - 4 * r * r;
            (x as i32, y as i32, quarters as f64 / 4.0)
        })
        .collect()
}

/// The first difference between the decisions reported and expected, in
/// words.
fn first_wrong_decision(yours: &[(i32, i32, f64)], expected: &[(i32, i32, f64)]) -> Option<String> {
    for (k, (y, e)) in yours.iter().zip(expected).enumerate() {
        if y.0 != e.0 || y.1 != e.1 || y.2.to_bits() != e.2.to_bits() {
            return Some(format!(
                "decision {k}: you reported d = {} at ({}, {}), the midpoint rule decides \
                 with d = F(x + 1, y − ½) = {} at ({}, {}) (F = x² + y² − R², d starts at \
                 5/4 − R and grows by 2x + 3 after E, 2(x − y) + 5 after SE)",
                y.2, y.0, y.1, e.2, e.0, e.1
            ));
        }
    }
    (yours.len() != expected.len()).then(|| {
        format!(
            "you reported {} decisions, the walk takes {}: one at every pixel of the \
             second octant with y > x, before the step from it",
            yours.len(),
            expected.len()
        )
    })
}

fn points(centre: Pixel, x: i32, y: i32) -> Vec<Pixel> {
    collect(|plot| circle_points(centre, x, y, &mut |p| plot(p)))
}

#[testkit::test]
fn circle_points_plots_each_mirror_image_once() {
    let c = Pixel::new(10, -4);
    let at = |dx: i32, dy: i32| Pixel::new(c.x + dx, c.y + dy);
    // 0 < x < y: eight different pixels.
    let eight = points(c, 2, 5);
    assert_eq!(eight.len(), 8, "(2, 5) has eight mirror images: {eight:?}");
    assert_pixels_eq(
        &[
            at(2, 5),
            at(5, 2),
            at(5, -2),
            at(2, -5),
            at(-2, -5),
            at(-5, -2),
            at(-5, 2),
            at(-2, 5),
        ],
        &eight,
        "circle_points(c, 2, 5)",
    );
    // x = 0: (0, y) and (-0, y) are one pixel. Four pixels on the axes.
    let axes = points(c, 0, 5);
    assert_eq!(axes.len(), 4, "(0, 5) has four mirror images: {axes:?}");
    assert_pixels_eq(
        &[at(0, 5), at(5, 0), at(0, -5), at(-5, 0)],
        &axes,
        "circle_points(c, 0, 5)",
    );
    // x = y: (x, y) and (y, x) are one pixel. Four pixels on the diagonals.
    let diagonals = points(c, 3, 3);
    assert_eq!(
        diagonals.len(),
        4,
        "(3, 3) has four mirror images: {diagonals:?}"
    );
    assert_pixels_eq(
        &[at(3, 3), at(-3, 3), at(3, -3), at(-3, -3)],
        &diagonals,
        "circle_points(c, 3, 3)",
    );
    // Radius 0: the centre, once.
    assert_eq!(
        points(c, 0, 0),
        [c],
        "circle_points({c}, 0, 0): all eight mirror images are the centre, plotted once"
    );
}

#[testkit::test]
fn small_radii_match_the_slides_by_hand() {
    // The slides' loop, run by hand (d after each step; E: d += 2x + 3,
    // SE: d += 2(x − y) + 5 with x, y before the step):
    //   R = 0: (0,0); no step: the centre alone.
    //   R = 1: d = 0.25; (0,1); SE → (1,0), past the diagonal: stop.
    //   R = 2: d = −0.75; (0,2); E, d = 2.25 → (1,2); SE → (2,1): stop.
    //   R = 3: d = −1.75; (0,3); E, d = 1.25 → (1,3); SE, d = 2.25 → (2,2).
    //   R = 5: d = −3.75; (0,5); E, d = −0.75 → (1,5); E, d = 4.25 → (2,5);
    //          SE, d = 3.25 → (3,4); SE → (4,3): stop.
    // Each second-octant pixel mirrored eight ways gives these grids.
    for (radius, rows) in HAND_CIRCLES {
        let centre = Pixel::new(-3, 7);
        let yours = circle(centre, radius);
        assert_pixels_eq(
            &grid_pixels(centre, rows),
            &yours,
            &format!("midpoint_circle({centre}, {radius})"),
        );
        assert_eq!(
            first_duplicate(&yours),
            None,
            "midpoint_circle({centre}, {radius}) plots the pixel on the left twice: mirror images \
             that coincide are plotted once"
        );
    }
}

#[testkit::test]
fn radius_8_follows_the_slides_step_by_step() {
    //   8 |■■■        d: −6.75 E −3.75 E 1.25 SE −5.75 E 3.25 SE 2.25 SE
    //   7 |   ■■         (0,8)  (1,8)  (2,8)  (3,7)  (4,7)  (5,6)  (6,5):
    //   6 |     ■        the last step crossed the diagonal: not plotted
    //     +------ x
    let centre = Pixel::new(0, 0);
    let octant: Vec<Pixel> = circle(centre, 8)
        .into_iter()
        .filter(|p| 0 <= p.x && p.x <= p.y)
        .collect();
    let expected = [(0, 8), (1, 8), (2, 8), (3, 7), (4, 7), (5, 6)].map(|(x, y)| Pixel::new(x, y));
    assert_pixels_eq(
        &expected,
        &octant,
        "the second octant of midpoint_circle((0, 0), 8)",
    );
}

#[testkit::test]
fn the_decision_variable_follows_the_slides_by_hand() {
    // The traces above: d at each pixel before its step.
    let traces: [(i32, &[Decision]); 5] = [
        (0, &[]),
        (1, &[(0, 1, 0.25)]),
        (2, &[(0, 2, -0.75), (1, 2, 2.25)]),
        (
            5,
            &[(0, 5, -3.75), (1, 5, -0.75), (2, 5, 4.25), (3, 4, 3.25)],
        ),
        (
            8,
            &[
                (0, 8, -6.75),
                (1, 8, -3.75),
                (2, 8, 1.25),
                (3, 7, -5.75),
                (4, 7, 3.25),
                (5, 6, 2.25),
            ],
        ),
    ];
    for (radius, expected) in traces {
        let yours = decisions(Pixel::new(4, -2), radius);
        if let Some(wrong) = first_wrong_decision(&yours, expected) {
            panic!("midpoint_circle((4, -2), {radius}): {wrong}");
        }
    }
}

#[testkit::test]
fn circles_of_small_radii() {
    let sheet = radius_sheet(&[0, 1, 2, 3, 5, 8], |c, r, canvas| {
        midpoint_circle(c, r, |p| canvas.set(p, INK), |_, _, _| {})
    });
    testkit::insta::assert_snapshot!("circles_of_small_radii", sheet);
}

#[testkit::test]
fn hostile_input_draws_nothing_and_returns_at_once() {
    let origin = Pixel::new(0, 0);
    for (centre, radius) in [
        (origin, -1),
        (origin, i32::MIN),
        (origin, i32::MAX),
        (origin, MAX_COORD + 1),
        (Pixel::new(i32::MAX, i32::MAX), 0),
        (Pixel::new(i32::MIN, 0), 3),
        (Pixel::new(MAX_COORD, 0), 1),
        (Pixel::new(0, -MAX_COORD), 1),
        (Pixel::new(MAX_COORD / 2, 0), MAX_COORD / 2 + 1),
    ] {
        let drawn = count(|plot| midpoint_circle(centre, radius, plot, |_, _, _| {}));
        assert!(
            drawn == 0,
            "midpoint_circle({centre}, {radius}) must draw nothing (a negative radius, or a circle \
             reaching beyond ±MAX_COORD = {MAX_COORD}); yours drew {drawn} pixels"
        );
    }
    // Right at the limit: radius 0 is the centre, and a circle touching
    // ±MAX_COORD is drawn.
    let edge = Pixel::new(MAX_COORD, -MAX_COORD);
    assert_eq!(
        circle(edge, 0),
        [edge],
        "midpoint_circle({edge}, 0): radius 0 is the centre pixel, plotted once, even at ±MAX_COORD"
    );
    let touching = Pixel::new(MAX_COORD - 3, 3 - MAX_COORD);
    assert_pixels_eq(
        &circle_pixels(touching, 3),
        &circle(touching, 3),
        "a circle touching ±MAX_COORD",
    );
}

#[testkit::test]
fn huge_radius_is_still_exact() {
    // |d| reaches 2R; an f32 holds d = k + ¼ exactly only below 2²², and
    // from radii of about eight million on its rounding picks wrong
    // pixels. The f64 of the sheet does not. (Only the first 100 000
    // columns of the second octant are compared, to keep the test quick.)
    const COLUMNS: i32 = 100_000;
    let radius = 10_313_530;
    let centre = Pixel::new(0, 0);
    let mut yours = Vec::new();
    midpoint_circle(
        centre,
        radius,
        |p| {
            if (0..COLUMNS).contains(&p.x) && p.x <= p.y {
                yours.push(p);
            }
        },
        |_, _, _| {},
    );
    let r = i64::from(radius);
    let expected: Vec<Pixel> = (0..i64::from(COLUMNS))
        .map(|x| Pixel::new(x as i32, circle_row(r, x) as i32))
        .collect();
    assert_pixels_eq(
        &expected,
        &yours,
        &format!("the first {COLUMNS} columns of midpoint_circle({centre}, {radius})"),
    );
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn pixels_are_the_nearest_in_each_column_of_the_second_octant(centre in pixel(50), radius in 0..120) {
        let yours = circle(centre, radius);
        assert_pixels_eq(&circle_pixels(centre, radius), &yours, &format!("midpoint_circle({centre}, {radius})"));
    }

    #[testkit::test]
    fn each_decision_is_f_at_the_midpoint_before_the_step(centre in pixel(1000), radius in 0..3000) {
        let yours = decisions(centre, radius);
        if let Some(wrong) = first_wrong_decision(&yours, &decisions_by_definition(radius)) {
            prop_assert!(false, "midpoint_circle({}, {}): {}", centre, radius, wrong);
        }
    }

    #[testkit::test]
    fn no_pixel_is_plotted_twice(centre in pixel(50), radius in 0..120) {
        let yours = circle(centre, radius);
        prop_assert!(yours.contains(&Pixel::new(centre.x + radius, centre.y)), "{}({}, {}) does not draw its rightmost point {}", "midpoint_circle", centre, radius, Pixel::new(centre.x + radius, centre.y));
        prop_assert_eq!(first_duplicate(&yours), None, "midpoint_circle({}, {}) plots a pixel twice", centre, radius);
    }

    #[testkit::test]
    fn circle_has_eightfold_symmetry(centre in pixel(50), radius in 0..120) {
        let yours = circle(centre, radius);
        prop_assert!(yours.contains(&Pixel::new(centre.x + radius, centre.y)), "{}({}, {}) does not draw its rightmost point {}", "midpoint_circle", centre, radius, Pixel::new(centre.x + radius, centre.y));
        if let Some((p, image)) = missing_mirror_image(&yours, centre, true) {
            prop_assert!(false, "midpoint_circle({}, {}) draws {} but not its mirror image {}", centre, radius, p, image);
        }
    }

    #[testkit::test]
    fn every_pixel_is_within_half_a_pixel_of_the_circle(centre in pixel(50), radius in 1..120) {
        // With m = max(|dx|, |dy|) and n = min(|dx|, |dy|): the circle
        // crosses the pixel's row or column (the one along n) between
        // m − ½ and m + ½, i.e. |√(R² − n²) − m| < ½, in integers
        // (2m − 1)² < 4(R² − n²) < (2m + 1)².
        let r = i64::from(radius);
        let yours = circle(centre, radius);
        prop_assert!(yours.contains(&Pixel::new(centre.x + radius, centre.y)), "{}({}, {}) does not draw its rightmost point {}", "midpoint_circle", centre, radius, Pixel::new(centre.x + radius, centre.y));
        for p in yours {
            let (dx, dy) = (i64::from(p.x - centre.x).abs(), i64::from(p.y - centre.y).abs());
            let (m, n) = (dx.max(dy), dx.min(dy));
            let s = 4 * (r * r - n * n);
            prop_assert!((2 * m - 1).pow(2) < s && s < (2 * m + 1).pow(2),
                "midpoint_circle({}, {}) draws {}, more than half a pixel off the circle", centre, radius, p);
        }
    }

    #[testkit::test]
    fn one_pixel_per_column_of_the_second_octant_and_no_gaps(centre in pixel(50), radius in 0..120) {
        let yours = circle(centre, radius);
        // The second octant (0 ≤ dx ≤ dy): columns 0, 1, 2, … each once,
        // each one row below the last or level with it.
        let mut octant: Vec<(i32, i32)> = yours.iter()
            .map(|p| (p.x - centre.x, p.y - centre.y))
            .filter(|&(dx, dy)| 0 <= dx && dx <= dy)
            .collect();
        octant.sort();
        let columns: Vec<i32> = octant.iter().map(|&(dx, _)| dx).collect();
        let expected: Vec<i32> = (0..second_octant(radius).len() as i32).collect();
        prop_assert_eq!(columns, expected, "midpoint_circle({}, {}): the columns dx of its pixels in the second octant (0 ≤ dx ≤ dy), left, must be 0, 1, 2, … each once, right", centre, radius);
        for w in octant.windows(2) {
            prop_assert!(w[1].1 == w[0].1 || w[1].1 == w[0].1 - 1, "midpoint_circle({}, {}): in the second octant offset {:?} is followed by {:?}; the next column is on the same row (E) or one below (SE)", centre, radius, w[0], w[1]);
        }
        // All around: a closed loop of touching pixels.
        closed_loop(&yours, centre).map_err(|e| TestCaseError::fail(format!("midpoint_circle({centre}, {radius}) is not a closed 8-connected loop: {e}")))?;
    }

    #[testkit::test]
    fn circles_near_the_coordinate_limit_are_exact(radius in 0..40, slack in 0..3, sx in prop::bool::ANY, sy in prop::bool::ANY) {
        let far = MAX_COORD - radius - slack;
        let centre = Pixel::new(if sx { far } else { -far }, if sy { far } else { -far });
        assert_pixels_eq(&circle_pixels(centre, radius), &circle(centre, radius), &format!("midpoint_circle({centre}, {radius})"));
        let over = Pixel::new(centre.x, if sy { far + slack + 1 } else { -far - slack - 1 });
        prop_assert_eq!(count(|plot| midpoint_circle(over, radius, plot, |_, _, _| {})), 0, "midpoint_circle({}, {}) reaches beyond ±MAX_COORD = {}: it must draw nothing (left: the pixels yours drew)", over, radius, MAX_COORD);
    }

    #[testkit::test]
    fn hostile_input_draws_nothing_or_the_exact_circle(
        centre in hostile_pixel(),
        radius in prop_oneof![Just(i32::MIN), Just(-1), Just(MAX_COORD + 1), Just(i32::MAX), any::<i32>(), 0..40],
    ) {
        if within_limits(centre, radius, radius) && radius < 1000 {
            assert_pixels_eq(&circle_pixels(centre, radius), &circle(centre, radius), &format!("midpoint_circle({centre}, {radius})"));
        } else if !within_limits(centre, radius, radius) {
            prop_assert_eq!(count(|plot| midpoint_circle(centre, radius, plot, |_, _, _| {})), 0, "midpoint_circle({}, {}) reaches beyond ±MAX_COORD = {} or has a negative radius: it must draw nothing (left: the pixels yours drew)", centre, radius, MAX_COORD);
        }
        // Refusing one is no reason to refuse the next.
        prop_assert!(count(|plot| midpoint_circle(Pixel::new(0, 0), 3, plot, |_, _, _| {})) > 0, "midpoint_circle((0, 0), 3), called after midpoint_circle({}, {}), drew nothing: refusing one circle is no reason to refuse the next", centre, radius);
    }
}
