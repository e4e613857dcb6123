//! Task 1: the z-buffer with OpenGL's depth functions, clear value and
//! depth range.

mod common;

use buffers::raster::fill_triangle;
use buffers::zbuffer::{Compare, DepthRange, DepthState, clear, depth_test};
use canvas::{Canvas, Fragment, Pixel, Rgba};
use common::{assert_same_canvas, fragment, interpenetrating_triangles, nearest_fragment_picture};
use proptest::prelude::*;

const RED: Rgba = Rgba::RED;
const BLUE: Rgba = Rgba::BLUE;

#[testkit::test]
fn depth_functions_compare_incoming_with_stored() {
    use Compare::*;
    // incoming 0.25, 0.5, 0.75 against stored 0.5: (<, =, >)
    let table = [
        (Never, [false, false, false]),
        (Less, [true, false, false]),
        (Equal, [false, true, false]),
        (LEqual, [true, true, false]),
        (Greater, [false, false, true]),
        (NotEqual, [true, false, true]),
        (GEqual, [false, true, true]),
        (Always, [true, true, true]),
    ];
    for (func, expected) in table {
        let yours = [0.25, 0.5, 0.75].map(|z| func.passes(z, 0.5));
        assert_eq!(
            yours, expected,
            "{func:?} for incoming 0.25, 0.5, 0.75 vs stored 0.5"
        );
    }
    assert_eq!(DepthState::DEFAULT.func, Less, "OpenGL's default is LESS");
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn less_and_lequal_differ_only_on_ties(a in 0.0f32..=1.0, b in 0.0f32..=1.0, tie in any::<bool>()) {
        let b = if tie { a } else { b };
        let differ = Compare::Less.passes(a, b) != Compare::LEqual.passes(a, b);
        prop_assert_eq!(differ, a == b, "LESS vs LEQUAL for {} and {}", a, b);
        let differ = Compare::Greater.passes(a, b) != Compare::GEqual.passes(a, b);
        prop_assert_eq!(differ, a == b, "GREATER vs GEQUAL for {} and {}", a, b);
    }

    #[testkit::test]
    fn depth_functions_are_related_as_their_operators(a in 0.0f32..=1.0, b in 0.0f32..=1.0, tie in any::<bool>()) {
        use Compare::*;
        let b = if tie { a } else { b };
        let p = |f: Compare| f.passes(a, b);
        let exactly_one = [p(Less), p(Equal), p(Greater)].iter().filter(|&&x| x).count();
        prop_assert_eq!(exactly_one, 1, "exactly one of <, =, > holds for {} and {}", a, b);
        prop_assert_eq!(p(LEqual), p(Less) || p(Equal));
        prop_assert_eq!(p(GEqual), p(Greater) || p(Equal));
        prop_assert_eq!(p(NotEqual), !p(Equal));
        prop_assert!(!p(Never) && p(Always));
        prop_assert_eq!(p(Less), Greater.passes(b, a));
    }

    #[testkit::test]
    fn draw_order_does_not_change_the_image_for_distinct_depths(
        pixels in prop::collection::vec((0..6i32, 0..5i32), 1..40),
        order in Just((0..40usize).collect::<Vec<_>>()).prop_shuffle(),
    ) {
        // Fragment i has depth (i + 1) / 64: all depths distinct.
        let fragments: Vec<Fragment> = pixels
            .iter()
            .enumerate()
            .map(|(i, &(x, y))| {
                let hue = i as f32 / 40.0;
                fragment(x, y, (i + 1) as f32 / 64.0, Rgba::rgb(hue, 1.0 - hue, 0.5))
            })
            .collect();
        let draw = |order: &mut dyn Iterator<Item = usize>| {
            let mut canvas = Canvas::new(6, 5);
            for i in order {
                depth_test(&mut canvas, fragments[i], &DepthState::DEFAULT);
            }
            canvas
        };
        let forward = draw(&mut (0..fragments.len()));
        let shuffled = draw(&mut order.iter().copied().filter(|&i| i < fragments.len()));
        prop_assert_eq!(&forward, &shuffled, "the order changed the image");
        // And it is the nearest fragment's colour everywhere.
        for y in 0..5 {
            for x in 0..6 {
                let nearest = fragments
                    .iter()
                    .filter(|f| f.pixel == Pixel::new(x, y))
                    .min_by(|a, b| a.depth.total_cmp(&b.depth));
                let colour = nearest.map_or(Rgba::BLACK, |f| Rgba::from_rgba8(f.colour.to_rgba8()));
                prop_assert_eq!(forward.get(Pixel::new(x, y)), Some(colour), "pixel ({}, {})", x, y);
                let depth = nearest.map_or(1.0, |f| f.depth);
                prop_assert_eq!(forward.depth(Pixel::new(x, y)), Some(depth), "depth at ({}, {})", x, y);
            }
        }
    }
}

