//! Task 3a: the filled circle, one span per row.

mod common;

use std::collections::{BTreeMap, BTreeSet};

use canvas::{MAX_COORD, Pixel};
use circles::filled_circle::filled_circle;
use common::{
    INK, circle_pixels, collect, count, disc_pixels, first_duplicate, grid_pixels,
    missing_mirror_image, radius_sheet, within_limits,
};
use proptest::prelude::*;
use testkit::assert_pixels_eq;
use testkit::strategies::{hostile_pixel, pixel};

fn disc(centre: Pixel, radius: i32) -> Vec<Pixel> {
    collect(|plot| filled_circle(centre, radius, plot))
}

#[testkit::test]
fn small_discs_are_their_outlines_filled() {
    // The outlines of tests/common's HAND_CIRCLES with every row filled
    // from its leftmost to its rightmost pixel.
    let discs: [(i32, &[&str]); 5] = [
        (0, &["#"]),
        (1, &[".#.", "###", ".#."]),
        (2, &[".###.", "#####", "#####", "#####", ".###."]),
        (
            3,
            &[
                "..###..", ".#####.", "#######", "#######", "#######", ".#####.", "..###..",
            ],
        ),
        (
            5,
            &[
                "...#####...",
                "..#######..",
                ".#########.",
                "###########",
                "###########",
                "###########",
                "###########",
                "###########",
                ".#########.",
                "..#######..",
                "...#####...",
            ],
        ),
    ];
    for (radius, rows) in discs {
        let centre = Pixel::new(2, 9);
        let yours = disc(centre, radius);
        assert_pixels_eq(
            &grid_pixels(centre, rows),
            &yours,
            &format!("filled_circle({centre}, {radius})"),
        );
        assert_eq!(
            first_duplicate(&yours),
            None,
            "filled_circle({centre}, {radius}) plots the pixel on the left twice: each row is one \
             span, every pixel plotted once"
        );
    }
}

