//! Task 1: tessellation levels per patch, computed by your WGSL
//! `tessellation_levels` in a compute pass.

mod common;

use glam::{DMat4, DVec2, DVec4, Mat4, Vec2, Vec3};
use gpu_tessellation::passes::{ControlSettings, LevelMode, run_control};
use gpu_tessellation::passes::{MAX_TESS_LEVEL, QuadLevels};
use gpu_tessellation::patch::BezierPatch;
use gpu_tessellation::wgsl;
use proptest::prelude::*;

/// Viewport of the adaptive tests.
const VIEWPORT: Vec2 = Vec2::new(640.0, 480.0);

/// Control-point indices of the four boundaries, in `outer` order.
const BOUNDARIES: [[usize; 4]; 4] = [
    [0, 4, 8, 12],
    [0, 1, 2, 3],
    [3, 7, 11, 15],
    [12, 13, 14, 15],
];

fn camera(eye: Vec3) -> Mat4 {
    let proj =
        glam::camera::rh::proj::directx::perspective(0.9, VIEWPORT.x / VIEWPORT.y, 0.1, 50.0);
    proj * glam::camera::rh::view::look_at_mat4(eye, Vec3::ZERO, Vec3::Y)
}

/// The definition in f64: control polygon length in pixels over the target.
fn cpu_levels(patch: &BezierPatch, view_proj: Mat4, pixels_per_segment: f64) -> QuadLevels {
    let m: DMat4 = view_proj.as_dmat4();
    let project = |k: usize| {
        let c = m * DVec4::from((common::gl_points(patch)[k], 1.0));
        // The GPU's viewport transform: the same pixels the shader measures in.
        (c.w > 1e-6).then(|| {
            canvas::ndc_to_window(
                c.truncate().truncate() / c.w,
                VIEWPORT.x as u32,
                VIEWPORT.y as u32,
            )
        })
    };
    let outer = BOUNDARIES.map(|b| {
        let pts: Option<Vec<_>> = b.iter().map(|&k| project(k)).collect();
        match pts {
            None => MAX_TESS_LEVEL,
            Some(p) => {
                let length: f64 = p.windows(2).map(|w| w[0].distance(w[1])).sum();
                (length / pixels_per_segment).clamp(1.0, f64::from(MAX_TESS_LEVEL)) as f32
            }
        }
    });
    QuadLevels {
        outer,
        inner: [outer[1].max(outer[3]), outer[0].max(outer[2])],
    }
}

fn close(gpu: f32, cpu: f32) -> bool {
    (gpu - cpu).abs() <= 1e-4 * cpu.abs() + 1e-3
}

#[testkit::test]
fn uniform_levels_are_clamped_to_one_and_64() {
    let piece = wgsl::CONTROL.written();
    let Some(gpu) = common::gpu() else { return };
    let patches = [BezierPatch::flat(DVec2::ZERO, DVec2::ONE, 0.0)];
    for (asked, expected) in [
        (7.25, 7.25),
        (0.5, 1.0),
        (1.0, 1.0),
        (64.0, 64.0),
        (1000.0, 64.0),
    ] {
        let settings = ControlSettings {
            view_proj: Mat4::IDENTITY,
            viewport: VIEWPORT,
            mode: LevelMode::Uniform(asked),
        };
        let levels = run_control(&gpu, piece, &patches, &settings).unwrap();
        assert_eq!(
            levels,
            [QuadLevels::uniform(expected)],
            "uniform level {asked}"
        );
    }
}

