//! Task 4: Liang-Barsky line clipping in the segment's parameter.

mod common;

use clipping::liang_barsky::liang_barsky;

line_clipping_spec!(liang_barsky);

#[testkit::test]
fn endpoints_inside_are_kept_exactly() {
    // t_in = 0 and t_out = 1 must give the endpoints themselves, not
    // P₀ + 1 · Δ (which can round).
    let seg = s(0.1, 0.7, 30.3, 5.9);
    let got = clip(seg, ten())
        .expect("(0.1, 0.7) → (30.3, 5.9) starts inside [0, 10]²: a piece is left, yours None");
    assert_eq!(
        got.from, seg.from,
        "t_in stayed 0 (the start is inside): the piece starts at the endpoint itself"
    );
    let seg = s(30.3, 5.9, 0.1, 0.7);
    let got = clip(seg, ten())
        .expect("(30.3, 5.9) → (0.1, 0.7) ends inside [0, 10]²: a piece is left, yours None");
    assert_eq!(
        got.to, seg.to,
        "t_out stayed 1 (the end is inside): the piece ends at the endpoint itself, not at \
         P₀ + 1 · Δ"
    );
}
