//! Task 2: the midpoint circle in integers, with second-order differences.

mod common;

use canvas::{MAX_COORD, Pixel};
use circles::integer_circle::{Walk, integer_circle};
use common::{
    HAND_CIRCLES, INK, circle_pixels, circle_row, closed_loop, collect, count, first_duplicate,
    grid_pixels, missing_mirror_image, radius_sheet, within_limits,
};
use proptest::prelude::*;
use testkit::assert_pixels_eq;
use testkit::strategies::{hostile_pixel, pixel};

/// Checks the states of the walk `integer_circle` reports, as they come,
/// against their definitions: one at every pixel of the walk from
/// `(0, R)` while `y > x`, with `h = d − ¼ = (x + 1)² + y² − y − R²`,
/// `ΔE = 2x + 3`, `ΔSE = 2(x − y) + 5`; none for a circle that draws
/// nothing. At each one it also steps a copy that no circle has (see
/// [`odd_step`]): the walk must add what it holds.
struct WalkCheck {
    radius: i64,
    x: i64,
    y: i64,
    count: u64,
    walks: bool,
    error: Option<String>,
}

impl WalkCheck {
    fn new(centre: Pixel, radius: i32) -> Self {
        let walks = within_limits(centre, radius, radius);
        let r = i64::from(radius);
        Self {
            radius: r,
            x: 0,
            y: r,
            count: 0,
            walks,
            error: None,
        }
    }

    fn expected(&self) -> Option<Walk> {
        let (x, y, r) = (self.x, self.y, self.radius);
        (self.walks && y > x).then(|| Walk {
            x: x as i32,
            y: y as i32,
            h: (x + 1) * (x + 1) + y * y - y - r * r,
            delta_e: 2 * x + 3,
            delta_se: 2 * (x - y) + 5,
        })
    }

    fn see(&mut self, walk: Walk) {
        if self.error.is_some() {
            return;
        }
        match self.expected() {
            None => {
                self.error = Some(format!(
                    "reported {walk:?} after the walk ended (after {} states)",
                    self.count
                ));
            }
            Some(expected) if expected != walk => {
                self.error = Some(format!(
                    "state {} is {walk:?}, by the definitions it is {expected:?}",
                    self.count
                ));
            }
            Some(expected) => {
                if let Err(error) = odd_step(expected) {
                    self.error = Some(format!("at state {}: {error}", self.count));
                    return;
                }
                self.x += 1;
                if expected.h >= 0 {
                    self.y -= 1;
                }
                self.count += 1;
            }
        }
    }

    #[track_caller]
    fn finish(self, call: &str) {
        if let Some(error) = &self.error {
            panic!("{call}: {error}");
        }
        if let Some(missing) = self.expected() {
            panic!(
                "{call}: {} states reported, the walk goes on at {missing:?}",
                self.count
            );
        }
    }
}

/// What `Walk::step` must make of `walk`: the table's sums, whatever the
/// numbers are.
fn by_the_table(walk: Walk) -> Walk {
    if walk.h < 0 {
        Walk {
            x: walk.x + 1,
            y: walk.y,
            h: walk.h + walk.delta_e,
            delta_e: walk.delta_e + 2,
            delta_se: walk.delta_se + 2,
        }
    } else {
        Walk {
            x: walk.x + 1,
            y: walk.y - 1,
            h: walk.h + walk.delta_se,
            delta_e: walk.delta_e + 2,
            delta_se: walk.delta_se + 4,
        }
    }
}

