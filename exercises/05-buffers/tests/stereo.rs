//! Task 7: stereo buffering — two cameras with parallel axes and
//! asymmetric frusta, a stereo buffer and the anaglyph.
//!
//! The cameras are checked by what they do to points, not by their
//! matrices: where a point lands in each eye's picture (its normalised
//! device coordinates), computed here from the mono camera's own frame.

use buffers::stereo::{
    Eye, Glasses, StereoBuffer, StereoCamera, StereoError, anaglyph, aspect_ratio, render_stereo,
};
use canvas::{Canvas, Pixel, Rgba};
use glam::camera::rh::{proj::opengl, view};
use glam::{Mat4, Vec3};
use proptest::prelude::*;
use scene::{Mesh, Mode, Pipeline};

/// A camera that looks along no axis, with an `up` that is not
/// perpendicular to its view direction and a wide picture.
fn tilted(separation: f32, convergence: f32) -> StereoCamera {
    StereoCamera {
        eye: Vec3::new(1.0, 2.0, 5.0),
        target: Vec3::new(-0.5, 0.5, -1.0),
        up: Vec3::new(0.1, 1.0, 0.2),
        fov_y: 0.9,
        near: 0.5,
        far: 30.0,
        separation,
        convergence,
    }
}

const ASPECT: f32 = 1.6;

/// The mono camera's frame: forward, right and the true up, orthonormal.
fn frame(c: &StereoCamera) -> (Vec3, Vec3, Vec3) {
    let forward = (c.target - c.eye).normalize();
    let right = forward.cross(c.up).normalize();
    (forward, right, right.cross(forward))
}

/// The world point `x` to the right, `y` up and `d` ahead of the mono eye.
fn at(c: &StereoCamera, x: f32, y: f32, d: f32) -> Vec3 {
    let (forward, right, up) = frame(c);
    c.eye + x * right + y * up + d * forward
}

/// Where `p` lands in the picture of `eye`: the normalised device
/// coordinates of `projection · view · p` after the perspective divide.
fn ndc(c: &StereoCamera, eye: Eye, p: Vec3) -> Vec3 {
    let clip = c.projection(eye, ASPECT) * c.view(eye) * p.extend(1.0);
    clip.truncate() / clip.w
}

/// `x / d` in the mono camera's picture, in NDC: `x / (d · tan(fov/2) · aspect)`.
fn mono_ndc_x(c: &StereoCamera, x: f32, d: f32) -> f32 {
    x / (d * (0.5 * c.fov_y).tan() * ASPECT)
}

/// `y / d` in the mono camera's picture, in NDC: `y / (d · tan(fov/2))`.
fn mono_ndc_y(c: &StereoCamera, y: f32, d: f32) -> f32 {
    y / (d * (0.5 * c.fov_y).tan())
}

fn close(a: Vec3, b: Vec3, tolerance: f32) -> bool {
    (a - b).abs().max_element() <= tolerance
}

#[testkit::test]
fn the_eyes_stand_half_the_separation_to_either_side() {
    let c = tilted(0.4, 6.0);
    let (_, right, _) = frame(&c);
    let left = c.eye_position(Eye::Left);
    let right_eye = c.eye_position(Eye::Right);
    assert!(
        close(left, c.eye - 0.2 * right, 1e-5),
        "the left eye stands at {left}, expected eye − s/2 · right = {} \
         (right = normalize((target − eye) × up))",
        c.eye - 0.2 * right
    );
    assert!(
        close(right_eye, c.eye + 0.2 * right, 1e-5),
        "the right eye stands at {right_eye}, expected eye + s/2 · right = {}",
        c.eye + 0.2 * right
    );
}

#[testkit::test]
fn without_separation_each_eye_is_the_mono_camera() {
    let c = tilted(0.0, 6.0);
    let mono_view = view::look_at_mat4(c.eye, c.target, c.up);
    let mono_projection = opengl::perspective(c.fov_y, ASPECT, c.near, c.far);
    for eye in Eye::BOTH {
        assert!(
            c.view(eye).abs_diff_eq(mono_view, 1e-5),
            "{eye:?} eye with s = 0: the view must be gluLookAt(eye, target, up)\n  got      {}\n  expected {mono_view}",
            c.view(eye)
        );
        assert!(
            c.projection(eye, ASPECT).abs_diff_eq(mono_projection, 1e-5),
            "{eye:?} eye with s = 0: the projection must be gluPerspective(fov_y, aspect, near, far)\n  got      {}\n  expected {mono_projection}",
            c.projection(eye, ASPECT)
        );
    }
}

