//! Task 7 (bonus): the midpoint line from both endpoints at once.

mod common;

use std::cell::RefCell;

use canvas::{MAX_COORD, Pixel};
use common::nearest_pixels;
use lines::two_ended::two_ended_midpoint_line;
use proptest::prelude::*;
use testkit::strategies::pixel_line;

/// What `two_ended_midpoint_line` did, in the order it did it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Event {
    Plot(Pixel),
    Step(i64),
}

/// Every call `two_ended_midpoint_line(from, to, …)` makes, in order.
fn events(from: Pixel, to: Pixel) -> Vec<Event> {
    let events = RefCell::new(Vec::new());
    two_ended_midpoint_line(
        from,
        to,
        |p| events.borrow_mut().push(Event::Plot(p)),
        |d| events.borrow_mut().push(Event::Step(d)),
    );
    events.into_inner()
}

/// The calls by the reporting rule, from the line's definition `p₀ … p_n`:
/// `p₀`, `p_n`, then alternately a report and a pixel of the walker from
/// `from` and of the walker from `to`. A walker's `k`-th step (from 0)
/// leaves the pixel `k` columns from its start, `j` rows away from it
/// along the minor axis; its decision variable there is twice `F` at the
/// next midpoint in its own first octant, `2·short·(k + 1) − long·(2j + 1)`
/// (the test's closed form: the walkers get there by adding).
fn by_the_walkers(from: Pixel, to: Pixel) -> Vec<Event> {
    let far = MAX_COORD.unsigned_abs();
    if [from.x, from.y, to.x, to.y]
        .iter()
        .any(|c| c.unsigned_abs() > far)
    {
        return Vec::new();
    }
    let pixels = nearest_pixels(from, to, None);
    let (dx, dy) = (i64::from(to.x - from.x), i64::from(to.y - from.y));
    let x_major = dx.abs() >= dy.abs();
    let (long, short) = if x_major {
        (dx.abs(), dy.abs())
    } else {
        (dy.abs(), dx.abs())
    };
    let rows = |p: Pixel, start: Pixel| {
        i64::from(if x_major {
            p.y - start.y
        } else {
            p.x - start.x
        })
        .abs()
    };
    let d = |k: usize, p: Pixel, start: Pixel| {
        2 * short * (k as i64 + 1) - long * (2 * rows(p, start) + 1)
    };
    let n = pixels.len() - 1;
    let mut events = vec![Event::Plot(from)];
    if n == 0 {
        return events;
    }
    events.push(Event::Plot(to));
    let (mut low, mut high, mut k) = (0, n, 0);
    while low + 1 < high {
        events.push(Event::Step(d(k, pixels[low], from)));
        low += 1;
        events.push(Event::Plot(pixels[low]));
        if low + 1 < high {
            events.push(Event::Step(d(k, pixels[high], to)));
            high -= 1;
            events.push(Event::Plot(pixels[high]));
        }
        k += 1;
    }
    events
}

/// The pixels `two_ended_midpoint_line(from, to, …)` plots, after
/// checking where its reports come and what they say against
/// [`by_the_walkers`] (the pixels themselves are the tests' to compare).
/// Every test goes through here, so every test grades the two walkers,
/// not only the order of the pixels.
#[track_caller]
fn two_ended(from: Pixel, to: Pixel) -> Vec<Pixel> {
    let events = events(from, to);
    let expected = by_the_walkers(from, to);
    let same = |got: Option<&Event>, want: Option<&Event>| match (got, want) {
        (Some(Event::Plot(_)), Some(Event::Plot(_))) | (None, None) => true,
        (Some(Event::Step(a)), Some(Event::Step(b))) => a == b,
        _ => false,
    };
    // Nothing drawn at all is for the tests to show, with the line's pixels.
    if !events.is_empty()
        && let Some(n) =
            (0..events.len().max(expected.len())).find(|&n| !same(events.get(n), expected.get(n)))
    {
        let want = match expected.get(n) {
            Some(Event::Step(d)) => format!(
                "step({d}), the report of the walker from {} before its step {}",
                if n % 4 == 2 { from } else { to },
                (n - 2) / 4
            ),
            Some(Event::Plot(_)) => "a pixel".to_owned(),
            None => "nothing: the line has ended".to_owned(),
        };
        let got = events
            .get(n)
            .map_or("nothing".to_owned(), |e| format!("{e:?}"));
        panic!(
            "two_ended_midpoint_line({from}, {to}): call {n} is {got}, by the reporting rule it is {want} (the calls: {events:?})"
        );
    }
    events
        .into_iter()
        .filter_map(|e| match e {
            Event::Plot(p) => Some(p),
            Event::Step(_) => None,
        })
        .collect()
}

/// The pixels of the line in the two walkers' order: `p₀, p_n, p₁,
/// p_(n−1), …` of the definition's `p₀ … p_n` (the middle one last).
fn walkers_order(from: Pixel, to: Pixel) -> Vec<Pixel> {
    let pixels = nearest_pixels(from, to, None);
    let (mut low, mut high) = (0, pixels.len());
    let mut order = Vec::with_capacity(pixels.len());
    while low < high {
        order.push(pixels[low]);
        low += 1;
        if low < high {
            high -= 1;
            order.push(pixels[high]);
        }
    }
    order
}

