//! Task 5a: antialiasing by unweighted area sampling.

mod common;

use canvas::{Canvas, Pixel, Rgba, Vec2};
use common::collect_weighted;
use lines::area_sampling::area_sampling_line;
use proptest::prelude::*;
use testkit::strategies::{hostile_point, point};

fn area(from: Vec2, to: Vec2) -> Vec<(Pixel, f32)> {
    collect_weighted(|plot| area_sampling_line(from, to, plot))
}

#[testkit::test]
fn horizontal_line_through_pixel_centres_covers_half_the_end_pixels() {
    // The rectangle [0, 4] × [−½, ½]: pixels 1..3 lie inside, pixels 0 and
    // 4 half inside.
    let mut got = area(Vec2::new(0.0, 0.0), Vec2::new(4.0, 0.0));
    got.sort_by_key(|&(p, _)| p);
    let expected = [(0, 0.5), (1, 1.0), (2, 1.0), (3, 1.0), (4, 0.5)];
    assert_eq!(got.len(), expected.len(), "{got:?}");
    for ((p, w), (x, e)) in got.iter().zip(expected) {
        assert_eq!(*p, Pixel::new(x, 0));
        assert!(
            (w - e).abs() < 1e-5,
            "pixel {p}: intensity {w}, expected {e}"
        );
    }
}

#[testkit::test]
fn horizontal_line_between_rows_splits_them_evenly() {
    // y = ½ lies on the border of rows 0 and 1: each gets half of every column.
    let got = area(Vec2::new(0.5, 0.5), Vec2::new(3.5, 0.5));
    let total: f32 = got.iter().map(|&(_, w)| w).sum();
    assert!((total - 3.0).abs() < 1e-5);
    for &(p, w) in &got {
        assert!(
            (1..=3).contains(&p.x) && (0..=1).contains(&p.y),
            "unexpected pixel {p}"
        );
        assert!((w - 0.5).abs() < 1e-5, "pixel {p}: intensity {w}");
    }
}

#[testkit::test]
fn zero_length_line_draws_nothing() {
    assert!(area(Vec2::new(2.0, 2.0), Vec2::new(2.0, 2.0)).is_empty());
    // Half a pixel of length already covers something.
    assert!(!area(Vec2::new(2.0, 2.0), Vec2::new(2.5, 2.0)).is_empty());
}

#[testkit::test]
fn a_shallow_line() {
    let mut canvas = Canvas::new(24, 10);
    area_sampling_line(Vec2::new(1.0, 1.0), Vec2::new(22.0, 8.0), |p, w| {
        canvas.blend(p, Rgba::WHITE, w)
    });
    testkit::assert_raster_snapshot!("a_shallow_line", canvas);
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn intensities_add_up_to_the_length(from in point(40.0), to in point(40.0)) {
        let got = area(from, to);
        let total: f64 = got.iter().map(|&(_, w)| f64::from(w)).sum();
        let length = f64::from(from.distance(to));
        prop_assert!((total - length).abs() <= 1e-3 * length.max(1.0), "total intensity {total} for length {length}");
    }

    #[testkit::test]
    fn intensity_is_in_zero_to_one_and_no_pixel_repeats(from in point(40.0), to in point(40.0)) {
        let got = area(from, to);
        if from.distance(to) >= 0.5 {
            prop_assert!(!got.is_empty(), "{from} -> {to} covers no pixel");
        }
        let mut seen = std::collections::HashSet::new();
        for (p, w) in got {
            prop_assert!(w > 0.0 && w <= 1.0, "pixel {p}: intensity {w}");
            prop_assert!(seen.insert(p), "pixel {p} plotted twice");
        }
    }

    #[testkit::test]
    fn reversed_line_gives_the_same_intensities(from in point(40.0), to in point(40.0)) {
        let mut forward = area(from, to);
        let mut backward = area(to, from);
        if from.distance(to) >= 0.5 {
            prop_assert!(!forward.is_empty(), "{from} -> {to} covers no pixel");
        }
        forward.sort_by_key(|&(p, _)| p);
        backward.sort_by_key(|&(p, _)| p);
        prop_assert_eq!(forward.len(), backward.len());
        for ((p, a), (q, b)) in forward.into_iter().zip(backward) {
            prop_assert_eq!(p, q);
            prop_assert!((a - b).abs() < 1e-4, "pixel {p}: {a} forwards, {b} backwards");
        }
    }

    #[testkit::test]
    fn hostile_endpoints_draw_nothing(a in hostile_point(), b in point(100.0)) {
        let finite_and_small = a.x.abs() <= canvas::MAX_COORD as f32 && a.y.abs() <= canvas::MAX_COORD as f32;
        if !finite_and_small {
            prop_assert!(area(a, b).is_empty());
            prop_assert!(area(b, a).is_empty());
        }
        // Refusing a line is no reason to refuse the next one.
        prop_assert!(!area(b, b + Vec2::new(3.0, 1.0)).is_empty(), "{b} -> {b} + (3, 1) drew nothing");
    }
}

/// The fan of the seed's antialiasing comparison, by unweighted area
/// sampling (the ends at the pixel centres).
#[testkit::test]
fn the_fan_of_lines_matches_the_reference_image() {
    let canvas = common::fan_picture(|from, to, plot| {
        area_sampling_line(from.centre(), to.centre(), plot);
    });
    common::assert_fan("area_sampling_fan", &canvas);
}