#[testkit::test]
fn both_eyes_look_the_same_way_as_the_mono_camera() {
    let c = tilted(0.5, 6.0);
    let (forward, right, up) = frame(&c);
    for eye in Eye::BOTH {
        let v = c.view(eye);
        let origin = v.transform_point3(c.eye_position(eye));
        assert!(
            close(origin, Vec3::ZERO, 1e-4),
            "{eye:?} eye: its view must put its own position at the origin of eye space, got {origin}"
        );
        let looks = v.transform_vector3(forward);
        assert!(
            close(looks, Vec3::NEG_Z, 1e-5),
            "{eye:?} eye: the mono view direction must be its −z axis (parallel axes), \
             got {looks}: turning the eyes towards the target (toe-in) tilts their pictures \
             against each other"
        );
        assert!(
            close(v.transform_vector3(right), Vec3::X, 1e-5)
                && close(v.transform_vector3(up), Vec3::Y, 1e-5),
            "{eye:?} eye: right and up must stay the mono camera's"
        );
    }
}

#[testkit::test]
fn a_point_behind_the_zero_parallax_plane_moves_right_in_the_right_picture() {
    let c = tilted(0.5, 6.0);
    let far_point = at(&c, 0.3, -0.2, 12.0);
    let near_point = at(&c, 0.3, -0.2, 3.0);
    let parallax = |p| ndc(&c, Eye::Right, p).x - ndc(&c, Eye::Left, p).x;
    assert!(
        parallax(far_point) > 0.01,
        "a point behind the plane at c must lie farther right in the right eye's \
         picture (uncrossed parallax), got x_right − x_left = {}",
        parallax(far_point)
    );
    assert!(
        parallax(near_point) < -0.01,
        "a point in front of the plane at c must lie farther left in the right eye's \
         picture (crossed parallax), got x_right − x_left = {}",
        parallax(near_point)
    );
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..testkit::proptest_config() })]

    /// With parallel axes a point lies in the same row of both pictures;
    /// toe-in fails for every point away from the centre.
    #[testkit::test]
    fn no_point_has_vertical_parallax(
        x in -1.0f32..1.0, y in -1.0f32..1.0, d in 1.0f32..25.0,
        s in 0.05f32..0.8, c in 2.0f32..12.0,
    ) {
        let camera = tilted(s, c);
        let (x, y) = (x * 0.4 * d, y * 0.4 * d);
        let p = at(&camera, x, y, d);
        let (l, r) = (ndc(&camera, Eye::Left, p), ndc(&camera, Eye::Right, p));
        prop_assert!(
            (l.y - r.y).abs() <= 1e-4 && (l.z - r.z).abs() <= 1e-4,
            "the point {x} right, {y} up and {d} ahead of the mono eye lands at y = {} \
             (depth {}) in the left picture and y = {} (depth {}) in the right one: the two \
             pictures may differ only in x",
            l.y, l.z, r.y, r.z
        );
        prop_assert!(
            (l.y - mono_ndc_y(&camera, y, d)).abs() <= 1e-4,
            "the point {x} right, {y} up and {d} ahead lands at y = {} in the left picture, \
             the mono camera puts it at y = {}: the eyes move sideways only",
            l.y, mono_ndc_y(&camera, y, d)
        );
    }

    /// Both frusta cut the same window out of the plane at distance `c`.
    #[testkit::test]
    fn points_on_the_zero_parallax_plane_land_on_the_same_spot(
        x in -1.0f32..1.0, y in -1.0f32..1.0, s in 0.05f32..0.8, c in 2.0f32..12.0,
    ) {
        let camera = tilted(s, c);
        let p = at(&camera, x * 0.4 * c, y * 0.4 * c, c);
        let (l, r) = (ndc(&camera, Eye::Left, p), ndc(&camera, Eye::Right, p));
        prop_assert!(
            (l.x - r.x).abs() <= 1e-4 && (l.y - r.y).abs() <= 1e-4,
            "a point on the zero-parallax plane (d = c = {c}) lands at x = {} in the left \
             picture and x = {} in the right one: shift each frustum by s/2 · near / c \
             towards the middle",
            l.x, r.x
        );
        let mono = mono_ndc_x(&camera, x * 0.4 * c, c);
        prop_assert!(
            (l.x - mono).abs() <= 1e-4,
            "a point on the zero-parallax plane lands at x = {} in both pictures, the mono \
             camera puts it at x = {mono}: on that plane all three pictures agree",
            l.x
        );
    }

    /// The parallax of a point at distance `d`, in NDC:
    /// `s · (1/c − 1/d) / (tan(fov/2) · aspect)`, and the two pictures
    /// average to the mono camera's.
    #[testkit::test]
    fn the_parallax_is_s_times_one_over_c_minus_one_over_d(
        x in -1.0f32..1.0, y in -1.0f32..1.0, d in 1.0f32..25.0,
        s in 0.05f32..0.8, c in 2.0f32..12.0,
    ) {
        let camera = tilted(s, c);
        let (x, y) = (x * 0.4 * d, y * 0.4 * d);
        let p = at(&camera, x, y, d);
        let (l, r) = (ndc(&camera, Eye::Left, p), ndc(&camera, Eye::Right, p));
        let expected = s * (1.0 / c - 1.0 / d) / ((0.5 * camera.fov_y).tan() * ASPECT);
        prop_assert!(
            (r.x - l.x - expected).abs() <= 2e-4,
            "parallax x_right − x_left = {} for s = {s}, c = {c}, d = {d}; expected {expected}",
            r.x - l.x
        );
        let middle = 0.5 * (l.x + r.x);
        prop_assert!(
            (middle - mono_ndc_x(&camera, x, d)).abs() <= 2e-4,
            "the two pictures must average to the mono camera's: (x_left + x_right)/2 = \
             {middle}, mono {}",
            mono_ndc_x(&camera, x, d)
        );
    }
}

