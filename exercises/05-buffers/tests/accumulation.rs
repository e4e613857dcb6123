//! Task 6: double buffering and jittered accumulation.

mod common;

use buffers::accumulation::{
    AccumError, AccumOp, AccumulationBuffer, DoubleBuffer, JITTER_8, blend, jittered_antialias,
    smooth_triangle,
};
use buffers::raster::fill_triangle;
use canvas::{Canvas, Pixel, Rgba, Vec2, Vec4, Vertex};
use common::{assert_same_canvas, vertex};
use proptest::prelude::*;

#[testkit::test]
fn drawing_into_the_back_buffer_shows_only_after_the_swap() {
    let mut buffers = DoubleBuffer::try_new(4, 3).unwrap();
    let p = Pixel::new(1, 2);
    buffers.back_mut().set(p, Rgba::RED);
    assert_eq!(
        buffers.front().get(p),
        Some(Rgba::BLACK),
        "the back buffer leaked to the front"
    );
    buffers.swap();
    assert_eq!(
        buffers.front().get(p),
        Some(Rgba::RED),
        "the swap did not show the frame"
    );
    // The old front is now the back buffer, with its old content.
    assert_eq!(buffers.back_mut().get(p), Some(Rgba::BLACK));
    buffers.back_mut().set(p, Rgba::GREEN);
    assert_eq!(buffers.front().get(p), Some(Rgba::RED));
    let before = buffers.clone();
    buffers.swap();
    buffers.swap();
    let mut restored = before.clone();
    assert_same_canvas(
        before.front(),
        buffers.front(),
        "two swaps must restore the front buffer",
    );
    assert_same_canvas(
        restored.back_mut(),
        buffers.back_mut(),
        "two swaps must restore the back buffer",
    );
    assert_eq!(buffers.front().get(p), Some(Rgba::RED));
}

/// A 2 × 1 canvas with the 8-bit colours 51/255 = 0.2 and 102/255 = 0.4.
fn two_pixels() -> Canvas {
    let mut c = Canvas::new(2, 1);
    c.set(Pixel::new(0, 0), Rgba::new(0.2, 0.4, 0.0, 1.0));
    c.set(Pixel::new(1, 0), Rgba::new(0.4, 0.2, 1.0, 0.0));
    c
}

fn close(a: Vec4, b: Vec4) -> bool {
    (a - b).abs().max_element() < 1e-6
}

#[testkit::test]
fn each_operation_does_what_glaccum_says() {
    let mut canvas = two_pixels();
    let mut acc = AccumulationBuffer::try_new(2, 1).unwrap();
    let p = Pixel::new(0, 0);
    assert_eq!(acc.get(p), Some(Vec4::ZERO), "a new buffer is cleared to 0");
    // The colour at p is (0.2, 0.4, 0, 1).
    let steps = [
        (
            AccumOp::Load,
            2.0,
            Vec4::new(0.4, 0.8, 0.0, 2.0),
            "acc = 2 · colour",
        ),
        (
            AccumOp::Accum,
            0.5,
            Vec4::new(0.5, 1.0, 0.0, 2.5),
            "acc += 0.5 · colour",
        ),
        (
            AccumOp::Mult,
            0.5,
            Vec4::new(0.25, 0.5, 0.0, 1.25),
            "acc *= 0.5",
        ),
        (
            AccumOp::Add,
            -0.04,
            Vec4::new(0.21, 0.46, -0.04, 1.21),
            "acc += −0.04 in every channel, unclamped",
        ),
    ];
    let mut was = acc.get(p).unwrap();
    for (op, value, expected, rule) in steps {
        acc.accum(op, value, &mut canvas).unwrap();
        let yours = acc.get(p).unwrap();
        assert!(
            close(yours, expected),
            "{op:?} {value}: {rule}, from {was} to {expected}; yours {yours}"
        );
        was = yours;
    }
    assert_same_canvas(
        &two_pixels(),
        &canvas,
        "LOAD, ACCUM, MULT and ADD must leave the canvas alone (only RETURN writes it)",
    );
    // colour = 2·acc = (0.42, 0.92, −0.08, 2.42), clamped and rounded to 8 bits
    acc.accum(AccumOp::Return, 2.0, &mut canvas).unwrap();
    assert_eq!(
        canvas.get(p).unwrap().to_rgba8(),
        [107, 235, 0, 255],
        "RETURN 2"
    );
    assert_eq!(acc.get(Pixel::new(2, 0)), None);
}

