//! Task 3: the double-step line.

mod common;

use std::cell::RefCell;

use canvas::{MAX_COORD, Pixel};
use common::{INK, nearest_pixels, octant_sheet};
use lines::double_step::{DoubleStep, Pattern, double_step_line};
use proptest::prelude::*;
use testkit::{assert_pixels_eq, strategies::pixel_line};

/// What `double_step_line` did, in the order it did it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Event {
    Plot(Pixel),
    Step(DoubleStep),
}

/// Every call `double_step_line(from, to, …)` makes, in order.
fn events(from: Pixel, to: Pixel) -> Vec<Event> {
    let events = RefCell::new(Vec::new());
    double_step_line(
        from,
        to,
        |p| events.borrow_mut().push(Event::Plot(p)),
        |s| events.borrow_mut().push(Event::Step(s)),
    );
    events.into_inner()
}

/// The pixels of `double_step_line(from, to, …)`, after checking every
/// report it made (see [`check_reports`]). Every test goes through here,
/// so every test grades the double step, not only its pixels.
#[track_caller]
fn double_step(from: Pixel, to: Pixel) -> Vec<Pixel> {
    let events = events(from, to);
    if let Err(error) = check_reports(from, to, &events) {
        panic!("double_step_line({from}, {to}): {error}");
    }
    events
        .iter()
        .filter_map(|e| match e {
            Event::Plot(p) => Some(*p),
            Event::Step(_) => None,
        })
        .collect()
}

/// The reports against the definition, in the order they came: `from`
/// first, then per double step the report *before* its two pixels, then
/// the endpoint alone after an odd number of steps. Double step `k`
/// starts in column `i = 2k` at the definition's row `j` there (first
/// octant terms, counted from `from`); its decision variable is twice
/// `F(x, y) = Δy·x − Δx·y` at the midpoint `(i + 2, j + ½)` for `m ≤ ½`
/// (the slides' `d`), at `(i + 2, j + 3/2)` for `m > ½` (the mirrored
/// `e`); its pattern shows the definition's rows in columns `i + 1` and
/// `i + 2`. The closed form is the test's: the algorithm gets there by
/// adding `incr1` or `incr2`.
fn check_reports(from: Pixel, to: Pixel, events: &[Event]) -> Result<(), String> {
    if events.is_empty() {
        return Ok(());
    }
    let (dx, dy) = (i64::from(to.x - from.x), i64::from(to.y - from.y));
    let x_major = dx.abs() >= dy.abs();
    let (long, short) = if x_major {
        (dx.abs(), dy.abs())
    } else {
        (dy.abs(), dx.abs())
    };
    let line = nearest_pixels(from, to, None);
    // Rows along the minor axis, counted away from `from`.
    let row = |p: Pixel| {
        let minor = if x_major { p.y - from.y } else { p.x - from.x };
        i64::from(minor).abs()
    };
    let mut expected = vec![Event::Plot(from)];
    for k in 0..(long / 2) as usize {
        let (i, j) = (2 * k as i64, row(line[2 * k]));
        let d = if 2 * short <= long {
            2 * short * (i + 2) - long * (2 * j + 1)
        } else {
            2 * short * (i + 2) - long * (2 * j + 3)
        };
        let rows = [row(line[2 * k + 1]) - j, row(line[2 * k + 2]) - j];
        let pattern = [
            Pattern::Flat,
            Pattern::StepSecond,
            Pattern::StepFirst,
            Pattern::Steep,
        ]
        .into_iter()
        .find(|p| p.rows() == rows)
        .expect("two pixels of a line lie on one of four patterns");
        expected.push(Event::Step(DoubleStep { d, pattern }));
        expected.push(Event::Plot(line[2 * k + 1]));
        expected.push(Event::Plot(line[2 * k + 2]));
    }
    if long % 2 == 1 {
        expected.push(Event::Plot(to));
    }
    // The pixels themselves are the tests' to compare (with a diff); here
    // only where they come, and what the reports say.
    let same = |got: &Event, want: &Event| match (got, want) {
        (Event::Plot(_), Event::Plot(_)) => true,
        (Event::Step(a), Event::Step(b)) => a == b,
        _ => false,
    };
    for (n, want) in expected.iter().enumerate() {
        let got = events.get(n);
        if got.is_some_and(|got| same(got, want)) {
            continue;
        }
        let what = match want {
            Event::Step(s) => format!(
                "the report of double step {} before its two pixels, {s:?}",
                (n - 1) / 3
            ),
            Event::Plot(_) => "a pixel".to_owned(),
        };
        return Err(match got {
            None => format!(
                "call {n} should be {what}, but there are only {n} calls \
                 ({} double steps of {long} steps: report each to `step` before its two pixels)",
                long / 2
            ),
            Some(got) => {
                format!("call {n} is {got:?}, but should be {what} (the calls: {events:?})")
            }
        });
    }
    if events.len() > expected.len() {
        return Err(format!(
            "{} calls after the line's last pixel: {:?}",
            events.len() - expected.len(),
            &events[expected.len()..]
        ));
    }
    Ok(())
}