/// A stereo buffer with the given colour at pixel (1, 0) of each eye.
fn pair(left: Rgba, right: Rgba) -> StereoBuffer {
    let mut buffer = StereoBuffer::try_new(3, 2).unwrap();
    buffer.draw_buffer(Eye::Left).set(Pixel::new(1, 0), left);
    buffer.draw_buffer(Eye::Right).set(Pixel::new(1, 0), right);
    buffer
}

#[testkit::test]
fn the_anaglyph_takes_red_from_the_left_picture_and_green_and_blue_from_the_right() {
    let left = Rgba::new(0.8, 0.4, 0.2, 0.5);
    let right = Rgba::new(0.6, 0.2, 1.0, 0.0);
    let p = Pixel::new(1, 0);
    let cyan = anaglyph(&pair(left, right), Glasses::RedCyan);
    assert_eq!(
        cyan.get(p).map(Rgba::to_rgba8),
        Some(Rgba::new(0.8, 0.2, 1.0, 1.0).to_rgba8()),
        "red-cyan: red from the left picture, green and blue from the right, alpha 1"
    );
    let green = anaglyph(&pair(left, right), Glasses::RedGreen);
    assert_eq!(
        green.get(p).map(Rgba::to_rgba8),
        Some(Rgba::new(0.8, 0.2, 0.0, 1.0).to_rgba8()),
        "red-green: red from the left picture, green from the right, no blue, alpha 1"
    );
    assert_eq!(
        (cyan.width(), cyan.height()),
        (3, 2),
        "the anaglyph has the pictures' size"
    );
    assert_eq!(
        cyan.get(Pixel::new(0, 1)),
        Some(Rgba::BLACK),
        "black in both pictures stays black"
    );
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, ..testkit::proptest_config() })]

    /// What both eyes see alike in grey needs no filter: through red-cyan
    /// glasses the anaglyph of a grey picture shown to both eyes is that
    /// picture.
    #[testkit::test]
    fn a_grey_picture_seen_by_both_eyes_is_its_own_red_cyan_anaglyph(
        levels in prop::collection::vec(any::<u8>(), 12),
    ) {
        let mut buffer = StereoBuffer::try_new(4, 3).unwrap();
        let mut grey = Canvas::new(4, 3);
        for (i, &level) in levels.iter().enumerate() {
            let p = Pixel::new(i as i32 % 4, i as i32 / 4);
            let colour = Rgba::from_rgba8([level, level, level, 255]);
            grey.set(p, colour);
            for eye in Eye::BOTH {
                buffer.draw_buffer(eye).set(p, colour);
            }
        }
        prop_assert_eq!(anaglyph(&buffer, Glasses::RedCyan), grey);
    }
}

fn mesh(name: &str) -> Mesh {
    scene::ply::load(scene::data::path(name)).expect("a shipped mesh loads")
}

