//! Task 6: the CPU render of a trimmed Bézier surface — tessellation,
//! z-buffer, discard, Phong with the seed's two lights, wireframe
//! (seed 000, §4.1–4.2.3, Listing 13, Figs. 15, 19, 21, 25–27).

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
    assert!(
        c.abs_diff_eq(d * 1.1, 1e-15),
        "phong(n = +y at the origin, eye (0, 0, 10), d = {d}): light 1 above gives φ₁ = 1, its \
         reflection misses the eye (ψ₁ = 0), light 2 below gives nothing: d · AMBIENT + d = \
         {}; yours {c}",
        d * 1.1
    );
}

#[testkit::test]
fn phong_highlight_when_the_eye_is_in_the_reflection() {
    // Eye straight above: r₁ · e = 1, so ψ₁ = 1 and white is added.
    let d = DVec3::new(0.5, 0.25, 1.0);
    let c = phong(DVec3::Y, DVec3::ZERO, DVec3::new(0.0, 5.0, 0.0), d);
    assert!(
        c.abs_diff_eq(d * 1.1 + DVec3::ONE, 1e-15),
        "phong(n = +y at the origin, eye (0, 5, 0), d = {d}): the eye lies in light 1's \
         reflection, r₁ · e = 1, ψ₁ = 1: d · 1.1 + SPECULAR = {}; yours {c}",
        d * 1.1 + DVec3::ONE
    );
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
        "phong(n = +y, the eye 10° off the reflection, d = {d}): ψ₁ = max(r₁ · e, 0)^150 = \
         cos¹⁵⁰(10°) = {psi}, colour d · 1.1 + ψ₁ · SPECULAR = {}; yours {c}",
        d * 1.1 + DVec3::splat(psi)
    );
}

#[testkit::test]
fn phong_underside_is_lit_by_the_second_light() {
    // n = −y: light 2 at (0, −10, 0) is straight below, eye below too.
    let d = DVec3::new(0.2, 0.4, 0.6);
    let c = phong(DVec3::NEG_Y, DVec3::ZERO, DVec3::new(0.0, -3.0, 0.0), d);
    assert!(
        c.abs_diff_eq(d * 1.1 + DVec3::ONE, 1e-15),
        "phong(n = −y at the origin, eye (0, −3, 0), d = {d}): light 2 at (0, −10, 0) lies \
         straight below, φ₂ = 1, and the eye in its reflection, ψ₂ = 1: d · 1.1 + SPECULAR = \
         {}; yours {c}",
        d * 1.1 + DVec3::ONE
    );
}

