//! Task 5c: Wu's antialiased line.

mod common;

use std::cell::RefCell;
use std::collections::BTreeMap;

use canvas::{Canvas, MAX_COORD, Pixel, Rgba};
use lines::wu::wu_line_traced;
use proptest::prelude::*;
use testkit::strategies::pixel_line;

/// What `wu_line_traced` did, in the order it did it.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Event {
    Plot(Pixel, f32),
    Error(u64),
}

/// Every call `wu_line_traced(from, to, …)` makes, in order.
fn events(from: Pixel, to: Pixel) -> Vec<Event> {
    let events = RefCell::new(Vec::new());
    wu_line_traced(
        from,
        to,
        |p, w| events.borrow_mut().push(Event::Plot(p, w)),
        |e| events.borrow_mut().push(Event::Error(e)),
    );
    events.into_inner()
}

/// The calls of Wu's line by the reporting rule of `wu_line_traced`, from
/// the closed form: column `k` (of `1 … Δmajor − 1`) holds the accumulator
/// `k · ⌈Δminor / Δmajor · 2⁶⁴⌉ mod 2⁶⁴`, its row `j` is the number of
/// wraps so far, `⌊k · ⌈…⌉ / 2⁶⁴⌋`, and its far pixel weighs the top 8
/// bits. (The algorithm gets there by adding, column by column.)
fn by_the_rule(from: Pixel, to: Pixel) -> Vec<Event> {
    if [from.x, from.y, to.x, to.y]
        .iter()
        .any(|c| c.unsigned_abs() > MAX_COORD as u32)
    {
        return Vec::new();
    }
    let (dx, dy) = (i64::from(to.x - from.x), i64::from(to.y - from.y));
    let x_major = dx.abs() >= dy.abs();
    let (long, short) = if x_major {
        (dx.unsigned_abs(), dy.unsigned_abs())
    } else {
        (dy.unsigned_abs(), dx.unsigned_abs())
    };
    // (i, j) in first-octant terms back to the line's octant.
    let pixel = |i: u64, j: u64| {
        let (major, minor) = (i as i32, j as i32);
        let (sx, sy) = (dx.signum() as i32, dy.signum() as i32);
        if x_major {
            Pixel::new(from.x + sx * major, from.y + sy * minor)
        } else {
            Pixel::new(from.x + sx * minor, from.y + sy * major)
        }
    };
    let mut events = vec![Event::Plot(from, 1.0)];
    if long == 0 {
        return events;
    }
    if short == 0 || short == long {
        events
            .extend((1..long).map(|i| Event::Plot(pixel(i, if short == 0 { 0 } else { i }), 1.0)));
    } else {
        let adjust = (u128::from(short) << 64).div_ceil(u128::from(long));
        for k in 1..long {
            let sum = u128::from(k) * adjust;
            let (error, j) = (sum as u64, (sum >> 64) as u64);
            let far = (error >> 56) as f32 / 256.0;
            events.push(Event::Error(error));
            events.push(Event::Plot(pixel(k, j), 1.0 - far));
            events.push(Event::Plot(pixel(k, j + 1), far));
        }
    }
    events.push(Event::Plot(to, 1.0));
    events
}

/// The calls of `wu_line_traced(from, to, …)` against the reporting rule,
/// in order (see [`by_the_rule`]): `Ok` or what differs first.
fn check(from: Pixel, to: Pixel, events: &[Event]) -> Result<(), String> {
    let expected = by_the_rule(from, to);
    let Some(n) = (0..events.len().max(expected.len())).find(|&n| events.get(n) != expected.get(n))
    else {
        return Ok(());
    };
    let call = |e: &Event| match e {
        Event::Error(e) => format!("error({e:#018x})"),
        Event::Plot(p, w) => format!("plot({p}, {w})"),
    };
    let why = match expected.get(n) {
        Some(e @ Event::Error(_)) => format!(
            "{}: the accumulator of column {k}, k · ⌈Δminor / Δmajor · 2⁶⁴⌉ wrapped to 64 bits with k = {k}",
            call(e),
            k = n.div_ceil(3)
        ),
        Some(e @ Event::Plot(..)) => format!(
            "{} (f = the top 8 bits of the accumulator reported last, / 256)",
            call(e)
        ),
        None => "nothing: the line has ended".to_owned(),
    };
    let got = events.get(n).map_or("nothing".to_owned(), call);
    Err(format!(
        "wu_line_traced({from}, {to}): call {n} is {got}, by the reporting rule it is {why}"
    ))
}

