//! The window, driven by egui_kittest (the egui project's own test
//! harness): it shows your picture and your stages, its controls change
//! the picture, and a stage that loops leaves it usable.
#![cfg(feature = "window")]

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use course_viewer::meshes::shipped_meshes;
use course_viewer::{Stages, ViewerApp};
use eframe::egui;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

const SIZE: egui::Vec2 = egui::vec2(1100.0, 760.0);

fn harness(stages: Stages) -> Harness<'static, ViewerApp> {
    // The stages' panics are shown in the window, not on the terminal.
    course_viewer::stages::quiet_panics();
    let (meshes, problems) = shipped_meshes();
    assert!(problems.is_empty(), "{problems:?}");
    let mut app = ViewerApp::new(meshes, stages, Vec::new());
    assert!(app.select_mesh("star.ply"));
    // Frame times differ from run to run: not in the snapshots.
    app.set_show_timing(false);
    app.settings_mut().width = 200;
    app.settings_mut().height = 200;
    Harness::builder()
        .with_size(SIZE)
        .build_ui_state(|ui, app: &mut ViewerApp| app.show(ui), app)
}

/// Waits for the frame asked for and lets the window show it.
fn settle(harness: &mut Harness<'static, ViewerApp>) {
    assert!(
        harness.state_mut().wait_for_frame(Duration::from_secs(60)),
        "no frame within a minute"
    );
    harness.run_steps(3);
}

#[test]
fn the_window_shows_your_picture_and_your_stages() {
    let mut harness = harness(Stages::yours());
    settle(&mut harness);
    harness.get_by_label("clipping: ok");
    harness.get_by_label("lines: ok");
    harness.get_by_label("fill: not used by this picture");
    let wireframe = harness.state().frame().unwrap().canvas.clone();
    harness.snapshot("viewer_star_wireframe");

    harness.get_by_label("Filled").click();
    harness.run_steps(2);
    settle(&mut harness);
    harness.get_by_label("fill: ok");
    harness.get_by_label("lines: not used by this picture");
    let filled = harness.state().frame().unwrap().canvas.clone();
    assert_ne!(
        wireframe.to_image(),
        filled.to_image(),
        "the picture follows the control"
    );

    harness.get_by_label("Depth test").click();
    harness.run_steps(2);
    settle(&mut harness);
    harness.get_by_label("depth test: not used by this picture");
    harness.get_by_label("fill: ok");
}

#[test]
fn a_stage_at_todo_is_named_on_screen() {
    let mut stages = Stages::yours();
    stages.line.run = Some(Arc::new(
        |_: &canvas::Vertex, _: &canvas::Vertex, _: &mut dyn FnMut(canvas::Fragment)| {
            todo!("dda: plot one fragment per major-axis column")
        },
    ));
    let mut harness = harness(stages);
    settle(&mut harness);
    harness.get_by_label("lines: not written yet: dda: plot one fragment per major-axis column");
    harness.snapshot("viewer_todo_stage");
}

/// Topic 04 without topic 01: your clipping's polygons are outlined by
/// the window itself, labelled as such, where your lines draw nothing;
/// with your lines they are outlined only when asked for.
#[test]
fn clipped_polygons_are_outlined_by_the_window_without_your_lines() {
    const LABEL: &str = "Yellow: your clipped polygons, outlined by the window (not by your lines)";
    let mut stages = Stages::yours();
    stages.line.run = None;
    let mut harness = harness(stages);
    settle(&mut harness);
    harness.get_by_label("clipping: ok");
    harness.get_by_label(
        "lines: left out: its topic is not in this build (it does not compile, or was not graded with it)",
    );
    let frame = harness.state().frame().unwrap();
    assert!(!frame.clipped.is_empty());
    assert_eq!(
        frame.clipped.len(),
        frame.polygons.1,
        "every polygon clipping kept"
    );
    assert!(frame.canvas.pixels_not(canvas::Rgba::BLACK).is_empty());
    harness.get_by_label(LABEL);
    harness.snapshot("viewer_clipped_outlines");

    let mut harness = self::harness(Stages::yours());
    settle(&mut harness);
    assert!(
        harness.query_by_label(LABEL).is_none(),
        "your lines draw them"
    );
    harness
        .get_by_label("Outline your clipped polygons (drawn by the window, not by your lines)")
        .click();
    harness.run_steps(2);
    harness.get_by_label(LABEL);
}

