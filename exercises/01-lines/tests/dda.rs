//! Task 1: the DDA line with colour and depth interpolation.

mod common;

use canvas::{Canvas, Fragment, Pixel, Rgba, Vec2, Vertex, round_half_away};
use common::{INK, has_tie, nearest_pixels, octant_sheet, one_step_per_column};
use lines::dda::dda_line;
use proptest::prelude::*;
use testkit::image::{Tolerance, assert_image_matches};
use testkit::strategies::{hostile_point, pixel_line, vertex};

fn dda(from: &Vertex, to: &Vertex) -> Vec<Fragment> {
    let mut fragments = Vec::new();
    dda_line(from, to, |f| fragments.push(f));
    fragments
}

fn white(x: f32, y: f32) -> Vertex {
    Vertex::new(Vec2::new(x, y), 0.5, INK)
}

fn pixels(fragments: &[Fragment]) -> Vec<Pixel> {
    fragments.iter().map(|f| f.pixel).collect()
}

#[testkit::test]
fn colour_and_depth_are_interpolated_linearly() {
    // Black at depth 0 to white at depth 1 over four columns:
    // t = 0, 1/4, 1/2, 3/4, 1.
    let from = Vertex::new(Vec2::new(0.0, 0.0), 0.0, Rgba::BLACK);
    let to = Vertex::new(Vec2::new(4.0, 1.0), 1.0, Rgba::WHITE);
    let fragments = dda(&from, &to);
    assert_eq!(
        pixels(&fragments),
        [(0, 0), (1, 0), (2, 1), (3, 1), (4, 1)].map(|(x, y)| Pixel::new(x, y))
    );
    for (k, f) in fragments.iter().enumerate() {
        let t = k as f32 / 4.0;
        assert!(
            (f.depth - t).abs() < 1e-6,
            "depth at column {k}: {} instead of {t}",
            f.depth
        );
        assert!(
            f.colour.approx_eq(Rgba::grey(t), 1e-6),
            "colour at column {k}: {:?}",
            f.colour
        );
    }
}

#[testkit::test]
fn rounding_is_half_away_from_zero() {
    // (0,0) -> (4,2): at x = 1 and x = 3 the line is at y = 0.5 and 1.5,
    // rounded up; going the other way at negative coordinates, down.
    let up = pixels(&dda(&white(0.0, 0.0), &white(4.0, 2.0)));
    assert_eq!(
        up,
        [(0, 0), (1, 1), (2, 1), (3, 2), (4, 2)].map(|(x, y)| Pixel::new(x, y))
    );
    let down = pixels(&dda(&white(0.0, 0.0), &white(-4.0, -2.0)));
    assert_eq!(
        down,
        [(0, 0), (-1, -1), (-2, -1), (-3, -2), (-4, -2)].map(|(x, y)| Pixel::new(x, y))
    );
}

#[testkit::test]
fn t_is_clamped_when_the_first_column_lies_before_the_endpoint() {
    // The endpoint x = 0.4 rounds to column 0, 0.4 before the line starts.
    let from = Vertex::new(Vec2::new(0.4, 0.0), 0.2, Rgba::BLACK);
    let to = Vertex::new(Vec2::new(3.6, 0.0), 0.8, Rgba::WHITE);
    let fragments = dda(&from, &to);
    assert_eq!(
        pixels(&fragments),
        [0, 1, 2, 3, 4].map(|x| Pixel::new(x, 0))
    );
    assert_eq!(fragments[0].depth, 0.2);
    assert_eq!(fragments[0].colour, Rgba::BLACK);
    assert_eq!(fragments[4].depth, 0.8);
    assert_eq!(fragments[4].colour, Rgba::WHITE);
}

#[testkit::test]
fn the_first_column_starts_on_the_ideal_line() {
    // From x = 0.4 the first column is 0, 0.4 before the endpoint: its
    // minor coordinate is the ideal line's there, from.y + slope·(0 − 0.4)
    // = −0.2, not from.y. Slope ½, so column x holds round(½x − 0.2).
    let fragments = dda(&white(0.4, 0.0), &white(10.4, 5.0));
    let expected: Vec<Pixel> = (0..=10)
        .map(|x| Pixel::new(x, round_half_away(0.5 * x as f32 - 0.2)))
        .collect();
    assert_eq!(
        pixels(&fragments),
        expected,
        "dda_line((0.4, 0), (10.4, 5)): the minor coordinate starts on the ideal line at the \
         first column's centre, from.minor + slope·(first − from.major) = −0.2 at column 0, \
         and grows by the slope ½ per column (starting at from.minor = 0 instead puts column \
         1 at round(0.5) = 1)"
    );
}

