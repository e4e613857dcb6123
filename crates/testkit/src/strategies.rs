//! proptest strategies for the course's inputs, hostile ones included.

use canvas::{Pixel, Rgba, Vec2, Vertex};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};

/// The seed of every property test's random cases (see [`proptest_config`]);
/// the grader hands the same to a test whose configuration forgot it.
pub use wire::SEED;

/// The configuration every property test in the course uses: 256 cases,
/// no failure files written next to the tests (a student's copy of the
/// tests must stay untouched; the grader checks it), and the cases drawn
/// from one fixed [`SEED`], so that the same code meets the same cases in
/// every run and a grade can be repeated. `PROPTEST_RNG_SEED=N` (or
/// `PROPTEST_CASES=N`) in the environment draws other cases.
#[must_use]
pub fn proptest_config() -> Config {
    Config {
        cases: 256,
        failure_persistence: None,
        rng_seed: RngSeed::Fixed(SEED),
        ..Config::default()
    }
}

/// Pixels with both coordinates in `-extent..=extent`.
pub fn pixel(extent: i32) -> impl Strategy<Value = Pixel> {
    (-extent..=extent, -extent..=extent).prop_map(|(x, y)| Pixel::new(x, y))
}

/// Pixels inside a `width × height` canvas.
pub fn pixel_on_canvas(width: u32, height: u32) -> impl Strategy<Value = Pixel> {
    (0..width as i32, 0..height as i32).prop_map(|(x, y)| Pixel::new(x, y))
}

/// The two endpoints of a line between pixels in `-extent..=extent`,
/// including zero-length lines and every octant.
pub fn pixel_line(extent: i32) -> impl Strategy<Value = [Pixel; 2]> {
    (pixel(extent), pixel(extent)).prop_map(|(a, b)| [a, b])
}

/// Continuous points with coordinates in `-extent..=extent`.
pub fn point(extent: f32) -> impl Strategy<Value = Vec2> {
    (-extent..=extent, -extent..=extent).prop_map(|(x, y)| Vec2::new(x, y))
}

/// Points on the half-pixel lattice (`k / 2`): they hit the ties of every
/// rounding rule, where off-by-one errors hide.
pub fn half_pixel_point(extent: i32) -> impl Strategy<Value = Vec2> {
    (-2 * extent..=2 * extent, -2 * extent..=2 * extent)
        .prop_map(|(x, y)| Vec2::new(x as f32 / 2.0, y as f32 / 2.0))
}

/// Opaque colours with channels in `[0, 1]`.
pub fn colour() -> impl Strategy<Value = Rgba> {
    (0.0f32..=1.0, 0.0f32..=1.0, 0.0f32..=1.0).prop_map(|(r, g, b)| Rgba::rgb(r, g, b))
}

/// Vertices with positions in `-extent..=extent`, depths in `[0, 1]` and
/// opaque colours.
pub fn vertex(extent: f32) -> impl Strategy<Value = Vertex> {
    (point(extent), 0.0f32..=1.0, colour()).prop_map(|(p, d, c)| Vertex::new(p, d, c))
}

/// Floats that break naive code: NaN, infinities, huge and tiny values,
/// negative zero and values just past [`canvas::MAX_COORD`].
pub fn hostile_f32() -> impl Strategy<Value = f32> {
    prop_oneof![
        Just(f32::NAN),
        Just(f32::INFINITY),
        Just(f32::NEG_INFINITY),
        Just(1e30),
        Just(-1e30),
        Just(f32::MAX),
        Just(f32::MIN),
        Just(f32::MIN_POSITIVE),
        Just(-0.0),
        Just(canvas::MAX_COORD as f32 * 2.0),
        -1e9f32..1e9,
    ]
}

/// Points with at least one hostile coordinate.
pub fn hostile_point() -> impl Strategy<Value = Vec2> {
    prop_oneof![
        (hostile_f32(), -100.0f32..100.0).prop_map(|(x, y)| Vec2::new(x, y)),
        (-100.0f32..100.0, hostile_f32()).prop_map(|(x, y)| Vec2::new(x, y)),
        (hostile_f32(), hostile_f32()).prop_map(|(x, y)| Vec2::new(x, y)),
    ]
}

/// Pixels anywhere in the `i32` range, biased to the extremes.
pub fn hostile_pixel() -> impl Strategy<Value = Pixel> {
    let coord = prop_oneof![
        Just(i32::MIN),
        Just(i32::MAX),
        Just(canvas::MAX_COORD),
        Just(-canvas::MAX_COORD - 1),
        any::<i32>(),
    ];
    (coord.clone(), coord).prop_map(|(x, y)| Pixel::new(x, y))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::test_runner::TestRunner;

    /// The cases one run of a property test meets.
    fn drawn() -> Vec<Vec2> {
        let cases = std::cell::RefCell::new(Vec::new());
        TestRunner::new(proptest::test_runner::contextualize_config(
            proptest_config(),
        ))
        .run(&point(100.0), |p| {
            cases.borrow_mut().push(p);
            Ok(())
        })
        .unwrap();
        cases.into_inner()
    }

    #[test]
    fn every_run_meets_the_same_cases() {
        if std::env::var_os("PROPTEST_RNG_SEED").is_some() {
            return;
        }
        let first = drawn();
        assert_eq!(first.len(), 256);
        assert_eq!(first, drawn(), "a second run drew other cases");
    }
}