/// Steps a copy of the circle's state `walk` that no circle has: `h`
/// moved by about 2⁶⁰ away from 0 (so the step goes the same way, and a
/// float, with 53 bits, cannot hold it), `ΔE` and `ΔSE` moved far from
/// `2x + 3` and `2(x − y) + 5`. `Walk::step` must give the table's sums
/// of what it holds: a walk that recomputes its increments from `x` and
/// `y`, or `h` from the radius, or adds in `f64`, gives other numbers.
fn odd_step(walk: Walk) -> Result<(), String> {
    const FAR: i64 = (1 << 60) + 1;
    let odd = Walk {
        h: if walk.h < 0 {
            walk.h - FAR
        } else {
            walk.h + FAR
        },
        delta_e: walk.delta_e + (3 << 40) + 7,
        delta_se: walk.delta_se - (5 << 40) - 9,
        ..walk
    };
    let mut yours = odd;
    yours.step();
    let expected = by_the_table(odd);
    if yours == expected {
        Ok(())
    } else {
        Err(format!(
            "Walk::step of {odd:?} gives {yours:?}, adding what it holds gives {expected:?} \
             (the step must add the increments it carries, in integers)"
        ))
    }
}

/// Runs `integer_circle`, checking every state it reports (see
/// [`WalkCheck`]): every test grades the integer walk, not only its
/// pixels.
#[track_caller]
fn draw(centre: Pixel, radius: i32, plot: impl FnMut(Pixel)) {
    let mut check = WalkCheck::new(centre, radius);
    integer_circle(centre, radius, plot, |w| check.see(w));
    check.finish(&format!("integer_circle({centre}, {radius})"));
}

fn circle(centre: Pixel, radius: i32) -> Vec<Pixel> {
    collect(|plot| draw(centre, radius, plot))
}

#[testkit::test]
fn small_radii_match_the_slides_by_hand() {
    // The same grids as the float version (see tests/midpoint_circle.rs),
    // now from h = d − ¼ = 1 − R, ΔE = 3, ΔSE = 5 − 2R. For R = 5:
    //   (0,5) h = −4 E → (1,5) h = −1 E → (2,5) h = 4 SE → (3,4) h = 3 SE
    //   → (4,3): past the diagonal, stop. (ΔE: 3, 5, 7, 9; ΔSE: −5, −3, −1, 3.)
    for (radius, rows) in HAND_CIRCLES {
        let centre = Pixel::new(4, -2);
        let yours = circle(centre, radius);
        assert_pixels_eq(
            &grid_pixels(centre, rows),
            &yours,
            &format!("integer_circle({centre}, {radius})"),
        );
        assert_eq!(
            first_duplicate(&yours),
            None,
            "integer_circle({centre}, {radius}) plots the pixel on the left twice: mirror images \
             that coincide are plotted once"
        );
    }
}

#[testkit::test]
fn radius_8_follows_the_differences_step_by_step() {
    //   h   −7  E  −4  E   1  SE  −6  E   3  SE   2  SE
    //   ΔE   3      5      7       9     11      13
    //   ΔSE −11    −9     −7      −3     −1       3
    //   pixel (0,8) (1,8) (2,8)  (3,7)  (4,7)   (5,6)   then (6,5): stop
    let octant: Vec<Pixel> = circle(Pixel::new(0, 0), 8)
        .into_iter()
        .filter(|p| 0 <= p.x && p.x <= p.y)
        .collect();
    let expected = [(0, 8), (1, 8), (2, 8), (3, 7), (4, 7), (5, 6)].map(|(x, y)| Pixel::new(x, y));
    assert_pixels_eq(
        &expected,
        &octant,
        "the second octant of integer_circle((0, 0), 8)",
    );
    let mut states = Vec::new();
    integer_circle(Pixel::new(0, 0), 8, |_| {}, |w| states.push(w));
    let table: Vec<_> = states
        .iter()
        .map(|d| (d.x, d.y, d.h, d.delta_e, d.delta_se))
        .collect();
    assert_eq!(
        table,
        [
            (0, 8, -7, 3, -11),
            (1, 8, -4, 5, -9),
            (2, 8, 1, 7, -7),
            (3, 7, -6, 9, -3),
            (4, 7, 3, 11, -1),
            (5, 6, 2, 13, 3),
        ],
        "integer_circle((0, 0), 8): the reported states (x, y, h, ΔE, ΔSE), one at each pixel \
         of the walk with y > x, from Walk::start(8) by the table's sums"
    );
}

