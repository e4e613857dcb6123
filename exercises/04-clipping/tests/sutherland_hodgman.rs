//! Task 2: Sutherland-Hodgman, a polygon against one plane and against all
//! six planes of the clip volume.

mod common;

use canvas::{Rgba, Vec2, Vec4};
use clipping::sutherland_hodgman::{clip_against_plane, clip_polygon};
use clipping::{ClipError, ClipPlane, ClipVertex};
use common::{
    VOLUME_PLANES, assert_same_polygon, cv, excess, flat, is_on_edge, outline_distance,
    polygon_text, shoelace, vertex_text,
};
use proptest::prelude::*;

/// The plane `x ≤ w`.
const RIGHT: ClipPlane = VOLUME_PLANES[0];
/// Positions of order 1..10 in `f32`: rounding stays far below this.
const TOLERANCE: f32 = 1e-5;

/// `clip_polygon` against the six planes, for valid input.
#[track_caller]
fn clip(polygon: &[ClipVertex]) -> Vec<ClipVertex> {
    clip_polygon(polygon, &VOLUME_PLANES).unwrap_or_else(|e| {
        panic!(
            "clip_polygon(…, the six planes): every coordinate is finite and within \
             MAX_CLIP_COORD, so the answer is Ok; yours {e:?}\ninput:\n{}",
            polygon_text(polygon)
        )
    })
}

/// `clip_against_plane`, for valid input.
#[track_caller]
fn clip_one(polygon: &[ClipVertex], plane: ClipPlane) -> Vec<ClipVertex> {
    clip_against_plane(polygon, plane).unwrap_or_else(|e| {
        panic!(
            "clip_against_plane(…, {}): every coordinate is finite and within MAX_CLIP_COORD, \
             so the answer is Ok; yours {e:?}\ninput:\n{}",
            plane.vector,
            polygon_text(polygon)
        )
    })
}

/// Asserts that `got` is `expected` vertex for vertex, to [`TOLERANCE`]
/// in position and colour; names `what` and shows both polygons.
#[track_caller]
fn assert_close(got: &[ClipVertex], expected: &[ClipVertex], what: &str) {
    let both = || {
        format!(
            "expected:\n{}\nyours:\n{}",
            polygon_text(expected),
            polygon_text(got)
        )
    };
    assert!(
        got.len() == expected.len(),
        "{what}: yours has {} vertices, expected {}\n{}",
        got.len(),
        expected.len(),
        both()
    );
    for (i, (g, e)) in got.iter().zip(expected).enumerate() {
        assert!(
            g.position.distance(e.position) <= TOLERANCE && g.colour.approx_eq(e.colour, TOLERANCE),
            "{what}: vertex {i} differs by more than {TOLERANCE} in position or colour\n{}",
            both()
        );
    }
}

/// A polygon with a vertex well inside the volume keeps at least that
/// vertex, so its clipped polygon has three vertices or more.
fn keeps_what_is_inside(polygon: &[ClipVertex], got: &[ClipVertex]) -> Result<(), TestCaseError> {
    let inside = polygon.len() >= 3 && polygon.iter().any(|v| excess(v.position) < -1e-3);
    if inside && got.len() < 3 {
        return Err(TestCaseError::fail(format!(
            "a polygon with a vertex inside the volume keeps at least that vertex (3 or more \
             vertices), yours clipped it to {}\ninput:\n{}\nyours:\n{}",
            got.len(),
            polygon_text(polygon),
            polygon_text(got)
        )));
    }
    Ok(())
}