/// The lecture's example: an 8 × 8 buffer cleared to "∞" (1 here), a
/// polygon of constant depth 5, then a tilted one with depths 2..7 (all in
/// tenths). Rows are written top first, as on the slide.
fn seed_example(func: Compare) -> Canvas {
    let mut canvas = Canvas::new(8, 8);
    clear(&mut canvas, Rgba::BLACK, 1.0).unwrap();
    let state = DepthState::with_func(func);
    for r in 0..7 {
        for c in 0..7 - r {
            depth_test(&mut canvas, fragment(c, 7 - r, 0.5, RED), &state);
        }
    }
    for r in 2..8 {
        for c in 0..r - 1 {
            let z = (9 - r + c) as f32 / 10.0;
            depth_test(&mut canvas, fragment(c, 7 - r, z, BLUE), &state);
        }
    }
    canvas
}

fn depth_rows(canvas: &Canvas) -> Vec<String> {
    (0..8)
        .rev()
        .map(|y| {
            (0..8)
                .map(|x| match canvas.depth(Pixel::new(x, y)) {
                    Some(1.0) => "∞".to_string(),
                    Some(z) => format!("{}", (z * 10.0).round()),
                    None => "?".to_string(),
                })
                .collect::<Vec<_>>()
                .join(" ")
        })
        .collect()
}

fn colour_rows(canvas: &Canvas) -> Vec<String> {
    (0..8)
        .rev()
        .map(|y| {
            (0..8)
                .map(|x| match canvas.get(Pixel::new(x, y)) {
                    Some(c) if c == RED => 'R',
                    Some(c) if c == BLUE => 'B',
                    _ => '.',
                })
                .collect()
        })
        .collect()
}

#[testkit::test]
fn seed_example_keeps_the_nearer_depth_per_pixel() {
    let expected_depths = [
        "5 5 5 5 5 5 5 ∞",
        "5 5 5 5 5 5 ∞ ∞",
        "5 5 5 5 5 ∞ ∞ ∞",
        "5 5 5 5 ∞ ∞ ∞ ∞",
        "5 5 5 ∞ ∞ ∞ ∞ ∞",
        "4 5 6 7 ∞ ∞ ∞ ∞",
        "3 4 5 6 7 ∞ ∞ ∞",
        "2 3 4 5 6 7 ∞ ∞",
    ];
    for func in [Compare::Less, Compare::LEqual] {
        assert_eq!(depth_rows(&seed_example(func)), expected_depths, "{func:?}");
    }
}

#[testkit::test]
fn seed_example_less_and_lequal_differ_on_the_ties_only() {
    // The two ties (5 against 5), at (0, 3) and (1, 2), keep red with LESS
    // and go to blue with LEQUAL, the seed pseudo-code's `pz <= readZ`.
    let less = [
        "RRRRRRR.", "RRRRRR..", "RRRRR...", "RRRR....", "RRR.....", "BRBB....", "BBBBB...",
        "BBBBBB..",
    ];
    let lequal = [
        "RRRRRRR.", "RRRRRR..", "RRRRR...", "RRRR....", "BRR.....", "BBBB....", "BBBBB...",
        "BBBBBB..",
    ];
    assert_eq!(colour_rows(&seed_example(Compare::Less)), less, "LESS");
    assert_eq!(
        colour_rows(&seed_example(Compare::LEqual)),
        lequal,
        "LEQUAL"
    );
}