#[testkit::test]
fn a_step_adds_what_the_walk_holds() {
    // The table of `Walk` by hand, on the circle of radius 8 (see the trace
    // above): at (3, 7), h = −6 < 0 goes E, h + ΔE = −6 + 9 = 3, ΔE 9 → 11,
    // ΔSE −3 → −1; then h = 3 ≥ 0 goes SE, h + ΔSE = 3 − 1 = 2.
    let walk = |x, y, h, delta_e, delta_se| Walk {
        x,
        y,
        h,
        delta_e,
        delta_se,
    };
    const START: &str = "the state at (0, R) is h = 1 − R, ΔE = 3, ΔSE = 5 − 2R";
    const E: &str = "h < 0 steps E: x + 1, h + ΔE, ΔE + 2, ΔSE + 2";
    const SE: &str = "h ≥ 0 steps SE: x + 1, y − 1, h + ΔSE, ΔE + 2, ΔSE + 4";
    assert_eq!(
        Walk::start(8),
        walk(0, 8, -7, 3, -11),
        "Walk::start(8): {START}"
    );
    assert_eq!(
        Walk::start(0),
        walk(0, 0, 1, 3, 5),
        "Walk::start(0): {START}"
    );
    let mut at = walk(3, 7, -6, 9, -3);
    at.step();
    assert_eq!(at, walk(4, 7, 3, 11, -1), "step from (3, 7), h = −6: {E}");
    at.step();
    assert_eq!(at, walk(5, 6, 2, 13, 3), "step from (4, 7), h = 3: {SE}");
    // States no circle has: the step adds what it holds all the same. An
    // f64 holds 2⁶⁰ + 1 as 2⁶⁰, and 2x + 3 would be 3 here, not 1000.
    let mut odd = walk(0, 100, (1 << 60) + 1, 1000, -7);
    odd.step();
    assert_eq!(
        odd,
        walk(1, 99, (1 << 60) - 6, 1002, -3),
        "step from {{ x: 0, y: 100, h: 2⁶⁰ + 1, ΔE: 1000, ΔSE: −7 }}, no circle's state: {SE}, \
         adding what it holds, in integers"
    );
    let mut odd = walk(10, 20, -(1 << 60) - 1, 1000, -7);
    odd.step();
    assert_eq!(
        odd,
        walk(11, 20, -(1 << 60) + 999, 1002, -5),
        "step from {{ x: 10, y: 20, h: −2⁶⁰ − 1, ΔE: 1000, ΔSE: −7 }}, no circle's state: {E}, \
         adding what it holds, in integers"
    );
}

#[testkit::test]
fn every_radius_up_to_300_matches_the_midpoint_definition() {
    let centre = Pixel::new(-17, 23);
    for radius in 0..=300 {
        let yours = circle(centre, radius);
        assert_pixels_eq(
            &circle_pixels(centre, radius),
            &yours,
            &format!("integer_circle({centre}, {radius})"),
        );
        assert_eq!(
            first_duplicate(&yours),
            None,
            "integer_circle({centre}, {radius}) plots a pixel twice"
        );
    }
}