#[testkit::test]
fn triangle_across_the_right_plane_becomes_a_quadrilateral() {
    //  y                        clipped at x = w = 1; the closing edge
    //  3 C                      C → A comes first, then A → B, B → C:
    //  2 |  ╲ ●  I₂ (1, 2)
    //  1 |   ┃  ╲               output: A, I₁, I₂, C
    //  0 A───●───────B          I₁ = A + (1/3 − ε)(B − A)
    //    0   1       3          I₂ = B + (2/3 + ε)(C − B)
    let (a, b, c) = (
        flat(0.0, 0.0, Rgba::RED),
        flat(3.0, 0.0, Rgba::GREEN),
        flat(0.0, 3.0, Rgba::BLUE),
    );
    let eps = clipping::CLIP_NUDGE;
    let i1 = ClipVertex {
        position: Vec4::new(3.0 * (1.0 / 3.0 - eps), 0.0, 0.0, 1.0),
        colour: Rgba::RED.lerp(Rgba::GREEN, 1.0 / 3.0 - eps),
    };
    let i2 = ClipVertex {
        position: Vec4::new(
            3.0 - 3.0 * (2.0 / 3.0 + eps),
            3.0 * (2.0 / 3.0 + eps),
            0.0,
            1.0,
        ),
        colour: Rgba::GREEN.lerp(Rgba::BLUE, 2.0 / 3.0 + eps),
    };
    let got = clip_one(&[a, b, c], RIGHT);
    assert_close(
        &got,
        &[a, i1, i2, c],
        "clip_against_plane(A (0, 0), B (3, 0), C (0, 3); x ≤ w): from the closing edge C → A \
         on, inside E emits E, leaving emits I, entering emits I then E: A, I₁, I₂, C",
    );
    // The new vertices lie just inside, by the nudge.
    let (x1, x2) = (got[1].position.x, got[2].position.x);
    assert!(
        x1 < 1.0 && x2 < 1.0,
        "the crossings I₁, I₂ lie just inside x = w = 1, t moved by CLIP_NUDGE towards the inside \
         endpoint: yours at x = {x1} and x = {x2}"
    );
}

#[testkit::test]
fn the_closing_edge_is_clipped_too() {
    // Only the closing edge C → A leaves the volume; forgetting it loses
    // the two crossings on it.
    //
    //   A (0, 0) → B (0, 0.5) → C (3, 0.25) → back to A
    let polygon = [
        flat(0.0, 0.0, Rgba::WHITE),
        flat(0.0, 0.5, Rgba::WHITE),
        flat(3.0, 0.25, Rgba::WHITE),
    ];
    let got = clip_one(&polygon, RIGHT);
    let call = "clip_against_plane(A (0, 0), B (0, 0.5), C (3, 0.25); x ≤ w)";
    assert!(
        got.len() == 4,
        "{call}: A, B and the crossings on B → C and on the closing edge C → A are 4 vertices, \
         yours {}:\n{}",
        got.len(),
        polygon_text(&got)
    );
    // Both new vertices on x ≈ 1: one on B → C (y ≈ 5/12), one on C → A
    // (y ≈ 1/12).
    let ys: Vec<f32> = got
        .iter()
        .filter(|v| (v.position.x - 1.0).abs() < 1e-4)
        .map(|v| v.position.y)
        .collect();
    assert!(
        ys.len() == 2,
        "{call}: two new vertices on x = 1 (B → C and C → A cross it), yours has {}:\n{}",
        ys.len(),
        polygon_text(&got)
    );
    assert!(
        ys.iter().any(|y| (y - 5.0 / 12.0).abs() < 1e-4),
        "{call}: the crossing of B → C at y = 5/12 is missing; yours on x = 1 at y = {ys:?}"
    );
    assert!(
        ys.iter().any(|y| (y - 1.0 / 12.0).abs() < 1e-4),
        "{call}: the crossing of the closing edge C → A at y = 1/12 is missing (the walk starts \
         with the edge from the last vertex to the first); yours on x = 1 at y = {ys:?}"
    );
}

#[testkit::test]
fn crossing_at_a_vertex_on_the_plane_is_that_vertex() {
    //  y                        A lies on x = w = 1: the edge A → B
    //  1 C                      crosses at t = 0, and the nudged t is
    //    |  ╲                   kept in [0, 1], so the new vertex is A
    //  0 |   A───────B          itself, not a step beyond it
    //    0   1       3
    let (a, b, c) = (
        flat(1.0, 0.0, Rgba::RED),
        flat(3.0, 0.0, Rgba::GREEN),
        flat(0.0, 1.0, Rgba::BLUE),
    );
    let got = clip_one(&[a, b, c], RIGHT);
    let call = "clip_against_plane(A (1, 0), B (3, 0), C (0, 1); x ≤ w), A on the plane";
    assert!(
        got.len() == 4,
        "{call}: A (on the plane counts as inside), the crossing on A → B (A itself), the \
         crossing on B → C, and C are 4 vertices, yours {}:\n{}",
        got.len(),
        polygon_text(&got)
    );
    let rule = "the crossing at t = 0 is A itself, the nudged t kept in [0, 1]";
    for (i, vertex, name) in [(0, a, "A"), (1, a, "the crossing on A → B"), (3, c, "C")] {
        assert!(
            got[i] == vertex,
            "{call}: vertex {i} is {name}, {} ({rule}); yours {}",
            vertex_text(vertex),
            vertex_text(got[i])
        );
    }
}

