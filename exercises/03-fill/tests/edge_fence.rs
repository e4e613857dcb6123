//! Task 4: edge fill and fence fill, the same pixels as the even-odd rule,
//! and how many inversions each needs.

mod common;

use canvas::{Pixel, Vec2, Viewport};
use common::{
    POLYGON_VIEWPORT, any_polygon, collect, even_odd_pixels, first_duplicate, grid_pixels,
    hostile_polygon, star_polygon,
};
use fill::edge_fence::{edge_fill, fence_fill};
use proptest::prelude::*;
use testkit::assert_pixels_eq;

fn by_edges(vertices: &[Vec2], viewport: Viewport) -> (Vec<Pixel>, u64) {
    let mut n = 0;
    let pixels = collect(|plot| n = edge_fill(vertices, viewport, plot));
    (pixels, n)
}

fn by_fence(vertices: &[Vec2], fence: i32, viewport: Viewport) -> (Vec<Pixel>, u64) {
    let mut n = 0;
    let pixels = collect(|plot| n = fence_fill(vertices, fence, viewport, plot));
    (pixels, n)
}

fn v(points: &[(f32, f32)]) -> Vec<Vec2> {
    points.iter().map(|&(x, y)| Vec2::new(x, y)).collect()
}

#[testkit::test]
fn slides_rectangle_and_its_inversion_counts() {
    // (0.5, 0.5)–(4.5, 3.5) in a 20 × 10 viewport. Rows 1..=3 cross the
    // left edge at pixel 1 and the right edge at pixel 5.
    //   edge fill:           1..=19 and 5..=19: 19 + 15 = 34 per row, 102
    //   fence at 3:          [1, 3) and [3, 5):  2 + 2  =  4 per row, 12
    //   fence at 0 (left):   [0, 1) and [0, 5):  1 + 5  =  6 per row, 18
    let square = v(&[(0.5, 0.5), (4.5, 0.5), (4.5, 3.5), (0.5, 3.5)]);
    let viewport = Viewport::new(0, 0, 19, 9);
    let expected = grid_pixels(Pixel::new(0, 0), &[".####", ".####", ".####", "....."]);
    let (pixels, n) = by_edges(&square, viewport);
    assert_pixels_eq(&expected, &pixels, "edge fill");
    assert_eq!(n, 102, "edge fill inversions");
    for (fence, inversions) in [(3, 12), (0, 18)] {
        let (pixels, n) = by_fence(&square, fence, viewport);
        assert_pixels_eq(&expected, &pixels, &format!("fence fill, fence {fence}"));
        assert_eq!(n, inversions, "fence fill inversions, fence {fence}");
    }
}

#[testkit::test]
fn empty_degenerate_and_hostile_polygons_fill_nothing() {
    for shape in [
        v(&[]),
        v(&[(1.0, 1.0)]),
        v(&[(1.0, 1.0), (5.0, 5.0)]),
        v(&[(1.0, 1.0), (5.0, 5.0), (9.0, 9.0)]),
        v(&[(f32::NAN, 1.0), (5.0, 5.0), (9.0, 1.0)]),
        v(&[(0.0, 0.0), (f32::INFINITY, 0.0), (0.0, 5.0)]),
    ] {
        assert_eq!(
            by_edges(&shape, POLYGON_VIEWPORT).0,
            [],
            "edge fill {shape:?}"
        );
        assert_eq!(
            by_fence(&shape, 0, POLYGON_VIEWPORT).0,
            [],
            "fence fill {shape:?}"
        );
    }
    let huge = v(&[(-1e30, -1e30), (1e30, -1e30), (1e30, 1e30), (-1e30, 1e30)]);
    let small = Viewport::new(-2, -2, 2, 2);
    assert_eq!(
        by_edges(&huge, small).0.len(),
        25,
        "edge fill, a huge square clipped"
    );
    assert_eq!(
        by_fence(&huge, i32::MIN, small).0.len(),
        25,
        "fence fill, a huge square clipped"
    );
}