#[testkit::test]
fn bad_values_and_sizes_are_errors_that_change_nothing() {
    let mut canvas = two_pixels();
    let mut acc = AccumulationBuffer::try_new(2, 1).unwrap();
    acc.accum(AccumOp::Load, 1.0, &mut canvas).unwrap();
    let before = acc.clone();
    for value in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        for op in [
            AccumOp::Accum,
            AccumOp::Load,
            AccumOp::Return,
            AccumOp::Mult,
            AccumOp::Add,
        ] {
            assert_eq!(
                acc.accum(op, value, &mut canvas),
                Err(AccumError::NotFinite),
                "{op:?} {value}"
            );
        }
    }
    let mut wrong_size = Canvas::new(3, 1);
    assert!(matches!(
        acc.accum(AccumOp::Return, 1.0, &mut wrong_size),
        Err(AccumError::SizeMismatch { .. })
    ));
    assert!(
        acc == before,
        "a failed accum must leave the buffer as it was"
    );
    assert_same_canvas(
        &two_pixels(),
        &canvas,
        "a failed accum must leave the canvas alone",
    );
    assert_same_canvas(
        &Canvas::new(3, 1),
        &wrong_size,
        "RETURN into a canvas of another size must leave it alone",
    );
    assert_eq!(
        AccumulationBuffer::try_new(u32::MAX, u32::MAX),
        Err(AccumError::TooLarge)
    );
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn accumulating_one_frame_gives_that_frame(levels in prop::collection::vec(any::<[u8; 4]>(), 12)) {
        let mut frame = Canvas::new(4, 3);
        for (i, &c) in levels.iter().enumerate() {
            frame.set(Pixel::new(i as i32 % 4, i as i32 / 4), Rgba::from_rgba8(c));
        }
        for op in [AccumOp::Accum, AccumOp::Load] {
            let mut acc = AccumulationBuffer::try_new(4, 3).unwrap();
            let mut source = frame.clone();
            acc.accum(op, 1.0, &mut source).unwrap();
            let mut out = Canvas::new(4, 3);
            acc.accum(AccumOp::Return, 1.0, &mut out).unwrap();
            prop_assert_eq!(&out, &frame, "{:?} 1 then RETURN 1", op);
        }
    }

    #[testkit::test]
    fn n_equal_frames_average_to_that_frame(levels in prop::collection::vec(any::<[u8; 4]>(), 6), n in 1usize..10) {
        let mut frame = Canvas::new(3, 2);
        for (i, &c) in levels.iter().enumerate() {
            frame.set(Pixel::new(i as i32 % 3, i as i32 / 3), Rgba::from_rgba8(c));
        }
        let jitter = vec![Vec2::ZERO; n];
        let out = jittered_antialias(3, 2, &jitter, |canvas, _| *canvas = frame.clone()).unwrap();
        let comparison = testkit::image::compare(&frame, &out, 1.0 / 255.0);
        prop_assert_eq!(comparison.mismatched, 0, "{} equal frames, largest difference {}", n, comparison.max_difference);
    }
}

