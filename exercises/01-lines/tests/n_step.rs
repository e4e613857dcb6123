//! Task 3b (bonus): the N-step line.

mod common;

use std::cell::RefCell;

use canvas::{MAX_COORD, Pixel};
use common::{INK, nearest_pixels, octant_sheet};
use lines::n_step::{MAX_N, NStep, n_step_line};
use proptest::prelude::*;
use testkit::{assert_pixels_eq, strategies::pixel_line};

/// What `n_step_line` did, in the order it did it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Event {
    Plot(Pixel),
    Step(NStep),
}

/// Every call `n_step_line(from, to, n, …)` makes, in order.
fn events(from: Pixel, to: Pixel, n: u32) -> Vec<Event> {
    let events = RefCell::new(Vec::new());
    n_step_line(
        from,
        to,
        n,
        |p| events.borrow_mut().push(Event::Plot(p)),
        |s| events.borrow_mut().push(Event::Step(s)),
    );
    events.into_inner()
}

/// A report, written as the tests write them: `(d, rises)`.
fn report(d: i64, rises: u32) -> Event {
    Event::Step(NStep { d, rises })
}

/// A pixel, written as the tests write them: `(x, y)`.
fn at(x: i32, y: i32) -> Event {
    Event::Plot(Pixel::new(x, y))
}

/// The line in first-octant terms: `(long, short)`, its `|Δ|` along the
/// major and the minor axis (x is major when `|Δx| ≥ |Δy|`).
fn axes(from: Pixel, to: Pixel) -> (i64, i64) {
    let (dx, dy) = (
        i64::from(to.x - from.x).abs(),
        i64::from(to.y - from.y).abs(),
    );
    (dx.max(dy), dx.min(dy))
}

/// The definition's pixels `p₀ … p_long` and their rows along the minor
/// axis, counted away from `from`.
fn rows_of_the_definition(from: Pixel, to: Pixel) -> (Vec<Pixel>, Vec<i64>) {
    let pixels = nearest_pixels(from, to, None);
    let x_major = (to.x - from.x).abs() >= (to.y - from.y).abs();
    let rows = pixels
        .iter()
        .map(|p| i64::from(if x_major { p.y - from.y } else { p.x - from.x }).abs())
        .collect();
    (pixels, rows)
}

/// The lower of the two rows the `k`-th column of a step can take,
/// counted from the step's start: `⌈k·short/long⌉ − 1`, and 0 on a line
/// along an axis.
fn lower_row(k: i64, long: i64, short: i64) -> i64 {
    if short == 0 {
        0
    } else {
        (k * short + long - 1).div_euclid(long) - 1
    }
}

/// Why `n_step_line(from, to, n, …)` draws nothing, if it does not.
fn draws_nothing(from: Pixel, to: Pixel, n: u32) -> Option<String> {
    if !(1..=MAX_N).contains(&n) {
        return Some(format!("n = {n} is outside 1..={MAX_N}"));
    }
    [from, to]
        .into_iter()
        .find(|p| p.x.unsigned_abs().max(p.y.unsigned_abs()) > MAX_COORD.unsigned_abs())
        .map(|p| format!("{p} lies beyond ±MAX_COORD = ±{MAX_COORD}"))
}

/// The calls by the reporting rule, from the line's definition: `from`,
/// then per step of `n` pixels its report before its pixels, then the
/// last `long mod n` pixels alone. The step from column `i` (first-octant
/// terms, counted from `from`), where the definition has row `j`, reports
/// twice `F(x, y) = short·x − long·y` at the midpoint of its last column,
/// `(i + n, j + q + ½)` with `q = ⌈n·short/long⌉ − 1` (0 along an axis),
/// and the rows the definition has in its columns `i + 1 … i + n`, bit
/// `k − 1` for a rise at the `k`-th. The closed form is the test's: the
/// algorithm gets there by adding `2n·short − 2r·long` per step.
fn by_the_reporting_rule(from: Pixel, to: Pixel, n: u32) -> Vec<Event> {
    if draws_nothing(from, to, n).is_some() {
        return Vec::new();
    }
    let (pixels, rows) = rows_of_the_definition(from, to);
    let (long, short) = axes(from, to);
    let n = i64::from(n);
    let q = lower_row(n, long, short);
    let mut events = vec![Event::Plot(from)];
    let mut i = 0;
    while i + n <= long {
        let j = rows[i as usize];
        let d = 2 * short * (i + n) - long * (2 * (j + q) + 1);
        let rises = (1..=n)
            .filter(|&k| rows[(i + k) as usize] > rows[(i + k - 1) as usize])
            .fold(0, |w, k| w | 1 << (k - 1));
        events.push(report(d, rises));
        events.extend((1..=n).map(|k| Event::Plot(pixels[(i + k) as usize])));
        i += n;
    }
    events.extend(pixels[(i + 1) as usize..].iter().map(|&p| Event::Plot(p)));
    events
}

