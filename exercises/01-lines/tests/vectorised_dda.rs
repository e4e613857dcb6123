//! Task 6 (bonus): the DDA in lanes of eight columns, each from the closed
//! form (seed 004's vectorised bonus).

mod common;

use canvas::{Fragment, MAX_COORD, Pixel, Rgba, Vec2, Vertex, round_half_away};
use common::{has_tie, nearest_pixels};
use lines::vectorised_dda::{Batch, LANES, vectorised_dda_line};
use proptest::prelude::*;
use testkit::strategies::{hostile_point, pixel_line, vertex};

/// What the line reports: its batches and its fragments.
fn run(from: &Vertex, to: &Vertex) -> (Vec<Batch>, Vec<Fragment>) {
    let (mut batches, mut fragments) = (Vec::new(), Vec::new());
    vectorised_dda_line(from, to, |b| batches.push(*b), |f| fragments.push(f));
    (batches, fragments)
}

fn white(x: f32, y: f32) -> Vertex {
    Vertex::new(Vec2::new(x, y), 0.5, Rgba::WHITE)
}

/// The line's frame: whether x is the major axis, and `from`'s major and
/// minor coordinates and the two differences, as the sheet defines them.
fn frame(from: &Vertex, to: &Vertex) -> (bool, f32, f32, f32, f32) {
    let (a, d) = (from.position, to.position - from.position);
    if d.x.abs() >= d.y.abs() {
        (true, a.x, a.y, d.x, d.y)
    } else {
        (false, a.y, a.x, d.y, d.x)
    }
}

/// The closed form of the sheet, `from.minor + slope · (X − from.major)`,
/// in `f64` and in this order: what every lane must hold, bit for bit.
fn closed_form(from: &Vertex, to: &Vertex, major: i32) -> f64 {
    let (_, a_major, a_minor, d_major, d_minor) = frame(from, to);
    let slope = if d_major == 0.0 {
        0.0
    } else {
        f64::from(d_minor) / f64::from(d_major)
    };
    f64::from(a_minor) + slope * (f64::from(major) - f64::from(a_major))
}

/// Checks the batches of a line against the sheet: consecutive columns
/// from `round(from.major)` to `round(to.major)`, [`LANES`] to a batch
/// but the last, every lane the closed form bit for bit, and the fragments
/// the batches' pixels in their order.
fn check_batches(
    from: &Vertex,
    to: &Vertex,
    batches: &[Batch],
    fragments: &[Fragment],
) -> Result<(), String> {
    let (x_major, a_major, _, d_major, _) = frame(from, to);
    let first = round_half_away(a_major);
    let last = round_half_away(a_major + d_major);
    let step = if last >= first { 1 } else { -1 };
    let columns = (i64::from(last) - i64::from(first)).unsigned_abs() as usize + 1;
    let lens: Vec<usize> = batches.iter().map(|b| b.len).collect();
    let expected_lens: Vec<usize> = (0..columns.div_ceil(LANES))
        .map(|k| (columns - k * LANES).min(LANES))
        .collect();
    if lens != expected_lens {
        return Err(format!(
            "{columns} columns come in batches of {expected_lens:?}, not {lens:?}"
        ));
    }
    let lanes = batches
        .iter()
        .flat_map(|b| (0..b.len).map(move |k| (b.major[k], b.minor[k])));
    for (n, (major, minor)) in lanes.enumerate() {
        let column = first + step * n as i32;
        if major != column {
            return Err(format!(
                "lane {n} of the line holds column {major}, not {column}"
            ));
        }
        let expected = closed_form(from, to, major);
        if minor.to_bits() != expected.to_bits() {
            return Err(format!(
                "column {major}: the lane holds minor = {minor:?}, the closed form \
                 from.minor + slope · (X − from.major) gives {expected:?}, with \
                 slope = f64(Δminor) / f64(Δmajor) and Δ = to − from taken in f32 \
                 (a running sum, or differences taken in f64, differ in the last bits)"
            ));
        }
        let rounded = expected.round() as i32;
        let pixel = if x_major {
            Pixel::new(major, rounded)
        } else {
            Pixel::new(rounded, major)
        };
        match fragments.get(n) {
            Some(f) if f.pixel == pixel => {}
            Some(f) => {
                return Err(format!(
                    "fragment {n} is {:?}, its lane says {pixel:?}",
                    f.pixel
                ));
            }
            None => return Err(format!("no fragment for lane {n} ({pixel:?})")),
        }
    }
    if fragments.len() != columns {
        return Err(format!(
            "{} fragments for {columns} columns",
            fragments.len()
        ));
    }
    Ok(())
}