/// `pixels` against the walkers' order of the line's definition.
fn check(from: Pixel, to: Pixel, pixels: &[Pixel]) -> Result<(), String> {
    let expected = walkers_order(from, to);
    if pixels == expected.as_slice() {
        return Ok(());
    }
    let mut sorted = pixels.to_vec();
    sorted.sort_by_key(|p| (p.x, p.y));
    let mut want = expected.clone();
    want.sort_by_key(|p| (p.x, p.y));
    if sorted == want {
        Err(format!(
            "{from:?} → {to:?}: the right pixels in the wrong order: {pixels:?}; \
             from both ends at once is {expected:?}"
        ))
    } else {
        Err(format!(
            "{from:?} → {to:?}: {pixels:?}; the line's pixels, from both ends at once, are {expected:?}"
        ))
    }
}

#[testkit::test]
fn the_walkers_meet_in_the_middle() {
    // (0,0) -> (7,3): eight pixels, four from each end.
    //   3 |......##      plot order: (0,0) (7,3) (1,0) (6,3)
    //   2 |....##..                  (2,1) (5,2) (3,1) (4,2)
    //   1 |..##....
    //   0 |##......
    let expected = [
        (0, 0),
        (7, 3),
        (1, 0),
        (6, 3),
        (2, 1),
        (5, 2),
        (3, 1),
        (4, 2),
    ]
    .map(|(x, y)| Pixel::new(x, y));
    assert_eq!(two_ended(Pixel::new(0, 0), Pixel::new(7, 3)), expected);
    // Each walker reports its own d before each of its steps: d = 2·3 − 7
    // = −1 (straight), then +2·3 to 5 (diagonal), then +2·(3 − 7) to −3
    // (straight); the walker from (7,3) walks its own first octant, where
    // the line is the same shape, so its d runs the same way.
    use Event::{Plot, Step};
    let at = |x, y| Plot(Pixel::new(x, y));
    assert_eq!(
        events(Pixel::new(0, 0), Pixel::new(7, 3)),
        [
            at(0, 0),
            at(7, 3),
            Step(-1),
            at(1, 0),
            Step(-1),
            at(6, 3),
            Step(5),
            at(2, 1),
            Step(5),
            at(5, 2),
            Step(-3),
            at(3, 1),
            Step(-3),
            at(4, 2),
        ],
        "the calls of two_ended_midpoint_line((0, 0), (7, 3)), in order"
    );
}

#[testkit::test]
fn ties_go_to_the_smaller_minor_coordinate_from_both_ends() {
    // (0,0) -> (8,2): ties at x = 2 (y = 0.5) and x = 6 (y = 1.5), one on
    // each walker's side. Mirroring the first walker's choice through the
    // centre would take y = 2 at x = 6.
    //   2 |.......##
    //   1 |...####..     x = 2 → y = 0, x = 6 → y = 1
    //   0 |###......
    let (from, to) = (Pixel::new(0, 0), Pixel::new(8, 2));
    let pixels = two_ended(from, to);
    check(from, to, &pixels).unwrap();
    assert!(pixels.contains(&Pixel::new(6, 1)), "x = 6 is a tie: y = 1");
    check(to, from, &two_ended(to, from)).unwrap();
    // Both ties are met with d = 0 (twice F at a midpoint on the line):
    // the walker from (0,0) goes straight there, the one from (8,2), whose
    // minor axis runs backwards, diagonally.
    let reports: Vec<_> = events(from, to)
        .into_iter()
        .filter_map(|e| match e {
            Event::Step(d) => Some(d),
            Event::Plot(_) => None,
        })
        .collect();
    assert_eq!(
        reports,
        [-4, -4, 0, 0, 4, -12, -8],
        "the reports of {from} -> {to}"
    );
}

#[testkit::test]
fn odd_and_even_counts_and_a_single_pixel() {
    for (from, to) in [
        (Pixel::new(0, 0), Pixel::new(0, 0)),
        (Pixel::new(3, 3), Pixel::new(4, 3)),
        (Pixel::new(3, 3), Pixel::new(5, 2)),
        (Pixel::new(-4, 9), Pixel::new(-2, -1)),
        (Pixel::new(10, 0), Pixel::new(-11, 0)),
    ] {
        check(from, to, &two_ended(from, to)).unwrap();
    }
}

#[testkit::test]
fn endpoints_beyond_the_limit_draw_nothing() {
    let far = MAX_COORD + 1;
    assert!(two_ended(Pixel::new(far, 0), Pixel::new(0, 0)).is_empty());
    assert!(two_ended(Pixel::new(0, 0), Pixel::new(0, -far)).is_empty());
    // An ordinary line after them is drawn.
    let (from, to) = (Pixel::new(-3, 2), Pixel::new(9, 7));
    check(from, to, &two_ended(from, to)).unwrap();
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn from_both_ends_in_every_octant([from, to] in pixel_line(60)) {
        check(from, to, &two_ended(from, to)).map_err(TestCaseError::fail)?;
    }

    #[testkit::test]
    fn a_line_drawn_backwards_covers_the_same_pixels([from, to] in pixel_line(60)) {
        let mut forward = two_ended(from, to);
        let mut backward = two_ended(to, from);
        check(to, from, &backward).map_err(TestCaseError::fail)?;
        forward.sort_by_key(|p| (p.x, p.y));
        backward.sort_by_key(|p| (p.x, p.y));
        prop_assert_eq!(forward, backward);
    }
}
