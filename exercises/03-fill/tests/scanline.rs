//! Task 2: scanline fill with an active edge table, the even-odd rule.

mod common;

use std::cell::RefCell;
use std::ops::ControlFlow;

use canvas::{Pixel, Span, Vec2, Viewport};
use common::{
    POLYGON_VIEWPORT, any_polygon, canvas_with, collect, crossing, even_odd_pixels,
    first_duplicate, grid_pixels, hostile_polygon, star_polygon,
};
use fill::scanline::{ActiveEdge, fill_spans};
use proptest::prelude::*;
use testkit::assert_pixels_eq;

/// The pixels of `fill_spans`, after checking the active edge table it
/// reported (see [`check_table`]): every test grades the table, not only
/// the pixels.
#[track_caller]
fn polygon(vertices: &[Vec2], viewport: Viewport) -> Vec<Pixel> {
    let spans = spans(vertices, viewport);
    collect(|plot| spans.into_iter().flat_map(Span::pixels).for_each(plot))
}

/// What `fill_spans` reports, in order.
#[derive(Clone, Debug, PartialEq)]
enum Event {
    Span(Span),
    Table(i32, Vec<ActiveEdge>),
}

/// The spans of `fill_spans`, after checking its table.
#[track_caller]
fn spans(vertices: &[Vec2], viewport: Viewport) -> Vec<Span> {
    let mut rows: Vec<(i32, Vec<ActiveEdge>)> = Vec::new();
    let mut spans = Vec::new();
    // Spans and tables in the order they came.
    for event in events_stopped_at(vertices, viewport, None) {
        match event {
            Event::Span(span) => {
                assert!(
                    rows.last().is_some_and(|(y, _)| *y == span.y),
                    "fill_spans({vertices:?}, {viewport:?}): {span:?} does not follow its \
                     row's table (report row y's active edges to `table`, then its spans)"
                );
                spans.push(span);
            }
            Event::Table(y, active) => rows.push((y, active)),
        }
    }
    check_table(vertices, viewport, &rows);
    spans
}

/// The active edge table row by row, as the sheet defines it: every row of
/// the viewport that some edge crosses (lower end in, upper end out),
/// upwards, and in it exactly those edges, at `x` = `crossing` bit for
/// bit, in order of `x`.
#[track_caller]
fn check_table(vertices: &[Vec2], viewport: Viewport, rows: &[(i32, Vec<ActiveEdge>)]) {
    let call = format!("fill_spans({vertices:?}, {viewport:?})");
    let valid = vertices.len() >= 3 && vertices.iter().all(|v| v.is_finite());
    let n = vertices.len();
    let expected_rows: Vec<(i32, Vec<ActiveEdge>)> = if valid && !viewport.is_empty() {
        (viewport.y_min..=viewport.y_max)
            .map(|y| {
                let crossing_edges = (0..n)
                    .filter(|&i| {
                        let (a, b) = (vertices[i], vertices[(i + 1) % n]);
                        (f64::from(a.y) <= f64::from(y)) != (f64::from(b.y) <= f64::from(y))
                    })
                    .map(|i| ActiveEdge {
                        edge: i,
                        x: crossing(vertices[i], vertices[(i + 1) % n], y),
                    })
                    .collect::<Vec<_>>();
                (y, crossing_edges)
            })
            .filter(|(_, active)| !active.is_empty())
            .collect()
    } else {
        Vec::new()
    };
    let reported: Vec<i32> = rows.iter().map(|(y, _)| *y).collect();
    let expected: Vec<i32> = expected_rows.iter().map(|(y, _)| *y).collect();
    assert_eq!(
        reported, expected,
        "{call}: the rows whose table was reported (each row of the viewport that an edge crosses, upwards, once)"
    );
    for ((y, active), (_, definition)) in rows.iter().zip(&expected_rows) {
        let mut edges: Vec<usize> = active.iter().map(|e| e.edge).collect();
        edges.sort_unstable();
        let wanted: Vec<usize> = definition.iter().map(|e| e.edge).collect();
        assert_eq!(
            edges, wanted,
            "{call}: the active edges of row {y} (edge i runs from vertex i to vertex i + 1); \
             yours {active:?}"
        );
        for entry in active {
            let exact = crossing(vertices[entry.edge], vertices[(entry.edge + 1) % n], *y);
            assert!(
                entry.x.to_bits() == exact.to_bits(),
                "{call}: in row {y} edge {} is at x = {}, `crossing` gives {exact}",
                entry.edge,
                entry.x
            );
        }
        assert!(
            active.windows(2).all(|pair| pair[0].x <= pair[1].x),
            "{call}: row {y}'s table is not sorted by x: {active:?}"
        );
    }
}