#[test]
fn a_looping_stage_leaves_the_window_usable() {
    let release = Arc::new(AtomicBool::new(false));
    let mut stages = Stages::yours();
    let held = Arc::clone(&release);
    stages.line.run = Some(Arc::new(
        move |_: &canvas::Vertex, _: &canvas::Vertex, _: &mut dyn FnMut(canvas::Fragment)| {
            // An endless loop, until the test lets it go.
            while !held.load(Ordering::Relaxed) {
                std::thread::sleep(Duration::from_millis(5));
            }
        },
    ));
    let mut harness = harness(stages);
    harness
        .state_mut()
        .set_slow_after(Duration::from_millis(200));
    let started = Instant::now();
    harness.run_steps(2);
    std::thread::sleep(Duration::from_millis(400));
    harness.run_steps(2);
    assert!(
        started.elapsed() < Duration::from_secs(30),
        "the window waited for the stage"
    );
    let warning = harness.query_by_label_contains("an endless loop?");
    assert!(warning.is_some(), "the window says the frame is stuck");
    // The controls still answer.
    harness.get_by_label("Filled").click();
    harness.run_steps(2);
    release.store(true, Ordering::Relaxed);
    settle(&mut harness);
}

/// Waits for the playground's drawing and lets the window show it.
fn settle_pixels(harness: &mut Harness<'static, ViewerApp>) {
    assert!(
        harness
            .state_mut()
            .wait_for_drawing(Duration::from_secs(60)),
        "no drawing within a minute"
    );
    harness.run_steps(3);
}

#[test]
fn the_pixel_playground_compares_your_pixels_with_the_definition() {
    let mut harness = harness(Stages::yours());
    harness.get_by_label("Pixel playground").click();
    harness.run_steps(2);
    settle_pixels(&mut harness);
    harness.get_by_label("lines: ok");
    let line = harness.state().drawing().unwrap().clone();
    harness.get_by_label(&line.summary());
    assert!(line.summary().starts_with("all "), "{}", line.summary());
    harness.snapshot("viewer_pixels_dda");

    // Stepping back shows one pixel less and says what decided the last.
    harness.get_by_label("Back").click();
    harness.run_steps(2);
    let shown = line.yours.len() - 1;
    harness.get_by_label(&format!("pixel {shown} of {}", line.yours.len()));
    harness.get_by_label(&line.yours[shown - 1].note);

    // Another primitive: the triangle, drawn by the fill stage.
    harness.get_by_label("Primitive").click();
    harness.run_steps(2);
    harness.get_by_label("Edge-function triangle (03)").click();
    harness.run_steps(2);
    settle_pixels(&mut harness);
    harness.get_by_label("fill: ok");
    let triangle = harness.state().drawing().unwrap();
    assert!(
        triangle.summary().starts_with("all "),
        "{}",
        triangle.summary()
    );
    assert_ne!(
        triangle.expected, line.expected,
        "the picture follows the control"
    );
    harness.snapshot("viewer_pixels_triangle");
}

#[test]
fn a_wrong_circle_is_marked_pixel_by_pixel() {
    let mut stages = Stages::yours();
    // One pixel too far out, everywhere.
    stages.circle.run = Some(Arc::new(
        |centre: canvas::Pixel, radius: i32, plot: &mut dyn FnMut(canvas::Pixel)| {
            let reference = Stages::yours().circle.run.unwrap();
            reference(centre, radius + 1, plot);
        },
    ));
    let mut harness = harness(stages);
    harness.state_mut().set_scene(course_viewer::Scene::Pixels);
    harness.state_mut().playground_mut().primitive =
        course_viewer::scenes::pixels::Primitive::Circle;
    settle_pixels(&mut harness);
    let summary = harness.state().drawing().unwrap().summary();
    assert!(summary.contains("only yours (+)"), "{summary}");
    harness.get_by_label(&summary);
    harness.snapshot("viewer_pixels_wrong_circle");
    // The last pixel's note: the circle's implicit function there.
    harness.get_by_label("Back").click();
    harness.run_steps(2);
    let drawing = harness.state().drawing().unwrap();
    let note = drawing.yours[drawing.yours.len() - 2].note.clone();
    assert!(note.contains("x² + y² − R² = "), "{note}");
    harness.get_by_label(&note);
}

