//! The pixel playground in the window, driven by egui_kittest: your
//! pixels beside the definition's, stepping through them, handles
//! dragged while the stage is slow.
#![cfg(feature = "window")]

mod common;

use std::sync::Arc;
use std::time::Duration;

use common::harness;
use course_viewer::{Stages, ViewerApp};
use eframe::egui;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

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
