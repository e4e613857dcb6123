//! Task 5c: Wu's antialiased line.

mod common;

use std::collections::BTreeMap;

use canvas::{Canvas, MAX_COORD, Pixel, Rgba};
use common::collect_weighted;
use lines::wu::wu_line;
use proptest::prelude::*;
use testkit::strategies::pixel_line;

fn wu(from: Pixel, to: Pixel) -> Vec<(Pixel, f32)> {
    collect_weighted(|plot| wu_line(from, to, plot))
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
}

#[testkit::test]
fn axis_parallel_and_diagonal_lines_are_solid() {
    for to in [Pixel::new(6, 0), Pixel::new(0, -6), Pixel::new(-6, 6)] {
        let got = wu(Pixel::new(0, 0), to);
        assert_eq!(got.len(), 7, "{to}: {got:?}");
        assert!(got.iter().all(|&(_, w)| w == 1.0), "{to}: {got:?}");
    }
}

#[testkit::test]
fn a_shallow_line() {
    let mut canvas = Canvas::new(24, 10);
    wu_line(Pixel::new(1, 1), Pixel::new(22, 8), |p, w| {
        canvas.blend(p, Rgba::WHITE, w)
    });
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
    let canvas = common::fan_picture(|from, to, plot| wu_line(from, to, plot));
    common::assert_fan("wu_fan", &canvas);
}