#[testkit::test]
fn bad_levels_and_surface_errors_are_reported() {
    let mut canvas = Canvas::new(8, 8);
    for level in [0, MAX_TESS_LEVEL + 1] {
        let s = RenderSettings {
            tess_level: level,
            ..settings(false)
        };
        let yours = render_surface(&mut canvas, hill, &common::NoTrim, &s);
        assert!(
            matches!(yours, Err(BezierError::InvalidSetting(_))),
            "render_surface with tess_level {level}: a level of 0 or above MAX_TESS_LEVEL = \
             {MAX_TESS_LEVEL} is InvalidSetting; yours {yours:?}"
        );
    }
    let failing = |_uv: DVec2| Err(BezierError::Empty);
    assert_eq!(
        render_surface(&mut canvas, failing, &common::NoTrim, &settings(false)),
        Err(BezierError::Empty),
        "render_surface with a surface closure that fails: its error is passed on"
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
    let drawn = canvas.pixels_not(background);
    assert!(
        drawn.is_empty(),
        "render_surface with a trim that trims every (u, v): every fragment is discarded, only \
         the background is left; yours drew {} pixels, first {:?}",
        drawn.len(),
        drawn.first()
    );
    // Without the trim the hill covers a good part of the picture.
    render_surface(&mut canvas, hill, &common::NoTrim, &settings(false)).unwrap();
    let covered = canvas.pixels_not(background).len();
    assert!(
        covered > (w * h / 5) as usize,
        "render_surface of the hill without a trim covers more than a fifth of the {w} × {h} \
         picture, {} pixels; yours {covered}",
        w * h / 5
    );
}

#[testkit::test]
fn figure_lit_hill_with_a_hole_and_wireframe() {
    // Seed 000, Abb. 15 and 21: the hill, a circle trimmed, two lights, the grid.
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

/// Compares a figure with its reference image.
fn check_figure(name: &str, canvas: &Canvas) {
    testkit::image::assert_image_matches(
        name,
        canvas,
        common::image_path(name),
        testkit::image::Tolerance {
            channel: 2.0 / 255.0,
            mismatched_fraction: 0.001,
        },
    );
}

/// Seed Abb. 19's trim: two ellipses cut out, by their closed forms (this
/// task's pictures do not rest on the trim tasks).
struct TwoEllipses([(DVec2, DVec2); 2]);

impl bezier::Trim for TwoEllipses {
    fn trims(&self, uv: DVec2) -> bool {
        self.0
            .iter()
            .any(|&(centre, radii)| ((uv - centre) / radii).length_squared() < 1.0)
    }
}

/// The region between an upper and a lower cubic Bézier curve whose
/// control points are evenly spaced in `u` from `u0` to `u1` (so that `u`
/// is linear in the curve parameter and `v` a cubic in it: seed 000's
/// eq. (2) in closed form), sharing their ends.
#[derive(Clone, Copy)]
struct CubicRegion {
    u0: f64,
    u1: f64,
    upper: [f64; 4],
    lower: [f64; 4],
}

impl CubicRegion {
    fn contains(&self, uv: DVec2) -> bool {
        let t = (uv.x - self.u0) / (self.u1 - self.u0);
        if !(0.0..=1.0).contains(&t) {
            return false;
        }
        let s = 1.0 - t;
        let v = |c: [f64; 4]| {
            c[0] * s * s * s + 3.0 * c[1] * t * s * s + 3.0 * c[2] * t * t * s + c[3] * t * t * t
        };
        uv.y < v(self.upper) && uv.y > v(self.lower)
    }
}

/// Seed Abb. 25 and 26: a cubic region cut out, with a smaller cubic
/// region inside it kept.
struct NestedCubics {
    outer: CubicRegion,
    inner: CubicRegion,
}

impl bezier::Trim for NestedCubics {
    fn trims(&self, uv: DVec2) -> bool {
        self.outer.contains(uv) && !self.inner.contains(uv)
    }
}

/// The seed's cubic region (`freeform::trim::CUBIC_REGION`: its inner
/// control points at thirds in `u`, so `u` is linear along both curves and
/// the region is its `v` coefficients) and a smaller one inside.
const NESTED_CUBICS: NestedCubics = NestedCubics {
    outer: {
        let p = freeform::trim::CUBIC_REGION;
        CubicRegion {
            u0: p[0].x,
            u1: p[3].x,
            upper: [p[0].y, p[1].y, p[2].y, p[3].y],
            lower: [p[0].y, p[4].y, p[5].y, p[3].y],
        }
    },
    inner: CubicRegion {
        u0: 0.3,
        u1: 0.7,
        upper: [0.5, 0.7, 0.62, 0.5],
        lower: [0.5, 0.36, 0.3, 0.5],
    },
};

#[testkit::test]
fn figure_hill_textured_with_two_ellipses_cut_out() {
    // Seed Abb. 19: the hill, lit and textured (the checker stands in for
    // the seed's bricks), two ellipses trimmed.
    let [w, h] = common::FIGURE_SIZE;
    let mut canvas = Canvas::new(w, h);
    let ellipses = TwoEllipses([
        (DVec2::new(0.3, 0.35), DVec2::new(0.18, 0.1)),
        (DVec2::new(0.65, 0.65), DVec2::new(0.12, 0.22)),
    ]);
    render_surface(&mut canvas, hill, &ellipses, &settings(false)).unwrap();
    check_figure("render_two_ellipses", &canvas);
}

#[testkit::test]
fn figure_nested_cubic_regions_solid_and_wireframe() {
    // Seed Abb. 25 and 26: a cubic region cut out with a cubic region kept
    // inside it, shaded (left) and in wireframe mode (right).
    let [w, h] = common::FIGURE_SIZE;
    let mut strip = Canvas::new(2 * w, h);
    for (k, wireframe) in [false, true].into_iter().enumerate() {
        let mut panel = Canvas::new(w, h);
        render_surface(&mut panel, hill, &NESTED_CUBICS, &settings(wireframe)).unwrap();
        for (p, colour) in panel.enumerate() {
            strip.set(canvas::Pixel::new(p.x + (k as u32 * w) as i32, p.y), colour);
        }
    }
    check_figure("render_nested_cubics", &strip);
}

#[testkit::test]
fn figure_several_trimmed_surfaces() {
    // Seed Abb. 27: several trimmed Bézier surfaces rendered: the hill
    // with a disc, a saddle with two ellipses, a wave with the nested cubic
    // regions.
    // Bicubic patches laid out as the hill is (u along +x, v along −z, the
    // heights in y), with other heights.
    let lifted = |heights: [[f64; 4]; 4]| {
        BezierPatch::from_fn(3, 3, |i, j| {
            DVec3::new(-0.5 + i as f64 / 3.0, heights[j][i], 0.5 - j as f64 / 3.0)
        })
        .unwrap()
    };
    let saddle = lifted([
        [0.35, 0.15, 0.05, 0.0],
        [0.15, 0.1, 0.1, 0.05],
        [0.05, 0.1, 0.1, 0.15],
        [0.0, 0.05, 0.15, 0.35],
    ]);
    let wave = lifted([
        [0.0, 0.25, 0.0, 0.1],
        [0.1, 0.0, 0.3, 0.0],
        [0.0, 0.35, 0.0, 0.2],
        [0.15, 0.0, 0.2, 0.0],
    ]);
    let disc = common::Disc {
        centre: DVec2::new(0.5, 0.45),
        radius: 0.2,
    };
    let ellipses = TwoEllipses([
        (DVec2::new(0.3, 0.3), DVec2::new(0.15, 0.1)),
        (DVec2::new(0.7, 0.7), DVec2::new(0.1, 0.18)),
    ]);
    let surfaces: [(BezierPatch, &dyn bezier::Trim); 3] = [
        (BezierPatch::seed_hill(), &disc),
        (saddle, &ellipses),
        (wave, &NESTED_CUBICS),
    ];
    let [w, h] = common::FIGURE_SIZE;
    let mut strip = Canvas::new(3 * w, h);
    for (k, (patch, trim)) in surfaces.iter().enumerate() {
        let mut panel = Canvas::new(w, h);
        let surface = |uv: DVec2| Ok(common::sample_def(patch, uv));
        render_surface(&mut panel, surface, *trim, &settings(false)).unwrap();
        for (p, colour) in panel.enumerate() {
            strip.set(canvas::Pixel::new(p.x + (k as u32 * w) as i32, p.y), colour);
        }
    }
    check_figure("render_several_surfaces", &strip);
}
