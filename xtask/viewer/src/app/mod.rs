//! The window's shell: the picture on the left, the controls and your
//! stages on the right, as in seed 004's Figure 2, for six scenes: your
//! pipeline ([`crate::scenes::mesh`]), the pixel playground
//! ([`crate::scenes::pixels`]), the curve scene ([`crate::scenes::curves`]),
//! the trimmed surface ([`crate::scenes::surfaces`]), the tessellation
//! ([`crate::scenes::tessellation`]) and the GPU passes
//! ([`crate::scenes::gpu`]).
//!
//! This module holds the scenes, switches between them and takes the
//! window's screenshot (`screenshot`); each scene's state, panel and
//! picture are in its folder under `scenes/`.

use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;

use eframe::egui;

use crate::live::LiveScene;
use crate::meshes::MeshEntry;
use crate::scenes::curves::{CurveDrawing, CurveSetup, CurvesScene};
use crate::scenes::gpu::{GpuDrawing, GpuScene, GpuSetup};
use crate::scenes::mesh::{Frame, MeshScene, Settings};
use crate::scenes::pixels::{Drawing, PixelsScene, Setup};
use crate::scenes::surfaces::{SurfaceDrawing, SurfaceSetup, SurfacesScene};
use crate::scenes::tessellation::{TessDrawing, TessSetup, TessellationScene};
use crate::stages::Stages;

mod screenshot;

/// What the window shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scene {
    /// Your pipeline drawing a mesh.
    Pipeline,
    /// One primitive on a magnified grid, beside its definition.
    Pixels,
    /// A Bézier curve and its de Casteljau construction.
    Curves,
    /// The seed's hill, trimmed, tessellated and lit.
    Surfaces,
    /// Surfaces cut into triangles by uniform or adaptive tessellation.
    Tessellation,
    /// Topic 10's passes on the GPU.
    Gpu,
}

/// The viewer's state.
pub struct ViewerApp {
    scene: Scene,
    mesh: MeshScene,
    playground: PixelsScene,
    curves: CurvesScene,
    surfaces: SurfacesScene,
    tessellation: TessellationScene,
    gpu: GpuScene,
    /// Topics whose stages are left out because they do not compile.
    not_compiling: Vec<String>,
    /// Where to save a screenshot of the window once the first picture
    /// shows, before closing it (the smoke test under Xvfb).
    window_screenshot: Option<PathBuf>,
    /// Whether that screenshot has been asked for.
    screenshot_asked: bool,
    /// Where the window's integration hands the screenshot over.
    screenshot: Arc<std::sync::Mutex<Option<Arc<egui::ColorImage>>>>,
    /// Whether the panels say what differs from run to run and machine to
    /// machine: how long a frame took, the GPU's name (off in snapshot
    /// tests).
    show_timing: bool,
}

impl ViewerApp {
    /// A viewer of `meshes` (at least one) drawing with `stages`;
    /// `not_compiling` names the topics left out of the build.
    ///
    /// # Panics
    /// If `meshes` is empty.
    #[must_use]
    pub fn new(meshes: Vec<MeshEntry>, stages: Stages, not_compiling: Vec<String>) -> Self {
        assert!(!meshes.is_empty(), "the viewer needs a mesh");
        Self {
            scene: Scene::Pipeline,
            playground: PixelsScene::new(stages.clone()),
            curves: CurvesScene::new(stages.clone()),
            surfaces: SurfacesScene::new(stages.clone()),
            tessellation: TessellationScene::new(stages.clone()),
            gpu: GpuScene::new(stages.clone()),
            mesh: MeshScene::new(meshes, stages),
            not_compiling,
            window_screenshot: None,
            screenshot_asked: false,
            screenshot: Arc::default(),
            show_timing: true,
        }
    }

    /// Selects the mesh called `name`, if there is one.
    pub fn select_mesh(&mut self, name: &str) -> bool {
        self.mesh.select(name)
    }

    /// Shows `scene`.
    pub fn set_scene(&mut self, scene: Scene) {
        self.scene = scene;
    }

