//! Task 3: the painter's algorithm, and the case where it fails.

mod common;

use buffers::painter::{farthest_depth, paint, painter_order};
use canvas::{Canvas, Rgba, Vertex};
use common::{differing_pixels, interpenetrating_triangles, nearest_fragment_picture, vertex};
use proptest::prelude::*;

fn flat(x: f32, y: f32, size: f32, depth: f32, colour: Rgba) -> [Vertex; 3] {
    [
        vertex(x, y, depth, colour),
        vertex(x + size, y, depth, colour),
        vertex(x, y + size, depth, colour),
    ]
}

#[testkit::test]
fn the_key_is_the_farthest_vertex() {
    let w = Rgba::WHITE;
    let t = [
        vertex(0.0, 0.0, 0.3, w),
        vertex(5.0, 0.0, 0.7, w),
        vertex(0.0, 5.0, 0.1, w),
    ];
    assert_eq!(farthest_depth(&t), Some(0.7));
    let mut nan = t;
    nan[2].depth = f32::NAN;
    assert_eq!(farthest_depth(&nan), None);
    nan[2].depth = f32::INFINITY;
    assert_eq!(farthest_depth(&nan), None);
}

#[testkit::test]
fn order_is_farthest_first_ties_stable_and_bad_depths_left_out() {
    let w = Rgba::WHITE;
    let triangles = [
        flat(0.0, 0.0, 4.0, 0.2, w),
        flat(0.0, 0.0, 4.0, 0.9, w),
        flat(0.0, 0.0, 4.0, 0.5, w),
        flat(0.0, 0.0, 4.0, f32::NAN, w),
        flat(0.0, 0.0, 4.0, 0.5, w),
        flat(0.0, 0.0, 4.0, 1.0, w),
    ];
    assert_eq!(painter_order(&triangles), [5, 1, 2, 4, 0]);
    assert_eq!(painter_order(&[]), Vec::<usize>::new());
}

/// Flat triangles at distinct depths: overlapping, never interpenetrating.
fn layered_scene() -> impl Strategy<Value = Vec<[Vertex; 3]>> {
    prop::collection::vec((0.0f32..20.0, 0.0f32..20.0, 3.0f32..14.0), 1..7).prop_map(|v| {
        v.into_iter()
            .enumerate()
            .map(|(i, (x, y, s))| {
                let depth = 0.1 + 0.12 * i as f32;
                let hue = i as f32 / 7.0;
                flat(x, y, s, depth, Rgba::rgb(hue, 0.5, 1.0 - hue))
            })
            .collect()
    })
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn layered_triangles_in_any_order_give_the_correct_picture(
        (scene, order) in layered_scene().prop_flat_map(|s| {
            let n = s.len();
            (Just(s), Just((0..n).collect::<Vec<_>>()).prop_shuffle())
        })
    ) {
        let shuffled: Vec<[Vertex; 3]> = order.iter().map(|&i| scene[i]).collect();
        let mut canvas = Canvas::new(32, 32);
        paint(&mut canvas, &shuffled);
        let expected = nearest_fragment_picture(32, 32, &scene);
        let wrong = differing_pixels(&expected, &canvas);
        prop_assert!(wrong.is_empty(), "pixels differ from the nearest-fragment picture: {:?}", wrong);
    }
}

fn painter_scene() -> Canvas {
    let mut canvas = Canvas::new(64, 64);
    canvas.clear(Rgba::grey(0.1));
    paint(&mut canvas, &interpenetrating_triangles());
    canvas
}

#[testkit::test]
fn interpenetrating_triangles_defeat_the_painter() {
    // Both triangles reach depth 0.8, so the sort key ties and the input
    // order stays: red first, then blue over all of red.
    let triangles = interpenetrating_triangles();
    assert_eq!(painter_order(&triangles), [0, 1]);
    let canvas = painter_scene();
    let mut expected = nearest_fragment_picture(64, 64, &triangles);
    for (p, c) in expected.clone().enumerate() {
        if c == Rgba::BLACK {
            expected.set(p, Rgba::grey(0.1));
        }
    }
    let wrong = differing_pixels(&expected, &canvas);
    assert!(
        !wrong.is_empty(),
        "the painter cannot draw interpenetration, yet the picture is right"
    );
    // Exactly the pixels where red is nearer (or tied, at x = 32, where the
    // first triangle keeps the pixel) but painted over by blue.
    let red = Rgba::from_rgba8(triangles[0][0].colour.to_rgba8());
    assert!(
        wrong
            .iter()
            .all(|&p| expected.get(p) == Some(red) && p.x <= 32),
        "{wrong:?}"
    );
    // Reversing the input only moves the error to the other half.
    let mut reversed = Canvas::new(64, 64);
    reversed.clear(Rgba::grey(0.1));
    paint(&mut reversed, &[triangles[1], triangles[0]]);
    let wrong = differing_pixels(&expected, &reversed);
    assert!(
        !wrong.is_empty() && wrong.iter().all(|&p| p.x > 32),
        "{wrong:?}"
    );
}

#[testkit::test]
fn interpenetrating_triangles_match_the_reference_image() {
    testkit::image::assert_image_matches(
        "painter_interpenetrating",
        &painter_scene(),
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/images/painter_interpenetrating.png"
        ),
        testkit::image::Tolerance::EXACT,
    );
}

#[testkit::test]
fn paint_leaves_the_depth_plane_alone_and_skips_bad_triangles() {
    let mut canvas = Canvas::new(8, 8);
    let mut bad = flat(0.0, 0.0, 6.0, 0.5, Rgba::RED);
    bad[1].depth = f32::NAN;
    let far_away = flat(1e30, 1e30, 1e30, 0.5, Rgba::RED);
    paint(
        &mut canvas,
        &[bad, far_away, flat(0.0, 0.0, 3.0, 0.4, Rgba::GREEN)],
    );
    let drawn = canvas.pixels_not(Rgba::BLACK);
    let red = drawn.iter().find(|&&p| canvas.get(p) != Some(Rgba::GREEN));
    assert!(
        red.is_none(),
        "the red triangles (one with a NaN depth, one beyond the canvas) must be skipped; \
         yours drew something other than the green one at {}",
        red.map_or(String::new(), |p| p.to_string())
    );
    assert!(
        !drawn.is_empty(),
        "the good green triangle must still be drawn after the bad ones"
    );
    let written = canvas
        .enumerate()
        .find(|&(p, _)| canvas.depth(p) != Some(1.0));
    if let Some((p, _)) = written {
        panic!(
            "paint uses no depth buffer, so the depth plane must stay at its clear value 1; \
             yours holds {} at {p}",
            canvas.depth(p).unwrap_or(f32::NAN)
        );
    }
}
