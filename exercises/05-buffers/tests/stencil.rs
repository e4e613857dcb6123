//! Task 5: the stencil test, the stencil operations and the write mask.

mod common;

use buffers::raster::fill_triangle;
use buffers::stencil::{StencilOp, StencilOutcome, StencilState, stencil_fragment, write_masked};
use buffers::zbuffer::Compare;
use canvas::{Canvas, Pixel, Rgba, Vertex};
use common::{fragment, fragments_of, vertex};
use proptest::prelude::*;

#[testkit::test]
fn operations_on_the_edge_values() {
    use StencilOp::*;
    // Stored values 0, 1, 254, 255 with reference 7.
    let table = [
        (Keep, [0, 1, 254, 255]),
        (Zero, [0, 0, 0, 0]),
        (Replace, [7, 7, 7, 7]),
        (Incr, [1, 2, 255, 255]),
        (IncrWrap, [1, 2, 255, 0]),
        (Decr, [0, 0, 253, 254]),
        (DecrWrap, [255, 0, 253, 254]),
        (Invert, [255, 254, 1, 0]),
    ];
    for (op, expected) in table {
        let yours = [0u8, 1, 254, 255].map(|v| op.apply(v, 7));
        assert_eq!(yours, expected, "{op:?} on 0, 1, 254, 255 (reference 7)");
    }
    assert_eq!(StencilOp::default(), Keep);
}

/// The stencil test of `func` with `reference` and `value_mask` against
/// `stored`.
fn passes(func: Compare, reference: u8, stored: u8, value_mask: u8) -> bool {
    let state = StencilState {
        func,
        reference,
        value_mask,
        ..StencilState::DEFAULT
    };
    state.test(stored)
}

#[testkit::test]
fn functions_compare_the_masked_reference_with_the_masked_stored_value() {
    use Compare::*;
    // ref 0xA1, stored 0xAF: 0xA1 < 0xAF in full, equal in the high nibble.
    let (reference, stored) = (0xA1, 0xAF);
    let full = [
        Never, Less, Equal, LEqual, Greater, NotEqual, GEqual, Always,
    ]
    .map(|f| passes(f, reference, stored, 0xFF));
    assert_eq!(
        full,
        [false, true, false, true, false, true, false, true],
        "mask 0xFF"
    );
    let high = [
        Never, Less, Equal, LEqual, Greater, NotEqual, GEqual, Always,
    ]
    .map(|f| passes(f, reference, stored, 0xF0));
    assert_eq!(
        high,
        [false, false, true, true, false, false, true, true],
        "mask 0xF0"
    );
    // The reference is on the left: LESS passes where ref < stored.
    assert!(passes(Less, 1, 2, 0xFF) && !passes(Less, 2, 1, 0xFF));
    assert!(passes(Greater, 2, 1, 0xFF) && !passes(Greater, 1, 2, 0xFF));
    assert_eq!(StencilState::DEFAULT.func, Always);
}

#[testkit::test]
fn write_mask_keeps_the_bits_outside_it() {
    assert_eq!(
        write_masked(0b1010_1010, 0b0101_0101, 0b0000_1111),
        0b1010_0101
    );
    assert_eq!(write_masked(0xAB, 0x00, 0x00), 0xAB);
    assert_eq!(write_masked(0xAB, 0x12, 0xFF), 0x12);
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn incr_and_decr_saturate_the_wrap_variants_wrap(v in any::<u8>(), r in any::<u8>()) {
        use StencilOp::*;
        let (incr, incr_wrap) = (Incr.apply(v, r), IncrWrap.apply(v, r));
        let (decr, decr_wrap) = (Decr.apply(v, r), DecrWrap.apply(v, r));
        if v < 255 {
            prop_assert_eq!(incr, v + 1);
            prop_assert_eq!(incr_wrap, v + 1);
        } else {
            prop_assert_eq!((incr, incr_wrap), (255, 0));
        }
        if v > 0 {
            prop_assert_eq!(decr, v - 1);
            prop_assert_eq!(decr_wrap, v - 1);
        } else {
            prop_assert_eq!((decr, decr_wrap), (0, 255));
        }
        prop_assert_eq!(DecrWrap.apply(incr_wrap, r), v, "wrapping ops are inverse");
        prop_assert_eq!(Invert.apply(Invert.apply(v, r), r), v, "INVERT twice is identity");
        prop_assert_eq!(u16::from(Invert.apply(v, r)) + u16::from(v), 255);
        prop_assert_eq!(Replace.apply(v, r), r);
        prop_assert_eq!(Keep.apply(v, r), v);
        prop_assert_eq!(Zero.apply(v, r), 0);
    }

    #[testkit::test]
    fn the_test_sees_only_the_masked_bits(r in any::<u8>(), s in any::<u8>(), mask in any::<u8>(), noise in any::<u8>()) {
        for f in Compare::ALL {
            // Changing bits outside the mask changes nothing.
            let (r2, s2) = (r ^ (noise & !mask), s ^ (noise.rotate_left(3) & !mask));
            prop_assert_eq!(passes(f, r, s, mask), passes(f, r2, s2, mask), "{:?}", f);
        }
        let (rm, sm) = (r & mask, s & mask);
        let p = |f: Compare| passes(f, r, s, mask);
        prop_assert_eq!(p(Compare::Less), rm < sm);
        prop_assert_eq!(p(Compare::Equal), rm == sm);
        prop_assert_eq!(p(Compare::LEqual), p(Compare::Less) || p(Compare::Equal));
        prop_assert_eq!(p(Compare::GEqual), !p(Compare::Less));
        prop_assert_eq!(p(Compare::Greater), !p(Compare::LEqual));
        prop_assert_eq!(p(Compare::NotEqual), !p(Compare::Equal));
        prop_assert!(!p(Compare::Never) && p(Compare::Always));
        // A zero mask compares 0 with 0.
        prop_assert!(passes(Compare::Equal, r, s, 0) && !passes(Compare::Less, r, s, 0));
    }

    #[testkit::test]
    fn write_mask_takes_masked_bits_from_new_and_the_rest_from_old(old in any::<u8>(), new in any::<u8>(), mask in any::<u8>()) {
        let w = write_masked(old, new, mask);
        for bit in 0..8 {
            let b = 1u8 << bit;
            let from = if mask & b != 0 { new } else { old };
            prop_assert_eq!(w & b, from & b, "bit {}", bit);
        }
    }
}