/// The scene: triangles shifted by `−j`, so that pixel centres sample it
/// at `centre + j`.
fn render(triangles: &[[Vertex; 3]]) -> impl FnMut(&mut Canvas, Vec2) + '_ {
    move |canvas: &mut Canvas, j: Vec2| {
        let viewport = canvas.viewport();
        for t in triangles {
            let moved = t.map(|v| Vertex {
                position: v.position - j,
                ..v
            });
            fill_triangle(moved, viewport, |f| canvas.set(f.pixel, f.colour));
        }
    }
}

/// Whether the point lies strictly inside the triangle (no sample of these
/// tests falls on an edge).
fn inside(t: &[Vertex; 3], q: Vec2) -> bool {
    let side = |a: Vec2, b: Vec2| (b - a).perp_dot(q - a);
    let s = [
        side(t[0].position, t[1].position),
        side(t[1].position, t[2].position),
        side(t[2].position, t[0].position),
    ];
    s.iter().all(|&v| v > 0.0) || s.iter().all(|&v| v < 0.0)
}

#[testkit::test]
fn one_centred_sample_gives_the_aliased_frame() {
    let triangles = [[
        vertex(1.3, 0.7, 0.5, Rgba::WHITE),
        vertex(9.1, 2.2, 0.5, Rgba::WHITE),
        vertex(3.4, 7.9, 0.5, Rgba::GREEN),
    ]];
    let mut aliased = Canvas::new(10, 8);
    render(&triangles)(&mut aliased, Vec2::ZERO);
    let out = jittered_antialias(10, 8, &[Vec2::ZERO], render(&triangles)).unwrap();
    assert_same_canvas(
        &aliased,
        &out,
        "one jitter offset (0, 0) accumulated with weight 1 and returned with 1 must give the \
         aliased frame",
    );
}

#[testkit::test]
fn edge_pixels_get_the_fraction_of_samples_inside() {
    // The given table: the Red Book's j8, moved around the pixel centre.
    let mut xs: Vec<f32> = JITTER_8.iter().map(|j| (j.x + 0.5) * 16.0).collect();
    let mut ys: Vec<f32> = JITTER_8.iter().map(|j| (j.y + 0.5) * 16.0).collect();
    xs.sort_by(f32::total_cmp);
    ys.sort_by(f32::total_cmp);
    // One sample in each eighth of the pixel, horizontally and vertically.
    let odd: Vec<f32> = (0..8).map(|k| (2 * k + 1) as f32).collect();
    assert_eq!(xs, odd);
    assert_eq!(ys, odd);
    assert_eq!(JITTER_8[0], Vec2::new(0.0625, -0.0625));

    let triangles = [[
        vertex(0.3, 0.2, 0.5, Rgba::WHITE),
        vertex(11.7, 2.1, 0.5, Rgba::WHITE),
        vertex(2.2, 8.9, 0.5, Rgba::WHITE),
    ]];
    let out = jittered_antialias(12, 10, &JITTER_8, render(&triangles)).unwrap();
    let mut partial = 0;
    for (p, c) in out.enumerate() {
        let hits = JITTER_8
            .iter()
            .filter(|&&j| inside(&triangles[0], p.centre() + j))
            .count();
        let expected = hits as f32 / 8.0;
        assert!(
            (c.r - expected).abs() <= 1.0 / 255.0,
            "{p}: {} of 8 samples inside, got {}",
            hits,
            c.r
        );
        if hits > 0 && hits < 8 {
            partial += 1;
        }
    }
    assert!(partial > 10, "the edges should be antialiased");
}

#[testkit::test]
fn no_jitter_is_an_error() {
    let result = jittered_antialias(4, 4, &[], |_, _| {});
    assert_eq!(result.err(), Some(AccumError::NoJitter));
}

