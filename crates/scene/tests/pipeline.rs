//! The transforms: the course camera, the perspective divide and the
//! viewport transform against exact known answers; clip space; the shipped
//! meshes against the view volume; `render` on hostile input.

use approx::assert_abs_diff_eq;
use canvas::{Canvas, Pixel, Rgba};
use glam::{Mat4, Vec2, Vec3, Vec4};
use proptest::prelude::*;
use scene::pipeline::{EYE, FAR, FOV_Y, NEAR};
use scene::{ClipVertex, Mesh, Mode, Pipeline, discard_outside, inside_view_volume};

/// Odd sizes, so that the canvas centre is a pixel centre: (50, 25).
const W: u32 = 101;
const H: u32 = 51;

/// Asserts that two glam values agree within `eps` in every component.
macro_rules! assert_close {
    ($a:expr, $b:expr, $eps:expr) => {{
        let (a, b) = ($a, $b);
        assert!(a.abs_diff_eq(b, $eps), "{a:?}\n  differs from\n{b:?}");
    }};
}

fn camera() -> Pipeline {
    Pipeline::for_mesh(&Mesh::default(), W, H)
}

fn clip(x: f32, y: f32, z: f32, w: f32) -> ClipVertex {
    ClipVertex::new(Vec4::new(x, y, z, w), Rgba::WHITE)
}

fn screen_of_world(p: Vec3) -> (Vec2, f32) {
    let c = camera();
    let v = c
        .screen(ClipVertex::new(
            c.model_view_projection() * p.extend(1.0),
            Rgba::WHITE,
        ))
        .expect("finite");
    (v.position, v.depth)
}

#[test]
fn projection_is_the_textbook_perspective_matrix() {
    // gluPerspective: f = cot(fov / 2), rows as written on paper.
    let f = 1.0 / (FOV_Y / 2.0).tan();
    let aspect = W as f32 / H as f32;
    let expected = Mat4::from_cols_array_2d(&[
        [f / aspect, 0.0, 0.0, 0.0],
        [0.0, f, 0.0, 0.0],
        [
            0.0,
            0.0,
            (FAR + NEAR) / (NEAR - FAR),
            2.0 * FAR * NEAR / (NEAR - FAR),
        ],
        [0.0, 0.0, -1.0, 0.0],
    ])
    .transpose();
    assert_close!(camera().projection, expected, 1e-6);
}

#[test]
fn view_moves_the_eye_to_the_origin_looking_down_minus_z() {
    let view = camera().view;
    assert_close!(view, Mat4::from_translation(-EYE), 1e-6);
    assert_eq!(camera().model, Mat4::IDENTITY);
}

#[test]
fn point_on_the_near_plane_has_depth_zero_at_the_centre() {
    let (pixel, depth) = screen_of_world(EYE - Vec3::Z * NEAR);
    assert_close!(pixel, Vec2::new(50.0, 25.0), 1e-4);
    assert_abs_diff_eq!(depth, 0.0, epsilon = 1e-6);
}

#[test]
fn point_on_the_far_plane_has_depth_one() {
    let (pixel, depth) = screen_of_world(EYE - Vec3::Z * FAR);
    assert_close!(pixel, Vec2::new(50.0, 25.0), 1e-4);
    assert_abs_diff_eq!(depth, 1.0, epsilon = 1e-6);
}

#[test]
fn frustum_corner_maps_to_the_top_right_pixel_centre() {
    // On the near plane the frustum is tan(fov/2)·near high and aspect
    // times as wide.
    let half_h = NEAR * (FOV_Y / 2.0).tan();
    let half_w = half_h * W as f32 / H as f32;
    let (pixel, depth) = screen_of_world(EYE + Vec3::new(half_w, half_h, -NEAR));
    assert_close!(pixel, Vec2::new(100.0, 50.0), 1e-3);
    assert_abs_diff_eq!(depth, 0.0, epsilon = 1e-6);
    let (pixel, _) = screen_of_world(EYE + Vec3::new(-half_w, -half_h, -NEAR));
    assert_close!(pixel, Vec2::ZERO, 1e-3);
}