/// The pixels of `n_step_line(from, to, n, …)`, after checking every
/// report it made, and where, against [`by_the_reporting_rule`]. Every
/// test goes through here, so every test grades the N-step, not only its
/// pixels.
#[track_caller]
fn n_step(from: Pixel, to: Pixel, n: u32) -> Vec<Pixel> {
    let events = events(from, to, n);
    if let Err(error) = check_reports(from, to, n, &events) {
        panic!("n_step_line({from}, {to}, n = {n}): {error}");
    }
    events
        .iter()
        .filter_map(|e| match e {
            Event::Plot(p) => Some(*p),
            Event::Step(_) => None,
        })
        .collect()
}

/// `events` against the reporting rule: the reports where they belong and
/// with the values they must have; the pixels are the tests' to compare
/// (with a diff), here only where they come.
fn check_reports(from: Pixel, to: Pixel, n: u32, events: &[Event]) -> Result<(), String> {
    let expected = by_the_reporting_rule(from, to, n);
    if expected.is_empty() && !events.is_empty() {
        let why = draws_nothing(from, to, n).unwrap_or_default();
        return Err(format!(
            "{why}, which draws nothing, but there are {} calls: {events:?}",
            events.len()
        ));
    }
    // Nothing drawn at all is for the tests to show, with the line's pixels.
    if events.is_empty() {
        return Ok(());
    }
    let (long, short) = axes(from, to);
    let (_, rows) = rows_of_the_definition(from, to);
    let q = lower_row(i64::from(n), long, short);
    let same = |got: &Event, want: &Event| match (got, want) {
        (Event::Plot(_), Event::Plot(_)) => true,
        (Event::Step(a), Event::Step(b)) => a == b,
        _ => false,
    };
    let per_step = n as usize + 1;
    let full_steps = long as usize / n as usize;
    for (c, want) in expected.iter().enumerate() {
        let got = events.get(c);
        if got.is_some_and(|got| same(got, want)) {
            continue;
        }
        let what = match want {
            Event::Step(s) => {
                let k = (c - 1) / per_step;
                let (i, j) = (k as i64 * i64::from(n), rows[k * n as usize]);
                format!(
                    "the report of step {k} before its {n} pixels, {s:?}: the step starts in \
                     column i = {i} on row j = {j}, d is twice F at the midpoint (i + n, j + q + ½) \
                     of its last column with q = {q} (⌈n·{short}/{long}⌉ − 1, 0 along an axis), and bit k − 1 of \
                     rises is set where its k-th pixel lies one row above the one before"
                )
            }
            Event::Plot(_) if c > full_steps * per_step => {
                "a pixel of the last, short step, which reports nothing".to_owned()
            }
            Event::Plot(_) => "a pixel".to_owned(),
        };
        return Err(match got {
            None => format!(
                "call {c} should be {what}, but there are only {c} calls \
                 ({} steps of {n} pixels in {long} columns: report each to `step` before its pixels)",
                long / i64::from(n)
            ),
            Some(got) => {
                format!("call {c} is {got:?}, but should be {what} (the calls: {events:?})")
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

/// The pixels of `n_step(from, to, n)` against the definition, in order.
#[track_caller]
fn assert_is_the_midpoint_line(from: Pixel, to: Pixel, n: u32) {
    let expected = nearest_pixels(from, to, None);
    let yours = n_step(from, to, n);
    let what = format!("n_step_line({from}, {to}, n = {n})");
    assert_pixels_eq(&expected, &yours, &what);
    assert_eq!(
        yours, expected,
        "{what}: the midpoint line's pixels, but not in order from `from` to `to`"
    );
}

#[testkit::test]
fn a_step_of_three_picks_each_of_its_four_patterns() {
    // (0,0) -> (12,3), slope 1/4, three pixels a step: at most one of
    // them rises. q = ⌈3·3/12⌉ − 1 = 0 and c₁ = c₂ = c₃ = 0, so
    // T₃ = 0, T₂ = 2Δy = 6, T₁ = 4Δy = 12; D₀ = 2·3Δy − Δx = 6, and a
    // step adds 6Δy − 2rΔx = 18 − 24r. Ties at x = 2, 6 and 10 stay low.
    //   3 |...........##   steps from x = 0, 3, 6, 9:
    //   2 |.......####..   D = 6:  T₃ < D ≤ T₂, the third pixel rises (0b100)
    //   1 |...####......   D = 0:  D ≤ T₃, none rises (0b000)
    //   0 |###..........   D = 18: T₁ < D, the first rises (0b001)
    //                      D = 12: T₂ < D ≤ T₁, the second rises (0b010)
    let (from, to) = (Pixel::new(0, 0), Pixel::new(12, 3));
    assert_eq!(
        events(from, to, 3),
        [
            at(0, 0),
            report(6, 0b100),
            at(1, 0),
            at(2, 0),
            at(3, 1),
            report(0, 0b000),
            at(4, 1),
            at(5, 1),
            at(6, 1),
            report(18, 0b001),
            at(7, 2),
            at(8, 2),
            at(9, 2),
            report(12, 0b010),
            at(10, 2),
            at(11, 3),
            at(12, 3),
        ],
        "the calls of n_step_line({from}, {to}, n = 3), in order: per step the report \
         (D = 2F at the last column's midpoint, the pattern) before its three pixels"
    );
    assert_is_the_midpoint_line(from, to, 3);
}

#[testkit::test]
fn steps_of_one_and_two_are_the_midpoint_line_and_the_double_step() {
    // N = 1: the midpoint line, its d = 2Δy − Δx before every pixel,
    // + 2Δy after E (0b0), + 2(Δy − Δx) after NE (0b1). (0,0) -> (5,2):
    let (from, to) = (Pixel::new(0, 0), Pixel::new(5, 2));
    assert_eq!(
        events(from, to, 1),
        [
            at(0, 0),
            report(-1, 0b0),
            at(1, 0),
            report(3, 0b1),
            at(2, 1),
            report(-3, 0b0),
            at(3, 1),
            report(1, 0b1),
            at(4, 2),
            report(-5, 0b0),
            at(5, 2),
        ],
        "n_step_line({from}, {to}, n = 1) reports the midpoint line's d before each pixel"
    );
    // N = 2: the double step's d and its patterns (flat 0b00, second up
    // 0b10, first up 0b01, both up 0b11): slope 3/8 has the slides'
    // d = 4Δy − Δx = 4 and cond = 2Δy = 6; slope 3/4 the mirrored
    // e = 4Δy − 3Δx = 0 (task 3's test, `each_pattern_appears_where_the_slope_allows_it`).
    let cases = [
        (
            Pixel::new(8, 3),
            [(4, 0b10), (0, 0b00), (12, 0b01), (8, 0b01)],
        ),
        (
            Pixel::new(8, 6),
            [(0, 0b01), (8, 0b11), (0, 0b01), (8, 0b11)],
        ),
    ];
    for (to, steps) in cases {
        let reports: Vec<NStep> = events(from, to, 2)
            .into_iter()
            .filter_map(|e| match e {
                Event::Step(s) => Some(s),
                Event::Plot(_) => None,
            })
            .collect();
        assert_eq!(
            reports,
            steps.map(|(d, rises)| NStep { d, rises }),
            "n_step_line({from}, {to}, n = 2) reports the double step's d (or e) and pattern"
        );
        assert_is_the_midpoint_line(from, to, 2);
    }
}

#[testkit::test]
fn a_short_last_step_is_plotted_without_a_report() {
    // (0,0) -> (8,3) three pixels a step: two steps, then two pixels
    // alone. q = ⌈9/8⌉ − 1 = 1, D₀ = 6Δy − 3Δx = −6, a step adds
    // 18 − 16r: 0b010 rises once, so D = −6 + 2 = −4.
    //   3 |.......##
    //   2 |.....##..    steps from x = 0 and 3: 0b010 twice;
    //   1 |..###....    x = 7, 8: the last, short step
    //   0 |##.......
    let (from, to) = (Pixel::new(0, 0), Pixel::new(8, 3));
    assert_eq!(
        events(from, to, 3),
        [
            at(0, 0),
            report(-6, 0b010),
            at(1, 0),
            at(2, 1),
            at(3, 1),
            report(-4, 0b010),
            at(4, 1),
            at(5, 2),
            at(6, 2),
            at(7, 3),
            at(8, 3),
        ],
        "the calls of n_step_line({from}, {to}, n = 3): the last 8 mod 3 = 2 pixels report nothing"
    );
    assert_is_the_midpoint_line(from, to, 3);
    // Shorter than one step: no report at all; a zero-length line is
    // its one pixel.
    let short = [Pixel::new(0, 0), Pixel::new(2, 1)];
    assert_eq!(
        events(short[0], short[1], 4),
        [at(0, 0), at(1, 0), at(2, 1)],
        "n_step_line({}, {}, n = 4): two columns, fewer than a step, report nothing",
        short[0],
        short[1]
    );
    let point = Pixel::new(-4, 7);
    assert_eq!(
        events(point, point, 5),
        [at(-4, 7)],
        "n_step_line({point}, {point}, n = 5) is the one pixel"
    );
    // Every leftover from 1 to n − 1, in every direction.
    for n in 2..=8 {
        for extra in 1..n {
            let length = 2 * n + extra;
            for to in [
                Pixel::new(length, 3),
                Pixel::new(-3, -length),
                Pixel::new(-length, length - 1),
            ] {
                assert_is_the_midpoint_line(Pixel::new(0, 0), to, n as u32);
            }
        }
    }
}

#[testkit::test]
fn ties_inside_a_step_follow_the_direction_rule() {
    // (0,0) -> (4,1), four pixels a step: at x = 2 the line is at y = ½,
    // a tie, and the midpoint rule takes the lower pixel both ways.
    // D₀ = 8Δy − Δx = 4 = T₂ = 2·2Δy: the second column's midpoint lies on
    // the line. Forwards the minor axis runs forwards and the tie stays
    // low: rows 0, 0, 1, 1 (0b0100). Backwards, from (4,1), the rows
    // count downwards and the same pixel (2,0) is row 1: rows 0, 1, 1, 1
    // (0b0010), the tie taken upwards in the line's own first octant.
    let expected = [(0, 0), (1, 0), (2, 0), (3, 1), (4, 1)].map(|(x, y)| Pixel::new(x, y));
    let (from, to) = (expected[0], expected[4]);
    assert_eq!(
        events(from, to, 4),
        [
            at(0, 0),
            report(4, 0b0100),
            at(1, 0),
            at(2, 0),
            at(3, 1),
            at(4, 1)
        ],
        "n_step_line({from}, {to}, n = 4): the tie D = T₂ stays on its row going forwards"
    );
    assert_eq!(
        events(to, from, 4),
        [
            at(4, 1),
            report(4, 0b0010),
            at(3, 1),
            at(2, 0),
            at(1, 0),
            at(0, 0)
        ],
        "n_step_line({to}, {from}, n = 4): the tie D = T₂ rises going backwards (the smaller y)"
    );
    // The ties of the slope 1/4 (x = 2, 6, 10) at every n, both ways.
    for n in 1..=8 {
        assert_is_the_midpoint_line(Pixel::new(0, 0), Pixel::new(12, 3), n);
        assert_is_the_midpoint_line(Pixel::new(12, 3), Pixel::new(0, 0), n);
        assert_is_the_midpoint_line(Pixel::new(0, 0), Pixel::new(-3, 12), n);
        assert_is_the_midpoint_line(Pixel::new(-3, 12), Pixel::new(0, 0), n);
    }
}

#[testkit::test]
fn lines_in_all_octants() {
    let sheet_of = |n| {
        octant_sheet(|from, to, canvas| {
            for p in n_step(from, to, n) {
                canvas.set(p, INK);
            }
        })
    };
    let sheet = sheet_of(3);
    testkit::insta::assert_snapshot!("lines_in_all_octants", sheet);
    for n in 1..=8 {
        let other = sheet_of(n);
        assert!(
            other == sheet,
            "n = {n} draws other pixels than n = 3 (every n draws the midpoint line):\n{other}"
        );
    }
}

#[testkit::test]
fn one_slope_uses_n_plus_one_of_the_two_to_the_n_patterns() {
    // Slope 73/200: no two columns of a step share a threshold, and the
    // line is long enough to meet every interval of D.
    let (from, to) = (Pixel::new(0, 0), Pixel::new(200, 73));
    for n in 1..=8 {
        assert_is_the_midpoint_line(from, to, n);
        let mut patterns: Vec<u32> = events(from, to, n)
            .into_iter()
            .filter_map(|e| match e {
                Event::Step(s) => Some(s.rises),
                Event::Plot(_) => None,
            })
            .collect();
        patterns.sort_unstable();
        patterns.dedup();
        assert_eq!(
            patterns.len(),
            n as usize + 1,
            "n_step_line({from}, {to}, n = {n}): the patterns reported, {patterns:?}, \
             should be n + 1 of the 2ⁿ words"
        );
    }
}

#[testkit::test]
fn endpoints_beyond_max_coord_and_n_outside_its_range_draw_nothing() {
    let origin = Pixel::new(0, 0);
    for (to, n) in [
        (Pixel::new(0, -MAX_COORD - 1), 3),
        (Pixel::new(MAX_COORD + 1, 0), 1),
        (Pixel::new(7, 3), 0),
        (Pixel::new(7, 3), MAX_N + 1),
    ] {
        assert_eq!(
            n_step(origin, to, n),
            [],
            "n_step_line({origin}, {to}, n = {n}) draws nothing"
        );
    }
    // At the limits themselves, a line is drawn: at MAX_COORD, and with
    // n = MAX_N (two steps of 32 pixels, then 6 alone).
    let edge = [Pixel::new(0, -MAX_COORD), Pixel::new(1, 4 - MAX_COORD)];
    assert_is_the_midpoint_line(edge[0], edge[1], 2);
    let corner = [
        Pixel::new(MAX_COORD - 70, -MAX_COORD),
        Pixel::new(MAX_COORD, 29 - MAX_COORD),
    ];
    assert_is_the_midpoint_line(corner[0], corner[1], MAX_N);
    assert_is_the_midpoint_line(corner[1], corner[0], MAX_N);
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn every_n_draws_the_midpoint_lines_pixels([from, to] in pixel_line(40), n in 1..=8u32) {
        assert_is_the_midpoint_line(from, to, n);
    }

    #[testkit::test]
    fn reversed_line_covers_same_pixels([from, to] in pixel_line(40), n in 1..=8u32) {
        let forward = n_step(from, to, n);
        prop_assert!(
            forward.contains(&from) && forward.contains(&to),
            "n_step_line({from}, {to}, n = {n}) must draw both endpoints: {forward:?}"
        );
        assert_pixels_eq(&forward, &n_step(to, from, n), &format!("{from} <-> {to}, n = {n}"));
    }

    #[testkit::test]
    fn steps_of_one_and_two_report_the_midpoint_lines_and_the_double_steps_decisions(
        [from, to] in pixel_line(40),
    ) {
        // Each written from its own task's definition: the midpoint
        // line's d at (i + 1, j + ½); the double step's d at (i + 2, j + ½)
        // for m ≤ ½ and e at (i + 2, j + 3/2) for m > ½.
        let (long, short) = axes(from, to);
        let (_, rows) = rows_of_the_definition(from, to);
        for n in [1, 2] {
            let mut expected = Vec::new();
            let mut i = 0;
            while i + n <= long {
                let j = rows[i as usize];
                let above = if n == 2 && 2 * short > long { 3 } else { 1 };
                let d = 2 * short * (i + n) - long * (2 * j + above);
                let rises = (1..=n)
                    .filter(|&k| rows[(i + k) as usize] > rows[(i + k - 1) as usize])
                    .fold(0, |w, k| w | 1 << (k - 1));
                expected.push(NStep { d, rises });
                i += n;
            }
            let reports: Vec<NStep> = events(from, to, n as u32)
                .into_iter()
                .filter_map(|e| match e {
                    Event::Step(s) => Some(s),
                    Event::Plot(_) => None,
                })
                .collect();
            prop_assert_eq!(
                reports,
                expected,
                "n_step_line({}, {}, n = {}): the {} decisions, in order",
                from,
                to,
                n,
                if n == 1 { "midpoint line's" } else { "double step's" }
            );
            // And every call in its place.
            n_step(from, to, n as u32);
        }
    }

    #[testkit::test]
    fn lines_near_the_coordinate_limit_are_exact(
        [from, to] in pixel_line(30),
        shift in prop_oneof![Just(MAX_COORD - 30), Just(30 - MAX_COORD)],
        n in 1..=8u32,
    ) {
        let moved = |p: Pixel| Pixel::new(p.x + shift, p.y - shift);
        assert_is_the_midpoint_line(moved(from), moved(to), n);
    }
}