#[testkit::test]
fn a_boundary_at_or_behind_the_eye_gets_the_maximum_level() {
    let piece = wgsl::CONTROL.written();
    let Some(gpu) = common::gpu() else { return };
    // Eye at z = 3 looking at the origin; P0 lies behind it, at z = 4.
    let flat = BezierPatch::flat(DVec2::splat(-0.5), DVec2::splat(0.5), 0.0);
    let mut points = common::gl_points(&flat);
    points[0].z = 4.0;
    let patch = common::from_gl_points(points);
    let view_proj = camera(Vec3::new(0.0, 0.0, 3.0));
    let settings = ControlSettings {
        view_proj,
        viewport: VIEWPORT,
        mode: LevelMode::Adaptive {
            pixels_per_segment: 10.0,
        },
    };
    let levels = run_control(&gpu, piece, std::slice::from_ref(&patch), &settings).unwrap()[0];
    assert_eq!(
        levels.outer[0], MAX_TESS_LEVEL,
        "u = 0 holds P0: {levels:?}"
    );
    assert_eq!(
        levels.outer[1], MAX_TESS_LEVEL,
        "v = 0 holds P0: {levels:?}"
    );
    let expected = cpu_levels(&patch, view_proj, 10.0);
    assert!(
        close(levels.outer[2], expected.outer[2]),
        "{levels:?} vs {expected:?}"
    );
    assert!(
        close(levels.outer[3], expected.outer[3]),
        "{levels:?} vs {expected:?}"
    );
    assert_eq!(levels.inner, [MAX_TESS_LEVEL; 2]);
}

/// ```text
///   A: P12 ··· P15     B: P12 ··· P15      B's u = 0 boundary is A's u = 1
///      :        :  ==     :        :      boundary, run the other way:
///      P0  ··· P3         P0  ··· P3      B.P0 = A.P15, ..., B.P12 = A.P3
/// ```
fn neighbour_sharing_reversed_boundary(a: &BezierPatch, rest: &BezierPatch) -> BezierPatch {
    let (a, mut b) = (common::gl_points(a), common::gl_points(rest));
    for (bk, ak) in [(0, 15), (4, 11), (8, 7), (12, 3)] {
        b[bk] = a[ak];
    }
    common::from_gl_points(b)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 12, ..testkit::proptest_config() })]

    #[testkit::test]
    fn adaptive_levels_follow_the_projected_control_polygon(
        patches in prop::collection::vec(common::patch(), 1..40),
        eye in (-1.5f32..1.5, -1.5f32..1.5, 3.0f32..6.0),
        target in 2.0f32..40.0,
    ) {
        let piece = wgsl::CONTROL.written();
        let Some(gpu) = common::gpu() else { return Ok(()) };
        let view_proj = camera(Vec3::new(eye.0, eye.1, eye.2));
        let settings = ControlSettings {
            view_proj,
            viewport: VIEWPORT,
            mode: LevelMode::Adaptive { pixels_per_segment: target },
        };
        let levels = run_control(&gpu, piece, &patches, &settings).unwrap();
        prop_assert_eq!(levels.len(), patches.len());
        for (patch, got) in patches.iter().zip(&levels) {
            let expected = cpu_levels(patch, view_proj, f64::from(target));
            let pairs = got.outer.iter().zip(&expected.outer).chain(got.inner.iter().zip(&expected.inner));
            for (g, e) in pairs {
                prop_assert!(close(*g, *e), "levels {:?}, expected {:?}", got, expected);
            }
        }
    }

    #[testkit::test]
    fn a_shared_boundary_gets_bit_identical_levels_from_both_patches(
        pairs in prop::collection::vec((common::patch(), common::patch()), 1..20),
        eye in (-1.5f32..1.5, -1.5f32..1.5, 3.0f32..6.0),
    ) {
        let piece = wgsl::CONTROL.written();
        let Some(gpu) = common::gpu() else { return Ok(()) };
        let patches: Vec<BezierPatch> = pairs
            .iter()
            .flat_map(|(a, rest)| [a.clone(), neighbour_sharing_reversed_boundary(a, rest)])
            .collect();
        let settings = ControlSettings {
            view_proj: camera(Vec3::new(eye.0, eye.1, eye.2)),
            viewport: VIEWPORT,
            mode: LevelMode::Adaptive { pixels_per_segment: 37.0 },
        };
        let levels = run_control(&gpu, piece, &patches, &settings).unwrap();
        for pair in levels.chunks_exact(2) {
            prop_assert_eq!(
                pair[0].outer[2].to_bits(),
                pair[1].outer[0].to_bits(),
                "A's u = 1 level {} but B's u = 0 level {}",
                pair[0].outer[2],
                pair[1].outer[0]
            );
        }
    }
}