#[testkit::test]
fn zero_length_line_is_one_fragment_with_the_first_colour() {
    let from = Vertex::new(Vec2::new(2.5, -1.5), 0.25, Rgba::RED);
    let to = Vertex::new(Vec2::new(2.5, -1.5), 0.75, Rgba::BLUE);
    let fragments = dda(&from, &to);
    assert_eq!(
        fragments,
        [Fragment {
            pixel: Pixel::new(3, -2),
            depth: 0.25,
            colour: Rgba::RED
        }]
    );
}

#[testkit::test]
fn lines_in_all_octants() {
    let sheet = octant_sheet(|from, to, canvas| {
        dda_line(
            &white(from.x as f32, from.y as f32),
            &white(to.x as f32, to.y as f32),
            |f| canvas.plot(f),
        );
    });
    testkit::insta::assert_snapshot!("lines_in_all_octants", sheet);
}

/// The sheet's figure 4: a star of lines with interpolated colours.
fn star() -> Canvas {
    let mut canvas = Canvas::new(129, 129);
    let centre = Vertex::new(Vec2::new(64.0, 64.0), 0.0, Rgba::WHITE);
    for k in 0..24 {
        let angle = k as f32 * std::f32::consts::TAU / 24.0;
        let hue = k as f32 / 24.0;
        let colour = Rgba::rgb(
            (0.5 + 0.5 * (std::f32::consts::TAU * hue).cos()).clamp(0.0, 1.0),
            (0.5 + 0.5 * (std::f32::consts::TAU * (hue - 1.0 / 3.0)).cos()).clamp(0.0, 1.0),
            (0.5 + 0.5 * (std::f32::consts::TAU * (hue - 2.0 / 3.0)).cos()).clamp(0.0, 1.0),
        );
        // Radii alternate so that the tips also test non-integer endpoints.
        let radius = if k % 2 == 0 { 60.0 } else { 44.3 };
        let tip = Vertex::new(
            centre.position + radius * Vec2::new(angle.cos(), angle.sin()),
            1.0,
            colour,
        );
        dda_line(&tip, &centre, |f| canvas.plot(f));
    }
    canvas
}

#[testkit::test]
fn star_of_coloured_lines_matches_the_reference_image() {
    let reference = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/images/dda_star.png");
    assert_image_matches("dda_star", &star(), reference, Tolerance::EXACT);
}