fn antialiased_scene() -> Canvas {
    let c = |r, g, b| Rgba::rgb(r, g, b);
    let triangles = [
        [
            vertex(3.0, 4.0, 0.5, c(0.9, 0.3, 0.2)),
            vertex(58.0, 12.0, 0.5, c(0.9, 0.3, 0.2)),
            vertex(20.0, 44.0, 0.5, c(0.9, 0.8, 0.2)),
        ],
        [
            vertex(30.0, 46.0, 0.5, c(0.2, 0.5, 0.9)),
            vertex(40.3, 9.7, 0.5, c(0.2, 0.9, 0.6)),
            vertex(61.0, 40.0, 0.5, c(0.2, 0.5, 0.9)),
        ],
        [
            vertex(5.0, 40.0, 0.5, Rgba::WHITE),
            vertex(14.0, 38.5, 0.5, Rgba::WHITE),
            vertex(6.0, 46.0, 0.5, Rgba::WHITE),
        ],
    ];
    jittered_antialias(64, 48, &JITTER_8, render(&triangles)).unwrap()
}

#[testkit::test]
fn antialiased_triangles_match_the_reference_image() {
    testkit::image::assert_image_matches(
        "accumulation_antialiased",
        &antialiased_scene(),
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/images/accumulation_antialiased.png"
        ),
        testkit::image::Tolerance::EXACT,
    );
}

// ---------------------------------------------------------------------------
// The slides' OpenGL route: smoothing by alpha blending.

fn close_rgba(a: Rgba, b: Rgba, tolerance: f32) -> bool {
    [a.r - b.r, a.g - b.g, a.b - b.b, a.a - b.a]
        .iter()
        .all(|d| d.abs() <= tolerance)
}

#[testkit::test]
fn blending_weights_the_fragment_by_its_alpha() {
    let red_quarter = Rgba::new(1.0, 0.0, 0.0, 0.25);
    let blue = Rgba::new(0.0, 0.0, 1.0, 1.0);
    let out = blend(red_quarter, blue);
    assert!(
        close_rgba(out, Rgba::new(0.25, 0.0, 0.75, 0.8125), 1e-6),
        "glBlendFunc(SRC_ALPHA, ONE_MINUS_SRC_ALPHA): red at alpha ¼ over opaque blue is \
         src·¼ + dst·¾ in every channel, alpha too (¼·¼ + 1·¾ = 0.8125); yours: {out:?}"
    );
    assert_eq!(
        blend(Rgba::new(0.3, 0.6, 0.9, 1.0), blue),
        Rgba::new(0.3, 0.6, 0.9, 1.0),
        "an opaque fragment (alpha 1) replaces the stored colour"
    );
    assert_eq!(
        blend(Rgba::new(0.3, 0.6, 0.9, 0.0), blue),
        blue,
        "a transparent fragment (alpha 0) leaves the stored colour"
    );
}

/// The triangle of `edge_pixels_get_the_fraction_of_samples_inside`.
fn smooth_test_triangle() -> [Vec2; 3] {
    [
        Vec2::new(0.3, 0.2),
        Vec2::new(11.7, 2.1),
        Vec2::new(2.2, 8.9),
    ]
}

#[testkit::test]
fn a_smooth_triangle_on_black_is_the_accumulated_one() {
    let vertices = smooth_test_triangle();
    let mut smooth = Canvas::new(12, 10);
    smooth.clear(Rgba::BLACK);
    smooth_triangle(&mut smooth, vertices, Rgba::WHITE);
    let triangles = [vertices.map(|v| Vertex::new(v, 0.5, Rgba::WHITE))];
    let accumulated = jittered_antialias(12, 10, &JITTER_8, render(&triangles)).unwrap();
    for (p, c) in accumulated.enumerate() {
        let s = smooth.get(p).expect("same size");
        assert!(
            (s.r - c.r).abs() <= 1.0 / 255.0,
            "{p}: smoothed {}, accumulated {}: on black, a white triangle blended with alpha = \
             its coverage (the fraction of the 8 jittered samples fill_triangle covers) is the \
             accumulated average of the 8 jittered frames",
            s.r,
            c.r
        );
    }
}