#[test]
fn perspective_divide_and_viewport_exact() {
    let c = camera();
    // NDC (0.5, 0.25, 0): x = 1.5 / 2 · 100, y = 1.25 / 2 · 50, depth ½.
    let v = c.screen(clip(1.0, 0.5, 0.0, 2.0)).unwrap();
    assert_eq!((v.position, v.depth), (Vec2::new(75.0, 31.25), 0.5));
}

#[test]
fn ndc_cube_corners_map_to_canvas_corner_pixels() {
    let c = camera();
    let low = c.screen(clip(-2.0, -2.0, -2.0, 2.0)).unwrap();
    assert_eq!((low.position, low.depth), (Vec2::ZERO, 0.0));
    let high = c.screen(clip(3.0, 3.0, 3.0, 3.0)).unwrap();
    assert_eq!((high.position, high.depth), (Vec2::new(100.0, 50.0), 1.0));
}

#[test]
fn negative_w_is_divided_naively_and_zero_w_is_skipped() {
    let c = camera();
    // Behind the eye: (1, 1) / −1 mirrors to the lower left corner.
    let v = c.screen(clip(1.0, 1.0, 0.0, -1.0)).unwrap();
    assert_eq!(v.position, Vec2::ZERO);
    assert_eq!(c.screen(clip(1.0, 1.0, 0.0, 0.0)), None);
    assert_eq!(c.screen(clip(f32::NAN, 0.0, 0.0, 1.0)), None);
    assert_eq!(c.screen(clip(f32::INFINITY, 0.0, 0.0, 1.0)), None);
}

#[test]
fn clip_vertex_lerp_is_exact_at_the_ends() {
    let a = ClipVertex::new(Vec4::new(0.1, 0.2, 0.3, 1.0), Rgba::RED);
    let b = ClipVertex::new(Vec4::new(-7.0, 3.0, 0.7, 2.5), Rgba::BLUE);
    assert_eq!(a.lerp(b, 0.0), a);
    assert_eq!(a.lerp(b, 1.0), b);
    let mid = a.lerp(b, 0.5);
    assert_close!(mid.position, Vec4::new(-3.45, 1.6, 0.5, 1.75), 1e-6);
    assert!(mid.colour.approx_eq(Rgba::new(0.5, 0.0, 0.5, 1.0), 1e-6));
}

#[test]
fn mesh_bounds_hold_every_position() {
    let mesh = Mesh {
        positions: vec![Vec3::new(1.0, -2.0, 3.0), Vec3::new(-1.0, 5.0, 0.0)],
        ..Mesh::default()
    };
    assert_eq!(
        mesh.bounds(),
        Some([Vec3::new(-1.0, -2.0, 0.0), Vec3::new(1.0, 5.0, 3.0)])
    );
    assert_eq!(Mesh::default().bounds(), None);
}

#[test]
fn clip_space_gives_one_polygon_per_valid_face() {
    let mesh = Mesh {
        positions: vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::ONE],
        colours: vec![Rgba::RED, Rgba::GREEN],
        faces: vec![vec![0, 1, 2], vec![0, 1, 9], vec![1, 3, 2]],
    };
    let identity = Pipeline {
        model: Mat4::IDENTITY,
        view: Mat4::IDENTITY,
        projection: Mat4::IDENTITY,
        width: W,
        height: H,
    };
    let polygons = identity.clip_space(&mesh);
    assert_eq!(polygons.len(), 2, "the face with index 9 is skipped");
    assert_eq!(
        polygons[0][1],
        ClipVertex::new(Vec4::new(1.0, 0.0, 0.0, 1.0), Rgba::GREEN)
    );
    assert_eq!(polygons[1][1], ClipVertex::new(Vec4::ONE, Rgba::WHITE));
}

fn shipped(name: &str) -> Vec<ClipVertex> {
    let mesh = scene::ply::load(scene::data::path(name)).unwrap();
    let c = Pipeline::for_mesh(&mesh, 512, 512);
    c.clip_space(&mesh).concat()
}

#[test]
fn plain_meshes_lie_inside_the_view_volume() {
    for name in ["plane.ply", "star.ply", "text.ply", "torus.ply"] {
        let outside = shipped(name)
            .iter()
            .filter(|v| !inside_view_volume(v))
            .count();
        assert_eq!(outside, 0, "{name}");
    }
}