#[testkit::test]
fn a_buffer_larger_than_any_canvas_is_refused() {
    // The whole i32 plane: 2⁶⁴ pixels to invert. Nothing is filled, at once.
    let huge = v(&[(-1e30, -1e30), (1e30, -1e30), (1e30, 1e30), (-1e30, 1e30)]);
    let everything = Viewport::new(i32::MIN, i32::MIN, i32::MAX, i32::MAX);
    assert_eq!(by_edges(&huge, everything), (vec![], 0));
    assert_eq!(by_fence(&huge, 0, everything), (vec![], 0));
    // The buffer spans the viewport's width and the polygon's rows: a small
    // polygon in a large viewport fills.
    let small = v(&[(-3.0, -3.0), (3.0, -3.0), (3.0, 3.0), (-3.0, 3.0)]);
    let large = Viewport::new(-1000, -1000, 1000, 1000);
    assert_eq!(by_edges(&small, large).0.len(), 36);
    assert_eq!(by_fence(&small, 0, large).0.len(), 36);
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn edge_fill_matches_the_even_odd_rule(shape in prop_oneof![star_polygon(), any_polygon()]) {
        let (yours, _) = by_edges(&shape, POLYGON_VIEWPORT);
        assert_pixels_eq(&even_odd_pixels(&shape, POLYGON_VIEWPORT), &yours, &format!("{shape:?}"));
        prop_assert_eq!(first_duplicate(&yours), None);
    }

    #[testkit::test]
    fn fence_fill_matches_the_even_odd_rule_for_any_fence(
        shape in prop_oneof![star_polygon(), any_polygon()], fence in -40..40,
    ) {
        let (yours, _) = by_fence(&shape, fence, POLYGON_VIEWPORT);
        assert_pixels_eq(&even_odd_pixels(&shape, POLYGON_VIEWPORT), &yours, &format!("{shape:?}, fence {fence}"));
        prop_assert_eq!(first_duplicate(&yours), None);
    }

    #[testkit::test]
    fn fence_at_the_right_end_inverts_as_much_as_edge_fill(shape in any_polygon()) {
        // Past the viewport's right edge, every crossing inverts from the
        // fence back to itself: the very pixels edge fill inverts.
        let (filled, edges) = by_edges(&shape, POLYGON_VIEWPORT);
        let (_, fence) = by_fence(&shape, POLYGON_VIEWPORT.x_max + 1, POLYGON_VIEWPORT);
        prop_assert_eq!(edges, fence);
        prop_assert!(filled.is_empty() || edges > 0, "{} pixels filled without an inversion", filled.len());
        if !even_odd_pixels(&shape, POLYGON_VIEWPORT).is_empty() {
            prop_assert!(edges > 0, "a polygon that covers pixels inverts none");
        }
    }

    #[testkit::test]
    fn clipping_keeps_exactly_the_pixels_in_the_viewport(
        shape in any_polygon(), x in -20..10, y in -20..10, w in 0..15, h in 0..15, fence in -30..30,
    ) {
        let viewport = Viewport::new(x, y, x + w, y + h);
        let expected = even_odd_pixels(&shape, viewport);
        assert_pixels_eq(&expected, &by_edges(&shape, viewport).0, &format!("edge fill {shape:?} in {viewport:?}"));
        assert_pixels_eq(&expected, &by_fence(&shape, fence, viewport).0, &format!("fence fill {shape:?} in {viewport:?}"));
    }

    #[testkit::test]
    fn hostile_polygons_never_panic(shape in hostile_polygon(), fence in any::<i32>()) {
        let small = Viewport::new(-5, -5, 5, 5);
        for (yours, _) in [by_edges(&shape, small), by_fence(&shape, fence, small)] {
            prop_assert!(yours.iter().all(|&p| small.contains(p)));
            prop_assert_eq!(first_duplicate(&yours), None);
        }
        // Refusing one is no reason to refuse the next.
        let square = v(&[(-3.0, -3.0), (3.0, -3.0), (3.0, 3.0), (-3.0, 3.0)]);
        prop_assert_eq!(by_edges(&square, small).0.len(), 36);
        prop_assert_eq!(by_fence(&square, fence, small).0.len(), 36);
    }
}