/// Drags handle 1 of the playground's line two cells right and one up,
/// from pixel (13, 8) to (15, 9), in four moves with `pause` after each,
/// and checks that the line followed. The grid is read off the window once,
/// before the drag: the pointer moves as a person's hand does, whatever
/// the window shows meanwhile.
fn drag_the_line_end(harness: &mut Harness<'static, ViewerApp>, pause: Duration) {
    harness.state_mut().set_scene(course_viewer::Scene::Pixels);
    settle_pixels(harness);
    let before = harness.state().drawing().unwrap().clone();
    let from = harness
        .state()
        .handle_on_screen(1)
        .expect("the grid is drawn");
    let cell = harness.state().handle_on_screen(0).unwrap().distance(from)
        / before.setup.handles[0].distance(before.setup.handles[1]);
    let to = from + egui::vec2(2.0 * cell, -cell);
    let input = harness.input_mut();
    input.events.push(egui::Event::PointerMoved(from));
    input.events.push(egui::Event::PointerButton {
        pos: from,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: egui::Modifiers::NONE,
    });
    harness.run_steps(2);
    for t in [0.25, 0.5, 0.75, 1.0] {
        harness
            .input_mut()
            .events
            .push(egui::Event::PointerMoved(from + (to - from) * t));
        harness.run_steps(1);
        // A hand takes a moment between two positions; moves within one
        // frame of each other were lost now and then on a loaded machine.
        std::thread::sleep(pause.max(Duration::from_millis(20)));
        harness.run_steps(1);
    }
    harness.input_mut().events.push(egui::Event::PointerButton {
        pos: to,
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: egui::Modifiers::NONE,
    });
    harness.run_steps(2);
    settle_pixels(harness);
    let after = harness.state().drawing().unwrap();
    assert_eq!(after.setup.handles[1], canvas::Vec2::new(15.0, 9.0));
    assert_eq!(
        after.setup.handles[0], before.setup.handles[0],
        "only the dragged handle moves"
    );
    assert!(after.expected.contains(&canvas::Pixel::new(15, 9)));
    assert!(after.summary().starts_with("all "), "{}", after.summary());
    assert_ne!(after.expected, before.expected);
}

#[test]
fn dragging_a_handle_moves_the_line_and_redraws_it() {
    let mut harness = harness(Stages::yours());
    drag_the_line_end(&mut harness, Duration::ZERO);
}

#[test]
fn a_slow_stage_does_not_move_the_grid_under_a_drag() {
    // Each line takes 60 ms and counts as slow after 20: while the handle
    // is dragged the notice of a slow stage comes and goes. The grid must
    // stay where the pointer found it.
    let mut stages = Stages::yours();
    let dda = Stages::yours().line.run.expect("the solutions draw lines");
    stages.line.run = Some(Arc::new(
        move |from: &canvas::Vertex,
              to: &canvas::Vertex,
              plot: &mut dyn FnMut(canvas::Fragment)| {
            std::thread::sleep(Duration::from_millis(60));
            dda(from, to, plot);
        },
    ));
    let mut harness = harness(stages);
    harness
        .state_mut()
        .set_slow_after(Duration::from_millis(20));
    drag_the_line_end(&mut harness, Duration::from_millis(40));
}

/// Waits for the curve scene's drawing and lets the window show it.
fn settle_curves(harness: &mut Harness<'static, ViewerApp>) {
    assert!(
        harness.state_mut().wait_for_curve(Duration::from_secs(60)),
        "no curve within a minute"
    );
    harness.run_steps(3);
}

#[test]
fn the_curve_scene_draws_your_de_casteljau_and_its_construction() {
    let mut harness = harness(Stages::yours());
    harness.get_by_label("Curves").click();
    harness.run_steps(2);
    settle_curves(&mut harness);
    harness.get_by_label("de Casteljau: ok");
    let drawing = harness.state().curve_drawing().unwrap().clone();
    assert_eq!(
        drawing.yours.len(),
        course_viewer::scenes::curves::SAMPLES + 1
    );
    assert!(
        drawing.deviation.unwrap() < 1e-12,
        "the solutions' curve is the definition's: {:?}",
        drawing.deviation
    );
    // The seed's Abbildung 6: four points, three levels below them, the
    // last one C(½), which lies on the curve.
    let sizes: Vec<usize> = drawing.levels.iter().map(Vec::len).collect();
    assert_eq!(sizes, [4, 3, 2, 1]);
    let point = drawing.levels[3][0];
    let on_curve = course_viewer::scenes::curves::definition(&drawing.setup.points, 0.5);
    assert!(
        point.distance(on_curve) < 1e-12,
        "{point} is not C(½) = {on_curve}"
    );
    harness.snapshot("viewer_curves");

    // More control points, another t: the construction follows.
    harness.state_mut().curves_mut().set_count(6);
    harness.state_mut().curves_mut().t = 0.25;
    harness.run_steps(2);
    settle_curves(&mut harness);
    let sizes: Vec<usize> = harness
        .state()
        .curve_drawing()
        .unwrap()
        .levels
        .iter()
        .map(Vec::len)
        .collect();
    assert_eq!(sizes, [6, 5, 4, 3, 2, 1]);
}