fn v(points: &[(f32, f32)]) -> Vec<Vec2> {
    points.iter().map(|&(x, y)| Vec2::new(x, y)).collect()
}

#[testkit::test]
fn slides_rectangle_as_a_polygon() {
    // (0.5, 0.5)–(4.5, 3.5) as four vertices: the same 4 × 3 pixels as
    // task 1's rectangle.
    let square = v(&[(0.5, 0.5), (4.5, 0.5), (4.5, 3.5), (0.5, 3.5)]);
    let expected = grid_pixels(Pixel::new(0, 0), &[".####", ".####", ".####", "....."]);
    assert_pixels_eq(
        &expected,
        &polygon(&square, POLYGON_VIEWPORT),
        "the slides' rectangle",
    );
}

#[testkit::test]
fn integer_square_keeps_left_and_bottom_edges() {
    //   3 .....    centres on x = 0 and y = 0 are in,
    //   2 ###..    those on x = 3 and y = 3 are out
    //   1 ###..
    //   0 ###..
    let square = v(&[(0.0, 0.0), (3.0, 0.0), (3.0, 3.0), (0.0, 3.0)]);
    let expected = grid_pixels(Pixel::new(0, 0), &["....", "###.", "###.", "###."]);
    for vertices in [square.clone(), square.iter().rev().copied().collect()] {
        assert_pixels_eq(
            &expected,
            &polygon(&vertices, POLYGON_VIEWPORT),
            "square, either winding",
        );
    }
}

#[testkit::test]
fn pentagram_has_a_hole_by_the_even_odd_rule() {
    // The five-pointed star drawn in one stroke: the centre pentagon is
    // crossed twice and stays empty.
    let star: Vec<Vec2> = (0..5)
        .map(|k| {
            let angle = std::f32::consts::FRAC_PI_2 + k as f32 * 4.0 * std::f32::consts::PI / 5.0;
            Vec2::new(8.0, 8.0) + 7.6 * Vec2::new(angle.cos(), angle.sin())
        })
        .collect();
    let yours = polygon(&star, Viewport::new(0, 0, 16, 16));
    assert!(
        !yours.contains(&Pixel::new(8, 8)),
        "the centre of a pentagram is outside"
    );
    assert!(
        yours.contains(&Pixel::new(8, 13)),
        "the top point is inside"
    );
    testkit::assert_raster_snapshot!("pentagram", canvas_with(17, 17, &yours));
}

#[testkit::test]
fn polygons_of_several_shapes() {
    let mut all = Vec::new();
    for shape in [
        // A triangle with a vertex exactly on a row and a horizontal top.
        v(&[(0.5, 0.5), (6.0, 3.0), (0.5, 6.0)]),
        // A concave arrow.
        v(&[(8.0, 1.0), (15.5, 4.0), (8.0, 7.0), (10.5, 4.0)]),
        // A notch whose tip (4, 10) lies on a row: counted twice (or not at
        // all), so row 10 is not split; the corners on row 8 fill nothing.
        v(&[
            (1.0, 8.0),
            (4.0, 10.0),
            (7.0, 8.0),
            (7.0, 11.0),
            (1.0, 11.0),
        ]),
    ] {
        all.extend(polygon(&shape, Viewport::new(0, 0, 15, 11)));
    }
    testkit::assert_raster_snapshot!("polygons_of_several_shapes", canvas_with(16, 12, &all));
}