    /// The pixel playground's set-up, to change what it draws.
    pub fn playground_mut(&mut self) -> &mut Setup {
        &mut self.playground.setup
    }

    /// The curve scene's set-up, to change what it draws.
    pub fn curves_mut(&mut self) -> &mut CurveSetup {
        &mut self.curves.setup
    }

    /// The curve scene's drawing on screen, if one has been drawn.
    #[must_use]
    pub fn curve_drawing(&self) -> Option<&CurveDrawing> {
        self.curves.live.drawing.as_ref()
    }

    /// Where control point `k` of the curve scene shows on screen, once
    /// the scene has been drawn (for tests that drag it).
    #[must_use]
    pub fn curve_point_on_screen(&self, k: usize) -> Option<egui::Pos2> {
        self.curves.point_on_screen(k)
    }

    /// Asks for the curve scene's drawing and waits for it, at most
    /// `limit` (for tests); whether it arrived.
    pub fn wait_for_curve(&mut self, limit: Duration) -> bool {
        self.curves.wait(limit)
    }

    /// The surface scene's set-up, to change what it draws.
    pub fn surfaces_mut(&mut self) -> &mut SurfaceSetup {
        &mut self.surfaces.setup
    }

    /// The surface scene's drawing on screen, if one has been drawn.
    #[must_use]
    pub fn surface_drawing(&self) -> Option<&SurfaceDrawing> {
        self.surfaces.live.drawing.as_ref()
    }

    /// Asks for the surface scene's drawing and waits for it, at most
    /// `limit` (for tests); whether it arrived.
    pub fn wait_for_surface(&mut self, limit: Duration) -> bool {
        self.surfaces.wait(limit)
    }

    /// The tessellation scene's set-up, to change what it draws.
    pub fn tessellation_mut(&mut self) -> &mut TessSetup {
        &mut self.tessellation.setup
    }

    /// The tessellation scene's drawing on screen, if one has been drawn.
    #[must_use]
    pub fn tessellation_drawing(&self) -> Option<&TessDrawing> {
        self.tessellation.live.drawing.as_ref()
    }

    /// Asks for the tessellation scene's drawing and waits for it, at most
    /// `limit` (for tests); whether it arrived.
    pub fn wait_for_tessellation(&mut self, limit: Duration) -> bool {
        self.tessellation.wait(limit)
    }

    /// The GPU scene's set-up, to change what it draws.
    pub fn gpu_mut(&mut self) -> &mut GpuSetup {
        &mut self.gpu.setup
    }

    /// The GPU scene's drawing on screen, if one has been drawn.
    #[must_use]
    pub fn gpu_drawing(&self) -> Option<&GpuDrawing> {
        self.gpu.live.drawing.as_ref()
    }

    /// Asks for the GPU scene's drawing and waits for it, at most `limit`
    /// (for tests); whether it arrived.
    pub fn wait_for_gpu(&mut self, limit: Duration) -> bool {
        self.gpu.wait(limit)
    }

    /// Where handle `k` of the playground shows on screen, once the grid
    /// has been drawn (for tests that drag it).
    #[must_use]
    pub fn handle_on_screen(&self, k: usize) -> Option<egui::Pos2> {
        self.playground.handle_on_screen(k)
    }

    /// The playground's drawing on screen, if one has been drawn.
    #[must_use]
    pub fn drawing(&self) -> Option<&Drawing> {
        self.playground.live.drawing.as_ref()
    }

    /// Asks for the playground's drawing and waits for it, at most
    /// `limit` (for tests); whether it arrived.
    pub fn wait_for_drawing(&mut self, limit: Duration) -> bool {
        self.playground.wait(limit)
    }

    /// Whether the stage list says how long each frame took.
    pub fn set_show_timing(&mut self, show: bool) {
        self.show_timing = show;
    }