#[testkit::test]
fn polygon_inside_comes_back_unchanged() {
    // A face of the cube lies on the far plane: on-plane vertices are inside.
    let face = [
        cv(-1.0, -1.0, 1.0, 1.0, Rgba::RED),
        cv(1.0, -1.0, 1.0, 1.0, Rgba::GREEN),
        cv(1.0, 1.0, 1.0, 1.0, Rgba::BLUE),
        cv(-1.0, 1.0, 1.0, 1.0, Rgba::WHITE),
    ];
    assert_same_polygon(
        &clip(&face),
        &face,
        "a face of the cube on the far plane z = w (on a plane counts as inside) comes back \
         unchanged, starting with the same vertex",
    );
    // Homogeneous: w = 4 makes the cube 4 times larger before the division.
    let pentagon: Vec<ClipVertex> = (0..5)
        .map(|k| {
            let a = k as f32 * std::f32::consts::TAU / 5.0;
            cv(
                3.0 * a.cos(),
                3.0 * a.sin(),
                0.5,
                4.0,
                Rgba::grey(k as f32 / 5.0),
            )
        })
        .collect();
    assert_same_polygon(
        &clip(&pentagon),
        &pentagon,
        "a pentagon inside −w ≤ x, y, z ≤ w with w = 4 (|x|, |y| ≤ 3) comes back unchanged",
    );
}

#[testkit::test]
fn polygon_outside_vanishes() {
    let beyond_right = [
        flat(1.5, 0.0, Rgba::WHITE),
        flat(4.0, -3.0, Rgba::WHITE),
        flat(4.0, 3.0, Rgba::WHITE),
    ];
    let got = clip(&beyond_right);
    assert!(
        got.is_empty(),
        "a triangle wholly beyond x = w vanishes, yours:\n{}",
        polygon_text(&got)
    );
    // Behind the eye (w < 0): outside although x/w, y/w, z/w look fine.
    let behind = [
        cv(-0.1, 0.0, -0.1, -1.0, Rgba::WHITE),
        cv(0.1, 0.0, -0.1, -1.0, Rgba::WHITE),
        cv(0.0, 0.1, -0.1, -1.0, Rgba::WHITE),
    ];
    let got = clip(&behind);
    assert!(
        got.is_empty(),
        "a triangle behind the eye (w = −1) is outside, although x/w, y/w, z/w lie in [−1, 1]; \
         yours:\n{}",
        polygon_text(&got)
    );
    // A large triangle passing a corner of the square: no vertex beyond a
    // common plane, yet nothing of it is inside.
    //
    //   ╲   ┌───┐
    //    ╲  │   │   edge x + y = −2.5 runs below the corner (−1, −1)
    //     ╲ └───┘
    let passing = [
        flat(-2.5, 0.0, Rgba::WHITE),
        flat(0.0, -2.5, Rgba::WHITE),
        flat(-9.0, -9.0, Rgba::WHITE),
    ];
    let got = clip(&passing);
    assert!(
        got.is_empty(),
        "(−2.5, 0), (0, −2.5), (−9, −9) passes below the corner (−1, −1): nothing of it is \
         inside, yours:\n{}",
        polygon_text(&got)
    );
    // Moved onto the square, the same triangle is kept in part.
    let crossing = passing.map(|v| flat(v.position.x + 2.0, v.position.y + 2.0, v.colour));
    let got = clip(&crossing);
    assert!(
        got.len() >= 3,
        "the same triangle moved by (2, 2) overlaps the square: 3 or more vertices are left, \
         yours {}:\n{}",
        got.len(),
        polygon_text(&got)
    );
}

