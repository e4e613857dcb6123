//! Task 5: triangles by edge functions, top-left rule, barycentric weights.

mod common;

use canvas::{Canvas, Fragment, MAX_COORD, Pixel, Rgba, Vec2, Vertex, Viewport};
use common::{canvas_with, collect_fragments, counts, grid_pixels, triangle_pixels};
use fill::edge_function::{EdgeWeights, SUBPIXEL_BITS, fill_triangle, snap};
use proptest::prelude::*;
use testkit::assert_pixels_eq;
use testkit::strategies::{half_pixel_point, hostile_point, point, vertex};

/// A viewport much larger than every triangle of these tests.
const WIDE: Viewport = Viewport::new(-40, -40, 40, 40);

/// Weights must sum to 1 and reproduce the vertices to this tolerance
/// (f32 arithmetic on values of order 1).
const WEIGHT_TOLERANCE: f32 = 1e-4;

fn at(x: f32, y: f32) -> Vertex {
    Vertex::new(Vec2::new(x, y), 0.5, Rgba::WHITE)
}

/// The edge weights of the sheet's integer edge functions at `pixel`'s
/// centre: vertex `k`'s is the edge function of the edge opposite it, on
/// the snapped vertices, signed to be `≥ 0` inside. `None` where a vertex
/// does not snap.
fn snapped_weights(vertices: [Vertex; 3], pixel: Pixel) -> Option<EdgeWeights> {
    let mut p = [[0_i64; 2]; 3];
    for (k, v) in vertices.iter().enumerate() {
        p[k] = [snap(v.position.x)?, snap(v.position.y)?];
    }
    let orient = |a: [i64; 2], b: [i64; 2], c: [i64; 2]| {
        i128::from(b[0] - a[0]) * i128::from(c[1] - a[1])
            - i128::from(b[1] - a[1]) * i128::from(c[0] - a[0])
    };
    let one = 1_i64 << SUBPIXEL_BITS;
    let centre = [i64::from(pixel.x) * one, i64::from(pixel.y) * one];
    let sign = orient(p[0], p[1], p[2]).signum();
    Some(std::array::from_fn(|k| {
        sign * orient(p[(k + 1) % 3], p[(k + 2) % 3], centre)
    }))
}

/// Your fragments, after checking the edge weights of every one against
/// the snapped edge functions (the instrument of this task: only a fill
/// that snaps and evaluates its edge functions in integers reports them).
fn fragments(vertices: [Vertex; 3], viewport: Viewport) -> Vec<Fragment> {
    let mut wrong = None;
    let got = collect_fragments(|plot| {
        fill_triangle(vertices, viewport, |f, weights| {
            let expected = snapped_weights(vertices, f.pixel);
            if wrong.is_none() && Some(weights) != expected {
                wrong = Some((f.pixel, weights, expected));
            }
            plot(f);
        });
    });
    if let Some((pixel, yours, expected)) = wrong {
        panic!(
            "fill_triangle({:?}, {viewport:?}) plots {pixel} with edge weights {yours:?}; \
             the edge functions of the snapped vertices give {expected:?} there \
             (exact integers in 1/256-pixel units, weights[k] for vertex k as given: \
             see the sheet, task 5)",
            positions(vertices)
        );
    }
    got
}

fn pixels(vertices: [Vertex; 3], viewport: Viewport) -> Vec<Pixel> {
    fragments(vertices, viewport)
        .iter()
        .map(|f| f.pixel)
        .collect()
}

fn positions(v: [Vertex; 3]) -> [Vec2; 3] {
    v.map(|v| v.position)
}

#[testkit::test]
fn right_triangle_keeps_its_left_edge_and_drops_the_others() {
    // (0, 0), (0, 4), (4, 0): centres on the left edge x = 0 are in, those
    // on the bottom edge y = 0 and on the hypotenuse x + y = 4 are out.
    //
    //   4 .....        the hypotenuse goes down-right: a right edge
    //   3 #....
    //   2 ##...
    //   1 ###..
    //   0 .....        the bottom edge drops out
    //     01234
    let expected = grid_pixels(
        Pixel::new(0, 0),
        &[".....", "#....", "##...", "###..", "....."],
    );
    for tri in [
        [at(0.0, 0.0), at(0.0, 4.0), at(4.0, 0.0)],
        [at(0.0, 0.0), at(4.0, 0.0), at(0.0, 4.0)],
    ] {
        assert_pixels_eq(
            &expected,
            &pixels(tri, WIDE),
            &format!("{:?}", positions(tri)),
        );
    }
}