/// The reports of `double_step_line` while drawing `from → to`.
fn steps(from: Pixel, to: Pixel) -> Vec<DoubleStep> {
    let mut steps = Vec::new();
    double_step_line(from, to, |_| {}, |s| steps.push(s));
    steps
}

#[testkit::test]
fn each_pattern_appears_where_the_slope_allows_it() {
    use Pattern::{Flat, Steep, StepFirst, StepSecond};
    let step = |(d, pattern)| DoubleStep { d, pattern };
    let origin = Pixel::new(0, 0);
    // Slope 1/4 from (0,0): patterns 1 (flat) and 3 (first pixel up). Ties
    // at x = 2 and x = 6 go to the lower row. The slides' d = 4Δy − Δx = 0,
    // incr1 = 4Δy = 8, incr2 = 4Δy − 2Δx = −8, cond = 2Δy = 4:
    //   2 |.......##   double steps from x = 0, 2, 4, 6:
    //   1 |...####..   d = 0: (1) flat, d = 8: (3) first up,
    //   0 |###......   d = 0: (1) flat, d = 8: (3) first up
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
        steps(origin, Pixel::new(8, 2)),
        [(0, Flat), (8, StepFirst), (0, Flat), (8, StepFirst)].map(step)
    );
    // Slope 3/8: pattern 2 (second pixel up) first; a tie at x = 4. Here
    // d = 4, incr1 = 12, incr2 = −4, cond = 6:
    //   3 |.......##   double steps from x = 0, 2, 4, 6:
    //   2 |.....##..   d = 4: (2) second up, d = 0: (1) flat,
    //   1 |..###....   d = 12: (3) first up, d = 8: (3) first up
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
        steps(origin, Pixel::new(8, 3)),
        [(4, StepSecond), (0, Flat), (12, StepFirst), (8, StepFirst)].map(step)
    );
    // Slope 3/4: patterns 3 and 4; ties at x = 2 and x = 6. The mirrored
    // e = 4Δy − 3Δx = 0 grows by 4Δy − 4Δx = −8 after pattern 4 and by
    // 4Δy − 2Δx = 8 after patterns 2 and 3; pattern 2 when e ≤ 2(Δy − Δx) = −4:
    //   6 |........#   double steps from x = 0, 2, 4, 6:
    //   5 |.......#.   e = 0: (3) first up, e = 8: (4) both up,
    //   4 |.....##..   e = 0: (3) first up, e = 8: (4) both up
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
        steps(origin, Pixel::new(8, 6)),
        [(0, StepFirst), (8, Steep), (0, StepFirst), (8, Steep)].map(step)
    );
}

#[testkit::test]
fn odd_number_of_steps_ends_on_the_endpoint() {
    // (0,0) -> (5,2): two double steps, each reported before its pixels,
    // then the endpoint alone. d = 4Δy − Δx = 3, incr2 = 4Δy − 2Δx = −2,
    // cond = 4: d = 3 and d = 1 both lie in (0, cond), pattern 2 twice.
    use Event::{Plot, Step};
    let (from, to) = (Pixel::new(0, 0), Pixel::new(5, 2));
    let at = |x, y| Plot(Pixel::new(x, y));
    let second_up = |d| {
        Step(DoubleStep {
            d,
            pattern: Pattern::StepSecond,
        })
    };
    assert_eq!(
        events(from, to),
        [
            at(0, 0),
            second_up(3),
            at(1, 0),
            at(2, 1),
            second_up(1),
            at(3, 1),
            at(4, 2),
            at(5, 2),
        ],
        "the calls of double_step_line({from}, {to}), in order"
    );
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