#[testkit::test]
fn triangle_covering_the_square_is_cut_to_the_square() {
    //   ●               the triangle covers [−1, 1]² entirely: what is
    //   │ ╲             left is the square itself, corners included
    //   │┌──╲──┐        (corners come from the boundary edges that an
    //   ││   ╲ │        earlier pass created)
    //   │└─────╲
    //   ●────────●
    let polygon = [
        flat(-3.0, -3.0, Rgba::WHITE),
        flat(9.0, -3.0, Rgba::WHITE),
        flat(-3.0, 9.0, Rgba::WHITE),
    ];
    let got = clip(&polygon);
    let call = "clip((−3, −3), (9, −3), (−3, 9)), covering [−1, 1]²";
    assert!(
        got.len() == 4,
        "{call}: the square's four corners are left, yours {} vertices:\n{}",
        got.len(),
        polygon_text(&got)
    );
    for corner in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
        let c = Vec2::new(corner.0, corner.1);
        assert!(
            got.iter()
                .any(|v| v.position.truncate().truncate().distance(c) < 1e-4),
            "{call}: the corner {c} is missing (it comes from an edge an earlier pass made \
             along the border); yours:\n{}",
            polygon_text(&got)
        );
    }
    let area = shoelace(&got);
    assert!(
        (area - 4.0).abs() < 1e-4,
        "{call}: the square, counter-clockwise, has area 4; yours {area}"
    );
}

#[testkit::test]
fn depth_and_colour_are_interpolated_at_the_near_plane() {
    // An edge from z/w = 0 to z = −3, w = 1 (in front of the near plane),
    // clipped at z = −w: the new vertex has z/w = −1 and the colour a third
    // of the way... t = l_a / (l_a − l_b) with l = −z − w: l_a = −1,
    // l_b = 2, so t = 1/3 from the inside vertex.
    let polygon = [
        cv(0.0, 0.0, 0.0, 1.0, Rgba::BLACK),
        cv(0.0, 0.5, -3.0, 1.0, Rgba::WHITE),
        cv(0.5, 0.0, 0.0, 1.0, Rgba::BLACK),
    ];
    let got = clip(&polygon);
    let new: Vec<&ClipVertex> = got.iter().filter(|v| !polygon.contains(v)).collect();
    assert!(
        new.len() == 2,
        "the edges into and out of (0, 0.5, −3, 1) cross the near plane −z ≤ w: two new \
         vertices, yours {}:\n{}",
        new.len(),
        polygon_text(&got)
    );
    for v in new {
        let depth = v.position.z / v.position.w;
        assert!(
            (depth + 1.0).abs() < 1e-4,
            "a vertex on the near plane has z/w = −1; yours {} has {depth}",
            vertex_text(*v)
        );
        assert!(
            (v.colour.r - 1.0 / 3.0).abs() < 1e-4,
            "the crossing lies at t = l_a / (l_a − l_b) = 1/3 from the black vertex inside, so \
             its colour is black.lerp(white, 1/3), red 1/3 (interpolated in clip space); yours {}",
            vertex_text(*v)
        );
    }
}

#[testkit::test]
fn degenerate_polygons_are_clipped_like_any_other() {
    assert_same_polygon(&clip(&[]), &[], "no vertices clip to no vertices");
    let point = [flat(0.5, 0.5, Rgba::WHITE)];
    assert_same_polygon(
        &clip(&point),
        &point,
        "one vertex inside comes back unchanged",
    );
    assert_same_polygon(
        &clip(&[flat(5.0, 0.5, Rgba::WHITE)]),
        &[],
        "one vertex outside (x = 5 > w) vanishes",
    );
    // A "polygon" of two vertices is an edge there and back: its part
    // inside, end to end.
    let got = clip(&[flat(0.0, 0.0, Rgba::WHITE), flat(4.0, 0.0, Rgba::WHITE)]);
    let call = "clip((0, 0), (4, 0))";
    assert!(
        got.len() == 3,
        "{call}, an edge there and back: the edge (0, 0) → (4, 0) leaves at x = 1, the closing \
         edge comes back in, so (0, 0) and two crossings near (1, 0) are left; yours {}:\n{}",
        got.len(),
        polygon_text(&got)
    );
    assert!(
        got.iter().all(|v| excess(v.position) <= 0.0),
        "{call}: every vertex left lies inside the volume; yours:\n{}",
        polygon_text(&got)
    );
    assert_same_polygon(
        &clip_polygon(&point, &[]).unwrap_or_else(|e| {
            panic!("clip_polygon(one vertex, &[]): with no planes there is nothing to do, Ok; yours {e:?}")
        }),
        &point,
        "clip_polygon(polygon, &[]): an empty list of planes returns the polygon unchanged",
    );
}