/// A state whose three ops are told apart by their results on stored 10:
/// sfail → 0 (ZERO), dpfail → 11 (INCR), dppass → 42 (REPLACE).
fn telling_state(func: Compare) -> StencilState {
    StencilState {
        func,
        reference: 42,
        stencil_fail: StencilOp::Zero,
        depth_fail: StencilOp::Incr,
        depth_pass: StencilOp::Replace,
        ..StencilState::DEFAULT
    }
}

#[testkit::test]
fn each_outcome_applies_its_own_operation() {
    let p = Pixel::new(0, 0);
    let setup = || {
        let mut canvas = Canvas::new(1, 1);
        canvas.set_stencil(p, 10);
        canvas.set_depth(p, 0.5);
        canvas
    };
    // Stencil fails: sfail, no colour, no depth.
    let mut c = setup();
    let out = stencil_fragment(
        &mut c,
        fragment(0, 0, 0.1, Rgba::RED),
        &telling_state(Compare::Never),
        true,
    );
    assert_eq!(out, Some(StencilOutcome::StencilFail));
    assert_eq!(
        (c.stencil(p), c.get(p), c.depth(p)),
        (Some(0), Some(Rgba::BLACK), Some(0.5))
    );
    // Stencil passes, depth fails (0.9 is behind 0.5): dpfail.
    let mut c = setup();
    let out = stencil_fragment(
        &mut c,
        fragment(0, 0, 0.9, Rgba::RED),
        &telling_state(Compare::Always),
        true,
    );
    assert_eq!(out, Some(StencilOutcome::DepthFail));
    assert_eq!(
        (c.stencil(p), c.get(p), c.depth(p)),
        (Some(11), Some(Rgba::BLACK), Some(0.5))
    );
    // Both pass: dppass, colour and depth written.
    let mut c = setup();
    let out = stencil_fragment(
        &mut c,
        fragment(0, 0, 0.1, Rgba::RED),
        &telling_state(Compare::Always),
        true,
    );
    assert_eq!(out, Some(StencilOutcome::DepthPass));
    assert_eq!(
        (c.stencil(p), c.get(p), c.depth(p)),
        (Some(42), Some(Rgba::RED), Some(0.1))
    );
    // Depth test off: the farther fragment passes, and no depth is written.
    let mut c = setup();
    let out = stencil_fragment(
        &mut c,
        fragment(0, 0, 0.9, Rgba::RED),
        &telling_state(Compare::Always),
        false,
    );
    assert_eq!(out, Some(StencilOutcome::DepthPass));
    assert_eq!(
        (c.stencil(p), c.get(p), c.depth(p)),
        (Some(42), Some(Rgba::RED), Some(0.5))
    );
    // Equal depth fails LESS.
    let mut c = setup();
    let out = stencil_fragment(
        &mut c,
        fragment(0, 0, 0.5, Rgba::RED),
        &telling_state(Compare::Always),
        true,
    );
    assert_eq!(out, Some(StencilOutcome::DepthFail));
    // Outside the canvas: nothing.
    let mut c = setup();
    let out = stencil_fragment(
        &mut c,
        fragment(1, 0, 0.1, Rgba::RED),
        &telling_state(Compare::Always),
        true,
    );
    assert_eq!(out, None);
    assert_eq!(c, setup());
}

