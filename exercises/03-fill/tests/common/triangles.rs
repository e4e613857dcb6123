//! The coverage cases every whole-triangle rasterizer of this topic meets
//! as the definition does (`blocked`, `vectorised`): each takes the
//! rasterizer under test as `pixels(positions, viewport)`, the pixels it
//! covers in the order it plots them.

use canvas::{Pixel, Vec2, Viewport};
use proptest::prelude::*;
use testkit::assert_pixels_eq;
use testkit::strategies::{half_pixel_point, hostile_point, point};

use super::{counts, triangle_pixels};

/// A viewport large enough for every generated triangle.
pub const WIDE: Viewport = Viewport::new(-50, -50, 50, 50);

/// A rasterizer under test: the pixels it covers, in plotting order.
pub type Pixels<'a> = &'a dyn Fn([Vec2; 3], Viewport) -> Vec<Pixel>;

/// The right triangle with legs of 20 pixels.
#[track_caller]
pub fn right_triangle(pixels: Pixels) {
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

/// A thin triangle near `MAX_COORD`, where edge functions reach 2⁶⁶.
#[track_caller]
pub fn far_from_the_origin(pixels: Pixels) {
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

/// Collinear, NaN, infinite and overflowing vertices draw nothing; a huge
/// triangle is clipped to the viewport.
#[track_caller]
pub fn degenerate_and_hostile(pixels: Pixels) {
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

/// Triangles large and small, and with vertices on half pixels.
pub fn any_triangle() -> impl Strategy<Value = [Vec2; 3]> {
    prop_oneof![
        prop::array::uniform3(point(45.0)),
        prop::array::uniform3(point(6.0)),
        prop::array::uniform3(half_pixel_point(30)),
    ]
}

/// Property: `tri` covers the pixels of the definition, each once.
#[track_caller]
pub fn covers_as_defined(pixels: Pixels, tri: [Vec2; 3]) -> Result<(), TestCaseError> {
    let yours = pixels(tri, WIDE);
    assert_pixels_eq(&triangle_pixels(tri, WIDE), &yours, &format!("{tri:?}"));
    prop_assert!(
        counts(&yours).values().all(|&n| n == 1),
        "a pixel plotted twice"
    );
    Ok(())
}

/// Property: in `viewport`, exactly the definition's pixels inside it.
#[track_caller]
pub fn clipped_as_defined(pixels: Pixels, tri: [Vec2; 3], viewport: Viewport) {
    assert_pixels_eq(
        &triangle_pixels(tri, viewport),
        &pixels(tri, viewport),
        &format!("{tri:?} in {viewport:?}"),
    );
}

/// Property: hostile vertices never panic, plot nothing outside the
/// viewport or twice, and do not stop the next, ordinary triangle.
#[track_caller]
pub fn survives_hostile_vertices(
    pixels: Pixels,
    [a, b, c]: [Vec2; 3],
) -> Result<(), TestCaseError> {
    let small = Viewport::new(-5, -5, 5, 5);
    let yours = pixels([a, b, c], small);
    prop_assert!(yours.iter().all(|&p| small.contains(p)));
    prop_assert!(counts(&yours).values().all(|&n| n == 1));
    let ordinary = [
        Vec2::new(-3.5, -3.5),
        Vec2::new(3.5, -3.5),
        Vec2::new(0.0, 3.5),
    ];
    assert_pixels_eq(
        &triangle_pixels(ordinary, small),
        &pixels(ordinary, small),
        "an ordinary triangle after a hostile one",
    );
    Ok(())
}

/// The vertices [`survives_hostile_vertices`] takes.
pub fn hostile_triangle() -> impl Strategy<Value = [Vec2; 3]> {
    (hostile_point(), point(20.0), hostile_point()).prop_map(|(a, b, c)| [a, b, c])
}