#[testkit::test]
fn never_draws_nothing_and_always_draws_the_last() {
    for (func, expected) in [(Compare::Never, Rgba::BLACK), (Compare::Always, BLUE)] {
        let mut canvas = Canvas::new(2, 1);
        let state = DepthState::with_func(func);
        depth_test(&mut canvas, fragment(0, 0, 0.1, RED), &state);
        depth_test(&mut canvas, fragment(0, 0, 0.9, BLUE), &state);
        assert_eq!(canvas.get(Pixel::new(0, 0)), Some(expected), "{func:?}");
    }
}

#[testkit::test]
fn clear_sets_colour_and_clamped_depth_everywhere() {
    let mut canvas = Canvas::new(3, 2);
    canvas.set_depth(Pixel::new(1, 1), 0.25);
    canvas.set(Pixel::new(2, 0), RED);
    let grey = Rgba::grey(0.4);
    for (value, stored) in [(0.75, 0.75), (7.0, 1.0), (f32::INFINITY, 1.0), (-2.0, 0.0)] {
        clear(&mut canvas, grey, value).unwrap();
        for (p, c) in canvas.enumerate().collect::<Vec<_>>() {
            assert_eq!(
                c,
                Rgba::from_rgba8(grey.to_rgba8()),
                "colour at {p} after clear"
            );
            assert_eq!(
                canvas.depth(p),
                Some(stored),
                "depth at {p} after clear({value})"
            );
        }
    }
    let before = canvas.clone();
    assert!(
        clear(&mut canvas, RED, f32::NAN).is_err(),
        "NaN clear depth"
    );
    assert_same_canvas(
        &before,
        &canvas,
        "a clear with a NaN depth must change nothing",
    );
}

#[testkit::test]
fn depth_range_maps_zero_to_near_and_one_to_far() {
    let range = DepthRange::try_new(0.25, 0.75).unwrap();
    assert_eq!((range.map(0.0), range.map(1.0)), (0.25, 0.75));
    assert!((range.map(0.5) - 0.5).abs() < 1e-7);
    let reversed = DepthRange::try_new(1.0, 0.0).unwrap();
    assert_eq!((reversed.map(0.0), reversed.map(1.0)), (1.0, 0.0));
    assert!((reversed.map(0.25) - 0.75).abs() < 1e-7);
    let clamped = DepthRange::try_new(-3.0, 9.0).unwrap();
    assert_eq!((clamped.near(), clamped.far()), (0.0, 1.0));
    assert!(DepthRange::try_new(f32::NAN, 1.0).is_err());
    assert!(DepthRange::try_new(0.0, f32::NAN).is_err());
    assert_eq!(
        DepthRange::default(),
        DepthRange::try_new(0.0, 1.0).unwrap()
    );
}

#[testkit::test]
fn depth_range_is_applied_before_the_test_and_the_write() {
    let mut canvas = Canvas::new(1, 1);
    canvas.set_depth(Pixel::new(0, 0), 0.6);
    let state = DepthState {
        range: DepthRange::try_new(0.5, 1.0).unwrap(),
        ..DepthState::DEFAULT
    };
    // 0.3 maps to 0.65: behind the stored 0.6.
    assert!(!depth_test(&mut canvas, fragment(0, 0, 0.3, RED), &state));
    // 0.1 maps to 0.55: in front, and 0.55 is stored.
    assert!(depth_test(&mut canvas, fragment(0, 0, 0.1, RED), &state));
    let stored = canvas.depth(Pixel::new(0, 0)).unwrap();
    assert!(
        (stored - 0.55).abs() < 1e-6,
        "stored {stored}, expected 0.55"
    );
}