#[testkit::test]
fn bad_input_is_an_error_not_a_panic() {
    let good = flat(0.0, 0.0, Rgba::WHITE);
    for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        let polygon = [good, good, cv(0.0, bad, 0.0, 1.0, Rgba::WHITE)];
        let rule = format!(
            "vertex 2 has y = {bad}: a non-finite coordinate is ClipError::NonFinite naming \
             the first such vertex"
        );
        assert_eq!(
            clip_polygon(&polygon, &VOLUME_PLANES),
            Err(ClipError::NonFinite { index: 2 }),
            "clip_polygon: {rule}"
        );
        assert_eq!(
            clip_against_plane(&polygon, RIGHT),
            Err(ClipError::NonFinite { index: 2 }),
            "clip_against_plane: {rule}"
        );
        let plane = ClipPlane::new(Vec4::new(bad, 0.0, 0.0, -1.0));
        assert_eq!(
            clip_polygon(&[good], &[RIGHT, plane]),
            Err(ClipError::InvalidPlane { index: 1 }),
            "clip_polygon with planes [x ≤ w, ({bad}, 0, 0, −1)]: a non-finite plane is \
             ClipError::InvalidPlane naming its index in the list"
        );
        assert_eq!(
            clip_against_plane(&[good], plane),
            Err(ClipError::InvalidPlane { index: 0 }),
            "clip_against_plane with the plane ({bad}, 0, 0, −1): a non-finite plane is \
             ClipError::InvalidPlane with index 0"
        );
    }
    let huge = [good, cv(1e30, 0.0, 0.0, 1.0, Rgba::WHITE), good];
    let rule = "vertex 1 has x = 1e30: a coordinate beyond ±MAX_CLIP_COORD (1e18) is \
                ClipError::OutOfRange naming the vertex";
    assert_eq!(
        clip_polygon(&huge, &VOLUME_PLANES),
        Err(ClipError::OutOfRange { index: 1 }),
        "clip_polygon: {rule}"
    );
    assert_eq!(
        clip_against_plane(&huge, RIGHT),
        Err(ClipError::OutOfRange { index: 1 }),
        "clip_against_plane: {rule}"
    );
}

#[testkit::test]
fn large_coordinates_within_the_limit_give_finite_vertices_inside() {
    // The sheet's nudge is 1e-6 of the *edge*: on edges 2e17 long it moves
    // a vertex by 2e11, so what is left may be anything down to nothing;
    // it must still be finite and inside.
    let polygon = [
        cv(-1e17, -1e17, 0.0, 1.0, Rgba::WHITE),
        cv(1e17, -1e17, 0.0, 1.0, Rgba::BLACK),
        cv(0.0, 1e17, 0.0, 1.0, Rgba::WHITE),
    ];
    let got = clip(&polygon);
    assert!(
        got.iter()
            .all(|v| v.position.is_finite() && excess(v.position) < 1e-3),
        "a triangle with corners at ±1e17: whatever is left must be finite and inside the \
         volume (to 1e-3); yours:\n{}",
        polygon_text(&got)
    );
    // At the same scale but with w as large, the triangle lies in the
    // volume (touching its faces) and is kept.
    let polygon = polygon.map(|v| {
        cv(
            v.position.x * 1e-2,
            v.position.y * 1e-2,
            0.0,
            1.0e15,
            v.colour,
        )
    });
    let got = clip(&polygon);
    assert!(
        got.len() >= 3,
        "the triangle at ±1e15 with w = 1e15 lies in the volume (touching its faces) and is \
         kept; yours {} vertices:\n{}",
        got.len(),
        polygon_text(&got)
    );
}

// ---------------------------------------------------------------------------
// Pictures: the sheet's `clipped_` meshes through the course pipeline.

/// The size of each of the four panels of a picture.
const PANEL: u32 = 256;

/// Renders `mesh` four times into one canvas, the course pipeline around
/// your clipping:
///
/// ```text
///   +-------------------+-------------------+
///   | wireframe,        | wireframe,        |
///   | without clipping  | with clipping     |
///   +-------------------+-------------------+
///   | filled,           | filled,           |
///   | without clipping  | with clipping     |
///   +-------------------+-------------------+
/// ```
///
/// Without clipping, vertices behind the eye are divided by a negative `w`
/// and land mirrored: the long stray edges and smeared triangles there are
/// what clipping removes.
fn four_panels(mesh_name: &str) -> canvas::Canvas {
    use scene::{Mode, Pipeline};
    let mesh = scene::ply::load(scene::data::path(mesh_name)).expect("a shipped mesh");
    let pipeline = Pipeline::for_mesh(&mesh, PANEL, PANEL);
    let polygons = pipeline.clip_space(&mesh);
    let clipped: Vec<Vec<ClipVertex>> = polygons.iter().map(|p| clip(p)).collect();
    let mut picture = canvas::Canvas::new(2 * PANEL, 2 * PANEL);
    for (column, input) in [&polygons, &clipped].into_iter().enumerate() {
        // y points up: the wireframe row is the upper one.
        for (row, mode) in [(1, Mode::Line), (0, Mode::Fill)] {
            let mut panel = canvas::Canvas::new(PANEL, PANEL);
            panel.clear(Rgba::BLACK);
            pipeline.render(input, mode, &mut panel);
            for (p, colour) in panel.enumerate() {
                let at = canvas::Pixel::new(
                    p.x + (column as u32 * PANEL) as i32,
                    p.y + (row * PANEL) as i32,
                );
                picture.set(at, colour);
            }
        }
    }
    picture
}

