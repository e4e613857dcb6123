//! What the window's tests share: the viewer in egui_kittest's harness
//! (the egui project's own test harness), at the window's size, showing
//! the star with your stages.

use course_viewer::meshes::shipped_meshes;
use course_viewer::{Stages, ViewerApp};
use eframe::egui;
use egui_kittest::Harness;

const SIZE: egui::Vec2 = egui::vec2(1100.0, 760.0);

/// The viewer drawing with `stages`, its frame times hidden.
pub fn harness(stages: Stages) -> Harness<'static, ViewerApp> {
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
