//! Task 3b: the midpoint ellipse in two regions.

mod common;

use std::collections::BTreeSet;

use canvas::{MAX_COORD, Pixel};
use circles::midpoint_ellipse::{MAX_SEMI_AXIS, midpoint_ellipse};
use common::{
    INK, circle_pixels, collect, connected, count, ellipse_pixels, ellipse_regions, ellipse_sheet,
    first_duplicate, grid_pixels, missing_mirror_image, nearest_row, within_limits,
};
use proptest::prelude::*;
use testkit::assert_pixels_eq;
use testkit::strategies::{hostile_pixel, pixel};

fn ellipse(centre: Pixel, a: i32, b: i32) -> Vec<Pixel> {
    collect(|plot| midpoint_ellipse(centre, a, b, plot))
}

fn expected(centre: Pixel, a: i32, b: i32) -> Vec<Pixel> {
    ellipse_pixels(centre, a, b, MAX_SEMI_AXIS)
}

#[testkit::test]
fn ellipse_5_by_3_matches_the_regions_by_hand() {
    // a² = 25, b² = 9. Region 1 holds column x while 18x − 25 < 0 or
    // (18x − 25)² < 900(25 − x²): columns 0..=4 (x = 5: 65² > 0).
    //   d = 4b² + a²(1 − 4b) = −239 at (0,3)
    //   E: d += 36(2x + 3)   SE: d += 36(2x + 3) − 200(y − 1)
    //   (0,3) −239 E → (1,3) −131 E → (2,3) 49 SE → (3,2) −99 E → (4,2)
    // Region 2, the same with a = 3 along y and b = 5: rows 0..=1
    // (y = 2: 91² = 8281 > 900·5); from (5,0), d = 100 + 9(1 − 20) = −71
    // → N → (5,1). The regions touch diagonally: (4,2), (5,1).
    let centre = Pixel::new(0, 0);
    let rows = [
        "...#####...", //
        ".##.....##.",
        "#.........#",
        "#.........#",
        "#.........#",
        ".##.....##.",
        "...#####...",
    ];
    assert_pixels_eq(
        &grid_pixels(centre, &rows),
        &ellipse(centre, 5, 3),
        "midpoint_ellipse((0, 0), 5, 3)",
    );
}

#[testkit::test]
fn flat_ellipse_stays_in_region_one_along_the_axis() {
    // a = 8, b = 1: 2b²x − a² = 2x − 64 < 0 in every column, so region 1
    // runs to x = 8. d = 4 + 64(1 − 4) = −188 at (0,1), then
    // E (−176, −156, −128, −92, −48, 4) to (6,1), SE (d = 64) to (7,0),
    // and on the axis E to (8,0). (In column 7 the ellipse is at
    // y = √(15)/8 ≈ 0.48: the lower pixel is nearer.) Region 2 is row 0
    // alone and ends on (8,0) too: plotted once.
    let centre = Pixel::new(0, 0);
    let rows = [
        "..#############..",
        "##.............##",
        "..#############..",
    ];
    let yours = ellipse(centre, 8, 1);
    assert_pixels_eq(
        &grid_pixels(centre, &rows),
        &yours,
        "midpoint_ellipse((0, 0), 8, 1)",
    );
    assert_eq!(
        first_duplicate(&yours),
        None,
        "midpoint_ellipse({centre}, 8, 1) plots the pixel on the left twice: where region 1 \
         reaches the axis and region 2 begins, (8, 0) is plotted once"
    );
}

#[testkit::test]
fn a_zero_semi_axis_gives_a_segment() {
    let c = Pixel::new(3, -3);
    let column: Vec<Pixel> = (-4..=4).map(|dy| Pixel::new(c.x, c.y + dy)).collect();
    let row: Vec<Pixel> = (-2..=2).map(|dx| Pixel::new(c.x + dx, c.y)).collect();
    for (a, b, segment) in [(0, 4, column), (2, 0, row), (0, 0, vec![c])] {
        let yours = ellipse(c, a, b);
        assert_pixels_eq(
            &segment,
            &yours,
            &format!("midpoint_ellipse({c}, {a}, {b})"),
        );
        assert_eq!(
            first_duplicate(&yours),
            None,
            "midpoint_ellipse({c}, {a}, {b}) plots a pixel twice"
        );
    }
}

#[testkit::test]
fn ellipses_of_several_shapes() {
    let axes = [
        (5, 3),
        (8, 4),
        (4, 8),
        (12, 5),
        (8, 1),
        (1, 8),
        (6, 6),
        (0, 3),
    ];
    let sheet = ellipse_sheet(&axes, |c, a, b, canvas| {
        midpoint_ellipse(c, a, b, |p| canvas.set(p, INK))
    });
    testkit::insta::assert_snapshot!("ellipses_of_several_shapes", sheet);
}