#[testkit::test]
fn depth_mask_off_writes_colour_but_not_depth() {
    let mut canvas = Canvas::new(1, 1);
    let state = DepthState {
        write: false,
        ..DepthState::DEFAULT
    };
    assert!(depth_test(&mut canvas, fragment(0, 0, 0.5, RED), &state));
    assert_eq!(canvas.get(Pixel::new(0, 0)), Some(RED));
    assert_eq!(canvas.depth(Pixel::new(0, 0)), Some(1.0));
    // A farther fragment still passes, since the depth stayed 1.
    assert!(depth_test(&mut canvas, fragment(0, 0, 0.9, BLUE), &state));
}

#[testkit::test]
fn bad_fragments_are_discarded() {
    let mut canvas = Canvas::new(2, 2);
    let always = DepthState::with_func(Compare::Always);
    for f in [
        fragment(0, 0, f32::NAN, RED),
        fragment(0, 0, -0.1, RED),
        fragment(0, 0, 1.5, RED),
        fragment(0, 0, f32::INFINITY, RED),
        fragment(-1, 0, 0.5, RED),
        fragment(0, 2, 0.5, RED),
        fragment(i32::MAX, i32::MIN, 0.5, RED),
    ] {
        assert!(
            !depth_test(&mut canvas, f, &always),
            "a fragment at {} with depth {} must be discarded (outside the canvas, or a depth \
             that is NaN or outside [0, 1]); yours passed it",
            f.pixel,
            f.depth
        );
    }
    assert_same_canvas(
        &Canvas::new(2, 2),
        &canvas,
        "a discarded fragment must change nothing",
    );
    // A good fragment after them passes.
    assert!(depth_test(&mut canvas, fragment(1, 1, 0.5, RED), &always));
}

/// `[0, 1]` includes both ends: a fragment exactly on the far plane
/// (depth 1) passes `LEQUAL` against a cleared buffer (1), one exactly on
/// the near plane (depth 0) passes `GEQUAL` against a stored 0.
#[testkit::test]
fn fragments_at_depth_zero_and_one_are_inside_the_range() {
    let p = Pixel::new(0, 0);
    for (func, depth, stored) in [
        (Compare::LEqual, 1.0, 1.0),
        (Compare::Equal, 1.0, 1.0),
        (Compare::GEqual, 0.0, 0.0),
        (Compare::Equal, 0.0, 0.0),
    ] {
        let mut canvas = Canvas::new(1, 1);
        canvas.set_depth(p, stored);
        let passed = depth_test(
            &mut canvas,
            fragment(0, 0, depth, RED),
            &DepthState::with_func(func),
        );
        assert!(
            passed && canvas.get(p) == Some(RED),
            "depth {depth:.1} lies in [0, 1] (both ends included) and passes {func:?} against the \
             stored {stored:.1}: it must be drawn; yours returned {passed} and the pixel is {}",
            if canvas.get(p) == Some(RED) {
                "red"
            } else {
                "not red"
            }
        );
    }
}

fn zbuffer_scene() -> Canvas {
    let mut canvas = Canvas::new(64, 64);
    clear(&mut canvas, Rgba::grey(0.1), 1.0).unwrap();
    let viewport = canvas.viewport();
    for triangle in interpenetrating_triangles() {
        fill_triangle(triangle, viewport, |f| {
            depth_test(&mut canvas, f, &DepthState::DEFAULT);
        });
    }
    canvas
}

#[testkit::test]
fn interpenetrating_triangles_match_the_nearest_fragment_picture() {
    let mut expected = nearest_fragment_picture(64, 64, &interpenetrating_triangles());
    // The oracle draws on black; paint its background like the scene's.
    for (p, c) in expected.clone().enumerate() {
        if c == Rgba::BLACK {
            expected.set(p, Rgba::grey(0.1));
        }
    }
    testkit::assert_canvas_eq(
        &expected,
        &zbuffer_scene(),
        0.0,
        "z-buffer vs nearest fragment",
    );
}

#[testkit::test]
fn interpenetrating_triangles_match_the_reference_image() {
    testkit::image::assert_image_matches(
        "zbuffer_interpenetrating",
        &zbuffer_scene(),
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/images/zbuffer_interpenetrating.png"
        ),
        testkit::image::Tolerance::EXACT,
    );
}
