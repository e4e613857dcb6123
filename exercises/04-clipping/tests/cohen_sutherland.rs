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
    for ((x, y), expected) in [
        ((5.0, 5.0), Outcode::INSIDE),
        ((-1.0, 5.0), Outcode::LEFT),
        ((11.0, 5.0), Outcode::RIGHT),
        ((5.0, -1.0), Outcode::BOTTOM),
        ((5.0, 11.0), Outcode::TOP),
        ((-1.0, 11.0), Outcode::LEFT | Outcode::TOP),
        ((11.0, 11.0), Outcode::RIGHT | Outcode::TOP),
        ((-1.0, -1.0), Outcode::LEFT | Outcode::BOTTOM),
        ((11.0, -1.0), Outcode::RIGHT | Outcode::BOTTOM),
    ] {
        let yours = code(x, y);
        assert!(
            yours == expected,
            "outcode(({x}, {y}), [0, 10]²): expected {:04b}, yours {:04b} (8 TOP y > max.y, \
             4 BOTTOM y < min.y, 2 RIGHT x > max.x, 1 LEFT x < min.x)",
            expected.0,
            yours.0
        );
    }
    assert_eq!(
        Outcode::LEFT | Outcode::TOP,
        Outcode(0b1001),
        "LEFT | TOP is the bits 1 and 8 together, 1001"
    );
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
        let yours = outcode(Vec2::new(x, y), w);
        assert!(
            yours == Outcode::INSIDE,
            "outcode(({x}, {y}), [0, 10]²): the window is closed, a point on its border is \
             inside, 0000; yours {:04b}",
            yours.0
        );
    }
    let yours = outcode(Vec2::new(-1e-6, 10.0), w);
    assert!(
        yours == Outcode::LEFT,
        "outcode((−1e-6, 10), [0, 10]²): just left of the border (x < min.x) and on the top one, \
         0001 LEFT; yours {:04b}",
        yours.0
    );
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
        let yours = outcode(p, window);
        prop_assert!(yours == expected, "outcode({}, {:?}): expected {:04b}, yours {:04b} (8 TOP y > max.y, 4 BOTTOM y < min.y, 2 RIGHT x > max.x, 1 LEFT x < min.x)", p, window, expected.0, yours.0);
    }
}