/// Rounding in your arithmetic may move an edge by a pixel where it meets
/// the border; nothing else may differ.
const PICTURE_TOLERANCE: testkit::image::Tolerance = testkit::image::Tolerance {
    channel: 4.0 / 255.0,
    mismatched_fraction: 0.002,
};

#[testkit::test]
fn clipped_star_matches_the_reference_image() {
    let picture = four_panels("clipped_star.ply");
    testkit::image::assert_image_matches(
        "clipping_clipped_star",
        &picture,
        concat!(env!("CARGO_MANIFEST_DIR"), "/tests/images/clipped_star.png"),
        PICTURE_TOLERANCE,
    );
}

#[testkit::test]
fn clipped_torus_matches_the_reference_image() {
    let picture = four_panels("clipped_torus.ply");
    testkit::image::assert_image_matches(
        "clipping_clipped_torus",
        &picture,
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/images/clipped_torus.png"
        ),
        PICTURE_TOLERANCE,
    );
}

#[testkit::test]
fn clipped_meshes_keep_everything_inside_and_lose_what_is_outside() {
    for name in ["clipped_star.ply", "clipped_torus.ply"] {
        let mesh = scene::ply::load(scene::data::path(name)).expect("a shipped mesh");
        let pipeline = scene::Pipeline::for_mesh(&mesh, PANEL, PANEL);
        let polygons = pipeline.clip_space(&mesh);
        let (mut cut, mut dropped) = (0, 0);
        for polygon in &polygons {
            let got = clip(polygon);
            if polygon.iter().all(|v| excess(v.position) <= 0.0) {
                assert_same_polygon(
                    &got,
                    polygon,
                    &format!("{name}: a face inside the volume comes back unchanged"),
                );
            } else if got.is_empty() {
                dropped += 1;
            } else {
                cut += 1;
            }
            assert!(
                got.iter().all(|v| excess(v.position) <= 1e-5),
                "{name}: every vertex of a clipped face lies inside the volume (to 1e-5); \
                 face:\n{}\nyours:\n{}",
                polygon_text(polygon),
                polygon_text(&got)
            );
        }
        // The sheet's point of these meshes: some faces cross the border.
        assert!(
            cut > 0,
            "{name}: some faces cross the border of the volume and are cut to what is inside; \
             yours cut none ({dropped} dropped, the rest unchanged)"
        );
    }
}

// ---------------------------------------------------------------------------
// Properties.

fn colour() -> impl Strategy<Value = Rgba> {
    testkit::strategies::colour()
}

/// A clip-space vertex with coordinates in `±4`, `w` in `[−1, 4]`.
fn any_vertex() -> impl Strategy<Value = ClipVertex> {
    (
        -4.0f32..4.0,
        -4.0f32..4.0,
        -4.0f32..4.0,
        -1.0f32..4.0,
        colour(),
    )
        .prop_map(|(x, y, z, w, c)| cv(x, y, z, w, c))
}

/// Polygons of 0 to 9 arbitrary clip-space vertices (any shape).
fn any_polygon() -> impl Strategy<Value = Vec<ClipVertex>> {
    prop::collection::vec(any_vertex(), 0..10)
}

/// Convex polygons in the plane `z = 0, w = 1`: points on a circle at
/// sorted angles, around a centre in `±2`, radius up to 3.
fn convex_flat_polygon() -> impl Strategy<Value = Vec<Vec2>> {
    (
        testkit::strategies::point(2.0),
        0.1f32..3.0,
        prop::collection::vec(0.0f32..std::f32::consts::TAU, 3..9),
    )
        .prop_map(|(centre, r, mut angles)| {
            angles.sort_by(f32::total_cmp);
            angles
                .into_iter()
                .map(|a| centre + r * Vec2::new(a.cos(), a.sin()))
                .collect()
        })
}