#[testkit::test]
fn top_edge_is_kept_and_bottom_edge_dropped() {
    //   2 #####.       (0, 2)–(5, 2) is a top edge: kept;
    //   1 .###..       the apex (2.5, −0.5) is below
    //   0 ..#...
    let tri = [at(0.0, 2.0), at(5.0, 2.0), at(2.5, -0.5)];
    let expected = grid_pixels(Pixel::new(0, 0), &["#####.", ".###..", "..#..."]);
    assert_pixels_eq(&expected, &pixels(tri, WIDE), "downward triangle");
    let flipped = [at(0.0, -2.0), at(5.0, -2.0), at(2.5, 0.5)];
    let expected = grid_pixels(Pixel::new(0, -2), &["..#...", ".###..", "......"]);
    assert_pixels_eq(&expected, &pixels(flipped, WIDE), "upward triangle");
}

#[testkit::test]
fn triangles_of_several_shapes() {
    let mut all = Vec::new();
    for tri in [
        [at(0.5, 0.5), at(6.5, 1.5), at(2.5, 7.5)],
        [at(8.0, 0.0), at(15.0, 0.0), at(15.0, 7.0)],
        [at(9.3, 7.8), at(8.2, 3.1), at(13.7, 7.2)],
        [at(0.0, 9.0), at(15.0, 9.5), at(0.0, 10.0)],
    ] {
        all.extend(pixels(tri, Viewport::new(0, 0, 15, 10)));
    }
    testkit::assert_raster_snapshot!("triangles_of_several_shapes", canvas_with(16, 11, &all));
}

#[testkit::test]
fn triangulated_grid_covers_every_pixel_once() {
    // A 6 × 6 grid of cells over [0, 24] × [0, 24], interior vertices
    // jittered, each cell split along an alternating diagonal; windings
    // alternate too. Left edge x = 0 and top edge y = 24 are kept, right
    // x = 24 and bottom y = 0 dropped: exactly x = 0..=23, y = 1..=24.
    const N: usize = 6;
    const CELL: f32 = 4.0;
    let mut grid = [[Vec2::ZERO; N + 1]; N + 1];
    for (i, column) in grid.iter_mut().enumerate() {
        for (j, v) in column.iter_mut().enumerate() {
            let inner = i > 0 && i < N && j > 0 && j < N;
            let jitter = if inner {
                Vec2::new(
                    ((i * 7 + j * 3) % 5) as f32 * 0.37 - 0.8,
                    ((i * 2 + j * 5) % 7) as f32 * 0.29 - 0.9,
                )
            } else {
                Vec2::ZERO
            };
            *v = Vec2::new(i as f32 * CELL, j as f32 * CELL) + jitter;
        }
    }
    let mut covered = Vec::new();
    for i in 0..N {
        for j in 0..N {
            let [a, b, c, d] = [
                grid[i][j],
                grid[i + 1][j],
                grid[i + 1][j + 1],
                grid[i][j + 1],
            ];
            let tris = if (i + j) % 2 == 0 {
                [[a, b, c], [a, c, d]]
            } else {
                [[a, b, d], [d, c, b]]
            };
            for tri in tris {
                let v = tri.map(|p| Vertex::new(p, 0.5, Rgba::WHITE));
                covered.extend(pixels(v, WIDE));
            }
        }
    }
    let expected: Vec<Pixel> = (1..=24)
        .flat_map(|y| (0..24).map(move |x| Pixel::new(x, y)))
        .collect();
    assert_pixels_eq(&expected, &covered, "the triangulated grid");
    let twice: Vec<_> = counts(&covered)
        .into_iter()
        .filter(|&(_, n)| n > 1)
        .collect();
    assert!(twice.is_empty(), "pixels covered more than once: {twice:?}");
}

/// A filled star of 24 triangles around a white centre, colours and
/// depths interpolated (the sheet's fill figure, as triangles).
fn star() -> Canvas {
    let mut canvas = Canvas::new(129, 129);
    let viewport = canvas.viewport();
    let centre = Vertex::new(Vec2::new(64.0, 64.0), 0.0, Rgba::WHITE);
    let tau = std::f32::consts::TAU;
    let tip = |k: usize| {
        let angle = k as f32 * tau / 24.0;
        // Long spikes alternate with short notches.
        let radius = if k.is_multiple_of(2) { 60.0 } else { 24.5 };
        let hue = k as f32 / 24.0;
        let colour = Rgba::rgb(
            0.5 + 0.5 * (tau * hue).cos(),
            0.5 + 0.5 * (tau * (hue - 1.0 / 3.0)).cos(),
            0.5 + 0.5 * (tau * (hue - 2.0 / 3.0)).cos(),
        );
        Vertex::new(
            centre.position + radius * Vec2::new(angle.cos(), angle.sin()),
            1.0,
            colour,
        )
    };
    for k in 0..24 {
        fill_triangle([centre, tip(k), tip(k + 1)], viewport, |f, _| {
            canvas.plot(f)
        });
    }
    canvas
}

