//! Task 6 (bonus): the blocked rasterizer, pixel for pixel the same as the
//! edge-function definition in `tests/common` (not your task 5).

mod common;

use std::collections::{HashMap, HashSet};

use canvas::{Pixel, Vec2, Viewport};
use common::{collect, counts, triangle_pixels};
use fill::blocked::{Block, Coverage, fill_triangle_blocked};
use proptest::prelude::*;
use testkit::assert_pixels_eq;
use testkit::strategies::{half_pixel_point, hostile_point, point};

/// Larger than a block in every direction, so that blocks are accepted
/// whole, rejected whole and tested per pixel.
const WIDE: Viewport = Viewport::new(-50, -50, 50, 50);

/// The pixels of `fill_triangle_blocked`, after checking the blocks it
/// reported (see [`check_blocks`]): every test grades the blocks, not only
/// the pixels.
#[track_caller]
fn pixels(positions: [Vec2; 3], viewport: Viewport) -> Vec<Pixel> {
    let mut blocks = Vec::new();
    let pixels =
        collect(|plot| fill_triangle_blocked(positions, viewport, plot, |b| blocks.push(b)));
    check_blocks(positions, viewport, &blocks);
    pixels
}

/// The blocks tile the part of the viewport the triangle may cover, 8 × 8
/// pixels each (less at the right and top ends), and each is classified as
/// its corners say: an `Outside` block holds no covered pixel, an `Inside`
/// block only covered ones, and a block whose four corners are covered is
/// `Inside` (the triangle is convex, so the corners decide).
#[track_caller]
fn check_blocks(positions: [Vec2; 3], viewport: Viewport, blocks: &[Block]) {
    let call = format!("fill_triangle_blocked({positions:?}, {viewport:?})");
    let covered: HashSet<Pixel> = triangle_pixels(positions, viewport).into_iter().collect();
    let right = blocks.iter().map(|b| b.max.x).max().unwrap_or(0);
    let top = blocks.iter().map(|b| b.max.y).max().unwrap_or(0);
    let mut owner: HashMap<Pixel, Block> = HashMap::new();
    for &block in blocks {
        let (w, h) = (block.max.x - block.min.x + 1, block.max.y - block.min.y + 1);
        assert!(
            (1..=8).contains(&w) && (1..=8).contains(&h),
            "{call}: {block:?} is not a block of at most 8 × 8 pixels"
        );
        assert!(
            (w == 8 || block.max.x == right) && (h == 8 || block.max.y == top),
            "{call}: {block:?} is smaller than 8 × 8 but not at the right or top end of the box"
        );
        assert!(
            viewport.contains(block.min) && viewport.contains(block.max),
            "{call}: {block:?} reaches outside the viewport"
        );
        let corners = [
            block.min,
            Pixel::new(block.max.x, block.min.y),
            Pixel::new(block.min.x, block.max.y),
            block.max,
        ];
        if corners.iter().all(|c| covered.contains(c)) {
            assert_eq!(
                block.coverage,
                Coverage::Inside,
                "{call}: all four corners of {block:?} are covered, so every pixel is: accept it whole"
            );
        }
        for y in block.min.y..=block.max.y {
            for x in block.min.x..=block.max.x {
                let p = Pixel::new(x, y);
                if let Some(other) = owner.insert(p, block) {
                    panic!("{call}: {p} lies in two blocks, {other:?} and {block:?}");
                }
                match block.coverage {
                    Coverage::Outside => assert!(
                        !covered.contains(&p),
                        "{call}: {block:?} is called outside, but {p} is covered"
                    ),
                    Coverage::Inside => assert!(
                        covered.contains(&p),
                        "{call}: {block:?} is called inside, but {p} is not covered"
                    ),
                    Coverage::Partial => {}
                }
            }
        }
    }
    for p in &covered {
        assert!(
            owner.contains_key(p),
            "{call}: the covered pixel {p} lies in no reported block (report each block to `block`)"
        );
    }
}