#[testkit::test]
fn smoothing_blends_the_covered_fraction_over_the_background() {
    let vertices = smooth_test_triangle();
    let background = Rgba::new(0.2, 0.4, 0.6, 1.0);
    let colour = Rgba::new(1.0, 0.1, 0.0, 1.0);
    let mut canvas = Canvas::new(12, 10);
    canvas.clear(background);
    smooth_triangle(&mut canvas, vertices, colour);
    let triangle = vertices.map(|v| Vertex::new(v, 0.5, colour));
    for (p, got) in canvas.enumerate() {
        let hits = JITTER_8
            .iter()
            .filter(|&&j| inside(&triangle, p.centre() + j))
            .count();
        let c = hits as f32 / 8.0;
        let expected = Rgba::new(
            colour.r * c + background.r * (1.0 - c),
            colour.g * c + background.g * (1.0 - c),
            colour.b * c + background.b * (1.0 - c),
            c * c + (1.0 - c),
        );
        let channels = [
            ("red", expected.r, got.r),
            ("green", expected.g, got.g),
            ("blue", expected.b, got.b),
            ("alpha", expected.a, got.a),
        ];
        let off: Vec<String> = channels
            .iter()
            .filter(|(_, e, y)| (e - y).abs() > 1.0 / 255.0)
            .map(|(name, e, y)| format!("{name} {e:.3}, yours {y:.3}"))
            .collect();
        let alpha_only = off.len() == 1 && off[0].starts_with("alpha");
        assert!(
            off.is_empty(),
            "{p}: {hits} of 8 samples inside, so src.a = {c}: every channel, alpha too, is \
             src·src.a + dst·(1 − src.a) over the background (0.2, 0.4, 0.6, 1); expected {}{}",
            off.join("; "),
            if alpha_only {
                " (Canvas::blend's alpha, s + dst.a·(1 − s), is another formula)"
            } else {
                ""
            }
        );
    }
}

/// Smoothing's known flaw: a square cut along its diagonal into two
/// triangles. Accumulation covers every sample once (the fill's top-left
/// rule), smoothing blends the two halves of a diagonal pixel — ½ over ½
/// is ¾ — and leaves a darker seam.
///
/// ```text
///   +-------+        accumulated: the square white
///   |     / |        smoothed:    a grey line along the diagonal
///   |   /   |
///   | /     |
///   +-------+
/// ```
#[testkit::test]
fn a_shared_edge_leaves_a_seam_when_smoothed_but_not_when_accumulated() {
    let (a, b, c, d) = (
        Vec2::new(1.5, 1.5),
        Vec2::new(9.5, 1.5),
        Vec2::new(9.5, 9.5),
        Vec2::new(1.5, 9.5),
    );
    let halves = [[a, b, d], [b, c, d]];
    let mut smooth = Canvas::new(11, 11);
    smooth.clear(Rgba::BLACK);
    for half in halves {
        smooth_triangle(&mut smooth, half, Rgba::WHITE);
    }
    let triangles = halves.map(|t| t.map(|v| Vertex::new(v, 0.5, Rgba::WHITE)));
    let accumulated = jittered_antialias(11, 11, &JITTER_8, render(&triangles)).unwrap();
    let interior: Vec<Pixel> = (2..=9)
        .flat_map(|y| (2..=9).map(move |x| Pixel::new(x, y)))
        .collect();
    for &p in &interior {
        let got = accumulated.get(p).expect("inside").r;
        assert!(
            got >= 254.0 / 255.0,
            "{p}: accumulation covers each sample of the square once, so it is white; got {got}"
        );
    }
    let darkest = interior
        .iter()
        .map(|&p| smooth.get(p).expect("inside").r)
        .fold(1.0f32, f32::min);
    assert!(
        darkest <= 0.9,
        "the pixels the shared diagonal cuts are covered partly by each half: blended one \
         after the other they stay darker than white (½ over ½ gives ¾), yet the darkest is \
         {darkest}"
    );
}
