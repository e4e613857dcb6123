//! Task 2: the midpoint circle in integers, with second-order differences.

mod common;

use canvas::{MAX_COORD, Pixel};
use circles::integer_circle::{Decision, integer_circle};
use common::{
    HAND_CIRCLES, INK, circle_pixels, circle_row, closed_loop, collect, count, first_duplicate,
    grid_pixels, missing_mirror_image, radius_sheet, within_limits,
};
use proptest::prelude::*;
use testkit::assert_pixels_eq;
use testkit::strategies::{hostile_pixel, pixel};

/// Checks the decisions `integer_circle` reports, as they come, against
/// their definitions: one at every pixel of the walk from `(0, R)` while
/// `y > x`, with `h = d − ¼ = (x + 1)² + y² − y − R²`, `ΔE = 2x + 3`,
/// `ΔSE = 2(x − y) + 5`; none for a circle that draws nothing.
struct DecisionCheck {
    radius: i64,
    x: i64,
    y: i64,
    count: u64,
    walks: bool,
    error: Option<String>,
}

impl DecisionCheck {
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

    fn expected(&self) -> Option<Decision> {
        let (x, y, r) = (self.x, self.y, self.radius);
        (self.walks && y > x).then(|| Decision {
            x: x as i32,
            y: y as i32,
            h: (x + 1) * (x + 1) + y * y - y - r * r,
            delta_e: 2 * x + 3,
            delta_se: 2 * (x - y) + 5,
        })
    }

    fn see(&mut self, decision: Decision) {
        if self.error.is_some() {
            return;
        }
        match self.expected() {
            None => {
                self.error = Some(format!(
                    "reported {decision:?} after the walk ended (after {} decisions)",
                    self.count
                ));
            }
            Some(expected) if expected != decision => {
                self.error = Some(format!(
                    "decision {} is {decision:?}, by the definitions it is {expected:?}",
                    self.count
                ));
            }
            Some(expected) => {
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
                "{call}: {} decisions reported, the walk goes on at {missing:?} (report one at every pixel with y > x to `step`)",
                self.count
            );
        }
    }
}

/// Runs `integer_circle`, checking every decision it reports (see
/// [`DecisionCheck`]): every test grades the integer walk, not only its
/// pixels.
#[track_caller]
fn draw(centre: Pixel, radius: i32, plot: impl FnMut(Pixel)) {
    let mut check = DecisionCheck::new(centre, radius);
    integer_circle(centre, radius, plot, |d| check.see(d));
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
            "radius {radius}: a pixel plotted twice"
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
    let mut decisions = Vec::new();
    integer_circle(Pixel::new(0, 0), 8, |_| {}, |d| decisions.push(d));
    let table: Vec<_> = decisions
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
        "(x, y, h, ΔE, ΔSE) at each pixel of the walk"
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
        assert_eq!(
            count(|plot| draw(centre, radius, plot)),
            0,
            "integer_circle({centre}, {radius})"
        );
    }
    let edge = Pixel::new(-MAX_COORD, MAX_COORD);
    assert_eq!(circle(edge, 0), [edge]);
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
        closed_loop(&yours, centre).map_err(TestCaseError::fail)?;
    }

    #[testkit::test]
    fn hostile_input_draws_nothing_or_the_exact_circle(
        centre in hostile_pixel(),
        radius in prop_oneof![Just(i32::MIN), Just(-1), Just(MAX_COORD + 1), Just(i32::MAX), any::<i32>(), 0..40],
    ) {
        if within_limits(centre, radius, radius) && radius < 1000 {
            assert_pixels_eq(&circle_pixels(centre, radius), &circle(centre, radius), &format!("integer_circle({centre}, {radius})"));
        } else if !within_limits(centre, radius, radius) {
            prop_assert_eq!(count(|plot| draw(centre, radius, plot)), 0, "integer_circle({}, {}) must draw nothing", centre, radius);
        }
        // Refusing one is no reason to refuse the next.
        prop_assert!(count(|plot| draw(Pixel::new(0, 0), 3, plot)) > 0, "integer_circle((0, 0), 3) drew nothing");
    }
}
