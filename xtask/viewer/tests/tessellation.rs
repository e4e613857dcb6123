//! The tessellation scene without a window: what it draws with your
//! topic 09 code, right, unfinished or failing.

use std::sync::Arc;

use course_viewer::scenes::tessellation::{
    Look, Method, Surface, TessSetup, Tessellated, Test, draw,
};
use course_viewer::stages::Decomposed;
use course_viewer::{Stages, Status};

fn setup(surface: Surface, method: Method) -> TessSetup {
    TessSetup {
        surface,
        method,
        size: 96,
        ..TessSetup::default()
    }
}

fn tessellated(setup: &TessSetup) -> Tessellated {
    let drawing = draw(setup, &Stages::yours());
    assert_eq!(drawing.status, Status::Ok, "{setup:?}");
    drawing.result.expect("a mesh")
}

#[test]
fn uniform_counts_follow_the_level_and_the_patches() {
    for (surface, patches) in [
        (Surface::SeedSurface, 1),
        (Surface::Hill, 1),
        (Surface::Patches, course_viewer_patches()),
        (Surface::Torus, 16),
        (Surface::NurbsTorus, 16),
        (Surface::Vase, 12),
    ] {
        for level in [1, 5] {
            let result = tessellated(&TessSetup {
                level,
                ..setup(surface, Method::Uniform)
            });
            let n = level as usize;
            assert_eq!(
                result.triangles,
                patches * 2 * n * n,
                "{surface:?} at {level}"
            );
            assert_eq!(
                result.vertices,
                patches * (n + 1) * (n + 1),
                "{surface:?} at {level}"
            );
            let background = canvas::Rgba::WHITE;
            assert!(
                result.canvas.pixels_not(background).len() > 96 * 96 / 10,
                "{surface:?} at {level}: the triangles are drawn"
            );
        }
    }
}

/// The patches of topic 09's example grid, counted from a uniform run at
/// level 1 (two triangles per patch).
fn course_viewer_patches() -> usize {
    let result = tessellated(&TessSetup {
        level: 1,
        ..setup(Surface::Patches, Method::Uniform)
    });
    assert!(result.triangles >= 4, "the example has several patches");
    result.triangles / 2
}

#[test]
fn per_patch_refines_as_the_tolerance_shrinks() {
    let coarse = tessellated(&TessSetup {
        tolerance: 0.05,
        ..setup(Surface::Patches, Method::PerPatch)
    });
    let fine = tessellated(&TessSetup {
        tolerance: 0.001,
        ..setup(Surface::Patches, Method::PerPatch)
    });
    assert!(
        fine.triangles > coarse.triangles,
        "{} triangles at 0.001, {} at 0.05",
        fine.triangles,
        coarse.triangles
    );
}

#[test]
fn fully_adaptive_refines_the_uniform_start() {
    let start = TessSetup {
        level: 8,
        ..setup(Surface::SeedSurface, Method::FullyAdaptive)
    };
    let unrefined = tessellated(&TessSetup { depth: 0, ..start });
    assert_eq!(
        unrefined.triangles,
        2 * 8 * 8,
        "no halving: the uniform start"
    );
    for test in Test::ALL {
        let refined = tessellated(&TessSetup {
            test,
            thresholds: test.default_thresholds(),
            ..start
        });
        assert!(
            refined.triangles > unrefined.triangles,
            "{test:?}: {} triangles",
            refined.triangles
        );
    }
    let loose = tessellated(&TessSetup {
        thresholds: [0.5, 0.3],
        ..start
    });
    let strict = tessellated(&TessSetup {
        thresholds: [0.05, 0.3],
        ..start
    });
    assert!(strict.triangles > loose.triangles);
}

#[test]
fn the_look_changes_the_picture() {
    let base = setup(Surface::Hill, Method::Uniform);
    let pictures: Vec<_> = [Look::Shaded, Look::Wireframe, Look::Both]
        .into_iter()
        .map(|look| tessellated(&TessSetup { look, ..base }).canvas.to_image())
        .collect();
    assert_ne!(pictures[0], pictures[1]);
    assert_ne!(pictures[1], pictures[2]);
    let turned = tessellated(&TessSetup { yaw: -60.0, ..base })
        .canvas
        .to_image();
    assert_ne!(turned, pictures[2]);
}

#[test]
fn an_unwritten_or_failing_tessellation_is_named() {
    course_viewer::stages::quiet_panics();
    let mut stages = Stages::yours();
    stages.tessellate.run = Some(Arc::new(
        |_: &TessSetup, _: Option<&Decomposed>| -> Result<Tessellated, String> {
            todo!("uniform: sample the (n_u+1)×(n_v+1) grid, then two triangles per cell")
        },
    ));
    let drawing = draw(&TessSetup::default(), &stages);
    assert_eq!(
        drawing.status,
        Status::NotYet(
            "uniform: sample the (n_u+1)×(n_v+1) grid, then two triangles per cell".to_owned()
        )
    );
    assert!(drawing.result.is_none());

    stages.tessellate.run = Some(Arc::new(
        |_: &TessSetup, _: Option<&Decomposed>| -> Result<Tessellated, String> {
            Err("the refinement would exceed 4194304 triangles".to_owned())
        },
    ));
    let drawing = draw(&TessSetup::default(), &stages);
    assert_eq!(
        drawing.status,
        Status::Failed("the refinement would exceed 4194304 triangles".to_owned())
    );

    let none = draw(&TessSetup::default(), &Stages::default());
    assert_eq!(
        none.status,
        Status::Missing,
        "without topic 09 in the build"
    );
}