#[testkit::test]
fn circles_of_small_radii() {
    let sheet = radius_sheet(&[0, 1, 2, 3, 5, 8], |c, r, canvas| {
        draw(c, r, |p| canvas.set(p, INK));
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
        (Pixel::new(MAX_COORD / 2, 0), MAX_COORD / 2 + 1),
    ] {
        let drawn = count(|plot| draw(centre, radius, plot));
        assert!(
            drawn == 0,
            "integer_circle({centre}, {radius}) must draw nothing (a negative radius, or a circle \
             reaching beyond ±MAX_COORD = {MAX_COORD}); yours drew {drawn} pixels"
        );
    }
    let edge = Pixel::new(-MAX_COORD, MAX_COORD);
    let yours = circle(edge, 0);
    assert_eq!(
        yours,
        [edge],
        "integer_circle({edge}, 0): radius 0 is the centre pixel, plotted once, even at ±MAX_COORD"
    );
    // Refusing one is no reason to refuse the next.
    assert_pixels_eq(
        &circle_pixels(origin, 3),
        &circle(origin, 3),
        "integer_circle((0, 0), 3)",
    );
}

#[testkit::test]
fn huge_radius_is_exact() {
    // R² overflows an i32 from R = 46 341 on; the differences never come
    // near that. (Only the first 100 000 columns of the second octant are
    // compared.)
    const COLUMNS: i32 = 100_000;
    let radius = 3_000_000;
    let centre = Pixel::new(1, 0);
    let mut yours = Vec::new();
    draw(centre, radius, |p| {
        let dx = p.x - centre.x;
        if (0..COLUMNS).contains(&dx) && dx <= p.y {
            yours.push(p);
        }
    });
    let r = i64::from(radius);
    let expected: Vec<Pixel> = (0..i64::from(COLUMNS))
        .map(|x| Pixel::new(x as i32 + 1, circle_row(r, x) as i32))
        .collect();
    assert_pixels_eq(
        &expected,
        &yours,
        &format!("the first {COLUMNS} columns of integer_circle({centre}, {radius})"),
    );
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn pixels_equal_the_float_midpoint_circle(centre in pixel(1000), radius in 0..500) {
        let yours = circle(centre, radius);
        assert_pixels_eq(&circle_pixels(centre, radius), &yours, &format!("integer_circle({centre}, {radius})"));
        prop_assert_eq!(first_duplicate(&yours), None, "integer_circle({}, {}) plots a pixel twice", centre, radius);
    }

    #[testkit::test]
    fn circle_has_eightfold_symmetry_and_no_gaps(centre in pixel(50), radius in 0..120) {
        let yours = circle(centre, radius);
        prop_assert!(yours.contains(&Pixel::new(centre.x + radius, centre.y)), "{}({}, {}) does not draw its rightmost point {}", "integer_circle", centre, radius, Pixel::new(centre.x + radius, centre.y));
        if let Some((p, image)) = missing_mirror_image(&yours, centre, true) {
            prop_assert!(false, "integer_circle({}, {}) draws {} but not its mirror image {}", centre, radius, p, image);
        }
        closed_loop(&yours, centre).map_err(|e| TestCaseError::fail(format!("integer_circle({centre}, {radius}) is not a closed 8-connected loop: {e}")))?;
    }

    #[testkit::test]
    fn hostile_input_draws_nothing_or_the_exact_circle(
        centre in hostile_pixel(),
        radius in prop_oneof![Just(i32::MIN), Just(-1), Just(MAX_COORD + 1), Just(i32::MAX), any::<i32>(), 0..40],
    ) {
        if within_limits(centre, radius, radius) && radius < 1000 {
            assert_pixels_eq(&circle_pixels(centre, radius), &circle(centre, radius), &format!("integer_circle({centre}, {radius})"));
        } else if !within_limits(centre, radius, radius) {
            prop_assert_eq!(count(|plot| draw(centre, radius, plot)), 0, "integer_circle({}, {}) reaches beyond ±MAX_COORD = {} or has a negative radius: it must draw nothing (left: the pixels yours drew)", centre, radius, MAX_COORD);
        }
        // Refusing one is no reason to refuse the next.
        prop_assert!(count(|plot| draw(Pixel::new(0, 0), 3, plot)) > 0, "integer_circle((0, 0), 3), called after integer_circle({}, {}), drew nothing: refusing one circle is no reason to refuse the next", centre, radius);
    }
}