/// The picture of `eye`, drawn with a pipeline built here from the
/// definitions (the eye moved along the right vector, the frustum shifted
/// by s/2 · near / c), for comparison with `render_stereo`.
fn expected_picture(c: &StereoCamera, eye: Eye, mesh: &Mesh, mode: Mode) -> Canvas {
    let (width, height) = (96, 72);
    let (_, right, _) = frame(c);
    let offset = eye.side() * 0.5 * c.separation * right;
    let top = c.near * (0.5 * c.fov_y).tan();
    let half = top * width as f32 / height as f32;
    let shift = -eye.side() * 0.5 * c.separation * c.near / c.convergence;
    let pipeline = Pipeline {
        model: Mat4::IDENTITY,
        view: view::look_at_mat4(c.eye + offset, c.target + offset, c.up),
        projection: opengl::frustum(-half + shift, half + shift, -top, top, c.near, c.far),
        width,
        height,
    };
    let mut canvas = Canvas::new(width, height);
    pipeline.render(&pipeline.clip_space(mesh), mode, &mut canvas);
    canvas
}

/// Silhouettes may round differently by a pixel where a matrix is
/// computed in another order.
const SILHOUETTES: testkit::image::Tolerance = testkit::image::Tolerance {
    channel: 2.0 / 255.0,
    mismatched_fraction: 0.01,
};

#[testkit::test]
fn render_stereo_draws_each_eye_through_its_own_camera_into_its_own_buffer() {
    let camera = StereoCamera::course(0.3);
    for (name, mode) in [("torus.ply", Mode::Fill), ("star.ply", Mode::Line)] {
        let mesh = mesh(name);
        let buffer = render_stereo(&camera, &mesh, mode, 96, 72).unwrap();
        for eye in Eye::BOTH {
            let expected = expected_picture(&camera, eye, &mesh, mode);
            let yours = buffer.get(eye);
            let comparison = testkit::image::compare(&expected, yours, SILHOUETTES.channel);
            assert!(
                comparison.mismatched
                    <= (SILHOUETTES.mismatched_fraction * comparison.total as f32) as usize
                    && !expected.pixels_not(Rgba::BLACK).is_empty(),
                "{name}, {mode:?}: the {eye:?} picture differs from the one seen through the \
                 {eye:?} eye's camera in {} of {} pixels",
                comparison.mismatched,
                comparison.total
            );
        }
    }
}

#[testkit::test]
fn render_stereo_refuses_a_camera_it_cannot_split() {
    let torus = mesh("torus.ply");
    let good = StereoCamera::course(0.3);
    let cases = [
        (
            StereoCamera {
                eye: Vec3::NAN,
                ..good
            },
            StereoError::NotFinite,
        ),
        (
            StereoCamera {
                convergence: f32::INFINITY,
                ..good
            },
            StereoError::NotFinite,
        ),
        (
            StereoCamera {
                target: good.eye,
                ..good
            },
            StereoError::NoDirection,
        ),
        (
            StereoCamera {
                up: Vec3::new(0.0, 0.0, -2.0),
                ..good
            },
            StereoError::NoDirection,
        ),
        (StereoCamera { near: 0.0, ..good }, StereoError::BadLens),
        (StereoCamera { far: 0.5, ..good }, StereoError::BadLens),
        (StereoCamera { fov_y: 3.2, ..good }, StereoError::BadLens),
        (
            StereoCamera {
                separation: -0.1,
                ..good
            },
            StereoError::BadStereo,
        ),
        (
            StereoCamera {
                convergence: 0.0,
                ..good
            },
            StereoError::BadStereo,
        ),
    ];
    for (camera, error) in cases {
        assert_eq!(
            render_stereo(&camera, &torus, Mode::Fill, 8, 8).err(),
            Some(error),
            "render_stereo must refuse {camera:?} with the error of StereoCamera::check"
        );
    }
    assert_eq!(
        render_stereo(&good, &torus, Mode::Fill, 1 << 15, 1 << 15).err(),
        Some(StereoError::TooLarge)
    );
    let empty = render_stereo(&good, &torus, Mode::Fill, 0, 0).unwrap();
    assert_eq!(
        empty.get(Eye::Left).width(),
        0,
        "an empty picture is no error"
    );
    assert_eq!(aspect_ratio(0, 5), 1.0);
}

/// The torus as a white wireframe: each line is drawn twice, red for the
/// left eye and cyan for the right, apart by its parallax (white where
/// the two coincide, on the zero-parallax plane through the origin).
fn torus_anaglyph() -> Canvas {
    let mut torus = mesh("torus.ply");
    torus.colours.clear();
    let buffer = render_stereo(&StereoCamera::course(0.3), &torus, Mode::Line, 240, 180).unwrap();
    anaglyph(&buffer, Glasses::RedCyan)
}

#[testkit::test]
fn the_torus_anaglyph_matches_the_reference_image() {
    testkit::image::assert_image_matches(
        "stereo_torus_anaglyph",
        &torus_anaglyph(),
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/images/stereo_torus_anaglyph.png"
        ),
        SILHOUETTES,
    );
}
