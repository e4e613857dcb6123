//! Task 5b: antialiasing after Gupta and Sproull.

mod common;

use canvas::{Canvas, MAX_COORD, Pixel, Rgba};
use common::{collect_weighted, nearest_pixels};
use lines::gupta_sproull::{TABLE_LEN, distance_table, filter, gupta_sproull_line};
use proptest::prelude::*;
use testkit::strategies::pixel_line;

fn gs(from: Pixel, to: Pixel) -> Vec<(Pixel, f32)> {
    collect_weighted(|plot| gupta_sproull_line(from, to, plot))
}

#[testkit::test]
fn the_table_falls_from_one_to_nothing() {
    let table = distance_table();
    assert_eq!(table.len(), TABLE_LEN);
    assert!((table[0] - 1.0).abs() < 1e-6);
    assert!(table.windows(2).all(|w| w[1] < w[0]), "{table:?}");
    assert!(table[TABLE_LEN - 1] < 0.01);
    assert_eq!(filter(1.6), 0.0);
}

/// The cone filter's volume over the strip, by brute force: a grid of
/// small cells over the disk of radius 1, each weighted by the cone's
/// height `1 − r` and counted when its centre lies in the strip
/// `|u − D| ≤ ½`.
fn cone_volume_over_strip(d: f64) -> f64 {
    const N: usize = 800;
    let h = 2.0 / N as f64;
    let mut volume = 0.0;
    for i in 0..N {
        let u = -1.0 + (i as f64 + 0.5) * h;
        if (u - d).abs() > 0.5 {
            continue;
        }
        for j in 0..N {
            let v = -1.0 + (j as f64 + 0.5) * h;
            let r = u.hypot(v);
            if r < 1.0 {
                volume += (1.0 - r) * h * h;
            }
        }
    }
    volume
}

#[testkit::test]
fn the_table_is_the_cone_volume_over_the_strip() {
    let table = distance_table();
    let full = cone_volume_over_strip(0.0);
    for (k, &value) in table.iter().enumerate() {
        let d = k as f64 / 16.0;
        let expected = cone_volume_over_strip(d) / full;
        assert!(
            (f64::from(value) - expected).abs() < 2e-3,
            "D = {d}: table {value}, brute force {expected:.4}"
        );
    }
}

#[testkit::test]
fn horizontal_line_has_full_middle_and_equal_neighbours() {
    let got = gs(Pixel::new(0, 0), Pixel::new(5, 0));
    assert_eq!(
        got.len(),
        18,
        "three pixels for each of six columns: {got:?}"
    );
    for (p, w) in got {
        let expected = if p.y == 0 { 1.0 } else { filter(1.0) };
        assert!(
            (-1..=1).contains(&p.y) && (0..=5).contains(&p.x),
            "unexpected pixel {p}"
        );
        assert!(
            (w - expected).abs() < 1e-6,
            "pixel {p}: intensity {w}, expected {expected}"
        );
    }
}

#[testkit::test]
fn diagonal_line_neighbours_are_cos_45_away() {
    // Pixel centres beside a 45° line lie 1/√2 ≈ 0.707 from it.
    let got = gs(Pixel::new(0, 0), Pixel::new(4, 4));
    for i in 0..=4 {
        assert!(
            got.iter().any(|&(p, _)| p == Pixel::new(i, i)),
            "({i}, {i}) on the line is not drawn: {got:?}"
        );
    }
    for (p, w) in got {
        let expected = if p.x == p.y {
            1.0
        } else {
            filter(std::f64::consts::FRAC_1_SQRT_2)
        };
        assert!(
            (w - expected).abs() < 1e-6,
            "pixel {p}: intensity {w}, expected {expected}"
        );
    }
}

#[testkit::test]
fn a_shallow_line() {
    let mut canvas = Canvas::new(24, 10);
    gupta_sproull_line(Pixel::new(1, 1), Pixel::new(22, 8), |p, w| {
        canvas.blend(p, Rgba::WHITE, w)
    });
    testkit::assert_raster_snapshot!("a_shallow_line", canvas);
}

#[testkit::test]
fn endpoints_beyond_max_coord_draw_nothing() {
    assert!(gs(Pixel::new(-MAX_COORD - 1, 0), Pixel::new(0, 0)).is_empty());
    // At the limit itself, a line is drawn.
    assert!(!gs(Pixel::new(-MAX_COORD, 0), Pixel::new(3 - MAX_COORD, 1)).is_empty());
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn middle_pixels_are_the_midpoint_line([from, to] in pixel_line(40)) {
        let got = gs(from, to);
        prop_assert_eq!(got.len() % 3, 0, "three pixels per column");
        let middles: Vec<Pixel> = got.iter().step_by(3).map(|&(p, _)| p).collect();
        prop_assert_eq!(middles, nearest_pixels(from, to, None), "every third pixel (the first of each column) is the midpoint line's");
    }

    #[testkit::test]
    fn intensities_are_table_values_and_never_above_full([from, to] in pixel_line(40)) {
        let table = distance_table();
        for (p, w) in gs(from, to) {
            prop_assert!(w == 0.0 || table.contains(&w), "pixel {p}: {w} is not a table value");
            prop_assert!((0.0..=1.0).contains(&w));
        }
    }

    #[testkit::test]
    fn intensity_matches_the_distance_to_the_line([from, to] in pixel_line(40)) {
        prop_assume!(from != to);
        let (a, b) = (from.centre().as_dvec2(), to.centre().as_dvec2());
        let n = (b - a).perp().normalize();
        let got = gs(from, to);
        prop_assert!(got.iter().any(|&(p, _)| p == from) && got.iter().any(|&(p, _)| p == to), "{from} -> {to} must draw both endpoints: {got:?}");
        for (p, w) in got {
            let d = (p.centre().as_dvec2() - a).dot(n).abs();
            // The table is sampled every 1/16 pixel: allow the value at a
            // neighbouring sample.
            let (lo, hi) = (filter(d + 1.0 / 32.0 + 1e-9), filter((d - 1.0 / 32.0 - 1e-9).max(0.0)));
            prop_assert!(w >= lo - 1e-6 && w <= hi + 1e-6, "pixel {p} at distance {d:.4}: {w} outside [{lo}, {hi}]");
        }
    }

    #[testkit::test]
    fn reversed_line_gives_the_same_intensities([from, to] in pixel_line(40)) {
        let mut forward = gs(from, to);
        let mut backward = gs(to, from);
        prop_assert!(forward.iter().any(|&(p, _)| p == from), "{from} -> {to} does not draw {from}: {forward:?}");
        forward.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.total_cmp(&b.1)));
        backward.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.total_cmp(&b.1)));
        prop_assert_eq!(forward, backward);
    }

    #[testkit::test]
    fn total_intensity_grows_with_length([from, to] in pixel_line(30)) {
        prop_assume!(from != to);
        let longer = Pixel::new(to.x + (to.x - from.x), to.y + (to.y - from.y));
        let sum = |v: Vec<(Pixel, f32)>| v.iter().map(|&(_, w)| w).sum::<f32>();
        prop_assert!(sum(gs(from, longer)) > sum(gs(from, to)));
    }
}

/// The fan of the seed's antialiasing comparison, by Gupta and Sproull.
#[testkit::test]
fn the_fan_of_lines_matches_the_reference_image() {
    let canvas = common::fan_picture(|from, to, plot| gupta_sproull_line(from, to, plot));
    common::assert_fan("gupta_sproull_fan", &canvas);
}
