//! Task 5: the stencil test, the stencil operations and the write mask.

mod common;

use buffers::raster::fill_triangle;
use buffers::stencil::{StencilOp, StencilOutcome, StencilState, stencil_fragment, write_masked};
use buffers::zbuffer::Compare;
use canvas::{Canvas, Pixel, Rgba, Vertex};
use common::{assert_same_canvas, fragment, fragments_of, vertex};
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
    for (func, reference, stored, expected) in [
        (Less, 1, 2, true),
        (Less, 2, 1, false),
        (Greater, 2, 1, true),
        (Greater, 1, 2, false),
    ] {
        assert_eq!(
            passes(func, reference, stored, 0xFF),
            expected,
            "{func:?} with reference {reference} and stored {stored}: the reference is on the \
             left, `reference OP stored`"
        );
    }
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

/// What one pixel holds, named for the messages.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Held {
    stencil: u8,
    colour: Rgba,
    depth: f32,
}

fn held(canvas: &Canvas, p: Pixel) -> Held {
    Held {
        stencil: canvas.stencil(p).unwrap(),
        colour: canvas.get(p).unwrap(),
        depth: canvas.depth(p).unwrap(),
    }
}

#[testkit::test]
fn each_outcome_applies_its_own_operation() {
    let p = Pixel::new(0, 0);
    // Stored: stencil 10, depth 0.5, colour black. The three ops give
    // sfail → 0, dpfail → 11, dppass → 42.
    let setup = || {
        let mut canvas = Canvas::new(1, 1);
        canvas.set_stencil(p, 10);
        canvas.set_depth(p, 0.5);
        canvas
    };
    let cases = [
        (
            "the stencil test fails (NEVER): sfail (ZERO), nothing drawn",
            Compare::Never,
            0.1,
            true,
            StencilOutcome::StencilFail,
            (0, Rgba::BLACK, 0.5),
        ),
        (
            "the stencil test passes, depth 0.9 is behind the stored 0.5: dpfail (INCR), nothing drawn",
            Compare::Always,
            0.9,
            true,
            StencilOutcome::DepthFail,
            (11, Rgba::BLACK, 0.5),
        ),
        (
            "the stencil test passes, depth 0.5 equals the stored 0.5 and fails LESS: dpfail (INCR)",
            Compare::Always,
            0.5,
            true,
            StencilOutcome::DepthFail,
            (11, Rgba::BLACK, 0.5),
        ),
        (
            "both tests pass (depth 0.1 before 0.5): dppass (REPLACE 42), colour and depth written",
            Compare::Always,
            0.1,
            true,
            StencilOutcome::DepthPass,
            (42, Rgba::RED, 0.1),
        ),
        (
            "the depth test is off, so depth 0.9 passes: dppass (REPLACE 42), colour written, depth not",
            Compare::Always,
            0.9,
            false,
            StencilOutcome::DepthPass,
            (42, Rgba::RED, 0.5),
        ),
    ];
    for (rule, func, depth, depth_test, outcome, (stencil, colour, stored_depth)) in cases {
        let mut c = setup();
        let out = stencil_fragment(
            &mut c,
            fragment(0, 0, depth, Rgba::RED),
            &telling_state(func),
            depth_test,
        );
        assert!(
            out == Some(outcome),
            "{rule}: the outcome is {outcome:?}; yours {out:?}"
        );
        let expected = Held {
            stencil,
            colour,
            depth: stored_depth,
        };
        assert_eq!(held(&c, p), expected, "{rule}: the pixel afterwards");
    }
    let mut c = setup();
    let out = stencil_fragment(
        &mut c,
        fragment(1, 0, 0.1, Rgba::RED),
        &telling_state(Compare::Always),
        true,
    );
    assert_eq!(out, None, "a pixel outside the canvas has no outcome");
    assert_same_canvas(&setup(), &c, "a pixel outside the canvas changes nothing");
}

/// OpenGL's eight stencil operations, written out for the oracle.
fn op_result(op: StencilOp, stored: u8, reference: u8) -> u8 {
    match op {
        StencilOp::Keep => stored,
        StencilOp::Zero => 0,
        StencilOp::Replace => reference,
        StencilOp::Incr => stored.saturating_add(1),
        StencilOp::IncrWrap => stored.wrapping_add(1),
        StencilOp::Decr => stored.saturating_sub(1),
        StencilOp::DecrWrap => stored.wrapping_sub(1),
        StencilOp::Invert => !stored,
    }
}

