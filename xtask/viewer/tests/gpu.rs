//! The GPU scene without a window: topic 10's passes on the GPU (lavapipe
//! where there is none), with the solutions, with a piece not written yet
//! and with WGSL that does not compile.

use course_viewer::scenes::gpu::{GpuDrawing, GpuSetup, GpuSurface, Levels, Spacing, draw};
use course_viewer::stages::trim::TrimShape;
use course_viewer::stages::{GpuPieces, decompose, gpu_frame};
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
    // A NURBS surface: split by the solutions' topic 08 first.
    let decomposed = setup.surface.nurbs().map(|data| {
        let (patches, status) = decompose(&Stages::yours(), &data);
        patches.unwrap_or_else(|| panic!("{status:?}"))
    });
    let drawing = gpu_frame(setup, pieces, decomposed.as_ref());
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
    // The chain: the NURBS surfaces split by topic 08, then drawn as
    // above, with the decomposition listed first.
    for (surface, patches) in [(GpuSurface::NurbsTorus, 16), (GpuSurface::Vase, 12)] {
        let drawing = draw(&GpuSetup { surface, ..small() }, &Stages::yours());
        let names: Vec<_> = statuses(&drawing);
        assert_eq!(names[0], ("decomposition", Status::Ok), "{surface:?}");
        assert!(
            names[1..].iter().all(|(_, s)| s.usable()),
            "{surface:?}: {names:?}"
        );
        assert!(drawing.canvas.is_some(), "{surface:?}");
        assert_eq!(drawing.triangles, patches * hill.triangles, "{surface:?}");
    }
}

/// The chain to the GPU: the vase (single interior knots) and the torus
/// from their NURBS data, split by topic 08's decomposition, raised to
/// bicubic and evaluated by topic 10's evaluation pass. Every vertex lies
/// where the NURBS surface's own definition puts it
/// (`testkit::oracles::nurbs_surface`), at the parameters of its patch.
#[test]
fn the_nurbs_chain_reaches_the_gpu_on_the_surface() {
    use gpu_tessellation::passes::{Domain, Patches, run_evaluation};
    let gpu = match gpu::Gpu::new() {
        Ok(gpu) => gpu,
        Err(e) => {
            assert!(
                std::env::var("GPU_REQUIRED").as_deref() != Ok("1"),
                "GPU_REQUIRED=1 but {e}"
            );
            eprintln!("SKIPPED (no GPU): {e}");
            return;
        }
    };
    // A 7 × 7 grid of domain points on each patch.
    let grid = Domain {
        points: (0..=6)
            .flat_map(|j| {
                (0..=6).map(move |i| glam::Vec3::new(i as f32 / 6.0, j as f32 / 6.0, 0.0))
            })
            .collect(),
        triangles: Vec::new(),
    };
    for data in [
        freeform::NurbsSurfaceData::vase(),
        freeform::NurbsSurfaceData::torus(0.7, 0.25),
    ] {
        let (decomposed, status) = decompose(&Stages::yours(), &data);
        let decomposed = decomposed.unwrap_or_else(|| panic!("{status:?}"));
        let raised: Vec<_> = decomposed
            .patches
            .iter()
            .map(|p| p.elevated_to(3, 3).unwrap())
            .collect();
        let domains = vec![&grid; raised.len()];
        let vertices = run_evaluation(&gpu, wgsl::EVALUATION, Patches::Rational(&raised), &domains)
            .unwrap()
            .read(&gpu)
            .unwrap();
        assert_eq!(vertices.len(), raised.len() * 49);
        for (k, vertex) in vertices.iter().enumerate() {
            let patch = k / 49;
            let (row, col) = (patch / decomposed.cols, patch % decomposed.cols);
            let (s, t) = (f64::from(vertex.param.x), f64::from(vertex.param.y));
            let u = (col as f64 + s) / decomposed.cols as f64;
            let v = (row as f64 + t) / decomposed.rows as f64;
            let expected = testkit::oracles::nurbs_surface(&data, u, v);
            let got = vertex.position.truncate().as_dvec3();
            assert!(
                got.distance(expected) < 2e-5,
                "patch {patch} at ({s}, {t}): {got}, S({u}, {v}) = {expected}"
            );
        }
    }
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
