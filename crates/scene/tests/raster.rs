//! The library rasterizer: lines as one-pixel-wide bands and
//! edge-function triangles, checked against pixels worked out by hand.

use canvas::{Canvas, Fragment, Pixel, Rgba, Vec2, Vertex};
use proptest::prelude::*;
use scene::raster::{depth_test, draw_line, fill_triangle};

fn v(x: f32, y: f32) -> Vertex {
    Vertex::new(Vec2::new(x, y), 0.5, Rgba::WHITE)
}

fn lit(canvas: &Canvas) -> Vec<Pixel> {
    canvas.pixels_not(Rgba::BLACK)
}

fn pixels(list: &[(i32, i32)]) -> Vec<Pixel> {
    list.iter().map(|&(x, y)| Pixel::new(x, y)).collect()
}

#[test]
fn horizontal_line_includes_both_endpoints_in_either_direction() {
    for (a, b) in [(v(1.0, 2.0), v(5.0, 2.0)), (v(5.0, 2.0), v(1.0, 2.0))] {
        let mut canvas = Canvas::new(8, 4);
        draw_line(&mut canvas, a, b);
        let expected = pixels(&[(1, 2), (2, 2), (3, 2), (4, 2), (5, 2)]);
        testkit::assert_pixels_eq(&expected, &lit(&canvas), "horizontal line");
    }
}

#[test]
fn a_sloped_line_covers_the_centres_within_half_a_pixel_of_it() {
    // (0, 0) → (4, 2): a centre (x, y) is in when its distance from the
    // line, |x − 2y| / √5, is at most ½: so (1, 0), (1, 1), (3, 1) and
    // (3, 2) at 1/√5 ≈ 0.45 are in, (0, 1) and (4, 1) at 2/√5 are out. A
    // DDA would draw one pixel per column; a band is not a line algorithm.
    let mut canvas = Canvas::new(6, 4);
    draw_line(&mut canvas, v(0.0, 0.0), v(4.0, 2.0));
    let expected = pixels(&[(0, 0), (1, 0), (1, 1), (2, 1), (3, 1), (3, 2), (4, 2)]);
    testkit::assert_pixels_eq(&expected, &lit(&canvas), "sloped line");
}

#[test]
fn a_diagonal_is_one_pixel_thick() {
    // (k + 1, k) lies 1/√2 from the diagonal: outside the band.
    let mut canvas = Canvas::new(6, 6);
    draw_line(&mut canvas, v(0.0, 0.0), v(5.0, 5.0));
    let expected = pixels(&[(0, 0), (1, 1), (2, 2), (3, 3), (4, 4), (5, 5)]);
    testkit::assert_pixels_eq(&expected, &lit(&canvas), "diagonal");
}

#[test]
fn steep_line_covers_each_of_its_rows_once_or_twice() {
    let mut canvas = Canvas::new(4, 8);
    draw_line(&mut canvas, v(1.0, 0.0), v(2.0, 6.0));
    let drawn = lit(&canvas);
    for y in 0..=6 {
        let n = drawn.iter().filter(|p| p.y == y).count();
        assert!((1..=2).contains(&n), "row {y}: {n} pixels");
    }
    assert!(drawn.iter().all(|p| (0..=6).contains(&p.y)));
}

#[test]
fn zero_length_line_draws_the_rounded_point() {
    let mut canvas = Canvas::new(4, 4);
    draw_line(&mut canvas, v(2.5, 1.5), v(2.5, 1.5));
    testkit::assert_pixels_eq(&pixels(&[(3, 2)]), &lit(&canvas), "point");
}

#[test]
fn line_interpolates_colour_and_depth() {
    let mut canvas = Canvas::new(5, 1);
    let a = Vertex::new(Vec2::new(0.0, 0.0), 0.0, Rgba::BLACK);
    let b = Vertex::new(Vec2::new(4.0, 0.0), 0.8, Rgba::WHITE);
    draw_line(&mut canvas, a, b);
    // Linear from a to b: the ends keep their own colours and depths.
    let close = |p: (i32, i32), colour: Rgba, depth: f32| {
        let p = Pixel::new(p.0, p.1);
        canvas
            .get(p)
            .is_some_and(|c| c.approx_eq(colour, 1.0 / 255.0))
            && canvas.depth(p).is_some_and(|d| (d - depth).abs() < 1e-5)
    };
    assert!(
        close((0, 0), Rgba::BLACK, 0.0),
        "{:?}",
        canvas.get(Pixel::new(0, 0))
    );
    assert!(
        close((4, 0), Rgba::WHITE, 0.8),
        "{:?}",
        canvas.get(Pixel::new(4, 0))
    );
    assert!(
        close((2, 0), Rgba::grey(0.5), 0.4),
        "{:?}",
        canvas.get(Pixel::new(2, 0))
    );
}

