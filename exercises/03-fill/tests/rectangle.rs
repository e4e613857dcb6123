//! Task 1: the axis-parallel rectangle, pixel centres in `[min, max)`.

mod common;

use canvas::{Pixel, Vec2, Viewport};
use common::{
    canvas_with, collect, counts, first_duplicate, grid_pixels, in_half_open_box, viewport_pixels,
};
use fill::rectangle::fill_rectangle;
use proptest::prelude::*;
use testkit::assert_pixels_eq;
use testkit::strategies::{half_pixel_point, hostile_point, point};

/// A viewport much larger than every rectangle of these tests.
const WIDE: Viewport = Viewport::new(-100, -100, 100, 100);

fn rectangle(min: Vec2, max: Vec2, viewport: Viewport) -> Vec<Pixel> {
    collect(|plot| fill_rectangle(min, max, viewport, plot))
}

#[testkit::test]
fn slides_rectangle_fills_four_by_three_pixels() {
    // The slides' example (0.5, 0.5)–(4.5, 3.5): centres x = 1..=4, y = 1..=3.
    let yours = rectangle(Vec2::new(0.5, 0.5), Vec2::new(4.5, 3.5), WIDE);
    let expected = grid_pixels(Pixel::new(0, 0), &[".####", ".####", ".####", "....."]);
    assert_pixels_eq(&expected, &yours, "fill_rectangle((0.5, 0.5), (4.5, 3.5))");
    assert_eq!(first_duplicate(&yours), None, "a pixel plotted twice");
}

#[testkit::test]
fn integer_corners_leave_out_the_right_column_and_top_row() {
    //   3 . . . .      centres on x = 4 and y = 3 lie on the
    //   2 # # # # .    excluded right and top edges
    //   1 # # # # .
    //   0 # # # # .
    //     0 1 2 3 4
    let yours = rectangle(Vec2::new(0.0, 0.0), Vec2::new(4.0, 3.0), WIDE);
    let expected = grid_pixels(Pixel::new(0, 0), &["####.", "####.", "####."]);
    assert_pixels_eq(&expected, &yours, "fill_rectangle((0, 0), (4, 3))");
}

#[testkit::test]
fn empty_and_inverted_boxes_fill_nothing() {
    for (min, max) in [
        (Vec2::new(1.0, 1.0), Vec2::new(1.0, 5.0)),
        (Vec2::new(1.0, 1.0), Vec2::new(5.0, 1.0)),
        (Vec2::new(5.0, 5.0), Vec2::new(1.0, 1.0)),
        (Vec2::new(0.2, 0.2), Vec2::new(0.8, 0.8)),
    ] {
        assert_eq!(
            rectangle(min, max, WIDE),
            [],
            "fill_rectangle({min}, {max})"
        );
    }
    // A box around one pixel centre fills that pixel.
    assert_eq!(
        rectangle(Vec2::new(0.5, 0.5), Vec2::new(1.5, 1.5), WIDE),
        [Pixel::new(1, 1)]
    );
}

#[testkit::test]
fn rectangles_of_several_shapes() {
    let mut pixels = Vec::new();
    for (min, max) in [
        (Vec2::new(1.0, 1.0), Vec2::new(4.0, 3.0)),
        (Vec2::new(5.5, 0.5), Vec2::new(6.5, 5.5)),
        (Vec2::new(7.2, 3.7), Vec2::new(10.0, 4.2)),
        (Vec2::new(-3.0, -3.0), Vec2::new(1.5, 0.5)),
    ] {
        pixels.extend(rectangle(min, max, Viewport::new(0, 0, 9, 5)));
    }
    testkit::assert_raster_snapshot!("rectangles_of_several_shapes", canvas_with(10, 6, &pixels));
}