#[test]
fn dragging_a_control_point_reshapes_the_curve() {
    let mut harness = harness(Stages::yours());
    harness.state_mut().set_scene(course_viewer::Scene::Curves);
    harness.run_steps(2);
    settle_curves(&mut harness);
    let before = harness.state().curve_drawing().unwrap().clone();
    let from = harness
        .state()
        .curve_point_on_screen(1)
        .expect("the curve is drawn");
    let to = from + egui::vec2(60.0, 80.0);
    harness
        .input_mut()
        .events
        .push(egui::Event::PointerMoved(from));
    harness.input_mut().events.push(egui::Event::PointerButton {
        pos: from,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: egui::Modifiers::NONE,
    });
    harness.run_steps(2);
    for t in [0.5, 1.0] {
        harness
            .input_mut()
            .events
            .push(egui::Event::PointerMoved(from + (to - from) * t));
        harness.run_steps(1);
        std::thread::sleep(Duration::from_millis(20));
        harness.run_steps(1);
    }
    harness.input_mut().events.push(egui::Event::PointerButton {
        pos: to,
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: egui::Modifiers::NONE,
    });
    harness.run_steps(2);
    settle_curves(&mut harness);
    let after = harness.state().curve_drawing().unwrap();
    let moved = after.setup.points[1] - before.setup.points[1];
    assert!(
        moved.x > 0.0 && moved.y < 0.0,
        "point 1 follows the pointer right and down: moved by {moved}"
    );
    assert_eq!(
        after.setup.points[0], before.setup.points[0],
        "only point 1 moves"
    );
    assert_ne!(after.yours, before.yours, "the curve is drawn again");
    assert!(after.deviation.unwrap() < 1e-12);
}

#[test]
fn a_de_casteljau_at_todo_is_named_in_the_curve_scene() {
    let mut stages = Stages::yours();
    stages.curve.run = Some(Arc::new(
        |_: &[glam::DVec2], _: f64| -> Result<glam::DVec2, String> {
            todo!("de_casteljau: repeated linear interpolation")
        },
    ));
    let mut harness = harness(stages);
    harness.state_mut().set_scene(course_viewer::Scene::Curves);
    harness.run_steps(2);
    settle_curves(&mut harness);
    harness
        .get_by_label("de Casteljau: not written yet: de_casteljau: repeated linear interpolation");
    let drawing = harness.state().curve_drawing().unwrap();
    assert!(drawing.yours.is_empty() && drawing.deviation.is_none());
    assert_eq!(drawing.levels.len(), 1, "only the control points show");
}

#[test]
fn wus_line_shows_each_pixels_intensity_beside_the_definitions() {
    let mut harness = harness(Stages::yours());
    harness.state_mut().set_scene(course_viewer::Scene::Pixels);
    harness.state_mut().playground_mut().primitive =
        course_viewer::scenes::pixels::Primitive::WuLine;
    harness.run_steps(2);
    settle_pixels(&mut harness);
    harness.get_by_label("Wu line: ok");
    let drawing = harness.state().drawing().unwrap().clone();
    let summary = drawing.summary();
    assert!(
        summary.starts_with("all ") && summary.contains("intensities within 0.00"),
        "{summary}"
    );
    harness.get_by_label(&summary);
    let last = drawing.yours.last().unwrap();
    assert!(
        last.note
            .starts_with("intensity 1.000, the definition's 1.000"),
        "{}",
        last.note
    );
    harness.snapshot("viewer_pixels_wu");
}

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

#[test]
fn the_curve_scene_draws_your_nurbs_curve() {
    let mut harness = harness(Stages::yours());
    harness.state_mut().set_scene(course_viewer::Scene::Curves);
    harness.run_steps(2);
    harness.get_by_label("NURBS (08)").click();
    harness.run_steps(2);
    harness.state_mut().curves_mut().set_count(6);
    harness.state_mut().curves_mut().degree = 2;
    harness.state_mut().curves_mut().weights = vec![1.0, 4.0, 1.0, 0.3, 1.0, 1.0];
    harness.run_steps(2);
    settle_curves(&mut harness);
    harness.get_by_label("NURBS curve: ok");
    harness.get_by_label("knots: 0.00 0.00 0.00 0.25 0.50 0.75 1.00 1.00 1.00");
    let drawing = harness.state().curve_drawing().unwrap();
    assert_eq!(drawing.knot_points.len(), 3);
    assert!(drawing.deviation.unwrap() < 1e-12);
    harness.snapshot("viewer_curves_nurbs");
}