    /// Reports a frame as slow (an endless loop?) after `limit`.
    pub fn set_slow_after(&mut self, limit: Duration) {
        self.mesh.live.worker.set_slow_after(limit);
        self.playground.live.worker.set_slow_after(limit);
        self.curves.live.worker.set_slow_after(limit);
        self.surfaces.live.worker.set_slow_after(limit);
        self.tessellation.live.worker.set_slow_after(limit);
        self.gpu.live.worker.set_slow_after(limit);
    }

    /// The settings the next frame is drawn with.
    pub fn settings_mut(&mut self) -> &mut Settings {
        &mut self.mesh.settings
    }

    /// The frame on screen, if one has been drawn.
    #[must_use]
    pub fn frame(&self) -> Option<&Frame> {
        self.mesh.live.drawing.as_ref()
    }

    /// Asks for the current frame and waits for it, at most `limit`
    /// (for tests and screenshots); whether it arrived.
    pub fn wait_for_frame(&mut self, limit: Duration) -> bool {
        self.mesh.wait(limit)
    }

    /// Loads the PLY file at `path` and shows it.
    pub fn open(&mut self, path: &str) {
        self.mesh.open(path);
    }

    /// Saves the picture on screen as a PNG at `path`.
    pub fn save(&mut self, path: &str) {
        self.mesh.save(path);
    }

    /// Draws the window's contents into `ui`.
    pub fn show(&mut self, ui: &mut egui::Ui) {
        match self.scene {
            Scene::Pipeline => {
                self.mesh.update(ui);
                self.two_panels(
                    ui,
                    |app, ui| app.mesh.controls(ui, &app.not_compiling, app.show_timing),
                    |app, ui| app.mesh.picture(ui),
                );
            }
            Scene::Pixels => {
                self.playground.update(ui);
                self.two_panels(
                    ui,
                    |app, ui| app.playground.controls(ui),
                    |app, ui| app.playground.picture(ui),
                );
            }
            Scene::Curves => {
                self.curves.update(ui);
                self.two_panels(
                    ui,
                    |app, ui| app.curves.controls(ui),
                    |app, ui| app.curves.picture(ui),
                );
            }
            Scene::Surfaces => {
                self.surfaces.update(ui);
                self.two_panels(
                    ui,
                    |app, ui| app.surfaces.controls(ui),
                    |app, ui| app.surfaces.picture(ui),
                );
            }
            Scene::Tessellation => {
                self.tessellation.update(ui);
                self.two_panels(
                    ui,
                    |app, ui| app.tessellation.controls(ui),
                    |app, ui| app.tessellation.picture(ui),
                );
            }
            Scene::Gpu => {
                self.gpu.update(ui);
                self.two_panels(
                    ui,
                    |app, ui| app.gpu.controls(ui, app.show_timing),
                    |app, ui| app.gpu.picture(ui),
                );
            }
        }
        self.window_screenshot(ui);
    }

    /// The scene switch at the top of the controls.
    fn scene_switch(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            ui.selectable_value(&mut self.scene, Scene::Pipeline, "Pipeline scene");
            ui.selectable_value(&mut self.scene, Scene::Pixels, "Pixel playground");
            ui.selectable_value(&mut self.scene, Scene::Curves, "Curves");
            ui.selectable_value(&mut self.scene, Scene::Surfaces, "Surfaces");
            ui.selectable_value(&mut self.scene, Scene::Tessellation, "Tessellation");
            ui.selectable_value(&mut self.scene, Scene::Gpu, "GPU");
        });
        ui.separator();
    }

    /// A scene's controls on the right (under the scene switch) and its
    /// picture on the left, as in seed 004's Figure 2.
    fn two_panels(
        &mut self,
        ui: &mut egui::Ui,
        controls: fn(&mut Self, &mut egui::Ui),
        picture: fn(&mut Self, &mut egui::Ui),
    ) {
        egui::Panel::right("controls")
            .default_size(320.0)
            .show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| {
                    self.scene_switch(ui);
                    controls(self, ui);
                });
            });
        egui::CentralPanel::default().show(ui, |ui| picture(self, ui));
    }
}

impl eframe::App for ViewerApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.show(ui);
    }
}