#[testkit::test]
fn star_of_interpolated_triangles_matches_the_reference_image() {
    let reference = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/images/edge_function_star.png"
    );
    testkit::image::assert_image_matches(
        "edge_function_star",
        &star(),
        reference,
        testkit::image::Tolerance::EXACT,
    );
}

#[testkit::test]
fn degenerate_and_hostile_triangles_draw_nothing() {
    let cases = [
        [at(0.0, 0.0), at(2.0, 2.0), at(5.0, 5.0)],
        [at(1.0, 1.0), at(1.0, 1.0), at(1.0, 1.0)],
        [at(1.0, 1.0), at(1.0, 1.0), at(6.0, 3.0)],
        [at(f32::NAN, 0.0), at(5.0, 0.0), at(0.0, 5.0)],
        [at(0.0, 0.0), at(f32::INFINITY, 0.0), at(0.0, 5.0)],
        [at(0.0, 0.0), at(1e30, 0.0), at(0.0, 1e30)],
        [at(-1e30, -1e30), at(1e30, -1e30), at(0.0, 1e30)],
    ];
    for tri in cases {
        assert_eq!(pixels(tri, WIDE), [], "{:?}", positions(tri));
    }
    // Huge but legal: clipped to the viewport, every pixel of it once.
    let big = [at(-1.6e7, -1.6e7), at(1.6e7, -1.6e7), at(0.0, 1.6e7)];
    let small = Viewport::new(-3, -3, 3, 3);
    let yours = pixels(big, small);
    assert_eq!(yours.len(), 49, "a huge triangle clipped to {small:?}");
    assert_eq!(
        pixels(
            [at(0.0, 0.0), at(5.0, 0.0), at(0.0, 5.0)],
            Viewport::new(1, 1, 0, 0)
        ),
        []
    );
}