#[testkit::test]
fn twenty_one_columns_come_in_batches_of_eight_eight_and_five() {
    // ```text
    //   y 8 ·  ·  ·  ·  ·  ·  ·  ·  ·  ·  ·  ·  ·  ·  ·  ·  ·  ·  ·  ■  ■
    //     …          (0, 0) → (20, 8): 21 columns, 8 + 8 + 5, no ties
    //   y 0 ■  ■  ·  ·  ·  ·  ·  ·  ·  ·  ·  ·  ·  ·  ·  ·  ·  ·  ·  ·  ·
    //       └──── batch 1 ─────┘ └──── batch 2 ─────┘ └── batch 3 ──┘
    // ```
    let (from, to) = (white(0.0, 0.0), white(20.0, 8.0));
    assert!(!has_tie(Pixel::new(0, 0), Pixel::new(20, 8)));
    let (batches, fragments) = run(&from, &to);
    assert_eq!(
        batches.iter().map(|b| b.len).collect::<Vec<_>>(),
        [8, 8, 5],
        "21 columns: two full batches of {LANES} and one of 5"
    );
    assert_eq!(&batches[1].major, &[8, 9, 10, 11, 12, 13, 14, 15]);
    assert_eq!(&batches[2].major[..5], &[16, 17, 18, 19, 20]);
    check_batches(&from, &to, &batches, &fragments).unwrap();
    let pixels: Vec<Pixel> = fragments.iter().map(|f| f.pixel).collect();
    assert_eq!(
        pixels,
        nearest_pixels(Pixel::new(0, 0), Pixel::new(20, 8), None),
        "the pixels nearest the line, as task 1's"
    );
}

#[testkit::test]
fn every_lane_is_the_closed_form_bit_for_bit() {
    // Long lines with fractional endpoints, shallow and steep, forwards and
    // backwards: after a few columns a running sum `minor += slope` no
    // longer has the closed form's bits.
    for (from, to) in [
        (white(0.3, 0.1), white(1000.7, 333.35)),
        (white(-17.25, 900.6), white(3.1, -411.45)),
        (white(500.5, -2.2), white(-777.7, 100.9)),
    ] {
        let (batches, fragments) = run(&from, &to);
        check_batches(&from, &to, &batches, &fragments)
            .unwrap_or_else(|e| panic!("{from:?} → {to:?}: {e}"));
    }
}

#[testkit::test]
fn colour_and_depth_are_task_ones() {
    // Black at depth 0 to white at depth 1 over 801 columns: a hundred full
    // batches and one of a single lane, t = k/800.
    let from = Vertex::new(Vec2::new(0.0, 0.0), 0.0, Rgba::BLACK);
    let to = Vertex::new(Vec2::new(800.0, 301.0), 1.0, Rgba::WHITE);
    let (batches, fragments) = run(&from, &to);
    check_batches(&from, &to, &batches, &fragments).unwrap();
    assert_eq!((batches.len(), batches[100].len), (101, 1));
    for (k, f) in fragments.iter().enumerate() {
        let t = k as f32 / 800.0;
        assert!(
            (f.depth - t).abs() < 1e-6,
            "depth at column {k}: {}",
            f.depth
        );
        assert!(
            f.colour.approx_eq(Rgba::grey(t), 1e-6),
            "colour at column {k}: {:?}",
            f.colour
        );
    }
    assert_eq!(fragments[0].colour, Rgba::BLACK);
    assert_eq!(fragments[800].colour, Rgba::WHITE);
}