#[testkit::test]
fn hostile_input_draws_nothing_and_returns_at_once() {
    let origin = Pixel::new(0, 0);
    for (centre, a, b) in [
        (origin, -1, 5),
        (origin, 5, -1),
        (origin, i32::MIN, i32::MIN),
        (origin, i32::MAX, 3),
        (origin, MAX_SEMI_AXIS + 1, 1),
        (origin, 1, MAX_SEMI_AXIS + 1),
        (Pixel::new(i32::MAX, 0), 0, 0),
        (Pixel::new(MAX_COORD, 0), 1, 0),
        (Pixel::new(0, -MAX_COORD), 4, 1),
    ] {
        let drawn = count(|plot| midpoint_ellipse(centre, a, b, plot));
        assert!(
            drawn == 0,
            "midpoint_ellipse({centre}, {a}, {b}) must draw nothing (a negative semi-axis, one \
             beyond MAX_SEMI_AXIS = {MAX_SEMI_AXIS}, or an ellipse reaching beyond ±MAX_COORD = \
             {MAX_COORD}); yours drew {drawn} pixels"
        );
    }
    // At the limits: the centre alone, and a segment touching MAX_COORD.
    let edge = Pixel::new(MAX_COORD, MAX_COORD);
    assert_eq!(
        ellipse(edge, 0, 0),
        [edge],
        "midpoint_ellipse({edge}, 0, 0): both semi-axes 0 is the centre pixel, plotted once, \
         even at ±MAX_COORD"
    );
    let touching = Pixel::new(0, MAX_COORD - 2);
    assert_pixels_eq(
        &expected(touching, 0, 2),
        &ellipse(touching, 0, 2),
        "a segment touching MAX_COORD",
    );
}