#[testkit::test]
fn filled_circles_of_small_radii() {
    let sheet = radius_sheet(&[0, 1, 2, 3, 5, 8], |c, r, canvas| {
        filled_circle(c, r, |p| canvas.set(p, INK))
    });
    testkit::insta::assert_snapshot!("filled_circles_of_small_radii", sheet);
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
        (Pixel::new(0, i32::MIN), 2),
        (Pixel::new(-MAX_COORD, 0), 1),
    ] {
        let drawn = count(|plot| filled_circle(centre, radius, plot));
        assert!(
            drawn == 0,
            "filled_circle({centre}, {radius}) must draw nothing (a negative radius, or a circle \
             reaching beyond ±MAX_COORD = {MAX_COORD}); yours drew {drawn} pixels"
        );
    }
    let corner = Pixel::new(MAX_COORD - 2, MAX_COORD - 2);
    assert_pixels_eq(
        &disc_pixels(corner, 2),
        &disc(corner, 2),
        "a filled circle touching MAX_COORD",
    );
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn pixels_are_those_whose_inner_midpoint_is_inside(centre in pixel(50), radius in 0..40) {
        let yours = disc(centre, radius);
        assert_pixels_eq(&disc_pixels(centre, radius), &yours, &format!("filled_circle({centre}, {radius})"));
    }

    #[testkit::test]
    fn no_pixel_is_plotted_twice(centre in pixel(50), radius in 0..40) {
        let yours = disc(centre, radius);
        prop_assert!(yours.contains(&centre), "filled_circle({}, {}) does not fill its centre", centre, radius);
        prop_assert_eq!(first_duplicate(&yours), None, "filled_circle({}, {}) plots a pixel twice", centre, radius);
    }

    #[testkit::test]
    fn every_pixel_centre_inside_the_circle_is_filled(centre in pixel(50), radius in 0..40) {
        let yours: BTreeSet<Pixel> = disc(centre, radius).into_iter().collect();
        for dy in -radius..=radius {
            for dx in -radius..=radius {
                let p = Pixel::new(centre.x + dx, centre.y + dy);
                if dx * dx + dy * dy <= radius * radius {
                    prop_assert!(yours.contains(&p), "filled_circle({}, {}) leaves out {}, whose centre is inside", centre, radius, p);
                }
            }
        }
    }

    #[testkit::test]
    fn filled_circle_is_its_outline_and_the_inside(centre in pixel(50), radius in 0..40) {
        // The midpoint circle's outline is part of the filled circle, and
        // every filled pixel off the outline has all four neighbours
        // filled: filling stops exactly at the outline.
        let yours: BTreeSet<Pixel> = disc(centre, radius).into_iter().collect();
        let outline: BTreeSet<Pixel> = circle_pixels(centre, radius).into_iter().collect();
        for p in &outline {
            prop_assert!(yours.contains(p), "filled_circle({}, {}) leaves out the outline pixel {}", centre, radius, p);
        }
        for p in yours.difference(&outline) {
            for q in [Pixel::new(p.x + 1, p.y), Pixel::new(p.x - 1, p.y), Pixel::new(p.x, p.y + 1), Pixel::new(p.x, p.y - 1)] {
                prop_assert!(yours.contains(&q), "filled_circle({}, {}): {} is filled and inside the outline, its neighbour {} is not", centre, radius, p, q);
            }
        }
    }

    #[testkit::test]
    fn each_row_is_one_span_symmetric_about_the_centre(centre in pixel(50), radius in 0..40) {
        let yours = disc(centre, radius);
        if let Some((p, image)) = missing_mirror_image(&yours, centre, true) {
            prop_assert!(false, "filled_circle({}, {}) fills {} but not its mirror image {}: the filled circle is symmetric about both axes and both diagonals", centre, radius, p, image);
        }
        let mut rows: BTreeMap<i32, Vec<i32>> = BTreeMap::new();
        for p in &yours {
            rows.entry(p.y).or_default().push(p.x);
        }
        prop_assert_eq!(rows.len() as i32, 2 * radius + 1, "filled_circle({}, {}) fills {} rows (left), the rows from centre.y − R to centre.y + R are 2R + 1 (right)", centre, radius, rows.len());
        for (y, mut xs) in rows {
            xs.sort();
            xs.dedup();
            let (lo, hi) = (xs[0], xs[xs.len() - 1]);
            prop_assert_eq!(xs.len() as i32, hi - lo + 1, "filled_circle({}, {}): row {} holds {} pixels (left) between x = {} and {}, one span holds {} (right): a row is one span without gaps", centre, radius, y, xs.len(), lo, hi, hi - lo + 1);
            prop_assert_eq!(lo + hi, 2 * centre.x, "filled_circle({}, {}): row {} spans x = {} to {}, a span symmetric about centre.x = {} has lo + hi = {} (right)", centre, radius, y, lo, hi, centre.x, 2 * centre.x);
        }
    }

    #[testkit::test]
    fn hostile_input_draws_nothing_or_the_exact_disc(
        centre in hostile_pixel(),
        radius in prop_oneof![Just(i32::MIN), Just(-1), Just(MAX_COORD + 1), Just(i32::MAX), any::<i32>(), 0..20],
    ) {
        if within_limits(centre, radius, radius) && radius < 100 {
            assert_pixels_eq(&disc_pixels(centre, radius), &disc(centre, radius), &format!("filled_circle({centre}, {radius})"));
        } else if !within_limits(centre, radius, radius) {
            prop_assert_eq!(count(|plot| filled_circle(centre, radius, plot)), 0, "filled_circle({}, {}) reaches beyond ±MAX_COORD = {} or has a negative radius: it must draw nothing (left: the pixels yours drew)", centre, radius, MAX_COORD);
        }
        // Refusing one is no reason to refuse the next.
        prop_assert!(count(|plot| filled_circle(Pixel::new(0, 0), 3, plot)) > 0, "filled_circle((0, 0), 3), called after filled_circle({}, {}), drew nothing: refusing one circle is no reason to refuse the next", centre, radius);
    }
}