#[testkit::test]
fn long_lines_stay_on_the_ideal_line() {
    // 4 000 001 columns, y = 0.3 x: adding the slope in f32 column by
    // column drifts about 29 500 pixels off the line by the end.
    let (from, to) = (white(0.0, 0.0), white(4_000_000.0, 1_200_000.0));
    let (mut count, mut worst) = (0_u64, (0.0_f64, Pixel::new(0, 0)));
    dda_line(&from, &to, |f| {
        count += 1;
        let off = (f64::from(f.pixel.y) - 0.3 * f64::from(f.pixel.x)).abs();
        if off > worst.0 {
            worst = (off, f.pixel);
        }
    });
    assert_eq!(count, 4_000_001, "one fragment per column");
    assert!(
        worst.0 <= 0.5 + 1e-6,
        "{} is {} pixels off the line y = 0.3 x (at most ½ after rounding)",
        worst.1,
        worst.0
    );
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn one_pixel_per_column_of_the_major_axis(from in vertex(50.0), to in vertex(50.0)) {
        let fragments = dda(&from, &to);
        let d = to.position - from.position;
        let x_major = d.x.abs() >= d.y.abs();
        let (a, b) = if x_major { (from.position.x, to.position.x) } else { (from.position.y, to.position.y) };
        let columns = (round_half_away(b) - round_half_away(a)).unsigned_abs() as usize + 1;
        prop_assert_eq!(fragments.len(), columns, "one fragment per column from round(from) to round(to)");
        one_step_per_column(&pixels(&fragments), x_major).map_err(TestCaseError::fail)?;
        let major = |p: Pixel| if x_major { p.x } else { p.y };
        prop_assert_eq!(major(fragments[0].pixel), round_half_away(a));
        prop_assert_eq!(major(fragments[columns - 1].pixel), round_half_away(b));
    }

    #[testkit::test]
    fn attributes_stay_between_the_endpoints(from in vertex(50.0), to in vertex(50.0)) {
        let fragments = dda(&from, &to);
        prop_assert!(!fragments.is_empty(), "no fragments for {from:?} -> {to:?}: a line has at least the first endpoint's pixel");
        for f in fragments {
            let between = |v: f32, a: f32, b: f32| v >= a.min(b) - 1e-6 && v <= a.max(b) + 1e-6;
            prop_assert!(between(f.depth, from.depth, to.depth), "depth {} outside [{}, {}]", f.depth, from.depth, to.depth);
            for (v, a, b) in [(f.colour.r, from.colour.r, to.colour.r), (f.colour.g, from.colour.g, to.colour.g), (f.colour.b, from.colour.b, to.colour.b)] {
                prop_assert!(between(v, a, b), "colour {:?} not between {:?} and {:?}", f.colour, from.colour, to.colour);
            }
        }
    }

    #[testkit::test]
    fn integer_endpoints_get_their_own_colours(
        [a, b] in pixel_line(40),
        (ca, cb) in (testkit::strategies::colour(), testkit::strategies::colour()),
    ) {
        let from = Vertex::new(a.centre(), 0.0, ca);
        let to = Vertex::new(b.centre(), 1.0, cb);
        let fragments = dda(&from, &to);
        let (first, last) = (fragments[0], fragments[fragments.len() - 1]);
        prop_assert_eq!((first.pixel, first.colour, first.depth), (a, ca, 0.0));
        if a != b {
            prop_assert_eq!((last.pixel, last.colour, last.depth), (b, cb, 1.0));
        }
    }

    #[testkit::test]
    fn agrees_with_the_midpoint_line_away_from_ties([a, b] in pixel_line(40)) {
        prop_assume!(!has_tie(a, b));
        let yours = pixels(&dda(&Vertex::new(a.centre(), 0.0, INK), &Vertex::new(b.centre(), 0.0, INK)));
        testkit::assert_pixels_eq(&nearest_pixels(a, b, None), &yours, &format!("dda_line({a}, {b})"));
    }

    #[testkit::test]
    fn reversed_line_covers_same_pixels_away_from_ties([a, b] in pixel_line(40)) {
        prop_assume!(!has_tie(a, b));
        let forward = pixels(&dda(&white(a.x as f32, a.y as f32), &white(b.x as f32, b.y as f32)));
        let backward = pixels(&dda(&white(b.x as f32, b.y as f32), &white(a.x as f32, a.y as f32)));
        prop_assert!(forward.contains(&a) && forward.contains(&b), "{a} -> {b} must draw both endpoints: {forward:?}");
        testkit::assert_pixels_eq(&forward, &backward, &format!("{a} <-> {b}"));
    }

    #[testkit::test]
    fn hostile_endpoints_draw_nothing_and_do_not_hang(a in hostile_point(), b in testkit::strategies::point(100.0)) {
        // Non-finite or beyond MAX_COORD: nothing is drawn.
        let finite_and_small = a.x.abs() <= canvas::MAX_COORD as f32 && a.y.abs() <= canvas::MAX_COORD as f32;
        let mut count = 0_u64;
        dda_line(&white(a.x, a.y), &white(b.x, b.y), |_| count += 1);
        if !finite_and_small {
            prop_assert_eq!(count, 0);
        }
        count = 0;
        dda_line(&white(b.x, b.y), &white(a.x, a.y), |_| count += 1);
        if !finite_and_small {
            prop_assert_eq!(count, 0);
        }
        // Refusing a line is no reason to refuse the next one.
        count = 0;
        dda_line(&white(b.x, b.y), &white(0.0, 0.0), |_| count += 1);
        prop_assert!(count > 0, "{b} -> (0, 0) drew nothing");
    }
}