#[testkit::test]
fn empty_degenerate_and_hostile_polygons_fill_nothing() {
    let cases = [
        v(&[]),
        v(&[(1.0, 1.0)]),
        v(&[(1.0, 1.0), (5.0, 5.0)]),
        v(&[(1.0, 1.0), (5.0, 1.0), (9.0, 1.0)]),
        v(&[(1.0, 1.0), (5.0, 5.0), (9.0, 9.0)]),
        v(&[(f32::NAN, 1.0), (5.0, 5.0), (9.0, 1.0)]),
        v(&[(0.0, 0.0), (f32::INFINITY, 0.0), (0.0, 5.0)]),
    ];
    for shape in cases {
        assert_eq!(polygon(&shape, POLYGON_VIEWPORT), [], "{shape:?}");
    }
    // Huge but finite: clipped, every pixel of the viewport once.
    let huge = v(&[(-1e30, -1e30), (1e30, -1e30), (1e30, 1e30), (-1e30, 1e30)]);
    let small = Viewport::new(-2, -2, 2, 2);
    assert_eq!(
        polygon(&huge, small).len(),
        25,
        "a huge square clipped to {small:?}"
    );
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
    fn reversed_and_rotated_polygons_fill_the_same(shape in any_polygon(), turn in 0usize..12) {
        let mut rotated = shape.clone();
        if !rotated.is_empty() {
            let k = turn % rotated.len();
            rotated.rotate_left(k);
        }
        let reversed: Vec<Vec2> = shape.iter().rev().copied().collect();
        let yours = polygon(&shape, POLYGON_VIEWPORT);
        prop_assert_eq!(yours.is_empty(), even_odd_pixels(&shape, POLYGON_VIEWPORT).is_empty(), "fills pixels exactly when the even-odd rule does");
        assert_pixels_eq(&yours, &polygon(&reversed, POLYGON_VIEWPORT), "reversed");
        assert_pixels_eq(&yours, &polygon(&rotated, POLYGON_VIEWPORT), "rotated");
    }

    #[testkit::test]
    fn clipping_keeps_exactly_the_pixels_in_the_viewport(
        shape in any_polygon(), x in -20..10, y in -20..10, w in 0..15, h in 0..15,
    ) {
        let viewport = Viewport::new(x, y, x + w, y + h);
        assert_pixels_eq(&even_odd_pixels(&shape, viewport), &polygon(&shape, viewport), &format!("{shape:?} in {viewport:?}"));
    }

    #[testkit::test]
    fn spans_come_bottom_up_and_left_to_right_without_overlap(shape in any_polygon()) {
        let spans = spans(&shape, POLYGON_VIEWPORT);
        prop_assert_eq!(spans.is_empty(), even_odd_pixels(&shape, POLYGON_VIEWPORT).is_empty(), "spans exactly when the even-odd rule fills pixels");
        for span in &spans {
            prop_assert!(!span.is_empty(), "empty span {:?}", span);
            prop_assert!(
                POLYGON_VIEWPORT.contains(Pixel::new(span.x_start, span.y))
                    && POLYGON_VIEWPORT.contains(Pixel::new(span.x_end, span.y)),
                "{:?} leaves the viewport", span
            );
        }
        for pair in spans.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            prop_assert!(
                a.y < b.y || (a.y == b.y && a.x_end < b.x_start),
                "{:?} then {:?}: rows go up, runs of a row go right and never overlap", a, b
            );
        }
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

/// A band one pixel wide along the diagonal, between two staircases of
/// unit steps: `4n` edges, `n` rows, two crossings per row. After the
/// shift by −½ the band holds the pixels `(j, j)`, `j = 0..n`.
fn diagonal_band(n: i32) -> Vec<Vec2> {
    let shift = |x: i32, y: i32| Vec2::new(x as f32 - 0.5, y as f32 - 0.5);
    let mut vertices = Vec::new();
    // Right staircase up: (0,0) → (1,0) → (1,1) → (2,1) → … → (n, n).
    for k in 0..n {
        vertices.push(shift(k, k));
        vertices.push(shift(k + 1, k));
    }
    vertices.push(shift(n, n));
    // Left staircase down: (n−1, n) → (n−1, n−1) → (n−2, n−1) → … → (0, 1),
    // closed by the edge back to (0, 0).
    for k in (0..n).rev() {
        vertices.push(shift(k, k + 1));
        if k > 0 {
            vertices.push(shift(k, k));
        }
    }
    vertices
}

#[testkit::test]
fn work_grows_with_the_active_edges_not_with_all_of_them() {
    // A small band, checked against the definition.
    let small = diagonal_band(20);
    let viewport = Viewport::new(-2, -2, 22, 22);
    let expected: Vec<Pixel> = (0..20).map(|j| Pixel::new(j, j)).collect();
    assert_pixels_eq(
        &even_odd_pixels(&small, viewport),
        &expected,
        "the definition",
    );
    assert_pixels_eq(&expected, &polygon(&small, viewport), "a band of 20 rows");
    // 200 000 edges over 50 000 rows: with an edge table each row looks at
    // its two active edges; testing every edge in every row is 10¹⁰ tests,
    // far beyond the time limit.
    let n = 50_000;
    let band = diagonal_band(n);
    // Row y's table holds the band's two edges there, at y − ½ and y + ½
    // (the vertical steps of the staircases).
    let mut spans = 0;
    let mut rows = 0;
    let mut wrong = None;
    let mut wrong_table = None;
    fill_spans(
        &band,
        Viewport::new(-1, -1, n, n),
        |span| {
            spans += 1;
            if (span.x_start, span.x_end) != (span.y, span.y) {
                wrong.get_or_insert(span);
            }
        },
        |y, active| {
            rows += 1;
            let xs: Vec<f64> = active.iter().map(|e| e.x).collect();
            if xs != [f64::from(y) - 0.5, f64::from(y) + 0.5] {
                wrong_table.get_or_insert((y, active.to_vec()));
            }
            ControlFlow::Continue(())
        },
    );
    assert_eq!(
        wrong, None,
        "in row y the band holds the pixel (y, y) alone"
    );
    assert_eq!(spans, n, "one span per row");
    assert_eq!(
        wrong_table, None,
        "row y's table holds two edges, at y − ½ and y + ½"
    );
    assert_eq!(rows, n, "one table per row");
}

/// Every call of `fill_spans`, in order, with `table` answering `Break` at
/// its report number `stop` (counted from 0) and `Continue` otherwise.
fn events_stopped_at(vertices: &[Vec2], viewport: Viewport, stop: Option<usize>) -> Vec<Event> {
    let events: RefCell<Vec<Event>> = RefCell::default();
    let mut tables = 0;
    fill_spans(
        vertices,
        viewport,
        |span| events.borrow_mut().push(Event::Span(span)),
        |y, active| {
            events.borrow_mut().push(Event::Table(y, active.to_vec()));
            tables += 1;
            if Some(tables - 1) == stop {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        },
    );
    events.into_inner()
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    /// The sheet: when `table` answers `Break`, the fill ends at once,
    /// before that row's spans; what came before is the same as in a fill
    /// that goes on.
    #[testkit::test]
    fn a_table_that_answers_break_ends_the_fill_before_its_row(shape in any_polygon(), at in 0usize..64) {
        let whole = events_stopped_at(&shape, POLYGON_VIEWPORT, None);
        let tables = whole.iter().filter(|e| matches!(e, Event::Table(..))).count();
        prop_assume!(tables > 0);
        let stop = at % tables;
        // The whole run's events up to and including report number `stop`.
        let mut seen = 0;
        let end = whole
            .iter()
            .position(|e| {
                let table = matches!(e, Event::Table(..));
                seen += usize::from(table);
                table && seen == stop + 1
            })
            .map_or(whole.len(), |i| i + 1);
        let stopped = events_stopped_at(&shape, POLYGON_VIEWPORT, Some(stop));
        prop_assert!(
            stopped.len() <= end || stopped[..end] != whole[..end],
            "fill_spans({:?}, {:?}): `table` answered Break at its report {} (row {:?}), \
             yet the fill went on with {:?}: stop at once, before that row's spans",
            shape, POLYGON_VIEWPORT, stop, whole[end - 1], stopped[end]
        );
        prop_assert_eq!(
            &stopped[..], &whole[..end],
            "fill_spans({:?}, {:?}) stopped by `table` at its report {}: the calls up to the stop \
             must be those of a fill that goes on",
            shape, POLYGON_VIEWPORT, stop
        );
    }
}

/// The active edge table's point: a row is ready when the rows below it
/// are. A sliver four billion rows tall, stopped after its first thousand
/// rows, costs a thousand rows; a fill that first finds every crossing of
/// every row (the slides' global sort, or any table derived from it) needs
/// eight billion crossings before its first row and runs out of memory or
/// time.
#[testkit::test]
fn the_first_rows_of_a_shape_four_billion_rows_tall_come_at_once() {
    let sliver = v(&[(-0.5, -2.0e9), (0.5, -2.0e9), (0.5, 2.0e9), (-0.5, 2.0e9)]);
    let viewport = Viewport::new(-4, i32::MIN, 4, i32::MAX);
    let first_row = -2_000_000_000;
    let mut rows = Vec::new();
    let mut spans = Vec::new();
    fill_spans(
        &sliver,
        viewport,
        |span| spans.push(span),
        |y, active| {
            rows.push((y, active.to_vec()));
            if rows.len() == 1000 {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        },
    );
    assert_eq!(
        rows.len(),
        1000,
        "`table` answered Break at the 1000th row: stop there"
    );
    for (k, (y, active)) in rows.iter().enumerate() {
        let expected = [
            ActiveEdge { edge: 3, x: -0.5 },
            ActiveEdge { edge: 1, x: 0.5 },
        ];
        assert!(
            *y == first_row + k as i32 && active[..] == expected[..],
            "report {k} of the sliver {sliver:?} in {viewport:?} is row {y} with {active:?}; \
             the table's row {} holds edge 3 at −0.5 and edge 1 at 0.5",
            first_row + k as i32
        );
    }
    let expected: Vec<Span> = (0..999).map(|k| Span::new(first_row + k, 0, 0)).collect();
    assert_eq!(
        spans, expected,
        "the sliver's spans: pixel 0 of each row before the stop, none in the row that stopped"
    );
}
