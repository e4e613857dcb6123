//! Task 3: outline parity fill, the same pixels as the even-odd rule.

mod common;

use canvas::{Pixel, Vec2, Viewport};
use common::{
    POLYGON_VIEWPORT, any_polygon, collect, crossing, even_odd_pixels, first_duplicate,
    grid_pixels, hostile_polygon, star_polygon,
};
use fill::parity::parity_fill;
use proptest::prelude::*;
use testkit::assert_pixels_eq;

/// The pixels of `parity_fill`, after checking the marks it reported (see
/// [`expected_toggles`]): every test grades the marking, not only the
/// pixels.
#[track_caller]
fn polygon(vertices: &[Vec2], viewport: Viewport) -> Vec<Pixel> {
    let mut toggles = Vec::new();
    let mut toggled_after_plot = None;
    let pixels = collect(|plot| {
        let plotted = std::cell::Cell::new(false);
        parity_fill(
            vertices,
            viewport,
            |p| {
                plotted.set(true);
                plot(p);
            },
            |m| {
                if plotted.get() {
                    toggled_after_plot.get_or_insert(m);
                }
                toggles.push(m);
            },
        );
    });
    let call = format!("parity_fill({vertices:?}, {viewport:?})");
    assert_eq!(
        toggled_after_plot, None,
        "{call}: a mark toggled after the first pixel was plotted (mark every crossing first, then fill)"
    );
    let mut expected = expected_toggles(vertices, viewport);
    toggles.sort();
    expected.sort();
    assert!(
        toggles == expected,
        "{call}: the marks toggled (sorted) are {toggles:?}, by the sheet's rule they are {expected:?}"
    );
    pixels
}

/// The marks the sheet's rule toggles: for every edge and every row it
/// crosses (`min y ≤ y < max y`) within the box, the pixel `⌈s⌉` (a
/// crossing left of the box toggles its first column, one right of it
/// nothing). The box: columns `⌈min x⌉ ..= ⌈max x⌉ − 1` and rows
/// `⌈min y⌉ ..= ⌈max y⌉ − 1` of the vertices, clipped to the viewport.
/// Nothing for a polygon that fills nothing or a box larger than any
/// canvas.
fn expected_toggles(vertices: &[Vec2], viewport: Viewport) -> Vec<Pixel> {
    if vertices.len() < 3 || viewport.is_empty() || !vertices.iter().all(|v| v.is_finite()) {
        return Vec::new();
    }
    let lo = vertices.iter().copied().fold(Vec2::INFINITY, Vec2::min);
    let hi = vertices.iter().copied().fold(Vec2::NEG_INFINITY, Vec2::max);
    let first = |v: f32, bound: i32| f64::from(v).ceil().max(f64::from(bound));
    let last = |v: f32, bound: i32| (f64::from(v).ceil() - 1.0).min(f64::from(bound));
    let (x0, x1) = (first(lo.x, viewport.x_min), last(hi.x, viewport.x_max));
    let (y0, y1) = (first(lo.y, viewport.y_min), last(hi.y, viewport.y_max));
    if x0 > x1 || y0 > y1 || (x1 - x0 + 1.0) * (y1 - y0 + 1.0) > canvas::Canvas::MAX_PIXELS as f64 {
        return Vec::new();
    }
    let mut toggles = Vec::new();
    let n = vertices.len();
    for i in 0..n {
        let (a, b) = (vertices[i], vertices[(i + 1) % n]);
        let (from, to) = (
            first(a.y.min(b.y), y0 as i32),
            last(a.y.max(b.y), y1 as i32),
        );
        if from > to {
            continue;
        }
        for y in from as i32..=to as i32 {
            let column = crossing(a, b, y).ceil().max(x0);
            if column <= x1 {
                toggles.push(Pixel::new(column as i32, y));
            }
        }
    }
    toggles
}

fn v(points: &[(f32, f32)]) -> Vec<Vec2> {
    points.iter().map(|&(x, y)| Vec2::new(x, y)).collect()
}

#[testkit::test]
fn slides_rectangle_as_a_polygon() {
    let square = v(&[(0.5, 0.5), (4.5, 0.5), (4.5, 3.5), (0.5, 3.5)]);
    let expected = grid_pixels(Pixel::new(0, 0), &[".####", ".####", ".####", "....."]);
    assert_pixels_eq(
        &expected,
        &polygon(&square, POLYGON_VIEWPORT),
        "the slides' rectangle",
    );
}

