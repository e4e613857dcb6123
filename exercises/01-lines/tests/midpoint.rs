//! Task 2: the midpoint line.

mod common;

use canvas::{MAX_COORD, Pixel};
use common::{INK, collect, nearest_pixels, octant_sheet, one_step_per_column};
use lines::midpoint::midpoint_line;
use proptest::prelude::*;
use testkit::{assert_pixels_eq, strategies::pixel_line};

fn midpoint(from: Pixel, to: Pixel) -> Vec<Pixel> {
    collect(|plot| midpoint_line(from, to, plot))
}

#[testkit::test]
fn first_octant_line_matches_the_grid() {
    // (0,0) -> (8,3): slope 3/8, one tie.
    //   3 |.......##
    //   2 |.....##..
    //   1 |..###....    (x = 1: y = 0.375 -> 0; x = 4: 1.5 is a tie -> 1)
    //   0 |##.......
    let expected = [
        (0, 0),
        (1, 0),
        (2, 1),
        (3, 1),
        (4, 1),
        (5, 2),
        (6, 2),
        (7, 3),
        (8, 3),
    ]
    .map(|(x, y)| Pixel::new(x, y));
    assert_eq!(midpoint(Pixel::new(0, 0), Pixel::new(8, 3)), expected);
    let mut backwards = expected;
    backwards.reverse();
    assert_eq!(midpoint(Pixel::new(8, 3), Pixel::new(0, 0)), backwards);
}

#[testkit::test]
fn tie_goes_east_left_to_right_and_southwest_right_to_left() {
    // (0,0) -> (2,1): at x = 1 the line is at y = 0.5, exactly between
    // (1,0) and (1,1). The slides: E going right, SW going left: (1,0).
    let right = midpoint(Pixel::new(0, 0), Pixel::new(2, 1));
    let left = midpoint(Pixel::new(2, 1), Pixel::new(0, 0));
    assert_eq!(
        right,
        [Pixel::new(0, 0), Pixel::new(1, 0), Pixel::new(2, 1)]
    );
    assert_eq!(left, [Pixel::new(2, 1), Pixel::new(1, 0), Pixel::new(0, 0)]);
}

#[testkit::test]
fn steep_tie_goes_to_the_left_pixel() {
    // (0,0) -> (1,2): at y = 1 the line is at x = 0.5: the smaller x wins.
    let up = midpoint(Pixel::new(0, 0), Pixel::new(1, 2));
    assert_eq!(up, [Pixel::new(0, 0), Pixel::new(0, 1), Pixel::new(1, 2)]);
    let down = midpoint(Pixel::new(1, 2), Pixel::new(0, 0));
    assert_eq!(down, [Pixel::new(1, 2), Pixel::new(0, 1), Pixel::new(0, 0)]);
}

#[testkit::test]
fn zero_length_line_is_its_endpoint() {
    assert_eq!(
        midpoint(Pixel::new(-4, 7), Pixel::new(-4, 7)),
        [Pixel::new(-4, 7)]
    );
}

#[testkit::test]
fn lines_in_all_octants() {
    let sheet = octant_sheet(|from, to, canvas| midpoint_line(from, to, |p| canvas.set(p, INK)));
    testkit::insta::assert_snapshot!("lines_in_all_octants", sheet);
}

#[testkit::test]
fn endpoints_beyond_max_coord_draw_nothing() {
    let far = Pixel::new(MAX_COORD + 1, 0);
    assert_eq!(midpoint(Pixel::new(0, 0), far), []);
    assert_eq!(
        midpoint(
            Pixel::new(i32::MIN, i32::MIN),
            Pixel::new(i32::MAX, i32::MAX)
        ),
        []
    );
    // At the limit itself, a line is drawn.
    let edge = [Pixel::new(MAX_COORD - 2, 0), Pixel::new(MAX_COORD, 1)];
    assert_eq!(
        midpoint(edge[0], edge[1]).len(),
        3,
        "{} -> {}",
        edge[0],
        edge[1]
    );
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn pixels_are_the_nearest_to_the_ideal_line([from, to] in pixel_line(40)) {
        let expected = nearest_pixels(from, to, None);
        let yours = midpoint(from, to);
        assert_pixels_eq(&expected, &yours, &format!("midpoint_line({from}, {to})"));
        prop_assert_eq!(yours, expected, "same pixels but not in order from `from` to `to`");
    }

    #[testkit::test]
    fn reversed_line_covers_same_pixels([from, to] in pixel_line(40)) {
        let forward = midpoint(from, to);
        let backward = midpoint(to, from);
        prop_assert!(forward.contains(&from) && forward.contains(&to), "{from} -> {to} must draw both endpoints: {forward:?}");
        assert_pixels_eq(&forward, &backward, &format!("{from} -> {to} (expected) vs {to} -> {from} (yours)"));
    }

    #[testkit::test]
    fn one_pixel_per_step_along_the_major_axis([from, to] in pixel_line(40)) {
        let pixels = midpoint(from, to);
        let x_major = (to.x - from.x).abs() >= (to.y - from.y).abs();
        let steps = (to.x - from.x).abs().max((to.y - from.y).abs());
        prop_assert_eq!(pixels.len(), steps as usize + 1);
        one_step_per_column(&pixels, x_major).map_err(TestCaseError::fail)?;
    }

    #[testkit::test]
    fn both_endpoints_are_drawn_first_and_last([from, to] in pixel_line(40)) {
        let pixels = midpoint(from, to);
        prop_assert_eq!(pixels.first(), Some(&from));
        prop_assert_eq!(pixels.last(), Some(&to));
    }

    #[testkit::test]
    fn lines_near_the_coordinate_limit_are_exact(
        [from, to] in pixel_line(30),
        shift in prop_oneof![Just(MAX_COORD - 30), Just(30 - MAX_COORD)],
    ) {
        let moved = |p: Pixel| Pixel::new(p.x + shift, p.y - shift);
        let (from, to) = (moved(from), moved(to));
        let expected = nearest_pixels(from, to, None);
        assert_pixels_eq(&expected, &midpoint(from, to), &format!("midpoint_line({from}, {to})"));
    }
}

/// The fan of the seed's antialiasing comparison, aliased: every pixel of
/// a line full white (the picture the antialiased ones improve on).
#[testkit::test]
fn the_fan_of_lines_matches_the_reference_image() {
    let canvas = common::fan_picture(|from, to, plot| midpoint_line(from, to, |p| plot(p, 1.0)));
    common::assert_fan("midpoint_fan", &canvas);
}
