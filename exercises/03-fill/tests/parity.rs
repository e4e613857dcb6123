//! Task 3: outline parity fill, the same pixels as the even-odd rule.

mod common;

use canvas::{Pixel, Vec2, Viewport};
use common::{
    POLYGON_VIEWPORT, any_polygon, collect, even_odd_pixels, first_duplicate, grid_pixels,
    hostile_polygon, star_polygon,
};
use fill::parity::parity_fill;
use proptest::prelude::*;
use testkit::assert_pixels_eq;

fn polygon(vertices: &[Vec2], viewport: Viewport) -> Vec<Pixel> {
    collect(|plot| parity_fill(vertices, viewport, plot))
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
