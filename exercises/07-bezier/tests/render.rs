//! Task 6: the CPU render of a trimmed Bézier surface — tessellation,
//! z-buffer, discard, Phong with the seed's two lights, wireframe
//! (seed 000, §4.1–4.2.3, Listing 13, Figs. 15, 21, 26).

mod common;

use bezier::render::{
    MAX_TESS_LEVEL, RenderSettings, SHININESS, SurfaceSample, phong, render_surface,
};
use bezier::{BezierError, BezierPatch};
use canvas::Canvas;
use glam::{DVec2, DVec3};

fn settings(wireframe: bool) -> RenderSettings {
    RenderSettings {
        camera: common::FIGURE_CAMERA,
        tess_level: 24,
        wireframe,
        background: common::BACKGROUND,
    }
}

fn hill(uv: DVec2) -> Result<SurfaceSample, BezierError> {
    Ok(common::sample_def(&BezierPatch::seed_hill(), uv))
}

#[testkit::test]
fn phong_lit_from_above_seen_from_the_side() {
    // n = +y at the origin: light 1 at (0, 10, 0) gives φ₁ = 1, its
    // reflection (0, 1, 0) misses the eye on +z (ψ₁ = 0); light 2 below
    // gives φ₂ = 0, ψ₂ = 0. Colour = 0.1 d + d.
    let d = DVec3::new(0.5, 0.25, 1.0);
    let c = phong(DVec3::Y, DVec3::ZERO, DVec3::new(0.0, 0.0, 10.0), d);
    assert!(c.abs_diff_eq(d * 1.1, 1e-15), "{c}");
}

#[testkit::test]
fn phong_highlight_when_the_eye_is_in_the_reflection() {
    // Eye straight above: r₁ · e = 1, so ψ₁ = 1 and white is added.
    let d = DVec3::new(0.5, 0.25, 1.0);
    let c = phong(DVec3::Y, DVec3::ZERO, DVec3::new(0.0, 5.0, 0.0), d);
    assert!(c.abs_diff_eq(d * 1.1 + DVec3::ONE, 1e-15), "{c}");
    // Tilted 10° away: r₁ · e = cos 10°, and cos¹⁵⁰(10°) ≈ 0.10 of the
    // highlight is left.
    let e = DVec3::new(
        0.0,
        10.0_f64.to_radians().cos(),
        10.0_f64.to_radians().sin(),
    ) * 5.0;
    let c = phong(DVec3::Y, DVec3::ZERO, e, d);
    let psi = 10.0_f64.to_radians().cos().powf(SHININESS);
    assert!(
        c.abs_diff_eq(d * 1.1 + DVec3::splat(psi), 1e-12),
        "{c} (ψ = {psi})"
    );
}

#[testkit::test]
fn phong_underside_is_lit_by_the_second_light() {
    // n = −y: light 2 at (0, −10, 0) is straight below, eye below too.
    let d = DVec3::new(0.2, 0.4, 0.6);
    let c = phong(DVec3::NEG_Y, DVec3::ZERO, DVec3::new(0.0, -3.0, 0.0), d);
    assert!(c.abs_diff_eq(d * 1.1 + DVec3::ONE, 1e-15), "{c}");
}

#[testkit::test]
fn bad_levels_and_surface_errors_are_reported() {
    let mut canvas = Canvas::new(8, 8);
    for level in [0, MAX_TESS_LEVEL + 1] {
        let s = RenderSettings {
            tess_level: level,
            ..settings(false)
        };
        assert!(matches!(
            render_surface(&mut canvas, hill, &common::NoTrim, &s),
            Err(BezierError::InvalidSetting(_))
        ));
    }
    let failing = |_uv: DVec2| Err(BezierError::Empty);
    assert_eq!(
        render_surface(&mut canvas, failing, &common::NoTrim, &settings(false)),
        Err(BezierError::Empty)
    );
}

#[testkit::test]
fn trimming_everything_leaves_the_background() {
    struct All;
    impl bezier::Trim for All {
        fn trims(&self, _uv: DVec2) -> bool {
            true
        }
    }
    let [w, h] = common::FIGURE_SIZE;
    let mut canvas = Canvas::new(w, h);
    render_surface(&mut canvas, hill, &All, &settings(false)).unwrap();
    // The canvas stores 8-bit levels: compare with the stored background.
    let background = canvas::Rgba::from_rgba8(common::BACKGROUND.to_rgba8());
    assert!(canvas.pixels_not(background).is_empty());
    // Without the trim the hill covers a good part of the picture.
    render_surface(&mut canvas, hill, &common::NoTrim, &settings(false)).unwrap();
    let covered = canvas.pixels_not(background).len();
    assert!(covered > (w * h / 5) as usize, "{covered} pixels");
}

#[testkit::test]
fn figure_lit_hill_with_a_hole_and_wireframe() {
    // Seed Figs. 15 and 26: the hill, a circle trimmed, two lights, the grid.
    let [w, h] = common::FIGURE_SIZE;
    let mut canvas = Canvas::new(w, h);
    let disc = common::Disc {
        centre: DVec2::splat(0.5),
        radius: 0.2,
    };
    let coarse = RenderSettings {
        tess_level: 12,
        ..settings(true)
    };
    render_surface(&mut canvas, hill, &disc, &coarse).unwrap();
    testkit::image::assert_image_matches(
        "render_hill_wireframe",
        &canvas,
        common::image_path("render_hill_wireframe"),
        testkit::image::Tolerance {
            channel: 2.0 / 255.0,
            mismatched_fraction: 0.001,
        },
    );
}

#[testkit::test]
fn figure_lit_hill_seen_from_below() {
    // The second light at (0, −10, 0) is below the hill; the normals are
    // the surface's own, not flipped (one-sided lighting).
    let [w, h] = common::FIGURE_SIZE;
    let mut canvas = Canvas::new(w, h);
    let below = RenderSettings {
        camera: bezier::zbuffer::Camera {
            eye: DVec3::new(0.3, -1.4, 1.2),
            target: DVec3::new(0.0, 0.1, 0.0),
            up: DVec3::Y,
            fov_y_degrees: 40.0,
        },
        ..settings(false)
    };
    let disc = common::Disc {
        centre: DVec2::new(0.3, 0.6),
        radius: 0.15,
    };
    render_surface(&mut canvas, hill, &disc, &below).unwrap();
    testkit::image::assert_image_matches(
        "render_hill_below",
        &canvas,
        common::image_path("render_hill_below"),
        testkit::image::Tolerance {
            channel: 2.0 / 255.0,
            mismatched_fraction: 0.001,
        },
    );
}