/// Star-shaped (often concave), simple polygons in the plane `z = 0,
/// w = 1`: one vertex per sector of the circle around a centre in `±1.5`,
/// so the angles increase and no gap reaches π.
fn star_flat_polygon() -> impl Strategy<Value = Vec<ClipVertex>> {
    (
        testkit::strategies::point(1.5),
        prop::collection::vec((0.0f32..1.0, 0.1f32..3.0, colour()), 3..12),
    )
        .prop_map(|(centre, spokes)| {
            let sector = std::f32::consts::TAU / spokes.len() as f32;
            spokes
                .into_iter()
                .enumerate()
                .map(|(k, (jitter, r, c))| {
                    let a = (k as f32 + jitter) * sector;
                    let p = centre + r * Vec2::new(a.cos(), a.sin());
                    flat(p.x, p.y, c)
                })
                .collect()
        })
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn every_output_vertex_lies_inside_the_volume(polygon in any_polygon()) {
        let got = clip(&polygon);
        keeps_what_is_inside(&polygon, &got)?;
        for v in got {
            prop_assert!(excess(v.position) <= 1e-5, "every vertex clip returns lies inside −w ≤ x, y, z ≤ w (to 1e-5); yours {} is outside by {}", vertex_text(v), excess(v.position));
        }
    }

    #[testkit::test]
    fn polygons_inside_are_unchanged(
        polygon in prop::collection::vec(
            (-1.0f32..=1.0, -1.0f32..=1.0, -1.0f32..=1.0, 0.01f32..4.0, colour())
                .prop_map(|(x, y, z, w, c)| cv(x * w, y * w, z * w, w, c)),
            0..10,
        ),
    ) {
        // Keep only vertices that are inside in f32 too (x·w may round out).
        let polygon: Vec<ClipVertex> =
            polygon.into_iter().filter(|v| excess(v.position) <= 0.0).collect();
        assert_same_polygon(&clip(&polygon), &polygon, "a polygon inside the volume comes back unchanged, starting with the same vertex");
    }

    #[testkit::test]
    fn polygons_beyond_one_plane_vanish(
        polygon in prop::collection::vec(any_vertex(), 1..10),
        k in 0usize..6,
    ) {
        // Move every vertex beyond plane k: x > w (say) by at least 0.5.
        let n = VOLUME_PLANES[k].vector;
        let moved: Vec<ClipVertex> = polygon
            .into_iter()
            .map(|mut v| {
                let l = v.position.dot(n);
                if l < 0.5 {
                    // Along the normal's xyz part, which raises l by its length (1).
                    v.position += (0.5 - l + 0.25) * n.truncate().extend(0.0);
                }
                v
            })
            .collect();
        let got = clip(&moved);
        prop_assert!(got.is_empty(), "a polygon wholly beyond plane {} ({}) vanishes\ninput:\n{}\nyours:\n{}", k, VOLUME_PLANES[k].vector, polygon_text(&moved), polygon_text(&got));
        // Refusing one is no reason to refuse the next.
        let inside = [flat(-0.5, -0.5, Rgba::WHITE), flat(0.5, -0.5, Rgba::WHITE), flat(0.0, 0.5, Rgba::WHITE)];
        let got = clip(&inside);
        prop_assert_eq!(got.len(), 3, "a triangle inside, clipped after one that vanished, keeps its 3 vertices (left: yours):\n{}", polygon_text(&got));
    }

    #[testkit::test]
    fn clipping_twice_changes_nothing(polygon in any_polygon()) {
        let once = clip(&polygon);
        keeps_what_is_inside(&polygon, &once)?;
        let twice = clip(&once);
        // A vertex that rounding left a hair outside may be cut off again,
        // by a crossing anywhere on an edge that runs along the plane; the
        // outline moves no further than that hair.
        prop_assert!(outline_distance(&once, &twice) <= 1e-4, "a clipped polygon lies in the volume: clipping it again moves its outline by no more than rounding (1e-4), yours by {}\nonce:\n{}\ntwice:\n{}", outline_distance(&once, &twice), polygon_text(&once), polygon_text(&twice));
    }

    #[testkit::test]
    fn new_vertices_of_one_pass_are_mixes_of_their_edge(
        polygon in any_polygon(),
        k in 0usize..6,
    ) {
        let plane = VOLUME_PLANES[k];
        let got = clip_one(&polygon, plane);
        // The test `v · p ≤ 0` written out: task 1's `inside` is not used,
        // so that this task is graded on its own.
        let inside = |v: ClipVertex| plane.distance(v.position) <= 0.0;
        let n = polygon.len();
        for v in got.iter().filter(|v| !polygon.contains(v)) {
            let on_an_edge = (0..n).any(|i| {
                let (a, b) = (polygon[i], polygon[(i + 1) % n]);
                inside(a) != inside(b) && is_on_edge(*v, a, b, 1e-4)
            });
            prop_assert!(on_an_edge, "clip_against_plane(…, {}): the new vertex {} is not S.lerp(E, t) in position and colour for any edge S → E with one endpoint inside\ninput:\n{}", plane.vector, vertex_text(*v), polygon_text(&polygon));
            prop_assert!(v.position.dot(plane.vector) <= 0.0, "clip_against_plane(…, {}): the new vertex {} lies outside (v · p = {} > 0); t is nudged towards the inside endpoint", plane.vector, vertex_text(*v), v.position.dot(plane.vector));
        }
        // Inside vertices are kept, in order; outside ones are dropped.
        let kept: Vec<ClipVertex> = got.iter().copied().filter(|v| polygon.contains(v)).collect();
        let expected: Vec<ClipVertex> =
            polygon.iter().copied().filter(|&v| inside(v)).collect();
        assert_same_polygon(&kept, &expected, &format!("clip_against_plane(…, {}): the input's vertices in yours are exactly those inside (v · p ≤ 0), in order", plane.vector));
    }

    #[testkit::test]
    fn all_vertices_are_mixes_of_the_polygon(polygon in any_polygon()) {
        keeps_what_is_inside(&polygon, &clip(&polygon))?;
        // Convex combinations of the input stay in its bounding box, in
        // every coordinate and every colour channel.
        let lo = polygon.iter().fold([f32::INFINITY; 8], |m, v| {
            let c = [v.position.x, v.position.y, v.position.z, v.position.w,
                     v.colour.r, v.colour.g, v.colour.b, v.colour.a];
            std::array::from_fn(|i| m[i].min(c[i]))
        });
        let hi = polygon.iter().fold([f32::NEG_INFINITY; 8], |m, v| {
            let c = [v.position.x, v.position.y, v.position.z, v.position.w,
                     v.colour.r, v.colour.g, v.colour.b, v.colour.a];
            std::array::from_fn(|i| m[i].max(c[i]))
        });
        for v in clip(&polygon) {
            let c = [v.position.x, v.position.y, v.position.z, v.position.w,
                     v.colour.r, v.colour.g, v.colour.b, v.colour.a];
            for i in 0..8 {
                prop_assert!(lo[i] - 1e-5 <= c[i] && c[i] <= hi[i] + 1e-5, "every vertex is a mix of the input's, inside its bounding box: {} of {} is {}, the input's lie in [{}, {}]", ["x", "y", "z", "w", "red", "green", "blue", "alpha"][i], vertex_text(v), c[i], lo[i], hi[i]);
            }
        }
    }

    #[testkit::test]
    fn convex_polygon_keeps_exactly_its_area_inside_the_square(polygon in convex_flat_polygon()) {
        let vertices: Vec<ClipVertex> = polygon.iter().map(|p| flat(p.x, p.y, Rgba::WHITE)).collect();
        let got = clip(&vertices);
        let expected = common::convex_area_in_square(&polygon);
        prop_assert!((shoelace(&got).abs() - expected).abs() <= 1e-4,
            "a convex polygon keeps exactly its area inside [−1, 1]²: yours {}, expected {} (the hull of the vertices inside and the edges' crossings)\nyours:\n{}", shoelace(&got).abs(), expected, polygon_text(&got));
    }

    #[testkit::test]
    fn clipping_never_adds_area(polygon in star_flat_polygon()) {
        let got = clip(&polygon);
        keeps_what_is_inside(&polygon, &got)?;
        let (before, after) = (shoelace(&polygon), shoelace(&got));
        prop_assert!(after.abs() <= before.abs() + 1e-5, "clipping never adds area: the polygon's signed area {}, yours after clipping {}", before, after);
        // Nor does it change the winding.
        prop_assert!(after * before >= -1e-9, "clipping keeps the winding: signed area {} before, yours {} after (the sign flipped)", before, after);
    }
}