#[test]
fn very_long_line_draws_its_visible_part_quickly() {
    // 2·10⁷ steps long, but only the 16 on the canvas are visited.
    let mut canvas = Canvas::new(16, 8);
    draw_line(&mut canvas, v(-1e7, 3.0), v(1e7, 3.0));
    let row: Vec<Pixel> = (0..16).map(|x| Pixel::new(x, 3)).collect();
    testkit::assert_pixels_eq(&row, &lit(&canvas), "long line");
    let mut canvas = Canvas::new(8, 16);
    draw_line(&mut canvas, v(2.0, 1e7), v(2.0, -1e7));
    let column: Vec<Pixel> = (0..16).map(|y| Pixel::new(2, y)).collect();
    testkit::assert_pixels_eq(&column, &lit(&canvas), "long column");
}

#[test]
fn lines_beyond_the_coordinate_limit_or_not_finite_draw_nothing() {
    let mut canvas = Canvas::new(8, 8);
    draw_line(&mut canvas, v(1.0, 1.0), v(1e30, 1.0));
    draw_line(&mut canvas, v(1.0, 1.0), v(f32::NAN, 1.0));
    draw_line(&mut canvas, v(f32::NEG_INFINITY, 1.0), v(1.0, 1.0));
    fill_triangle(&mut canvas, [v(0.0, 0.0), v(1e30, 0.0), v(0.0, 5.0)]);
    fill_triangle(&mut canvas, [v(0.0, 0.0), v(5.0, 0.0), v(f32::NAN, 5.0)]);
    assert!(lit(&canvas).is_empty());
}

/// The right triangle (0, 0), (4, 0), (0, 4) covers the centres with
/// x, y ≥ 0 and x + y ≤ 4 (edges included): 5 + 4 + 3 + 2 + 1 = 15 pixels.
#[test]
fn right_triangle_covers_its_closed_area_in_both_windings() {
    let expected: Vec<Pixel> = (0..=4)
        .flat_map(|y| (0..=4 - y).map(move |x| Pixel::new(x, y)))
        .collect();
    assert_eq!(expected.len(), 15);
    let (a, b, c) = (v(0.0, 0.0), v(4.0, 0.0), v(0.0, 4.0));
    for triangle in [[a, b, c], [a, c, b], [c, b, a]] {
        let mut canvas = Canvas::new(6, 6);
        fill_triangle(&mut canvas, triangle);
        testkit::assert_pixels_eq(&expected, &lit(&canvas), "right triangle");
    }
}

#[test]
fn degenerate_triangle_draws_nothing() {
    let mut canvas = Canvas::new(6, 6);
    fill_triangle(&mut canvas, [v(0.0, 0.0), v(2.0, 2.0), v(4.0, 4.0)]);
    fill_triangle(&mut canvas, [v(3.0, 3.0); 3]);
    assert!(lit(&canvas).is_empty());
}

#[test]
fn triangle_corners_get_their_own_colours() {
    let mut canvas = Canvas::new(5, 5);
    fill_triangle(
        &mut canvas,
        [
            Vertex::new(Vec2::new(0.0, 0.0), 0.0, Rgba::RED),
            Vertex::new(Vec2::new(4.0, 0.0), 0.5, Rgba::GREEN),
            Vertex::new(Vec2::new(0.0, 4.0), 1.0, Rgba::BLUE),
        ],
    );
    assert_eq!(canvas.get(Pixel::new(0, 0)), Some(Rgba::RED));
    assert_eq!(canvas.get(Pixel::new(4, 0)), Some(Rgba::GREEN));
    // Depth 1 is not less than the cleared depth 1: the corner fails the test.
    assert_eq!(canvas.get(Pixel::new(0, 4)), Some(Rgba::BLACK));
    // (2, 0) is halfway along the red-green edge.
    assert_eq!(canvas.depth(Pixel::new(2, 0)), Some(0.25));
}