#[test]
fn clipped_meshes_cross_the_near_plane_and_the_sides() {
    for name in ["clipped_star.ply", "clipped_torus.ply"] {
        let vertices = shipped(name);
        let p = |v: &ClipVertex| v.position;
        assert!(
            vertices.iter().any(|v| p(v).z < -p(v).w),
            "{name}: nothing before the near plane"
        );
        assert!(
            vertices
                .iter()
                .any(|v| p(v).w > 0.0 && p(v).x.abs() > p(v).w),
            "{name}: nothing beside the view"
        );
        assert!(
            vertices.iter().any(inside_view_volume),
            "{name}: nothing visible"
        );
    }
    assert!(
        shipped("clipped_torus.ply")
            .iter()
            .any(|v| v.position.w < 0.0),
        "clipped_torus: nothing behind the eye"
    );
}

#[test]
fn discard_outside_keeps_only_whole_polygons_inside() {
    let inside = vec![
        clip(0.0, 0.0, 0.0, 1.0),
        clip(1.0, 1.0, 1.0, 1.0),
        clip(-1.0, 0.5, 0.0, 1.0),
    ];
    let crossing = vec![
        clip(0.0, 0.0, 0.0, 1.0),
        clip(1.5, 0.0, 0.0, 1.0),
        clip(0.0, 1.0, 0.0, 1.0),
    ];
    let behind = vec![clip(0.0, 0.0, 0.0, -1.0); 3];
    let kept = discard_outside(&[inside.clone(), crossing, behind]);
    assert_eq!(kept, vec![inside]);
}

/// A clip-space vertex whose pixel position is `(x, y)` on a `size × size`
/// canvas, at NDC depth `z`.
fn at_pixel(x: f32, y: f32, z: f32, size: u32, colour: Rgba) -> ClipVertex {
    let ndc = |p: f32| 2.0 * p / (size - 1) as f32 - 1.0;
    ClipVertex::new(Vec4::new(ndc(x), ndc(y), z, 1.0), colour)
}

fn flat(size: u32) -> Pipeline {
    Pipeline {
        model: Mat4::IDENTITY,
        view: Mat4::IDENTITY,
        projection: Mat4::IDENTITY,
        width: size,
        height: size,
    }
}

#[test]
fn line_mode_draws_every_edge_once() {
    // A right triangle with corners (1, 1), (6, 1), (1, 6): its outline is
    // the two legs and the diagonal x + y = 7.
    let s = 8;
    let triangle = vec![
        at_pixel(1.0, 1.0, 0.0, s, Rgba::WHITE),
        at_pixel(6.0, 1.0, 0.0, s, Rgba::WHITE),
        at_pixel(1.0, 6.0, 0.0, s, Rgba::WHITE),
    ];
    let mut canvas = Canvas::new(s, s);
    flat(s).render(&[triangle], Mode::Line, &mut canvas);
    let mut expected: Vec<Pixel> = Vec::new();
    for y in 1..=6 {
        for x in 1..=6 {
            if x == 1 || y == 1 || x + y == 7 {
                expected.push(Pixel::new(x, y));
            }
        }
    }
    testkit::assert_pixels_eq(&expected, &canvas.pixels_not(Rgba::BLACK), "outline");
}

#[test]
fn fill_mode_covers_the_closed_polygon_and_interpolates_colour() {
    // The square [1, 5]² as a quad: 25 pixels, white at the top-right
    // corner, black at the lower left.
    let s = 8;
    let quad = vec![
        at_pixel(1.0, 1.0, 0.0, s, Rgba::BLACK),
        at_pixel(5.0, 1.0, 0.0, s, Rgba::grey(0.5)),
        at_pixel(5.0, 5.0, 0.0, s, Rgba::WHITE),
        at_pixel(1.0, 5.0, 0.0, s, Rgba::grey(0.5)),
    ];
    let mut canvas = Canvas::new(s, s);
    canvas.clear(Rgba::RED);
    flat(s).render(&[quad], Mode::Fill, &mut canvas);
    let covered = canvas.pixels_not(Rgba::RED);
    let expected: Vec<Pixel> = (1..=5)
        .flat_map(|y| (1..=5).map(move |x| Pixel::new(x, y)))
        .collect();
    testkit::assert_pixels_eq(&expected, &covered, "filled quad");
    assert_eq!(canvas.get(Pixel::new(5, 5)), Some(Rgba::WHITE));
    assert_eq!(canvas.get(Pixel::new(1, 1)), Some(Rgba::BLACK));
    assert_eq!(
        canvas.get(Pixel::new(3, 3)),
        Some(Rgba::from_rgba8([128, 128, 128, 255]))
    );
}

