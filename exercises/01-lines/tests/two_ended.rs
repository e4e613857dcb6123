//! Task 7 (bonus): the midpoint line from both endpoints at once.

mod common;

use canvas::{MAX_COORD, Pixel};
use common::{collect, nearest_pixels};
use lines::two_ended::two_ended_midpoint_line;
use proptest::prelude::*;
use testkit::strategies::pixel_line;

fn two_ended(from: Pixel, to: Pixel) -> Vec<Pixel> {
    collect(|plot| two_ended_midpoint_line(from, to, plot))
}

/// The pixels of the line in the two walkers' order: `p₀, p_n, p₁,
/// p_(n−1), …` of the definition's `p₀ … p_n` (the middle one last).
fn walkers_order(from: Pixel, to: Pixel) -> Vec<Pixel> {
    let pixels = nearest_pixels(from, to, None);
    let (mut low, mut high) = (0, pixels.len());
    let mut order = Vec::with_capacity(pixels.len());
    while low < high {
        order.push(pixels[low]);
        low += 1;
        if low < high {
            high -= 1;
            order.push(pixels[high]);
        }
    }
    order
}

/// `pixels` against the walkers' order of the line's definition.
fn check(from: Pixel, to: Pixel, pixels: &[Pixel]) -> Result<(), String> {
    let expected = walkers_order(from, to);
    if pixels == expected.as_slice() {
        return Ok(());
    }
    let mut sorted = pixels.to_vec();
    sorted.sort_by_key(|p| (p.x, p.y));
    let mut want = expected.clone();
    want.sort_by_key(|p| (p.x, p.y));
    if sorted == want {
        Err(format!(
            "{from:?} → {to:?}: the right pixels in the wrong order: {pixels:?}; \
             from both ends at once is {expected:?}"
        ))
    } else {
        Err(format!(
            "{from:?} → {to:?}: {pixels:?}; the line's pixels, from both ends at once, are {expected:?}"
        ))
    }
}

#[testkit::test]
fn the_walkers_meet_in_the_middle() {
    // (0,0) -> (7,3): eight pixels, four from each end.
    //   3 |......##      plot order: (0,0) (7,3) (1,0) (6,3)
    //   2 |....##..                  (2,1) (5,2) (3,1) (4,2)
    //   1 |..##....
    //   0 |##......
    let expected = [
        (0, 0),
        (7, 3),
        (1, 0),
        (6, 3),
        (2, 1),
        (5, 2),
        (3, 1),
        (4, 2),
    ]
    .map(|(x, y)| Pixel::new(x, y));
    assert_eq!(two_ended(Pixel::new(0, 0), Pixel::new(7, 3)), expected);
}

#[testkit::test]
fn ties_go_to_the_smaller_minor_coordinate_from_both_ends() {
    // (0,0) -> (8,2): ties at x = 2 (y = 0.5) and x = 6 (y = 1.5), one on
    // each walker's side. Mirroring the first walker's choice through the
    // centre would take y = 2 at x = 6.
    //   2 |.......##
    //   1 |...####..     x = 2 → y = 0, x = 6 → y = 1
    //   0 |###......
    let (from, to) = (Pixel::new(0, 0), Pixel::new(8, 2));
    let pixels = two_ended(from, to);
    check(from, to, &pixels).unwrap();
    assert!(pixels.contains(&Pixel::new(6, 1)), "x = 6 is a tie: y = 1");
    check(to, from, &two_ended(to, from)).unwrap();
}

#[testkit::test]
fn odd_and_even_counts_and_a_single_pixel() {
    for (from, to) in [
        (Pixel::new(0, 0), Pixel::new(0, 0)),
        (Pixel::new(3, 3), Pixel::new(4, 3)),
        (Pixel::new(3, 3), Pixel::new(5, 2)),
        (Pixel::new(-4, 9), Pixel::new(-2, -1)),
        (Pixel::new(10, 0), Pixel::new(-11, 0)),
    ] {
        check(from, to, &two_ended(from, to)).unwrap();
    }
}

#[testkit::test]
fn endpoints_beyond_the_limit_draw_nothing() {
    let far = MAX_COORD + 1;
    assert!(two_ended(Pixel::new(far, 0), Pixel::new(0, 0)).is_empty());
    assert!(two_ended(Pixel::new(0, 0), Pixel::new(0, -far)).is_empty());
    // An ordinary line after them is drawn.
    let (from, to) = (Pixel::new(-3, 2), Pixel::new(9, 7));
    check(from, to, &two_ended(from, to)).unwrap();
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn from_both_ends_in_every_octant([from, to] in pixel_line(60)) {
        check(from, to, &two_ended(from, to)).map_err(TestCaseError::fail)?;
    }

    #[testkit::test]
    fn a_line_drawn_backwards_covers_the_same_pixels([from, to] in pixel_line(60)) {
        let mut forward = two_ended(from, to);
        let mut backward = two_ended(to, from);
        check(to, from, &backward).map_err(TestCaseError::fail)?;
        forward.sort_by_key(|p| (p.x, p.y));
        backward.sort_by_key(|p| (p.x, p.y));
        prop_assert_eq!(forward, backward);
    }
}
