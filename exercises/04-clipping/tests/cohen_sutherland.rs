//! Task 3: Cohen-Sutherland line clipping with outcodes.

mod common;

use clipping::cohen_sutherland::{Outcode, cohen_sutherland, outcode};

line_clipping_spec!(cohen_sutherland);

#[testkit::test]
fn outcodes_of_the_nine_regions() {
    //    1001 │ 1000 │ 1010
    //   ──────┼──────┼──────        window [0, 10]²
    //    0001 │ 0000 │ 0010
    //   ──────┼──────┼──────
    //    0101 │ 0100 │ 0110
    let w = ten();
    let code = |x: f32, y: f32| outcode(Vec2::new(x, y), w);
    assert_eq!(code(5.0, 5.0), Outcode::INSIDE);
    assert_eq!(code(-1.0, 5.0), Outcode::LEFT);
    assert_eq!(code(11.0, 5.0), Outcode::RIGHT);
    assert_eq!(code(5.0, -1.0), Outcode::BOTTOM);
    assert_eq!(code(5.0, 11.0), Outcode::TOP);
    assert_eq!(code(-1.0, 11.0), Outcode::LEFT | Outcode::TOP);
    assert_eq!(code(11.0, 11.0), Outcode::RIGHT | Outcode::TOP);
    assert_eq!(code(-1.0, -1.0), Outcode::LEFT | Outcode::BOTTOM);
    assert_eq!(code(11.0, -1.0), Outcode::RIGHT | Outcode::BOTTOM);
    assert_eq!(Outcode::LEFT | Outcode::TOP, Outcode(0b1001));
}

#[testkit::test]
fn points_on_the_border_are_inside() {
    let w = ten();
    for (x, y) in [
        (0.0, 0.0),
        (10.0, 10.0),
        (0.0, 5.0),
        (5.0, 10.0),
        (10.0, 0.0),
    ] {
        assert_eq!(outcode(Vec2::new(x, y), w), Outcode::INSIDE, "({x}, {y})");
    }
    assert_eq!(outcode(Vec2::new(-1e-6, 10.0), w), Outcode::LEFT);
}

#[testkit::test]
fn outcodes_drawn_around_a_window() {
    // One character per pixel centre: the outcode in hex, for the window
    // [4, 10] × [2, 6] (centres on its border are inside).
    let w = ClipWindow::try_new(Vec2::new(4.0, 2.0), Vec2::new(10.0, 6.0)).expect("valid");
    let grid = canvas::ascii_grid(15, 9, |p| {
        let code = outcode(p.centre(), w);
        char::from_digit(u32::from(code.0), 16).unwrap_or('?')
    });
    // ascii_grid's first line is its ink legend; this grid has its own.
    let body: Vec<&str> = grid.lines().skip(1).collect();
    let grid = format!(
        "outcode in hex: 1 LEFT, 2 RIGHT, 4 BOTTOM, 8 TOP\n{}",
        body.join("\n")
    );
    insta::assert_snapshot!(grid);
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn outcode_bits_are_the_four_half_planes(
        p in testkit::strategies::point(30.0),
        window in common::window(),
    ) {
        let (min, max) = (window.min(), window.max());
        let expected = [
            (p.x < min.x, Outcode::LEFT),
            (p.x > max.x, Outcode::RIGHT),
            (p.y < min.y, Outcode::BOTTOM),
            (p.y > max.y, Outcode::TOP),
        ]
        .into_iter()
        .filter(|(beyond, _)| *beyond)
        .fold(Outcode::INSIDE, |code, (_, bit)| code | bit);
        prop_assert_eq!(outcode(p, window), expected);
    }
}