fn any_triangle() -> impl Strategy<Value = [Vertex; 3]> {
    prop_oneof![
        prop::array::uniform3(vertex(30.0)),
        // Vertices on the half-pixel lattice put centres on edges and
        // vertices: the fill rule's cases.
        prop::array::uniform3((half_pixel_point(12), vertex(1.0)))
            .prop_map(|v| v.map(|(p, v)| Vertex::new(p, v.depth, v.colour))),
    ]
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn covered_pixels_match_the_definition(tri in any_triangle()) {
        let yours = pixels(tri, WIDE);
        let expected = triangle_pixels(positions(tri), WIDE);
        assert_pixels_eq(&expected, &yours, &format!("{:?}", positions(tri)));
        prop_assert!(counts(&yours).values().all(|&n| n == 1), "a pixel plotted twice");
    }

    #[testkit::test]
    fn clipping_keeps_exactly_the_pixels_in_the_viewport(
        tri in any_triangle(), x in -20..10, y in -20..10, w in 0..15, h in 0..15,
    ) {
        let viewport = Viewport::new(x, y, x + w, y + h);
        let expected = triangle_pixels(positions(tri), viewport);
        assert_pixels_eq(&expected, &pixels(tri, viewport), &format!("{:?} in {viewport:?}", positions(tri)));
    }

    #[testkit::test]
    fn both_windings_fill_the_same_pixels(tri in any_triangle()) {
        let [a, b, c] = tri;
        prop_assert_eq!(pixels(tri, WIDE).is_empty(), triangle_pixels(positions(tri), WIDE).is_empty(), "fills pixels exactly when the definition does");
        assert_pixels_eq(&pixels([a, b, c], WIDE), &pixels([a, c, b], WIDE), "reversed winding");
        assert_pixels_eq(&pixels([a, b, c], WIDE), &pixels([b, c, a], WIDE), "rotated vertices");
    }

    #[testkit::test]
    fn two_triangles_sharing_an_edge_cover_each_pixel_once(
        a in half_pixel_point(12), b in half_pixel_point(12),
        c in point(12.0), d in point(12.0),
    ) {
        // c and d on opposite sides of a–b (else the pair overlaps), as
        // the fill sees them: decided exactly on the positions snapped to
        // its 1/256-pixel grid. A d on c's side is mirrored through a.
        let snapped = |p: Vec2| [common::snap(p.x).unwrap(), common::snap(p.y).unwrap()];
        let side = |p: Vec2| {
            let (a, b, p) = (snapped(a), snapped(b), snapped(p));
            (i128::from(b[0] - a[0]) * i128::from(p[1] - a[1])
                - i128::from(b[1] - a[1]) * i128::from(p[0] - a[0]))
            .signum()
        };
        let d = if side(c) == side(d) { 2.0 * a - d } else { d };
        prop_assume!(side(c) * side(d) < 0);
        let first = pixels([at(a.x, a.y), at(b.x, b.y), at(c.x, c.y)], WIDE);
        let second = pixels([at(b.x, b.y), at(a.x, a.y), at(d.x, d.y)], WIDE);
        let expected = triangle_pixels([a, b, c], WIDE).len() + triangle_pixels([b, a, d], WIDE).len();
        prop_assert_eq!(first.len() + second.len(), expected, "the two triangles fill as many pixels as they cover");
        let mut both = first.clone();
        both.extend(&second);
        prop_assert!(counts(&both).values().all(|&n| n == 1), "a pixel on the shared edge twice");
    }

    #[testkit::test]
    fn weights_sum_to_one_and_reproduce_the_vertices(tri in any_triangle()) {
        // One-hot colours: red, green and blue are the three weights.
        let hot = [Rgba::new(1.0, 0.0, 0.0, 0.0), Rgba::new(0.0, 1.0, 0.0, 0.0), Rgba::new(0.0, 0.0, 1.0, 0.0)];
        let v: [Vertex; 3] = std::array::from_fn(|k| Vertex::new(tri[k].position, tri[k].depth, hot[k]));
        let got = fragments(v, WIDE);
        prop_assert_eq!(got.is_empty(), triangle_pixels(positions(v), WIDE).is_empty(), "fills pixels exactly when the definition does");
        for f in got {
            let w = [f.colour.r, f.colour.g, f.colour.b];
            prop_assert!((w.iter().sum::<f32>() - 1.0).abs() < WEIGHT_TOLERANCE, "weights {w:?} at {}", f.pixel);
            prop_assert!(w.iter().all(|&l| (-WEIGHT_TOLERANCE..=1.0 + WEIGHT_TOLERANCE).contains(&l)), "weights {w:?} at {}", f.pixel);
            for k in 0..3 {
                if f.pixel.centre() == v[k].position {
                    prop_assert!((w[k] - 1.0).abs() < WEIGHT_TOLERANCE, "vertex {k} at {} has weights {w:?}", f.pixel);
                }
            }
        }
    }

    #[testkit::test]
    fn depth_lies_between_the_vertex_depths(tri in any_triangle()) {
        let lo = tri.iter().map(|v| v.depth).fold(f32::INFINITY, f32::min);
        let hi = tri.iter().map(|v| v.depth).fold(f32::NEG_INFINITY, f32::max);
        let got = fragments(tri, WIDE);
        prop_assert_eq!(got.is_empty(), triangle_pixels(positions(tri), WIDE).is_empty(), "fills pixels exactly when the definition does");
        for f in got {
            prop_assert!(f.depth >= lo - WEIGHT_TOLERANCE && f.depth <= hi + WEIGHT_TOLERANCE,
                "depth {} at {} outside [{lo}, {hi}]", f.depth, f.pixel);
        }
    }

    #[testkit::test]
    fn hostile_vertices_never_panic(a in hostile_point(), b in point(20.0), c in hostile_point()) {
        let small = Viewport::new(-5, -5, 5, 5);
        let yours = pixels([at(a.x, a.y), at(b.x, b.y), at(c.x, c.y)], small);
        prop_assert!(yours.iter().all(|&p| small.contains(p)));
        prop_assert!(counts(&yours).values().all(|&n| n == 1));
        // Refusing one is no reason to refuse the next.
        let ordinary = [at(-3.5, -3.5), at(3.5, -3.5), at(0.0, 3.5)];
        assert_pixels_eq(&triangle_pixels(positions(ordinary), small), &pixels(ordinary, small), "an ordinary triangle after a hostile one");
    }
}

#[testkit::test]
fn work_is_the_bounding_box_not_the_viewport() {
    // A viewport of 2²⁵ × 2²⁵ pixels: a fill that tests every pixel of the
    // viewport instead of the triangle's bounding box never finishes.
    let huge = Viewport::new(-MAX_COORD, -MAX_COORD, MAX_COORD, MAX_COORD);
    let tri = [at(0.0, 0.0), at(6.0, 1.0), at(2.0, 5.0)];
    let around = Viewport::new(-2, -2, 8, 8);
    assert_pixels_eq(
        &triangle_pixels(positions(tri), around),
        &pixels(tri, huge),
        "a small triangle in a huge viewport",
    );
}
