//! Task 4: viewport intersection without rounding the slope.

mod common;

use canvas::{Canvas, MAX_COORD, Pixel, Rgba, Viewport};
use common::{collect, nearest_pixels};
use lines::viewport::clipped_midpoint_line;
use proptest::prelude::*;
use testkit::{assert_pixels_eq, strategies::pixel_line};

fn clipped(from: Pixel, to: Pixel, viewport: Viewport) -> Vec<Pixel> {
    collect(|plot| clipped_midpoint_line(from, to, viewport, plot))
}

fn viewport() -> impl Strategy<Value = Viewport> {
    (-20..20, -20..20, 0..25, 0..25).prop_map(|(x, y, w, h)| Viewport::new(x, y, x + w, y + h))
}

#[testkit::test]
fn line_entering_through_the_bottom_starts_at_the_right_column() {
    // (0,0) -> (20,5), viewport rows 2..=4. Row 2 starts where the ideal
    // line crosses y = 1.5 (x = 6), a tie that goes to the lower row: so
    // the first visible pixel is (7, 2), not the rounded crossing of y = 2
    // (x = 8). Row 4 ends where the line crosses y = 4.5 (x = 18, a tie
    // that stays in row 4).
    let viewport = Viewport::new(0, 2, 30, 4);
    let pixels = clipped(Pixel::new(0, 0), Pixel::new(20, 5), viewport);
    assert_eq!(pixels.first(), Some(&Pixel::new(7, 2)));
    assert_eq!(pixels.last(), Some(&Pixel::new(18, 4)));
    assert_pixels_eq(
        &nearest_pixels(Pixel::new(0, 0), Pixel::new(20, 5), Some(viewport)),
        &pixels,
        "(0,0) -> (20,5) in rows 2..=4",
    );
}

#[testkit::test]
fn lines_crossing_a_viewport() {
    // The viewport is the canvas's middle; the outline shows its border.
    let viewport = Viewport::new(4, 3, 20, 12);
    let mut canvas = Canvas::new(25, 16);
    for x in viewport.x_min - 1..=viewport.x_max + 1 {
        for y in [viewport.y_min - 1, viewport.y_max + 1] {
            canvas.set(Pixel::new(x, y), Rgba::grey(0.3));
        }
    }
    for y in viewport.y_min - 1..=viewport.y_max + 1 {
        for x in [viewport.x_min - 1, viewport.x_max + 1] {
            canvas.set(Pixel::new(x, y), Rgba::grey(0.3));
        }
    }
    let lines = [
        ((-10, -4), (40, 20)),
        ((0, 15), (30, 0)),
        ((12, -50), (14, 60)),
        ((-5, 8), (9, 30)),
    ];
    for ((x0, y0), (x1, y1)) in lines {
        clipped_midpoint_line(Pixel::new(x0, y0), Pixel::new(x1, y1), viewport, |p| {
            canvas.set(p, Rgba::WHITE)
        });
    }
    testkit::assert_raster_snapshot!("lines_crossing_a_viewport", canvas);
}

#[testkit::test]
fn far_outside_line_is_clipped_before_iterating() {
    // Billions of columns: only an implementation that starts at the
    // viewport finishes within the time limit.
    let (from, to) = (Pixel::new(i32::MIN + 1, -7), Pixel::new(i32::MAX, 19));
    let viewport = Viewport::new(0, -10, 63, 30);
    assert_pixels_eq(
        &nearest_pixels(from, to, Some(viewport)),
        &clipped(from, to, viewport),
        "a line across the whole i32 range",
    );
    let (from, to) = (Pixel::new(3, i32::MAX), Pixel::new(-2, i32::MIN));
    assert_pixels_eq(
        &nearest_pixels(from, to, Some(viewport)),
        &clipped(from, to, viewport),
        "a steep line across the whole i32 range",
    );
}

#[testkit::test]
fn empty_viewport_and_lines_outside_draw_nothing() {
    let line = (Pixel::new(0, 0), Pixel::new(10, 3));
    assert_eq!(clipped(line.0, line.1, Viewport::new(5, 5, 4, 9)), []);
    assert_eq!(clipped(line.0, line.1, Viewport::new(0, 4, 10, 9)), []);
    assert_eq!(clipped(line.0, line.1, Viewport::new(11, 0, 20, 9)), []);
    // The part inside a viewport that the line crosses is drawn.
    assert!(!clipped(line.0, line.1, Viewport::new(2, 0, 8, 9)).is_empty());
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn draws_exactly_the_visible_part_of_the_line([from, to] in pixel_line(60), viewport in viewport()) {
        let expected = nearest_pixels(from, to, Some(viewport));
        let yours = clipped(from, to, viewport);
        assert_pixels_eq(&expected, &yours, &format!("clipped_midpoint_line({from}, {to}, {viewport:?})"));
        prop_assert_eq!(yours, expected, "same pixels but not in order from `from` to `to`");
    }

    /// Lines between random extreme pixels, billions of columns long,
    /// through a small viewport: only a walk that starts at the viewport's
    /// first visible column finishes in time.
    #[testkit::test]
    fn huge_lines_are_exact_inside(
        from in testkit::strategies::hostile_pixel(),
        to in testkit::strategies::hostile_pixel(),
        viewport in viewport(),
    ) {
        let expected = nearest_pixels(from, to, Some(viewport));
        assert_pixels_eq(&expected, &clipped(from, to, viewport), &format!("clipped_midpoint_line({from}, {to}, {viewport:?})"));
        // Random extremes mostly miss a small viewport; this one crosses it.
        let (a, b) = (Pixel::new(-MAX_COORD, 3 - MAX_COORD), Pixel::new(MAX_COORD, MAX_COORD - 1));
        let small = Viewport::new(-5, -5, 5, 5);
        let through = nearest_pixels(a, b, Some(small));
        prop_assert!(!through.is_empty(), "the line from {} to {} crosses {:?}", a, b, small);
        assert_pixels_eq(&through, &clipped(a, b, small), &format!("clipped_midpoint_line({a}, {b}, {small:?})"));
    }
}
