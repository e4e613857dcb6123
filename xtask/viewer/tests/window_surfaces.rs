//! The surface, tessellation and GPU scenes in the window, driven by
//! egui_kittest: your trimmed hill, your triangles, your GPU passes.
#![cfg(feature = "window")]

mod common;

use std::sync::Arc;
use std::time::Duration;

use common::harness;
use course_viewer::{Stages, ViewerApp};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

/// Waits for the surface scene's drawing and lets the window show it.
fn settle_surfaces(harness: &mut Harness<'static, ViewerApp>) {
    assert!(
        harness
            .state_mut()
            .wait_for_surface(Duration::from_secs(60)),
        "no surface within a minute"
    );
    harness.run_steps(3);
}

#[test]
fn the_surface_scene_draws_your_trimmed_hill() {
    let mut harness = harness(Stages::yours());
    harness.get_by_label("Surfaces").click();
    harness.run_steps(2);
    settle_surfaces(&mut harness);
    harness.get_by_label("surface: ok");
    harness.get_by_label("trim: ok");
    harness.get_by_label("render: ok");
    harness.get_by_label("07-bezier · simple_trim::CircleTrim::trims");
    let circle = harness.state().surface_drawing().unwrap().clone();
    harness.snapshot("viewer_surfaces");

    // Another trim from the menu: its parameters show, the picture changes.
    harness.get_by_label("Trim").click();
    harness.run_steps(2);
    harness.get_by_label("Newton, nested").click();
    harness.run_steps(2);
    assert!(
        harness.get_all_by_label("Newton steps").next().is_some(),
        "Newton's settings show for a Newton trim"
    );
    settle_surfaces(&mut harness);
    let nested = harness.state().surface_drawing().unwrap();
    assert_eq!(
        nested.setup.trim.shape,
        course_viewer::scenes::surfaces::TrimShape::Nested
    );
    assert_ne!(
        nested.cut, circle.cut,
        "the parameter square shows the new trim"
    );
    assert_ne!(nested.canvas.to_image(), circle.canvas.to_image());
    harness.get_by_label("07-bezier · newton_trim::NestedNewtonTrim::trims");

    // The wireframe, by its checkbox.
    harness.get_by_label("Wireframe").click();
    harness.run_steps(2);
    settle_surfaces(&mut harness);
    assert!(harness.state().surface_drawing().unwrap().setup.wireframe);
}

#[test]
fn an_unwritten_render_is_named_in_the_surface_scene() {
    let mut stages = Stages::yours();
    stages.surface_render.run = Some(Arc::new(
        |_: &mut canvas::Canvas,
         _: &dyn Fn(glam::DVec2) -> Result<(glam::DVec3, glam::DVec3), String>,
         _: &dyn Fn(glam::DVec2) -> bool,
         _: &course_viewer::stages::SurfaceView|
         -> Result<(), String> { todo!("render: check the level; sample the grid") },
    ));
    let mut harness = harness(stages);
    harness
        .state_mut()
        .set_scene(course_viewer::Scene::Surfaces);
    harness.run_steps(2);
    settle_surfaces(&mut harness);
    harness.get_by_label("render: not written yet: render: check the level; sample the grid");
    harness.get_by_label("surface: ok");
    let drawing = harness.state().surface_drawing().unwrap();
    assert!(
        drawing
            .canvas
            .pixels_not(canvas::Rgba::from_rgba8(
                course_viewer::scenes::surfaces::BACKGROUND.to_rgba8()
            ))
            .is_empty(),
        "nothing is drawn in its place"
    );
}

/// Waits for the tessellation scene's drawing and lets the window show it.
fn settle_tessellation(harness: &mut Harness<'static, ViewerApp>) {
    assert!(
        harness
            .state_mut()
            .wait_for_tessellation(Duration::from_secs(60)),
        "no tessellation within a minute"
    );
    harness.run_steps(3);
}

#[test]
fn the_tessellation_scene_draws_your_triangles() {
    let mut harness = harness(Stages::yours());
    harness.get_by_label("Tessellation").click();
    harness.run_steps(2);
    settle_tessellation(&mut harness);
    harness.get_by_label("tessellation: ok");
    harness.get_by_label("400 vertices, 512 triangles");
    harness.snapshot("viewer_tessellation");

    // Fully adaptive, by its radio button: the edge test refines the start.
    harness.get_by_label("Fully adaptive").click();
    harness.run_steps(2);
    settle_tessellation(&mut harness);
    harness.get_by_label("Edge test");
    let drawing = harness.state().tessellation_drawing().unwrap();
    assert_eq!(
        drawing.setup.method,
        course_viewer::scenes::tessellation::Method::FullyAdaptive
    );
    let triangles = drawing.result.as_ref().unwrap().triangles;
    assert!(triangles > 512, "{triangles} triangles");
    harness.get_by_label(
        "09-tessellation · fully_adaptive::refine with edge_tests, from tessellate_uniform",
    );
}

#[test]
fn the_gpu_scene_draws_with_your_passes() {
    let mut harness = harness(Stages::yours());
    harness.get_by_label("GPU").click();
    harness.run_steps(2);
    assert!(
        harness.state_mut().wait_for_gpu(Duration::from_secs(120)),
        "no GPU picture within two minutes"
    );
    harness.run_steps(3);
    let drawing = harness.state().gpu_drawing().unwrap();
    if drawing.canvas.is_none() && drawing.device.contains("adapter") {
        assert_ne!(
            std::env::var("GPU_REQUIRED").as_deref(),
            Ok("1"),
            "GPU_REQUIRED=1 but {}",
            drawing.device
        );
        eprintln!("SKIPPED (no GPU): {}", drawing.device);
        return;
    }
    for label in [
        "control: ok",
        "primitive generator: ok",
        "evaluation: ok",
        "shading: ok",
        "wireframe: ok",
        "128 triangles",
    ] {
        harness.get_by_label(label);
    }
    harness.snapshot("viewer_gpu");
}