#[testkit::test]
fn right_triangle_keeps_its_left_edge_and_drops_the_others() {
    let tri = [
        Vec2::new(0.0, 0.0),
        Vec2::new(0.0, 20.0),
        Vec2::new(20.0, 0.0),
    ];
    assert_pixels_eq(
        &triangle_pixels(tri, WIDE),
        &pixels(tri, WIDE),
        "right triangle, 20 pixels",
    );
}

#[testkit::test]
fn far_from_the_origin_blocks_still_agree() {
    // Near ±MAX_COORD edge functions reach 2⁶⁶: the corner tests need
    // i128, the lanes of partial blocks do not.
    let base = 16_000_000.0;
    let tri = [
        Vec2::new(base, base),
        Vec2::new(base + 37.3, base + 5.1),
        Vec2::new(-base, base + 29.8),
    ];
    let viewport = Viewport::new(15_999_990, 15_999_990, 16_000_040, 16_000_040);
    assert_pixels_eq(
        &triangle_pixels(tri, viewport),
        &pixels(tri, viewport),
        "far triangle",
    );
}

#[testkit::test]
fn degenerate_and_hostile_triangles_draw_nothing() {
    for tri in [
        [
            Vec2::new(0.0, 0.0),
            Vec2::new(2.0, 2.0),
            Vec2::new(5.0, 5.0),
        ],
        [
            Vec2::new(f32::NAN, 0.0),
            Vec2::new(5.0, 0.0),
            Vec2::new(0.0, 5.0),
        ],
        [
            Vec2::new(0.0, 0.0),
            Vec2::new(f32::INFINITY, 0.0),
            Vec2::new(0.0, 5.0),
        ],
        [
            Vec2::new(0.0, 0.0),
            Vec2::new(1e30, 0.0),
            Vec2::new(0.0, 1e30),
        ],
    ] {
        assert_eq!(pixels(tri, WIDE), [], "{tri:?}");
    }
    let big = [
        Vec2::new(-1.6e7, -1.6e7),
        Vec2::new(1.6e7, -1.6e7),
        Vec2::new(0.0, 1.6e7),
    ];
    assert_eq!(
        pixels(big, Viewport::new(-3, -3, 3, 3)).len(),
        49,
        "a huge triangle, clipped"
    );
}

fn any_triangle() -> impl Strategy<Value = [Vec2; 3]> {
    prop_oneof![
        prop::array::uniform3(point(45.0)),
        prop::array::uniform3(point(6.0)),
        prop::array::uniform3(half_pixel_point(30)),
    ]
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn covered_pixels_match_the_definition(tri in any_triangle()) {
        let yours = pixels(tri, WIDE);
        assert_pixels_eq(&triangle_pixels(tri, WIDE), &yours, &format!("{tri:?}"));
        prop_assert!(counts(&yours).values().all(|&n| n == 1), "a pixel plotted twice");
    }

    #[testkit::test]
    fn clipping_keeps_exactly_the_pixels_in_the_viewport(
        tri in any_triangle(), x in -40..20, y in -40..20, w in 0..30, h in 0..30,
    ) {
        let viewport = Viewport::new(x, y, x + w, y + h);
        assert_pixels_eq(&triangle_pixels(tri, viewport), &pixels(tri, viewport), &format!("{tri:?} in {viewport:?}"));
    }

    #[testkit::test]
    fn hostile_vertices_never_panic(a in hostile_point(), b in point(20.0), c in hostile_point()) {
        let small = Viewport::new(-5, -5, 5, 5);
        let yours = pixels([a, b, c], small);
        prop_assert!(yours.iter().all(|&p| small.contains(p)));
        prop_assert!(counts(&yours).values().all(|&n| n == 1));
        // Refusing one is no reason to refuse the next.
        let ordinary = [Vec2::new(-3.5, -3.5), Vec2::new(3.5, -3.5), Vec2::new(0.0, 3.5)];
        assert_pixels_eq(&triangle_pixels(ordinary, small), &pixels(ordinary, small), "an ordinary triangle after a hostile one");
    }
}
