//! Task 4: edge fill and fence fill, the same pixels as the even-odd rule,
//! and how many inversions each needs.

mod common;

use std::cell::RefCell;
use std::collections::HashMap;

use canvas::{Canvas, Pixel, Vec2, Viewport};
use common::{
    POLYGON_VIEWPORT, any_polygon, crossing, even_odd_pixels, first_duplicate, grid_pixels,
    hostile_polygon, star_polygon,
};
use fill::edge_fence::{edge_fill, fence_fill};
use proptest::prelude::*;
use testkit::assert_pixels_eq;

/// Edge fill's pixels and count, after checking its inversions pixel by
/// pixel (see [`check_inversions`]): every test grades the inverting, not
/// only the pixels it leaves.
#[track_caller]
fn by_edges(vertices: &[Vec2], viewport: Viewport) -> (Vec<Pixel>, u64) {
    traced(vertices, None, viewport, |plot, invert| {
        edge_fill(vertices, viewport, plot, invert)
    })
}

/// Fence fill's pixels and count, after checking its inversions.
#[track_caller]
fn by_fence(vertices: &[Vec2], fence: i32, viewport: Viewport) -> (Vec<Pixel>, u64) {
    traced(vertices, Some(fence), viewport, |plot, invert| {
        fence_fill(vertices, fence, viewport, plot, invert)
    })
}

/// Runs a fill, keeps its plots and inversions in order, and checks them.
#[track_caller]
fn traced(
    vertices: &[Vec2],
    fence: Option<i32>,
    viewport: Viewport,
    fill: impl FnOnce(&mut dyn FnMut(Pixel), &mut dyn FnMut(Pixel)) -> u64,
) -> (Vec<Pixel>, u64) {
    let call = match fence {
        None => format!("edge_fill({vertices:?}, {viewport:?})"),
        Some(fence) => format!("fence_fill({vertices:?}, {fence}, {viewport:?})"),
    };
    let plotted = RefCell::new(Vec::new());
    let inverted = RefCell::new(Vec::new());
    let mut late = None;
    let n = fill(&mut |p| plotted.borrow_mut().push(p), &mut |p| {
        if late.is_none() && !plotted.borrow().is_empty() {
            late = Some(p);
        }
        inverted.borrow_mut().push(p);
    });
    if let Some(p) = late {
        panic!(
            "{call}: the inversion of {p} comes after a pixel was plotted (invert first, then plot)"
        );
    }
    let inverted = inverted.into_inner();
    assert_eq!(
        n,
        inverted.len() as u64,
        "{call}: the count returned is not the number of inversions reported to `invert`"
    );
    check_inversions(
        &call,
        &expected_inversions(vertices, fence, viewport),
        &inverted,
    );
    (plotted.into_inner(), n)
}

/// How often each pixel is inverted, as the sheet defines it: for every
/// crossing of an edge with a row of the buffer (lower end in, upper end
/// out), `c = ⌈s⌉` clamped to `x_min ..= x_max + 1`; edge fill inverts
/// `c ..= x_max`, fence fill (fence `f` clamped alike) `c ..= f − 1` or
/// `f ..= c − 1`. Nothing for an invalid polygon or a buffer of more than
/// `Canvas::MAX_PIXELS`.
fn expected_inversions(
    vertices: &[Vec2],
    fence: Option<i32>,
    viewport: Viewport,
) -> HashMap<Pixel, u64> {
    let mut counts = HashMap::new();
    if vertices.len() < 3 || !vertices.iter().all(|v| v.is_finite()) || viewport.is_empty() {
        return counts;
    }
    let lo = vertices
        .iter()
        .map(|v| f64::from(v.y))
        .fold(f64::INFINITY, f64::min);
    let hi = vertices
        .iter()
        .map(|v| f64::from(v.y))
        .fold(f64::NEG_INFINITY, f64::max);
    let y0 = lo.ceil().max(f64::from(viewport.y_min));
    let y1 = (hi.ceil() - 1.0).min(f64::from(viewport.y_max));
    if y0 > y1 {
        return counts;
    }
    let (left, right) = (i64::from(viewport.x_min), i64::from(viewport.x_max) + 1);
    let height = (y1 - y0) as u64 + 1;
    if ((right - left) as u64).saturating_mul(height) > Canvas::MAX_PIXELS {
        return counts;
    }
    // Edge fill is a fence past the right end.
    let fence = fence.map_or(right, |f| i64::from(f).clamp(left, right));
    let n = vertices.len();
    for i in 0..n {
        let (a, b) = (vertices[i], vertices[(i + 1) % n]);
        for y in y0 as i32..=y1 as i32 {
            if (f64::from(a.y) <= f64::from(y)) == (f64::from(b.y) <= f64::from(y)) {
                continue;
            }
            let c = crossing(a, b, y).ceil().clamp(left as f64, right as f64) as i64;
            for x in c.min(fence)..c.max(fence) {
                *counts.entry(Pixel::new(x as i32, y)).or_insert(0) += 1;
            }
        }
    }
    counts
}

#[track_caller]
fn check_inversions(call: &str, expected: &HashMap<Pixel, u64>, inverted: &[Pixel]) {
    let mut yours: HashMap<Pixel, u64> = HashMap::new();
    for &p in inverted {
        *yours.entry(p).or_insert(0) += 1;
    }
    let mut pixels: Vec<Pixel> = expected.keys().chain(yours.keys()).copied().collect();
    pixels.sort_by_key(|p| (p.y, p.x));
    pixels.dedup();
    for p in pixels {
        let (want, got) = (
            expected.get(&p).copied().unwrap_or(0),
            yours.get(&p).copied().unwrap_or(0),
        );
        assert_eq!(
            got, want,
            "{call}: {p} is inverted {got} times, the crossings of its row invert it {want} times \
             (sheet, ‘What is counted’)"
        );
    }
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
    fn fence_through_a_vertex_as_the_slides_place_it(
        shape in prop_oneof![star_polygon(), any_polygon()], k in 0usize..12,
    ) {
        // The slides' fence is the vertical through a vertex, where two
        // edges meet: the column ⌈v.x⌉. The helper checks every pixel's
        // inversions.
        if let Some(v) = shape.get(k % shape.len().max(1)) {
            let fence = v.x.ceil() as i32;
            let (yours, _) = by_fence(&shape, fence, POLYGON_VIEWPORT);
            assert_pixels_eq(&even_odd_pixels(&shape, POLYGON_VIEWPORT), &yours, &format!("{shape:?}, fence {fence} through vertex {k}"));
        }
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