#[testkit::test]
fn hostile_corners_never_panic_and_stay_in_the_viewport() {
    let small = Viewport::new(-3, -2, 4, 5);
    let huge = [
        f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        1e30,
        -1e30,
        f32::MAX,
        f32::MIN,
    ];
    for &a in &huge {
        for &b in &huge {
            let yours = rectangle(Vec2::new(a, -1e30), Vec2::new(b, 1e30), small);
            assert!(
                yours.iter().all(|&p| small.contains(p)),
                "({a}, −1e30)–({b}, 1e30): a pixel outside the viewport"
            );
            assert_eq!(first_duplicate(&yours), None, "a pixel plotted twice");
        }
    }
    // The whole plane, clipped: every pixel of the viewport once.
    let all = rectangle(
        Vec2::splat(f32::NEG_INFINITY),
        Vec2::splat(f32::INFINITY),
        small,
    );
    assert_eq!(all.len(), 8 * 8, "(−∞, −∞)–(∞, ∞) clipped to {small:?}");
    assert_eq!(
        rectangle(Vec2::splat(f32::NAN), Vec2::splat(5.0), small),
        []
    );
    assert_eq!(
        rectangle(Vec2::ZERO, Vec2::splat(3.0), Viewport::new(1, 1, 0, 0)),
        []
    );
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn filled_pixels_are_the_centres_in_the_half_open_box(
        a in point(30.0), b in point(30.0), c in half_pixel_point(30), d in half_pixel_point(30),
        lattice in any::<bool>(),
    ) {
        let (a, b) = if lattice { (c, d) } else { (a, b) };
        let (min, max) = (a.min(b), a.max(b));
        let yours = rectangle(min, max, WIDE);
        let expected: Vec<Pixel> =
            viewport_pixels(WIDE).filter(|&p| in_half_open_box(p, min, max)).collect();
        assert_pixels_eq(&expected, &yours, &format!("fill_rectangle({min}, {max})"));
        prop_assert_eq!(first_duplicate(&yours), None);
    }

    #[testkit::test]
    fn rectangles_sharing_an_edge_cover_each_pixel_once(
        x in prop::array::uniform4(-30.0f32..30.0),
        y in prop::array::uniform2(-30.0f32..30.0),
        vertical in any::<bool>(),
    ) {
        // Split the box at x[1] (or, swapped, at y): left part [x0, x1),
        // right part [x1, x2); together they must be the box [x0, x2).
        let mut xs = [x[0], x[1], x[2]];
        xs.sort_by(f32::total_cmp);
        let (y0, y1) = (y[0].min(y[1]), y[0].max(y[1]));
        let flip = |v: Vec2| if vertical { Vec2::new(v.y, v.x) } else { v };
        let parts = [
            (Vec2::new(xs[0], y0), Vec2::new(xs[1], y1)),
            (Vec2::new(xs[1], y0), Vec2::new(xs[2], y1)),
        ];
        let mut yours = Vec::new();
        for (min, max) in parts {
            yours.extend(rectangle(flip(min), flip(max), WIDE));
        }
        let (min, max) = (flip(Vec2::new(xs[0], y0)), flip(Vec2::new(xs[2], y1)));
        let whole = rectangle(min, max, WIDE);
        let covers_a_centre = viewport_pixels(WIDE).any(|p| in_half_open_box(p, min, max));
        prop_assert_eq!(whole.is_empty(), !covers_a_centre, "fill_rectangle({}, {}) must fill {} pixel", min, max, if covers_a_centre { "at least one" } else { "no" });
        assert_pixels_eq(&whole, &yours, "two halves against the whole box");
        prop_assert!(counts(&yours).values().all(|&n| n == 1), "a pixel covered twice");
    }

    #[testkit::test]
    fn hostile_corners_stay_in_the_viewport(a in hostile_point(), b in hostile_point()) {
        let small = Viewport::new(-5, -5, 5, 5);
        let yours = rectangle(a, b, small);
        prop_assert!(yours.iter().all(|&p| small.contains(p)));
        prop_assert_eq!(first_duplicate(&yours), None);
        // Refusing one is no reason to refuse the next.
        prop_assert_eq!(rectangle(Vec2::new(-1.0, -1.0), Vec2::new(1.0, 1.0), small).len(), 4);
    }
}