#[testkit::test]
fn a_zero_length_line_is_one_lane() {
    let from = Vertex::new(Vec2::new(2.5, -1.5), 0.25, Rgba::RED);
    let to = Vertex::new(Vec2::new(2.5, -1.5), 0.75, Rgba::BLUE);
    let (batches, fragments) = run(&from, &to);
    assert_eq!(batches.len(), 1);
    assert_eq!((batches[0].len, batches[0].major[0]), (1, 3));
    assert_eq!(batches[0].minor[0], -1.5);
    assert_eq!(
        fragments,
        [Fragment {
            pixel: Pixel::new(3, -2),
            depth: 0.25,
            colour: Rgba::RED
        }]
    );
    // From the same start, a long line: lane by lane.
    let far = Vertex::new(Vec2::new(-90.2, 37.7), 0.75, Rgba::BLUE);
    let (batches, fragments) = run(&from, &far);
    check_batches(&from, &far, &batches, &fragments).unwrap();
}

#[testkit::test]
fn bad_endpoints_draw_nothing_and_report_nothing() {
    let beyond = MAX_COORD as f32 * 2.0;
    for (x, y) in [(f32::NAN, 0.0), (0.0, f32::INFINITY), (beyond, 1.0)] {
        let (batches, fragments) = run(&white(x, y), &white(3.0, 4.0));
        assert!(batches.is_empty() && fragments.is_empty(), "({x}, {y})");
    }
    // An ordinary line after them is drawn, lane by lane.
    let (from, to) = (white(1.1, 1.3), white(-60.7, 23.9));
    let (batches, fragments) = run(&from, &to);
    check_batches(&from, &to, &batches, &fragments).unwrap();
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn lanes_batches_and_pixels_follow_the_sheet(from in vertex(60.0), to in vertex(60.0)) {
        let (batches, fragments) = run(&from, &to);
        check_batches(&from, &to, &batches, &fragments).map_err(TestCaseError::fail)?;
        let (_, a_major, _, d_major, _) = frame(&from, &to);
        for (f, major) in fragments.iter().zip(batches.iter().flat_map(|b| b.major[..b.len].to_vec())) {
            let t = if d_major == 0.0 { 0.0 } else { ((major as f32 - a_major) / d_major).clamp(0.0, 1.0) };
            prop_assert!((f.depth - (from.depth * (1.0 - t) + to.depth * t)).abs() < 1e-6, "depth {} at column {}", f.depth, major);
            prop_assert!(f.colour.approx_eq(from.colour.lerp(to.colour, t), 1e-6), "colour {:?} at column {}", f.colour, major);
        }
    }

    #[testkit::test]
    fn integer_lines_are_the_nearest_pixels_both_ways([a, b] in pixel_line(40)) {
        prop_assume!(!has_tie(a, b));
        let pixels = |from: Pixel, to: Pixel| {
            let (from, to) = (white(from.x as f32, from.y as f32), white(to.x as f32, to.y as f32));
            let (batches, fragments) = run(&from, &to);
            check_batches(&from, &to, &batches, &fragments)?;
            Ok::<_, String>(fragments.iter().map(|f| f.pixel).collect::<Vec<_>>())
        };
        let forward = pixels(a, b).map_err(TestCaseError::fail)?;
        prop_assert_eq!(&forward, &nearest_pixels(a, b, None));
        let mut backward = pixels(b, a).map_err(TestCaseError::fail)?;
        backward.reverse();
        prop_assert_eq!(forward, backward, "a line drawn backwards covers the same pixels");
    }

    #[testkit::test]
    fn hostile_endpoints_draw_nothing(a in hostile_point(), b in testkit::strategies::point(100.0)) {
        // Non-finite or beyond MAX_COORD: no batch, no fragment.
        let finite_and_small = a.x.abs() <= MAX_COORD as f32 && a.y.abs() <= MAX_COORD as f32;
        for (from, to) in [(white(a.x, a.y), white(b.x, b.y)), (white(b.x, b.y), white(a.x, a.y))] {
            let (mut lanes, mut count) = (0_usize, 0_usize);
            vectorised_dda_line(&from, &to, |batch| lanes += batch.len, |_| count += 1);
            prop_assert_eq!(lanes, count, "one fragment per lane");
            if !finite_and_small {
                prop_assert_eq!(count, 0);
            }
        }
        // Refusing a line is no reason to refuse the next one.
        let (from, to) = (white(b.x, b.y), white(0.0, 0.0));
        let (batches, fragments) = run(&from, &to);
        check_batches(&from, &to, &batches, &fragments).map_err(TestCaseError::fail)?;
    }
}