#[test]
fn huge_triangle_fills_the_whole_canvas() {
    let mut canvas = Canvas::new(7, 5);
    fill_triangle(&mut canvas, [v(-1e6, -1e6), v(1e6, -1e6), v(0.0, 1e6)]);
    assert_eq!(lit(&canvas).len(), 35);
}

#[test]
fn depth_test_passes_only_nearer_fragments() {
    let mut canvas = Canvas::new(1, 1);
    let p = Pixel::new(0, 0);
    let fragment = |depth, colour| Fragment {
        pixel: p,
        depth,
        colour,
    };
    depth_test(&mut canvas, fragment(0.5, Rgba::RED));
    depth_test(&mut canvas, fragment(0.5, Rgba::GREEN));
    depth_test(&mut canvas, fragment(0.7, Rgba::BLUE));
    depth_test(&mut canvas, fragment(f32::NAN, Rgba::WHITE));
    assert_eq!(canvas.get(p), Some(Rgba::RED));
    depth_test(&mut canvas, fragment(-3.0, Rgba::GREEN));
    assert_eq!(
        (canvas.get(p), canvas.depth(p)),
        (Some(Rgba::GREEN), Some(-3.0))
    );
}

/// Brute-force oracle: whether the point lies in the closed triangle, by
/// the signs of three cross products (exact for the small integer
/// coordinates used below).
fn inside(p: Vec2, [a, b, c]: [Vec2; 3]) -> bool {
    let cross = |o: Vec2, d: Vec2, q: Vec2| (d - o).perp_dot(q - o);
    let s = [cross(a, b, p), cross(b, c, p), cross(c, a, p)];
    s.iter().all(|&x| x >= 0.0) || s.iter().all(|&x| x <= 0.0)
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[test]
    fn triangle_fill_matches_the_brute_force_oracle(
        corners in prop::array::uniform3((-4i32..20, -4i32..20)),
    ) {
        let points = corners.map(|(x, y)| Vec2::new(x as f32, y as f32));
        let mut canvas = Canvas::new(16, 16);
        fill_triangle(&mut canvas, points.map(|p| Vertex::new(p, 0.0, Rgba::WHITE)));
        let degenerate = (points[1] - points[0]).perp_dot(points[2] - points[0]) == 0.0;
        let expected: Vec<Pixel> = if degenerate { Vec::new() } else {
            canvas.enumerate().map(|(p, _)| p).filter(|p| inside(p.centre(), points)).collect()
        };
        testkit::assert_pixels_eq(&expected, &lit(&canvas), "triangle");
    }

    #[test]
    fn line_is_the_band_around_it_connected_and_with_both_ends(
        a in testkit::strategies::pixel(12), b in testkit::strategies::pixel(12),
    ) {
        let mut canvas = Canvas::new(32, 32);
        let shift = |p: Pixel| Vec2::new((p.x + 16) as f32, (p.y + 16) as f32);
        draw_line(&mut canvas, Vertex::new(shift(a), 0.0, Rgba::WHITE), Vertex::new(shift(b), 0.0, Rgba::WHITE));
        let drawn = lit(&canvas);
        let ends = [a, b].map(|p| Pixel::new(p.x + 16, p.y + 16));
        prop_assert!(ends.iter().all(|e| drawn.contains(e)));
        let steps = (a.x - b.x).abs().max((a.y - b.y).abs());
        // Exactly the centres in the band: within ½ of the segment across
        // it, and at most ½ beyond its ends along it.
        let (pa, pb) = (ends[0].centre(), ends[1].centre());
        let length = pa.distance(pb);
        let in_band = |p: Pixel| {
            let q = p.centre() - pa;
            if length == 0.0 {
                return q == Vec2::ZERO;
            }
            let d = (pb - pa) / length;
            d.perp_dot(q).abs() <= 0.5 && (-0.5..=length + 0.5).contains(&q.dot(d))
        };
        let expected: Vec<Pixel> = canvas.enumerate().map(|(p, _)| p).filter(|&p| in_band(p)).collect();
        testkit::assert_pixels_eq(&expected, &drawn, &format!("the band of {pa} → {pb}"));
        // At least one pixel per step, at most two.
        prop_assert!(drawn.len() as i32 > steps && drawn.len() as i32 <= 2 * (steps + 1), "{} pixels for {} steps", drawn.len(), steps);
        prop_assert!(drawn.iter().all(|p| drawn.iter().any(|q| q != p && q.touches(*p)) || steps == 0));
    }
}
