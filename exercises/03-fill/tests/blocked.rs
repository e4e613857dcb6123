//! Task 6 (bonus): the blocked rasterizer, pixel for pixel the same as the
//! edge-function definition in `tests/common` (not your task 5).

mod common;

use std::collections::{HashMap, HashSet};

use canvas::{Pixel, Vec2, Viewport};
use common::{collect, triangle_pixels, triangles};
use fill::blocked::{Block, Coverage, fill_triangle_blocked};
use proptest::prelude::*;

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
    triangles::right_triangle(&pixels);
}

#[testkit::test]
fn far_from_the_origin_blocks_still_agree() {
    // Near ±MAX_COORD edge functions reach 2⁶⁶: the corner tests need
    // i128, the lanes of partial blocks do not.
    triangles::far_from_the_origin(&pixels);
}

#[testkit::test]
fn degenerate_and_hostile_triangles_draw_nothing() {
    triangles::degenerate_and_hostile(&pixels);
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn covered_pixels_match_the_definition(tri in triangles::any_triangle()) {
        triangles::covers_as_defined(&pixels, tri)?;
    }

    #[testkit::test]
    fn clipping_keeps_exactly_the_pixels_in_the_viewport(
        tri in triangles::any_triangle(), x in -40..20, y in -40..20, w in 0..30, h in 0..30,
    ) {
        triangles::clipped_as_defined(&pixels, tri, Viewport::new(x, y, x + w, y + h));
    }

    #[testkit::test]
    fn hostile_vertices_never_panic(tri in triangles::hostile_triangle()) {
        triangles::survives_hostile_vertices(&pixels, tri)?;
    }
}