#[testkit::test]
fn largest_ellipse_is_exact() {
    // a²b² needs 80 bits, the region test 122: an i64 overflows long
    // before MAX_SEMI_AXIS. Only the first quadrant is compared.
    let (a, b) = (MAX_SEMI_AXIS, 1234);
    let centre = Pixel::new(0, 0);
    let mut yours = Vec::new();
    midpoint_ellipse(centre, a, b, |p| {
        if p.x >= 0 && p.y >= 0 {
            yours.push(p);
        }
    });
    let (one, two) = ellipse_regions(a, b);
    let quadrant: Vec<Pixel> = one
        .into_iter()
        .chain(two)
        .map(|(x, y)| Pixel::new(x as i32, y as i32))
        .collect();
    assert_pixels_eq(
        &quadrant,
        &yours,
        &format!("the first quadrant of midpoint_ellipse({centre}, {a}, {b})"),
    );
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn pixels_are_the_nearest_in_each_column_then_each_row(centre in pixel(50), a in 0..60, b in 0..60) {
        let yours = ellipse(centre, a, b);
        assert_pixels_eq(&expected(centre, a, b), &yours, &format!("midpoint_ellipse({centre}, {a}, {b})"));
    }

    #[testkit::test]
    fn equal_semi_axes_give_the_midpoint_circle(centre in pixel(50), radius in 0..200) {
        let yours = ellipse(centre, radius, radius);
        assert_pixels_eq(&circle_pixels(centre, radius), &yours, &format!("midpoint_ellipse({centre}, {radius}, {radius}) against the circle"));
    }

    #[testkit::test]
    fn no_pixel_is_plotted_twice(centre in pixel(50), a in 0..60, b in 0..60) {
        let yours = ellipse(centre, a, b);
        prop_assert!(yours.contains(&Pixel::new(centre.x + a, centre.y)), "midpoint_ellipse({}, {}, {}) does not draw its rightmost point {}", centre, a, b, Pixel::new(centre.x + a, centre.y));
        prop_assert_eq!(first_duplicate(&yours), None, "midpoint_ellipse({}, {}, {}) plots a pixel twice", centre, a, b);
    }

    #[testkit::test]
    fn ellipse_has_fourfold_symmetry(centre in pixel(50), a in 0..60, b in 0..60) {
        let yours = ellipse(centre, a, b);
        prop_assert!(yours.contains(&Pixel::new(centre.x + a, centre.y)), "midpoint_ellipse({}, {}, {}) does not draw its rightmost point {}", centre, a, b, Pixel::new(centre.x + a, centre.y));
        if let Some((p, image)) = missing_mirror_image(&yours, centre, false) {
            prop_assert!(false, "midpoint_ellipse({}, {}, {}) draws {} but not its mirror image {}", centre, a, b, p, image);
        }
    }

    #[testkit::test]
    fn swapping_the_semi_axes_transposes_the_ellipse(a in 0..60, b in 0..60) {
        let centre = Pixel::new(0, 0);
        let transposed: Vec<Pixel> = ellipse(centre, b, a).into_iter().map(|p| Pixel::new(p.y, p.x)).collect();
        prop_assert!(transposed.contains(&Pixel::new(a, 0)), "midpoint_ellipse(_, {}, {}) does not draw (0, {})", b, a, a);
        assert_pixels_eq(&ellipse(centre, a, b), &transposed, &format!("midpoint_ellipse(_, {a}, {b}) (expected) vs midpoint_ellipse(_, {b}, {a}) transposed (yours)"));
    }

    #[testkit::test]
    fn every_pixel_is_the_nearest_in_its_column_or_its_row(centre in pixel(50), a in 1..60, b in 1..60) {
        // Within half a pixel of the ellipse: along its column or its row.
        let yours = ellipse(centre, a, b);
        prop_assert!(yours.contains(&Pixel::new(centre.x + a, centre.y)), "midpoint_ellipse({}, {}, {}) does not draw its rightmost point {}", centre, a, b, Pixel::new(centre.x + a, centre.y));
        for p in yours {
            let (x, y) = (i64::from(p.x - centre.x).abs(), i64::from(p.y - centre.y).abs());
            let in_column = x <= i64::from(a) && nearest_row(a.into(), b.into(), x) == y;
            let in_row = y <= i64::from(b) && nearest_row(b.into(), a.into(), y) == x;
            prop_assert!(in_column || in_row, "midpoint_ellipse({}, {}, {}) draws {}, nearest to the ellipse neither in its column nor its row", centre, a, b, p);
        }
    }

    #[testkit::test]
    fn every_column_and_row_is_covered_without_gaps(centre in pixel(50), a in 0..60, b in 0..60) {
        // In the first quadrant every column 0..=a and every row 0..=b holds
        // a pixel, and the pixels touch: the outline has no gap.
        let yours = ellipse(centre, a, b);
        let quadrant: Vec<Pixel> = yours.iter().copied().filter(|p| p.x >= centre.x && p.y >= centre.y).collect();
        let columns: BTreeSet<i32> = quadrant.iter().map(|p| p.x - centre.x).collect();
        let rows: BTreeSet<i32> = quadrant.iter().map(|p| p.y - centre.y).collect();
        prop_assert_eq!(columns, (0..=a).collect::<BTreeSet<_>>(), "midpoint_ellipse({}, {}, {}): the columns dx its first-quadrant pixels fill (left) must be every column 0..=a (right)", centre, a, b);
        prop_assert_eq!(rows, (0..=b).collect::<BTreeSet<_>>(), "midpoint_ellipse({}, {}, {}): the rows dy its first-quadrant pixels fill (left) must be every row 0..=b (right)", centre, a, b);
        prop_assert!(connected(&yours), "midpoint_ellipse({}, {}, {}) falls apart: its pixels are not one 8-connected outline", centre, a, b);
    }

    #[testkit::test]
    fn hostile_input_draws_nothing_or_the_exact_ellipse(
        centre in hostile_pixel(),
        a in prop_oneof![Just(i32::MIN), Just(-1), Just(MAX_SEMI_AXIS + 1), Just(i32::MAX), any::<i32>(), 0..30],
        b in prop_oneof![Just(-1), Just(MAX_COORD + 1), any::<i32>(), 0..30],
    ) {
        let drawable = within_limits(centre, a, b) && a <= MAX_SEMI_AXIS && b <= MAX_SEMI_AXIS;
        if drawable && a < 1000 && b < 1000 {
            assert_pixels_eq(&expected(centre, a, b), &ellipse(centre, a, b), &format!("midpoint_ellipse({centre}, {a}, {b})"));
        } else if !drawable {
            prop_assert_eq!(count(|plot| midpoint_ellipse(centre, a, b, plot)), 0, "midpoint_ellipse({}, {}, {}) has a negative semi-axis, one beyond MAX_SEMI_AXIS = {}, or reaches beyond ±MAX_COORD = {}: it must draw nothing (left: the pixels yours drew)", centre, a, b, MAX_SEMI_AXIS, MAX_COORD);
        }
        // Refusing one is no reason to refuse the next.
        prop_assert!(count(|plot| midpoint_ellipse(Pixel::new(0, 0), 4, 2, plot)) > 0, "midpoint_ellipse((0, 0), 4, 2), called after midpoint_ellipse({}, {}, {}), drew nothing: refusing one ellipse is no reason to refuse the next", centre, a, b);
    }
}