/// Which slot's operation, with or without the write mask, gives `got`:
/// a hint for the message.
fn explain(got: u8, state: &StencilState, stored: u8, slot: usize) -> String {
    let slots = [
        ("stencil_fail", state.stencil_fail),
        ("depth_fail", state.depth_fail),
        ("depth_pass", state.depth_pass),
    ];
    let (name, op) = slots[slot];
    if op_result(op, stored, state.reference) == got {
        return format!("which is what {name} ({op:?}) gives without the write mask");
    }
    for (other, (name, op)) in slots.into_iter().enumerate() {
        let new = op_result(op, stored, state.reference);
        if other != slot && (stored & !state.write_mask) | (new & state.write_mask) == got {
            return format!("which is what {name} ({op:?}) gives through the write mask");
        }
        if other != slot && new == got {
            return format!("which is what {name} ({op:?}) gives without the write mask");
        }
    }
    "which none of the three operations gives".to_owned()
}

/// Every outcome, every operation in every slot, a partial write mask:
/// the stored value becomes `(old & !wm) | (op(old) & wm)` with the op of
/// the outcome. When both tests would fail, the stencil test comes first
/// and `stencil_fail` applies.
#[testkit::test]
fn every_outcome_writes_its_own_operation_through_the_write_mask() {
    let p = Pixel::new(0, 0);
    let (stored, reference, write_mask) = (0b1010_0110, 0b0101_1001, 0b0011_1100);
    // (what happens, stencil function, fragment depth, depth test on,
    // outcome, slot 0 = stencil_fail, 1 = depth_fail, 2 = depth_pass)
    let cases = [
        (
            "the stencil test fails (GREATER: ref 89 > stored 166 is false), the depth test would pass",
            Compare::Greater,
            0.1,
            true,
            StencilOutcome::StencilFail,
            0,
        ),
        (
            "both tests fail (the stencil test comes first)",
            Compare::Greater,
            0.9,
            true,
            StencilOutcome::StencilFail,
            0,
        ),
        (
            "the stencil test passes (LESS: 89 < 166), the depth test fails (0.9 behind 0.5)",
            Compare::Less,
            0.9,
            true,
            StencilOutcome::DepthFail,
            1,
        ),
        (
            "both tests pass (0.1 before 0.5)",
            Compare::Less,
            0.1,
            true,
            StencilOutcome::DepthPass,
            2,
        ),
        (
            "the stencil test passes, the depth test is off",
            Compare::Less,
            0.9,
            false,
            StencilOutcome::DepthPass,
            2,
        ),
    ];
    for (what, func, depth, depth_test, outcome, slot) in cases {
        for stencil_fail in StencilOp::ALL {
            for depth_fail in StencilOp::ALL {
                for depth_pass in StencilOp::ALL {
                    let state = StencilState {
                        func,
                        reference,
                        value_mask: 0xFF,
                        write_mask,
                        stencil_fail,
                        depth_fail,
                        depth_pass,
                    };
                    let mut canvas = Canvas::new(1, 1);
                    canvas.set_stencil(p, stored);
                    canvas.set_depth(p, 0.5);
                    let out = stencil_fragment(
                        &mut canvas,
                        fragment(0, 0, depth, Rgba::RED),
                        &state,
                        depth_test,
                    );
                    assert!(
                        out == Some(outcome),
                        "{what}: the outcome is {outcome:?}; yours {out:?}"
                    );
                    let (name, op) = [
                        ("stencil_fail", stencil_fail),
                        ("depth_fail", depth_fail),
                        ("depth_pass", depth_pass),
                    ][slot];
                    let new = op_result(op, stored, reference);
                    let expected = (stored & !write_mask) | (new & write_mask);
                    let got = canvas.stencil(p).unwrap();
                    assert!(
                        got == expected,
                        "{what}: {name} ({op:?}) applies through the write mask {write_mask:#010b}: \
                         stored {stored:#010b} becomes {expected:#010b}; yours {got:#010b}, {}",
                        explain(got, &state, stored, slot)
                    );
                }
            }
        }
    }
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