#[test]
fn nearer_polygon_wins_in_either_order() {
    let s = 6;
    let square = |z: f32, colour| {
        vec![
            at_pixel(0.0, 0.0, z, s, colour),
            at_pixel(5.0, 0.0, z, s, colour),
            at_pixel(5.0, 5.0, z, s, colour),
            at_pixel(0.0, 5.0, z, s, colour),
        ]
    };
    let near = square(-0.5, Rgba::GREEN);
    let far = square(0.5, Rgba::RED);
    for polygons in [[near.clone(), far.clone()], [far, near]] {
        for mode in [Mode::Line, Mode::Fill] {
            let mut canvas = Canvas::new(s, s);
            flat(s).render(&polygons, mode, &mut canvas);
            assert!(canvas.enumerate().all(|(_, c)| c != Rgba::RED), "{mode:?}");
            assert_eq!(canvas.get(Pixel::new(0, 0)), Some(Rgba::GREEN));
        }
    }
}

#[test]
fn vertex_that_cannot_be_divided_drops_its_edges_and_its_fill() {
    let s = 8;
    let triangle = vec![
        at_pixel(1.0, 1.0, 0.0, s, Rgba::WHITE),
        at_pixel(6.0, 1.0, 0.0, s, Rgba::WHITE),
        clip(0.0, 0.0, 0.0, 0.0),
    ];
    let mut canvas = Canvas::new(s, s);
    flat(s).render(std::slice::from_ref(&triangle), Mode::Line, &mut canvas);
    let bottom: Vec<Pixel> = (1..=6).map(|x| Pixel::new(x, 1)).collect();
    testkit::assert_pixels_eq(&bottom, &canvas.pixels_not(Rgba::BLACK), "edges left");
    let mut canvas = Canvas::new(s, s);
    flat(s).render(&[triangle], Mode::Fill, &mut canvas);
    assert!(canvas.pixels_not(Rgba::BLACK).is_empty());
}

fn hostile_vertex() -> impl Strategy<Value = ClipVertex> {
    let c = || {
        prop_oneof![
            3 => -4.0f32..4.0,
            1 => testkit::strategies::hostile_f32(),
        ]
    };
    (c(), c(), c(), c()).prop_map(|(x, y, z, w)| clip(x, y, z, w))
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[test]
    fn render_survives_unclipped_and_hostile_polygons(
        polygons in prop::collection::vec(prop::collection::vec(hostile_vertex(), 0..7), 0..6),
        fill in any::<bool>(),
    ) {
        let mode = if fill { Mode::Fill } else { Mode::Line };
        let mut canvas = Canvas::new(32, 24);
        Pipeline::for_mesh(&Mesh::default(), 32, 24).render(&polygons, mode, &mut canvas);
        flat(32).render(&polygons, mode, &mut canvas);
    }

    #[test]
    fn screen_of_a_point_inside_the_volume_lies_on_the_canvas(
        x in -1.0f32..=1.0, y in -1.0f32..=1.0, z in -1.0f32..=1.0, w in 0.01f32..100.0,
    ) {
        let v = camera().screen(clip(x * w, y * w, z * w, w)).unwrap();
        let p = Pixel::new(canvas::round_half_away(v.position.x), canvas::round_half_away(v.position.y));
        prop_assert!(Canvas::new(W, H).contains(p), "{:?}", v);
        prop_assert!((-1e-5..=1.0 + 1e-5).contains(&v.depth));
    }
}
