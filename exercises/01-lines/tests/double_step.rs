//! Task 3: the double-step line.

mod common;

use canvas::{MAX_COORD, Pixel};
use common::{INK, collect, nearest_pixels, octant_sheet};
use lines::double_step::double_step_line;
use proptest::prelude::*;
use testkit::{assert_pixels_eq, strategies::pixel_line};

fn double_step(from: Pixel, to: Pixel) -> Vec<Pixel> {
    collect(|plot| double_step_line(from, to, plot))
}

#[testkit::test]
fn each_pattern_appears_where_the_slope_allows_it() {
    // Slope 1/4 from (0,0): patterns 1 (flat) and 2 (step on the second
    // pixel) only. Ties at x = 2 and x = 6 go to the lower row.
    //   2 |.......##   double steps from x = 0, 2, 4, 6:
    //   1 |...####..   (1) flat, (2) second up, (1) flat, (2) second up
    //   0 |###......
    let flat = double_step(Pixel::new(0, 0), Pixel::new(8, 2));
    let expected = [
        (0, 0),
        (1, 0),
        (2, 0),
        (3, 1),
        (4, 1),
        (5, 1),
        (6, 1),
        (7, 2),
        (8, 2),
    ];
    assert_eq!(flat, expected.map(|(x, y)| Pixel::new(x, y)));
    // Slope 3/4: patterns 2, 3 and 4; ties at x = 2 and x = 6.
    //   6 |........#   double steps from x = 0, 2, 4, 6:
    //   5 |.......#.   (3) first up, (4) both up, (3) first up, (4) both up
    //   4 |.....##..
    //   3 |....#....
    //   2 |...#.....
    //   1 |.##......
    //   0 |#........
    let steep = double_step(Pixel::new(0, 0), Pixel::new(8, 6));
    let expected = [
        (0, 0),
        (1, 1),
        (2, 1),
        (3, 2),
        (4, 3),
        (5, 4),
        (6, 4),
        (7, 5),
        (8, 6),
    ];
    assert_eq!(steep, expected.map(|(x, y)| Pixel::new(x, y)));
}

#[testkit::test]
fn odd_number_of_steps_ends_on_the_endpoint() {
    let pixels = double_step(Pixel::new(0, 0), Pixel::new(5, 2));
    assert_eq!(pixels.len(), 6);
    assert_eq!(pixels.last(), Some(&Pixel::new(5, 2)));
    assert_pixels_eq(
        &nearest_pixels(Pixel::new(0, 0), Pixel::new(5, 2), None),
        &pixels,
        "(0,0) -> (5,2)",
    );
}

#[testkit::test]
fn ties_inside_a_double_step_follow_the_direction_rule() {
    // (0,0) -> (4,1) and back: at x = 2 the line is at y = 0.5; the
    // midpoint rule takes the lower pixel in both directions.
    let expected = [(0, 0), (1, 0), (2, 0), (3, 1), (4, 1)].map(|(x, y)| Pixel::new(x, y));
    assert_eq!(double_step(Pixel::new(0, 0), Pixel::new(4, 1)), expected);
    let mut backwards = expected;
    backwards.reverse();
    assert_eq!(double_step(Pixel::new(4, 1), Pixel::new(0, 0)), backwards);
}

#[testkit::test]
fn lines_in_all_octants() {
    let sheet = octant_sheet(|from, to, canvas| double_step_line(from, to, |p| canvas.set(p, INK)));
    testkit::insta::assert_snapshot!("lines_in_all_octants", sheet);
}

#[testkit::test]
fn endpoints_beyond_max_coord_draw_nothing() {
    assert_eq!(
        double_step(Pixel::new(0, 0), Pixel::new(0, -MAX_COORD - 1)),
        []
    );
    // At the limit itself, a line is drawn.
    let edge = [Pixel::new(0, -MAX_COORD), Pixel::new(1, 4 - MAX_COORD)];
    assert_eq!(
        double_step(edge[0], edge[1]).len(),
        5,
        "{} -> {}",
        edge[0],
        edge[1]
    );
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn double_step_equals_midpoint([from, to] in pixel_line(40)) {
        let expected = nearest_pixels(from, to, None);
        let yours = double_step(from, to);
        assert_pixels_eq(&expected, &yours, &format!("double_step_line({from}, {to})"));
        prop_assert_eq!(yours, expected, "same pixels but not in order from `from` to `to`");
    }

    #[testkit::test]
    fn reversed_line_covers_same_pixels([from, to] in pixel_line(40)) {
        let forward = double_step(from, to);
        prop_assert!(forward.contains(&from) && forward.contains(&to), "{from} -> {to} must draw both endpoints: {forward:?}");
        assert_pixels_eq(&forward, &double_step(to, from), &format!("{from} <-> {to}"));
    }
}