/// The plots of `wu_line_traced(from, to, …)`, after checking every call
/// it made against the reporting rule (see [`check`]): every test grades
/// the integer accumulator, not only the intensities.
#[track_caller]
fn wu(from: Pixel, to: Pixel) -> Vec<(Pixel, f32)> {
    let events = events(from, to);
    if let Err(error) = check(from, to, &events) {
        panic!("{error}");
    }
    events
        .into_iter()
        .filter_map(|e| match e {
            Event::Plot(p, w) => Some((p, w)),
            Event::Error(_) => None,
        })
        .collect()
}

/// The intensities summed per column of the major axis.
fn column_sums(from: Pixel, to: Pixel, got: &[(Pixel, f32)]) -> BTreeMap<i32, f32> {
    let x_major = (to.x - from.x).abs() >= (to.y - from.y).abs();
    let mut sums = BTreeMap::new();
    for &(p, w) in got {
        *sums.entry(if x_major { p.x } else { p.y }).or_insert(0.0) += w;
    }
    sums
}

#[testkit::test]
fn quarter_slope_splits_each_column_by_the_fraction() {
    // (0,0) -> (4,1): the ideal line is at y = 0.25, 0.5, 0.75 in columns
    // 1..3: the upper pixel gets that fraction (to 1/256), the lower the rest.
    let got = wu(Pixel::new(0, 0), Pixel::new(4, 1));
    let intensity = |p: Pixel| {
        got.iter()
            .filter(|&&(q, _)| q == p)
            .map(|&(_, w)| w)
            .sum::<f32>()
    };
    assert_eq!(intensity(Pixel::new(0, 0)), 1.0);
    assert_eq!(intensity(Pixel::new(4, 1)), 1.0);
    for (x, f) in [(1, 0.25), (2, 0.5), (3, 0.75)] {
        assert!(
            (intensity(Pixel::new(x, 1)) - f).abs() <= 1.0 / 256.0,
            "column {x}: {got:?}"
        );
        assert!(
            (intensity(Pixel::new(x, 0)) - (1.0 - f)).abs() <= 1.0 / 256.0,
            "column {x}: {got:?}"
        );
    }
    // (0,0) -> (3,1): the step 1/3 is no binary fraction. Rounded up to
    // 0x5555_5555_5555_5556 (a float's 53 bits end in …5400), it adds up
    // to 0xAAAA_AAAA_AAAA_AAAC in column 2; the top 8 bits give 0x55/256
    // and 0xAA/256.
    use Event::{Error, Plot};
    let at = |x, y, w| Plot(Pixel::new(x, y), w);
    assert_eq!(
        events(Pixel::new(0, 0), Pixel::new(3, 1)),
        [
            at(0, 0, 1.0),
            Error(0x5555_5555_5555_5556),
            at(1, 0, 1.0 - 85.0 / 256.0),
            at(1, 1, 85.0 / 256.0),
            Error(0xAAAA_AAAA_AAAA_AAAC),
            at(2, 0, 1.0 - 170.0 / 256.0),
            at(2, 1, 170.0 / 256.0),
            at(3, 1, 1.0),
        ],
        "the calls of wu_line_traced((0, 0), (3, 1)), in order"
    );
}

#[testkit::test]
fn the_accumulator_wraps_into_the_next_row() {
    // (0,0) -> (5,3): the step ⌈3/5 · 2⁶⁴⌉ wraps in columns 2 and 4, where
    // the ideal line (y = 1.2, 2.4) has passed a row; in column 2 the pair
    // is rows 1 and 2, the far row weighing 0.2.
    let (from, to) = (Pixel::new(0, 0), Pixel::new(5, 3));
    check(from, to, &events(from, to)).unwrap();
    let mut reports = Vec::new();
    wu_line_traced(from, to, |_, _| {}, |e| reports.push(e));
    let wraps: Vec<bool> = reports.windows(2).map(|w| w[1] < w[0]).collect();
    assert_eq!(
        wraps,
        [true, false, true],
        "which additions wrapped: {reports:x?}"
    );
    let got = wu(from, to);
    assert_eq!(got[3], (Pixel::new(2, 1), 1.0 - 51.0 / 256.0), "{got:?}");
    assert_eq!(got[4], (Pixel::new(2, 2), 51.0 / 256.0), "{got:?}");
}