#[test]
fn a_set_up_is_kept_drawable() {
    let mut setup = TessSetup {
        level: 0,
        tolerance: -1.0,
        thresholds: [f64::NAN, 0.0],
        depth: 99,
        yaw: f64::INFINITY,
        size: 3,
        ..TessSetup::default()
    };
    setup.tidy();
    assert_eq!(setup.level, 1);
    assert!(setup.tolerance > 0.0);
    assert!(setup.thresholds.iter().all(|t| *t > 0.0 && t.is_finite()));
    assert_eq!(setup.depth, course_viewer::scenes::tessellation::MAX_DEPTH);
    assert!(setup.yaw.is_finite());
    assert_eq!(setup.size, 16);
    assert_eq!(draw(&setup, &Stages::yours()).status, Status::Ok);
}

/// The chain the NURBS surfaces take: the data, split into rational
/// Bézier patches by topic 08's decomposition, tessellated by topic 09.
/// Every vertex lies where the NURBS surface's own definition puts it
/// (`testkit::oracles::nurbs_surface`, the double sum over the whole
/// net), at the parameters the patch grid gives it: both surfaces' spans
/// are equal, so the grid's `(u, v)` is the surface's times the spans.
#[test]
fn the_nurbs_chain_lands_every_vertex_on_the_surface() {
    for surface in [Surface::Vase, Surface::NurbsTorus] {
        let data = surface.nurbs().expect("a NURBS surface");
        let (spans_u, spans_v) = data.pieces();
        for method in [Method::Uniform, Method::PerPatch, Method::FullyAdaptive] {
            let drawing = draw(&setup(surface, method), &Stages::yours());
            assert_eq!(drawing.decomposition, Status::Ok, "{surface:?}");
            assert_eq!(drawing.status, Status::Ok, "{surface:?} {method:?}");
            let mesh = drawing.result.expect("a mesh");
            assert!(mesh.positions.len() > 12 * 4, "{surface:?} {method:?}");
            for (p, uv) in mesh.positions.iter().zip(&mesh.uvs) {
                let (u, v) = (uv.x / spans_u as f64, uv.y / spans_v as f64);
                let expected = testkit::oracles::nurbs_surface(&data, u, v);
                assert!(
                    p.distance(expected) < 1e-9,
                    "{surface:?} {method:?}: the vertex at {uv} is {p}, S({u}, {v}) = {expected}"
                );
            }
        }
    }
}

#[test]
fn an_unwritten_decomposition_is_named_and_stops_the_chain() {
    course_viewer::stages::quiet_panics();
    let mut stages = Stages::yours();
    stages.decompose.run = Some(Arc::new(
        |_: &freeform::NurbsSurfaceData| -> Result<Decomposed, String> {
            todo!("decompose: raise every interior knot to multiplicity p")
        },
    ));
    let drawing = draw(&setup(Surface::Vase, Method::Uniform), &stages);
    assert_eq!(
        drawing.decomposition,
        Status::NotYet("decompose: raise every interior knot to multiplicity p".to_owned())
    );
    assert_eq!(drawing.status, Status::NotReached);
    assert!(drawing.result.is_none());
    // The given surfaces do not need it.
    let torus = draw(&setup(Surface::Torus, Method::Uniform), &stages);
    assert_eq!(
        (torus.decomposition, torus.status),
        (Status::Unused, Status::Ok)
    );
    stages.decompose.run = None;
    let drawing = draw(&setup(Surface::NurbsTorus, Method::Uniform), &stages);
    assert_eq!(drawing.decomposition, Status::Missing, "without topic 08");
}

/// The report's chain picture is what the solutions draw (this suite runs
/// with them staged): regenerate it with `cargo xtask view --reference --
/// --chain vase --screenshot xtask/viewer/expected/nurbs-chain-vase.png
/// --size 200` when the chain changes, and look at it.
#[test]
fn the_reports_chain_picture_is_what_the_solutions_draw() {
    use course_viewer::scenes::mesh::REPORT_SIZE;
    use course_viewer::scenes::tessellation::{REPORT_CHAIN, chain_setup};
    let (file, surface) = REPORT_CHAIN;
    let drawing = draw(&chain_setup(surface, REPORT_SIZE), &Stages::yours());
    let picture = drawing.result.expect("the solutions draw the chain").canvas;
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("expected")
        .join(file);
    let expected =
        canvas::Canvas::load_png(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert_eq!(
        picture.to_image(),
        expected.to_image(),
        "{file} is not what the solutions draw"
    );
}