#[testkit::test]
fn operations_write_through_the_write_mask() {
    let p = Pixel::new(0, 0);
    let mut canvas = Canvas::new(1, 1);
    canvas.set_stencil(p, 0b1111_0000);
    let state = StencilState {
        reference: 0b0101_0101,
        write_mask: 0b0011_1100,
        depth_pass: StencilOp::Replace,
        ..StencilState::DEFAULT
    };
    stencil_fragment(&mut canvas, fragment(0, 0, 0.5, Rgba::WHITE), &state, false);
    assert_eq!(canvas.stencil(p), Some(0b1101_0100));
}

fn at(x: f32, y: f32) -> Vertex {
    vertex(x, y, 0.5, Rgba::WHITE)
}

/// The classic stencil mask: draw a triangle that only writes 1 into the
/// stencil, then a full-screen rectangle with `EQUAL 1`: it appears inside
/// the triangle only.
fn masked_rectangle() -> Canvas {
    let mut canvas = Canvas::new(16, 10);
    let mark = StencilState {
        reference: 1,
        depth_pass: StencilOp::Replace,
        ..StencilState::DEFAULT
    };
    let viewport = canvas.viewport();
    fill_triangle([at(1.0, 1.0), at(14.0, 3.0), at(5.0, 9.0)], viewport, |f| {
        let invisible = canvas::Fragment {
            colour: Rgba::BLACK,
            ..f
        };
        stencil_fragment(&mut canvas, invisible, &mark, false);
    });
    let test = StencilState {
        func: Compare::Equal,
        reference: 1,
        ..StencilState::DEFAULT
    };
    let full = [
        [at(-1.0, -1.0), at(17.0, -1.0), at(17.0, 11.0)],
        [at(-1.0, -1.0), at(17.0, 11.0), at(-1.0, 11.0)],
    ];
    for t in full {
        fill_triangle(t, viewport, |f| {
            stencil_fragment(&mut canvas, f, &test, false);
        });
    }
    canvas
}

#[testkit::test]
fn stencil_equal_masks_a_full_screen_rectangle_to_a_triangle() {
    let canvas = masked_rectangle();
    let triangle: Vec<Pixel> = fragments_of(&canvas, [at(1.0, 1.0), at(14.0, 3.0), at(5.0, 9.0)])
        .iter()
        .map(|f| f.pixel)
        .collect();
    testkit::assert_pixels_eq(
        &triangle,
        &canvas.pixels_not(Rgba::BLACK),
        "the masked rectangle",
    );
    testkit::assert_raster_snapshot!("masked_rectangle", canvas);
}

#[testkit::test]
fn incr_counts_the_depth_complexity() {
    // Overlapping triangles with INCR on every fragment: the stencil holds
    // how many triangles cover each pixel.
    let mut canvas = Canvas::new(12, 12);
    let count = StencilState {
        depth_pass: StencilOp::Incr,
        ..StencilState::DEFAULT
    };
    let triangles = [
        [at(0.0, 0.0), at(11.0, 0.0), at(0.0, 11.0)],
        [at(11.0, 11.0), at(0.0, 11.0), at(11.0, 0.0)],
        [at(2.0, 2.0), at(10.0, 3.0), at(4.0, 10.0)],
    ];
    let mut expected = [[0u8; 12]; 12];
    for t in triangles {
        for f in fragments_of(&canvas, t) {
            expected[f.pixel.y as usize][f.pixel.x as usize] += 1;
            stencil_fragment(&mut canvas, f, &count, false);
        }
    }
    for y in 0..12 {
        for x in 0..12 {
            assert_eq!(
                canvas.stencil(Pixel::new(x, y)),
                Some(expected[y as usize][x as usize]),
                "({x}, {y})"
            );
        }
    }
}

#[testkit::test]
fn incr_saturates_and_incr_wrap_wraps_in_the_buffer() {
    let p = Pixel::new(0, 0);
    for (op, after) in [(StencilOp::Incr, 255), (StencilOp::IncrWrap, 4)] {
        let mut canvas = Canvas::new(1, 1);
        canvas.set_stencil(p, 250);
        let state = StencilState {
            depth_pass: op,
            ..StencilState::DEFAULT
        };
        for _ in 0..10 {
            stencil_fragment(&mut canvas, fragment(0, 0, 0.5, Rgba::WHITE), &state, false);
        }
        assert_eq!(canvas.stencil(p), Some(after), "{op:?} ten times from 250");
    }
}