#[testkit::test]
fn axis_parallel_and_diagonal_lines_are_solid() {
    for to in [Pixel::new(6, 0), Pixel::new(0, -6), Pixel::new(-6, 6)] {
        let got = wu(Pixel::new(0, 0), to);
        assert_eq!(got.len(), 7, "{to}: {got:?}");
        assert!(got.iter().all(|&(_, w)| w == 1.0), "{to}: {got:?}");
    }
    // One row off them, the accumulator is back: five columns between the
    // ends, each reported and split in two.
    for to in [Pixel::new(6, 1), Pixel::new(1, -6), Pixel::new(-6, 5)] {
        let got = wu(Pixel::new(0, 0), to);
        assert_eq!(got.len(), 12, "{to}: {got:?}");
    }
}

#[testkit::test]
fn a_shallow_line() {
    let mut canvas = Canvas::new(24, 10);
    for (p, w) in wu(Pixel::new(1, 1), Pixel::new(22, 8)) {
        canvas.blend(p, Rgba::WHITE, w);
    }
    testkit::assert_raster_snapshot!("a_shallow_line", canvas);
}

#[testkit::test]
fn endpoints_beyond_max_coord_draw_nothing() {
    assert!(wu(Pixel::new(0, MAX_COORD + 1), Pixel::new(0, 0)).is_empty());
    // At the limit itself, a line is drawn.
    assert!(!wu(Pixel::new(0, MAX_COORD), Pixel::new(1, MAX_COORD - 3)).is_empty());
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn every_column_sums_to_one([from, to] in pixel_line(40)) {
        let got = wu(from, to);
        let steps = (to.x - from.x).abs().max((to.y - from.y).abs());
        let sums = column_sums(from, to, &got);
        prop_assert_eq!(sums.len(), steps as usize + 1, "one entry per column");
        for (column, sum) in sums {
            prop_assert!((sum - 1.0).abs() < 1e-5, "column {column} sums to {sum}");
        }
    }

    #[testkit::test]
    fn intensity_is_never_above_full([from, to] in pixel_line(40)) {
        let got = wu(from, to);
        prop_assert!(got.iter().any(|&(p, w)| p == from && w > 0.0), "{from} -> {to} does not draw {from}: {got:?}");
        for (p, w) in got {
            prop_assert!((0.0..=1.0).contains(&w), "pixel {p}: {w}");
        }
    }

    #[testkit::test]
    fn the_pixels_straddle_the_ideal_line([from, to] in pixel_line(40)) {
        // The intensity-weighted mean of each column is the ideal line's
        // position there, to within Wu's 8-bit intensities.
        let x_major = (to.x - from.x).abs() >= (to.y - from.y).abs();
        let (dm, dn) = if x_major { (to.x - from.x, to.y - from.y) } else { (to.y - from.y, to.x - from.x) };
        let mut mean: BTreeMap<i32, f64> = BTreeMap::new();
        for (p, w) in wu(from, to) {
            let (m, n) = if x_major { (p.x, p.y) } else { (p.y, p.x) };
            *mean.entry(m).or_insert(0.0) += f64::from(w) * f64::from(n);
        }
        let (m0, n0) = if x_major { (from.x, from.y) } else { (from.y, from.x) };
        prop_assert_eq!(mean.len(), dm.unsigned_abs() as usize + 1, "one column per step of the major axis");
        for (m, weighted) in mean {
            let ideal = if dm == 0 { f64::from(n0) } else { f64::from(n0) + f64::from(dn) * f64::from(m - m0) / f64::from(dm) };
            prop_assert!((weighted - ideal).abs() <= 2.0 / 256.0 + 1e-4, "column {m}: mean {weighted}, ideal {ideal}");
        }
    }

    #[testkit::test]
    fn both_endpoints_are_full([from, to] in pixel_line(40)) {
        let got = wu(from, to);
        prop_assert!(got.contains(&(from, 1.0)));
        prop_assert!(got.contains(&(to, 1.0)));
    }

    #[testkit::test]
    fn total_intensity_grows_with_length([from, to] in pixel_line(30)) {
        prop_assume!(from != to);
        let longer = Pixel::new(to.x + (to.x - from.x), to.y + (to.y - from.y));
        let sum = |v: Vec<(Pixel, f32)>| v.iter().map(|&(_, w)| w).sum::<f32>();
        prop_assert!(sum(wu(from, longer)) > sum(wu(from, to)));
    }
}

/// The fan of the seed's antialiasing comparison, by Wu's line.
#[testkit::test]
fn the_fan_of_lines_matches_the_reference_image() {
    let canvas = common::fan_picture(|from, to, plot| {
        for (p, w) in wu(from, to) {
            plot(p, w);
        }
    });
    common::assert_fan("wu_fan", &canvas);
}
