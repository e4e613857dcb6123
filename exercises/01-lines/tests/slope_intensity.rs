//! Task 5d: intensity compensation for the slope of aliased lines.

use canvas::Pixel;
use lines::slope_intensity::slope_intensity;
use proptest::prelude::*;
use testkit::strategies::pixel_line;

#[testkit::test]
fn axis_parallel_lines_get_one_over_root_two_and_diagonals_full() {
    let o = Pixel::new(0, 0);
    let r = std::f32::consts::FRAC_1_SQRT_2;
    // Slope 1/2: length √5 per 2 steps → √5 / (2√2).
    let half = 5.0_f32.sqrt() / (2.0 * 2.0_f32.sqrt());
    for (to, expected, rule) in [
        (Pixel::new(10, 0), r, "a horizontal line gets 1/√2"),
        (Pixel::new(0, -7), r, "a vertical line gets 1/√2"),
        (Pixel::new(-5, 5), 1.0, "a diagonal gets full intensity"),
        (o, r, "a single pixel counts as axis-parallel: 1/√2"),
        (
            Pixel::new(4, 2),
            half,
            "slope 1/2: length/steps = √5/2, times 1/√2",
        ),
    ] {
        let got = slope_intensity(o, to);
        assert!(
            (got - expected).abs() < 1e-6,
            "from (0, 0) to ({}, {}): {rule} = {expected}, yours {got}",
            to.x,
            to.y
        );
    }
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn ink_per_unit_length_is_the_same_for_every_slope([from, to] in pixel_line(1000)) {
        prop_assume!(from != to);
        let w = f64::from(slope_intensity(from, to));
        let (dx, dy) = (f64::from(to.x - from.x), f64::from(to.y - from.y));
        let pixels_per_length = dx.abs().max(dy.abs()) / dx.hypot(dy);
        prop_assert!(
            (w * pixels_per_length - std::f64::consts::FRAC_1_SQRT_2).abs() < 1e-5,
            "{} -> {}: intensity {} times {} pixels per unit length is {}, \
             not 1/√2: the ink per unit length must not depend on the slope",
            from, to, w, pixels_per_length, w * pixels_per_length
        );
        prop_assert!(
            w <= 1.0 && w > 0.7,
            "{} -> {}: intensity {} lies outside (1/√2, 1], between an axis-parallel line's and a diagonal's",
            from, to, w
        );
    }

    #[testkit::test]
    fn reversed_line_gets_the_same_intensity([from, to] in pixel_line(1000)) {
        let intensity = slope_intensity(from, to);
        prop_assert!(intensity > 0.0 && intensity <= 1.0, "{from} -> {to}: {intensity} is not in (0, 1]");
        prop_assert_eq!(intensity, slope_intensity(to, from));
    }
}
