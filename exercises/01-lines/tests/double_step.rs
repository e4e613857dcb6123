//! Task 3: the double-step line.

mod common;

use canvas::{MAX_COORD, Pixel};
use common::{INK, collect, nearest_pixels, octant_sheet};
use lines::double_step::{Pattern, double_step_line};
use proptest::prelude::*;
use testkit::{assert_pixels_eq, strategies::pixel_line};

/// The pixels of `double_step_line(from, to, …)`, after checking the
/// patterns it reported: one per double step, each the one its two pixels
/// show, and only those the slope allows. Every test goes through here, so
/// every test grades the double step, not only its pixels.
fn double_step(from: Pixel, to: Pixel) -> Vec<Pixel> {
    let mut patterns = Vec::new();
    let pixels = collect(|plot| double_step_line(from, to, plot, |p| patterns.push(p)));
    check_patterns(from, to, &pixels, &patterns);
    pixels
}

#[track_caller]
fn check_patterns(from: Pixel, to: Pixel, pixels: &[Pixel], patterns: &[Pattern]) {
    let line = format!("double_step_line({from}, {to})");
    if pixels.is_empty() {
        assert_eq!(patterns, [], "{line} drew nothing but reported patterns");
        return;
    }
    let (dx, dy) = (i64::from(to.x - from.x), i64::from(to.y - from.y));
    let x_major = dx.abs() >= dy.abs();
    let (long, short) = if x_major {
        (dx.abs(), dy.abs())
    } else {
        (dy.abs(), dx.abs())
    };
    assert_eq!(
        patterns.len() as i64,
        long / 2,
        "{line}: {} patterns reported for {} double steps (call `step` once per double step)",
        patterns.len(),
        long / 2
    );
    if pixels.len() as i64 == long + 1 {
        // Rows along the minor axis, counted away from `from`.
        let row = |p: Pixel| {
            let minor = if x_major { p.y - from.y } else { p.x - from.x };
            i64::from(minor).abs()
        };
        for (k, pattern) in patterns.iter().enumerate() {
            let base = row(pixels[2 * k]);
            let rows = [row(pixels[2 * k + 1]) - base, row(pixels[2 * k + 2]) - base];
            assert_eq!(
                rows,
                pattern.rows(),
                "{line}: double step {k} reported {pattern:?}, but its pixels {} and {} lie on rows {rows:?}",
                pixels[2 * k + 1],
                pixels[2 * k + 2]
            );
        }
    }
    if 2 * short <= long {
        assert!(
            !patterns.contains(&Pattern::Steep),
            "{line}: pattern 4 at a slope ≤ ½"
        );
    }
    if 2 * short >= long {
        assert!(
            !patterns.contains(&Pattern::Flat),
            "{line}: pattern 1 at a slope ≥ ½"
        );
    }
}

/// The patterns `double_step_line` reports while drawing `from → to`.
fn patterns(from: Pixel, to: Pixel) -> Vec<Pattern> {
    let mut patterns = Vec::new();
    double_step_line(from, to, |_| {}, |p| patterns.push(p));
    patterns
}

#[testkit::test]
fn each_pattern_appears_where_the_slope_allows_it() {
    use Pattern::{Flat, Steep, StepFirst, StepSecond};
    let origin = Pixel::new(0, 0);
    // Slope 1/4 from (0,0): patterns 1 (flat) and 3 (first pixel up). Ties
    // at x = 2 and x = 6 go to the lower row.
    //   2 |.......##   double steps from x = 0, 2, 4, 6:
    //   1 |...####..   (1) flat, (3) first up, (1) flat, (3) first up
    //   0 |###......
    let flat = double_step(origin, Pixel::new(8, 2));
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
    assert_eq!(
        patterns(origin, Pixel::new(8, 2)),
        [Flat, StepFirst, Flat, StepFirst]
    );
    // Slope 3/8: pattern 2 (second pixel up) first; a tie at x = 4.
    //   3 |.......##   double steps from x = 0, 2, 4, 6:
    //   2 |.....##..   (2) second up, (1) flat, (3) first up, (3) first up
    //   1 |..###....
    //   0 |##.......
    let gentle = double_step(origin, Pixel::new(8, 3));
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
    ];
    assert_eq!(gentle, expected.map(|(x, y)| Pixel::new(x, y)));
    assert_eq!(
        patterns(origin, Pixel::new(8, 3)),
        [StepSecond, Flat, StepFirst, StepFirst]
    );
    // Slope 3/4: patterns 3 and 4; ties at x = 2 and x = 6.
    //   6 |........#   double steps from x = 0, 2, 4, 6:
    //   5 |.......#.   (3) first up, (4) both up, (3) first up, (4) both up
    //   4 |.....##..
    //   3 |....#....
    //   2 |...#.....
    //   1 |.##......
    //   0 |#........
    let steep = double_step(origin, Pixel::new(8, 6));
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
    assert_eq!(
        patterns(origin, Pixel::new(8, 6)),
        [StepFirst, Steep, StepFirst, Steep]
    );
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
    let sheet = octant_sheet(|from, to, canvas| {
        for p in double_step(from, to) {
            canvas.set(p, INK);
        }
    });
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
