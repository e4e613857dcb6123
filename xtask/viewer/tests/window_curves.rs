//! The curve scene in the window, driven by egui_kittest: your de
//! Casteljau and its construction, your NURBS curve, control points
//! dragged.
#![cfg(feature = "window")]

mod common;

use std::sync::Arc;
use std::time::Duration;

use common::harness;
use course_viewer::{Stages, ViewerApp};
use eframe::egui;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

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