#[testkit::test]
fn two_crossings_in_one_pixel_cancel() {
    // A sliver between x = 0.2 and 0.8: both crossings of every row mark
    // pixel 1, and no centre lies inside. Setting marks (instead of
    // toggling them) would fill everything right of x = 1.
    //
    //   5      ·
    //   1    /   \      centres x = 0 and x = 1 are outside
    //   0   ·─────·
    let sliver = v(&[(0.2, 0.0), (0.8, 0.0), (0.5, 5.0)]);
    assert_eq!(polygon(&sliver, POLYGON_VIEWPORT), []);
    // A comb: the square [0.2, 3.6] × [0.5, 3.5] without the notch
    // [0.8, 3.0] × [0.5, 2.5]. Rows 1 and 2 cross at 0.2, 0.8 (both mark
    // pixel 1: they cancel), 3.0 and 3.6 (pixel 3 alone is inside).
    //
    //   3 .###
    //   2 ...#
    //   1 ...#
    let comb = v(&[
        (0.2, 0.5),
        (0.8, 0.5),
        (0.8, 2.5),
        (3.0, 2.5),
        (3.0, 0.5),
        (3.6, 0.5),
        (3.6, 3.5),
        (0.2, 3.5),
    ]);
    let expected = grid_pixels(Pixel::new(0, 1), &[".###", "...#", "...#"]);
    assert_pixels_eq(&expected, &polygon(&comb, POLYGON_VIEWPORT), "comb");
}

#[testkit::test]
fn empty_degenerate_and_hostile_polygons_fill_nothing() {
    for shape in [
        v(&[]),
        v(&[(1.0, 1.0)]),
        v(&[(1.0, 1.0), (5.0, 5.0)]),
        v(&[(1.0, 1.0), (5.0, 5.0), (9.0, 9.0)]),
        v(&[(f32::NAN, 1.0), (5.0, 5.0), (9.0, 1.0)]),
        v(&[(0.0, 0.0), (f32::NEG_INFINITY, 0.0), (0.0, 5.0)]),
    ] {
        assert_eq!(polygon(&shape, POLYGON_VIEWPORT), [], "{shape:?}");
    }
    let huge = v(&[(-1e30, -1e30), (1e30, -1e30), (1e30, 1e30), (-1e30, 1e30)]);
    assert_eq!(
        polygon(&huge, Viewport::new(-2, -2, 2, 2)).len(),
        25,
        "a huge square, clipped"
    );
}

#[testkit::test]
fn a_buffer_larger_than_any_canvas_is_refused() {
    // The whole i32 plane: 2⁶⁴ marks. Nothing is filled, at once.
    let huge = v(&[(-1e30, -1e30), (1e30, -1e30), (1e30, 1e30), (-1e30, 1e30)]);
    let everything = Viewport::new(i32::MIN, i32::MIN, i32::MAX, i32::MAX);
    assert_eq!(polygon(&huge, everything), []);
    // A small polygon in the same viewport needs a small buffer: it fills.
    let small = v(&[(-3.0, -3.0), (3.0, -3.0), (3.0, 3.0), (-3.0, 3.0)]);
    assert_eq!(polygon(&small, everything).len(), 36);
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn simple_polygons_match_the_even_odd_rule(shape in star_polygon()) {
        let yours = polygon(&shape, POLYGON_VIEWPORT);
        assert_pixels_eq(&even_odd_pixels(&shape, POLYGON_VIEWPORT), &yours, &format!("{shape:?}"));
        prop_assert_eq!(first_duplicate(&yours), None);
    }

    #[testkit::test]
    fn any_polygon_matches_the_even_odd_rule(shape in any_polygon()) {
        let yours = polygon(&shape, POLYGON_VIEWPORT);
        assert_pixels_eq(&even_odd_pixels(&shape, POLYGON_VIEWPORT), &yours, &format!("{shape:?}"));
        prop_assert_eq!(first_duplicate(&yours), None);
    }

    #[testkit::test]
    fn clipping_keeps_exactly_the_pixels_in_the_viewport(
        shape in any_polygon(), x in -20..10, y in -20..10, w in 0..15, h in 0..15,
    ) {
        let viewport = Viewport::new(x, y, x + w, y + h);
        assert_pixels_eq(&even_odd_pixels(&shape, viewport), &polygon(&shape, viewport), &format!("{shape:?} in {viewport:?}"));
    }

    #[testkit::test]
    fn hostile_polygons_never_panic(shape in hostile_polygon()) {
        let small = Viewport::new(-5, -5, 5, 5);
        let yours = polygon(&shape, small);
        prop_assert!(yours.iter().all(|&p| small.contains(p)));
        prop_assert_eq!(first_duplicate(&yours), None);
        // Refusing one is no reason to refuse the next.
        prop_assert_eq!(polygon(&v(&[(-3.0, -3.0), (3.0, -3.0), (3.0, 3.0), (-3.0, 3.0)]), small).len(), 36);
    }
}
