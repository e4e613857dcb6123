//! The GPU scene without a window: topic 10's passes on the GPU (lavapipe
//! where there is none), with the solutions, with a piece not written yet
//! and with WGSL that does not compile.

use course_viewer::gpu_scene::{GpuDrawing, GpuSetup, GpuSurface, Levels, Spacing, draw};
use course_viewer::stages::{GpuPieces, gpu_frame};
use course_viewer::surfaces::TrimShape;
use course_viewer::{Stages, Status};
use gpu_tessellation::wgsl;

fn small() -> GpuSetup {
    GpuSetup {
        width: 160,
        height: 120,
        ..GpuSetup::default()
    }
}

/// The drawing, or `None` after a skip line where there is no adapter
/// (a failure where `GPU_REQUIRED=1`, as under CI).
fn drawn(setup: &GpuSetup, pieces: GpuPieces) -> Option<GpuDrawing> {
    let drawing = gpu_frame(setup, pieces);
    if drawing.device.contains("adapter") && drawing.canvas.is_none() {
        assert!(
            std::env::var("GPU_REQUIRED").as_deref() != Ok("1"),
            "GPU_REQUIRED=1 but {}",
            drawing.device
        );
        eprintln!("SKIPPED (no GPU): {}", drawing.device);
        return None;
    }
    Some(drawing)
}

fn statuses(drawing: &GpuDrawing) -> Vec<(&'static str, Status)> {
    drawing
        .stages
        .iter()
        .map(|s| (s.name, s.status.clone()))
        .collect()
}

#[test]
fn the_solutions_draw_every_surface_on_the_gpu() {
    course_viewer::stages::quiet_panics();
    let Some(hill) = drawn(&small(), GpuPieces::YOURS) else {
        return;
    };
    assert_eq!(
        statuses(&hill),
        [
            ("control", Status::Ok),
            ("primitive generator", Status::Ok),
            ("evaluation", Status::Ok),
            ("shading", Status::Ok),
            ("trimming", Status::Unused),
            ("wireframe", Status::Ok),
        ]
    );
    let canvas = hill.canvas.as_ref().expect("a picture");
    let lit = canvas.pixels_not(canvas::Rgba::BLACK).len();
    assert!(lit > 160 * 120 / 5, "the hill covers {lit} pixels");
    for surface in [GpuSurface::SeedSurface, GpuSurface::Torus] {
        let drawing = drawn(&GpuSetup { surface, ..small() }, GpuPieces::YOURS).unwrap();
        assert!(
            drawing.canvas.is_some(),
            "{surface:?}: {:?}",
            statuses(&drawing)
        );
    }
    // The torus has 16 patches: 16 times the hill's triangles at one level.
    let torus = drawn(
        &GpuSetup {
            surface: GpuSurface::Torus,
            ..small()
        },
        GpuPieces::YOURS,
    )
    .unwrap();
    assert_eq!(torus.triangles, 16 * hill.triangles);
}

#[test]
fn levels_spacing_and_trims_change_the_picture() {
    course_viewer::stages::quiet_panics();
    let Some(base) = drawn(&small(), GpuPieces::YOURS) else {
        return;
    };
    let coarse = drawn(
        &GpuSetup {
            level: 3.0,
            ..small()
        },
        GpuPieces::YOURS,
    )
    .unwrap();
    assert!(coarse.triangles < base.triangles);
    let adaptive = drawn(
        &GpuSetup {
            levels: Levels::Adaptive,
            pixels_per_segment: 4.0,
            ..small()
        },
        GpuPieces::YOURS,
    )
    .unwrap();
    assert_ne!(adaptive.triangles, base.triangles);
    let odd = drawn(
        &GpuSetup {
            level: 5.5,
            spacing: Spacing::FractionalOdd,
            ..small()
        },
        GpuPieces::YOURS,
    )
    .unwrap();
    assert!(odd.canvas.is_some());
    let mut trimmed = small();
    trimmed.trim.shape = TrimShape::Nested;
    let trimmed = drawn(&trimmed, GpuPieces::YOURS).unwrap();
    assert_eq!(trimmed.stages[4].status, Status::Ok, "trimming");
    assert_ne!(
        trimmed.canvas.unwrap().to_image(),
        base.canvas.unwrap().to_image()
    );
}

#[test]
fn an_unwritten_shading_is_named_and_the_given_flat_colour_draws() {
    course_viewer::stages::quiet_panics();
    let pieces = GpuPieces {
        shading: wgsl::SHADING.with_text("// TODO render: write the WGSL fn shade\n"),
        ..GpuPieces::YOURS
    };
    let Some(drawing) = drawn(&small(), pieces) else {
        return;
    };
    assert_eq!(
        drawing.stages[3].status,
        Status::NotYet(
            "render: write the WGSL fn shade (drawn with the given flat colour meanwhile)"
                .to_owned()
        )
    );
    assert!(drawing.canvas.is_some());
}

#[test]
fn wgsl_that_does_not_compile_is_named_at_its_line_and_nothing_is_drawn() {
    course_viewer::stages::quiet_panics();
    let pieces = GpuPieces {
        evaluation: wgsl::EVALUATION.with_text("fn evaluate_patch(patch_index: u32 {\n"),
        ..GpuPieces::YOURS
    };
    let Some(drawing) = drawn(&small(), pieces) else {
        return;
    };
    assert!(
        matches!(&drawing.stages[2].status, Status::Failed(m) if m.contains("src/evaluation.wgsl:1:")),
        "{:?}",
        drawing.stages[2].status
    );
    assert_eq!(drawing.stages[3].status, Status::NotReached);
    assert!(drawing.canvas.is_none());
    // Without topic 10 in the build, every stage is missing.
    let none = draw(&small(), &Stages::default());
    assert!(none.stages.iter().all(|s| s.status == Status::Missing));
}

#[test]
fn every_unwritten_piece_is_named_not_only_the_first() {
    course_viewer::stages::quiet_panics();
    let pieces = GpuPieces {
        control: wgsl::CONTROL.with_text("// TODO control: write fn tessellation_levels\n"),
        evaluation: wgsl::EVALUATION.with_text("// TODO evaluation: write fn evaluate_patch\n"),
        shading: wgsl::SHADING.with_text("// TODO render: write fn shade\n"),
        ..GpuPieces::YOURS
    };
    let mut setup = small();
    setup.trim.shape = TrimShape::Circle;
    let Some(drawing) = drawn(&setup, pieces) else {
        return;
    };
    let not_yet = |m: &str| Status::NotYet(m.to_owned());
    assert_eq!(
        statuses(&drawing),
        [
            ("control", not_yet("control: write fn tessellation_levels")),
            ("primitive generator", Status::NotReached),
            ("evaluation", not_yet("evaluation: write fn evaluate_patch")),
            ("shading", not_yet("render: write fn shade")),
            ("trimming", Status::NotReached),
            ("wireframe", Status::NotReached),
        ]
    );
    assert!(drawing.canvas.is_none());
}
