//! The window: the picture on the left, the controls and your stages on
//! the right, as in seed 004's Figure 2. Six scenes: your pipeline
//! ([`crate::render`]), the pixel playground ([`crate::playground`]), the
//! curve scene ([`crate::curves`]), the trimmed surface
//! ([`crate::surfaces`]), the tessellation ([`crate::tessellation`]) and
//! the GPU passes ([`crate::gpu_scene`]).
//!
//! This module is the window's shell (the scenes' state, switching, the
//! screenshot); each scene's panel and picture is a file of its own
//! (`pipeline_ui`, `playground_ui`, `curves_ui`, `surfaces_ui`,
//! `tessellation_ui`, `gpu_ui`), and what they share is in `widgets`.

use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;

use eframe::egui;
use egui::TextureHandle;

use crate::curves::{self, CurveDrawing, CurveSetup, CurveWorker};
use crate::gpu_scene::{self, GpuDrawing, GpuSetup};
use crate::meshes::MeshEntry;
use crate::playground::{self, Drawing, PlaygroundWorker, Primitive, Setup};
use crate::render::{Frame, FrameWorker, Settings, frame_worker};
use crate::stages::Stages;
use crate::surfaces::{self, SurfaceDrawing, SurfaceSetup};
use crate::tessellation::{self as tess, TessDrawing, TessSetup};
use crate::worker::Worker;

mod curves_ui;
mod gpu_ui;
mod pipeline_ui;
mod playground_ui;
mod surfaces_ui;
mod tessellation_ui;
mod widgets;

use widgets::{canvas_image, unit_to_screen};

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

/// A scene drawn by a worker: its set-up, what was last asked for and
/// drawn, and the drawing's pictures on the GPU.
struct Live<J, R> {
    setup: J,
    worker: Worker<J, R>,
    asked: Option<J>,
    drawing: Option<R>,
    /// The drawing's pictures as textures, made when first shown.
    textures: Vec<TextureHandle>,
    /// Keeps a set-up drawable before it is asked for.
    tidy: fn(&mut J),
}

impl<J: Clone + PartialEq + Send + 'static, R: Send + 'static> Live<J, R> {
    fn new(setup: J, worker: Worker<J, R>, tidy: fn(&mut J)) -> Self {
        Self {
            setup,
            worker,
            asked: None,
            drawing: None,
            textures: Vec::new(),
            tidy,
        }
    }

    /// Asks for a drawing if the set-up changed since the last one.
    fn ask(&mut self) {
        (self.tidy)(&mut self.setup);
        if self.asked.as_ref() != Some(&self.setup) {
            self.worker.request(self.setup.clone());
            self.asked = Some(self.setup.clone());
        }
    }

    fn arrived(&mut self, drawing: R) {
        self.drawing = Some(drawing);
        self.textures.clear();
    }

    /// Takes the newest drawing, if one arrived; asks the window to look
    /// again soon while one is being drawn.
    fn poll(&mut self, ui: &egui::Ui) {
        if let Some(drawing) = self.worker.poll() {
            self.arrived(drawing);
        }
        if self.worker.busy_for().is_some() {
            ui.ctx().request_repaint_after(Duration::from_millis(100));
        }
    }

    /// Asks for the drawing and waits for it, at most `limit` (for tests);
    /// whether it arrived.
    fn wait(&mut self, limit: Duration) -> bool {
        self.ask();
        match self.worker.wait(limit) {
            Some(drawing) => {
                self.arrived(drawing);
                true
            }
            None => self.worker.busy_for().is_none(),
        }
    }
}

/// The curve scene's state.
struct Curves {
    setup: CurveSetup,
    worker: CurveWorker,
    asked: Option<CurveSetup>,
    drawing: Option<CurveDrawing>,
    /// The control point being dragged.
    dragging: Option<usize>,
    /// Where the unit square was last drawn on screen.
    area: Option<egui::Rect>,
    /// Whether the construction at `t` shows.
    construction: bool,
    /// Whether the definition's curve shows.
    definition: bool,
}

/// The pixel playground's state.
struct Playground {
    setup: Setup,
    worker: PlaygroundWorker,
    asked: Option<Setup>,
    drawing: Option<Drawing>,
    /// How many of your pixels show (stepping through them); `None`: all.
    steps: Option<usize>,
    /// The handle being dragged.
    dragging: Option<usize>,
    /// Each primitive's handles, kept while another one is shown.
    handles: [[glam::Vec2; 3]; 5],
    /// The primitive whose handles `setup` holds.
    primitive: Primitive,
    /// Where the grid was last drawn: its top-left corner and the size of
    /// a cell on screen.
    grid: Option<(egui::Pos2, f32)>,
}

/// The viewer's state.
pub struct ViewerApp {
    scene: Scene,
    playground: Playground,
    curves: Curves,
    surfaces: Live<SurfaceSetup, SurfaceDrawing>,
    tessellation: Live<TessSetup, TessDrawing>,
    gpu: Live<GpuSetup, GpuDrawing>,
    meshes: Vec<MeshEntry>,
    selected: usize,
    settings: Settings,
    worker: FrameWorker,
    /// The settings of the frame last asked for (a change asks again).
    asked: Option<(usize, Settings)>,
    frame: Option<Frame>,
    texture: Option<TextureHandle>,
    /// Where "Save PNG" writes.
    save_path: String,
    /// A PLY file to load.
    open_path: String,
    /// The last message for the user (saved, cannot load, ...).
    message: Option<String>,
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
    /// The pipeline scene outlines your clipped polygons over the picture.
    outline_clipped: bool,
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
            playground: Playground {
                setup: Setup::default(),
                worker: playground::worker(stages.clone()),
                asked: None,
                drawing: None,
                steps: None,
                dragging: None,
                handles: Primitive::ALL.map(Primitive::first_handles),
                primitive: Primitive::DdaLine,
                grid: None,
            },
            curves: Curves {
                setup: CurveSetup::default(),
                worker: curves::worker(stages.clone()),
                asked: None,
                drawing: None,
                dragging: None,
                area: None,
                construction: true,
                definition: true,
            },
            surfaces: Live::new(
                SurfaceSetup::default(),
                surfaces::worker(stages.clone()),
                SurfaceSetup::tidy,
            ),
            tessellation: Live::new(
                TessSetup::default(),
                tess::worker(stages.clone()),
                TessSetup::tidy,
            ),
            gpu: Live::new(
                GpuSetup::default(),
                gpu_scene::worker(stages.clone()),
                GpuSetup::tidy,
            ),
            meshes,
            selected: 0,
            settings: Settings::default(),
            worker: frame_worker(stages),
            asked: None,
            frame: None,
            texture: None,
            save_path: "target/view/picture.png".to_owned(),
            open_path: String::new(),
            message: None,
            not_compiling,
            window_screenshot: None,
            screenshot_asked: false,
            screenshot: Arc::default(),
            show_timing: true,
            outline_clipped: false,
        }
    }

    /// Saves a screenshot of the whole window to `path` once the first
    /// picture shows, then closes the window.
    pub fn screenshot_window_to(&mut self, path: PathBuf) {
        self.window_screenshot = Some(path);
    }

    /// Takes the screenshot [`Self::screenshot_window_to`] asked for.
    fn window_screenshot(&mut self, ui: &egui::Ui) {
        let Some(path) = self.window_screenshot.clone() else {
            return;
        };
        let taken = self
            .screenshot
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
            .take();
        if let Some(image) = taken {
            let [w, h] = image.size;
            let bytes: Vec<u8> = image.pixels.iter().flat_map(|c| c.to_array()).collect();
            match canvas_image(w, h, bytes).map(|canvas| canvas.save_png(&path)) {
                Some(Ok(())) => println!("wrote {}", path.display()),
                _ => eprintln!("error: cannot write the screenshot {}", path.display()),
            }
            ui.ctx().send_viewport_cmd(egui::ViewportCommand::Close);
            self.window_screenshot = None;
            return;
        }
        let shown = match self.scene {
            Scene::Pipeline => self.texture.is_some(),
            Scene::Pixels => self.playground.drawing.is_some(),
            Scene::Curves => self.curves.drawing.is_some(),
            Scene::Surfaces => !self.surfaces.textures.is_empty(),
            Scene::Tessellation => self.tessellation.drawing.is_some(),
            Scene::Gpu => self.gpu.drawing.is_some(),
        };
        if shown && !self.screenshot_asked {
            let slot = Arc::clone(&self.screenshot);
            let ctx = ui.ctx().clone();
            ui.ctx().request_screenshot(move |image| {
                *slot
                    .lock()
                    .unwrap_or_else(std::sync::PoisonError::into_inner) = Some(image);
                ctx.request_repaint();
            });
            self.screenshot_asked = true;
        }
        ui.ctx().request_repaint_after(Duration::from_millis(50));
    }

    /// Selects the mesh called `name`, if there is one.
    pub fn select_mesh(&mut self, name: &str) -> bool {
        match self.meshes.iter().position(|m| m.name == name) {
            Some(index) => {
                self.selected = index;
                true
            }
            None => false,
        }
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
        self.curves.drawing.as_ref()
    }

    /// Where control point `k` of the curve scene shows on screen, once
    /// the scene has been drawn (for tests that drag it).
    #[must_use]
    pub fn curve_point_on_screen(&self, k: usize) -> Option<egui::Pos2> {
        let area = self.curves.area?;
        let p = *self.curves.setup.points.get(k)?;
        Some(unit_to_screen(area, p))
    }

    /// Asks for the curve scene's drawing and waits for it, at most
    /// `limit` (for tests); whether it arrived.
    pub fn wait_for_curve(&mut self, limit: Duration) -> bool {
        self.ask_curves();
        match self.curves.worker.wait(limit) {
            Some(drawing) => {
                self.curves.drawing = Some(drawing);
                true
            }
            None => self.curves.worker.busy_for().is_none(),
        }
    }

    /// The surface scene's set-up, to change what it draws.
    pub fn surfaces_mut(&mut self) -> &mut SurfaceSetup {
        &mut self.surfaces.setup
    }

    /// The surface scene's drawing on screen, if one has been drawn.
    #[must_use]
    pub fn surface_drawing(&self) -> Option<&SurfaceDrawing> {
        self.surfaces.drawing.as_ref()
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
        self.tessellation.drawing.as_ref()
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
        self.gpu.drawing.as_ref()
    }

    /// Asks for the GPU scene's drawing and waits for it, at most `limit`
    /// (for tests); whether it arrived.
    pub fn wait_for_gpu(&mut self, limit: Duration) -> bool {
        self.gpu.wait(limit)
    }

    /// Asks for the curve scene's drawing if its set-up changed.
    fn ask_curves(&mut self) {
        let curves = &mut self.curves;
        curves.setup.tidy();
        if curves.asked.as_ref() != Some(&curves.setup) {
            curves.worker.request(curves.setup.clone());
            curves.asked = Some(curves.setup.clone());
        }
    }

    /// Where handle `k` of the playground shows on screen, once the grid
    /// has been drawn (for tests that drag it).
    #[must_use]
    pub fn handle_on_screen(&self, k: usize) -> Option<egui::Pos2> {
        let (origin, cell) = self.playground.grid?;
        let p = *self.playground.setup.handles.get(k)?;
        let top = self.playground.setup.size as f32 - 0.5;
        Some(egui::pos2(
            origin.x + (p.x + 0.5) * cell,
            origin.y + (top - p.y) * cell,
        ))
    }

    /// The playground's drawing on screen, if one has been drawn.
    #[must_use]
    pub fn drawing(&self) -> Option<&Drawing> {
        self.playground.drawing.as_ref()
    }

    /// Whether the stage list says how long each frame took.
    pub fn set_show_timing(&mut self, show: bool) {
        self.show_timing = show;
    }

    /// Reports a frame as slow (an endless loop?) after `limit`.
    pub fn set_slow_after(&mut self, limit: Duration) {
        self.worker.set_slow_after(limit);
        self.playground.worker.set_slow_after(limit);
        self.curves.worker.set_slow_after(limit);
        self.surfaces.worker.set_slow_after(limit);
        self.tessellation.worker.set_slow_after(limit);
        self.gpu.worker.set_slow_after(limit);
    }

    /// The settings the next frame is drawn with.
    pub fn settings_mut(&mut self) -> &mut Settings {
        &mut self.settings
    }

    /// The frame on screen, if one has been drawn.
    #[must_use]
    pub fn frame(&self) -> Option<&Frame> {
        self.frame.as_ref()
    }

    /// Asks for a frame if the settings changed since the last one.
    fn ask(&mut self) {
        let wanted = (self.selected, self.settings.clone());
        if self.asked.as_ref() != Some(&wanted) {
            self.worker.request((
                Arc::clone(&self.meshes[self.selected].mesh),
                self.settings.clone(),
            ));
            self.asked = Some(wanted);
        }
    }

    /// Asks for the playground's drawing if its set-up changed.
    fn ask_playground(&mut self) {
        let playground = &mut self.playground;
        let index = |p: Primitive| Primitive::ALL.iter().position(|q| *q == p).unwrap_or(0);
        if playground.setup.primitive != playground.primitive {
            // Each primitive keeps its own handles.
            playground.handles[index(playground.primitive)] = playground.setup.handles;
            playground.setup.handles = playground.handles[index(playground.setup.primitive)];
            playground.primitive = playground.setup.primitive;
        }
        playground.setup.tidy();
        if playground.asked.as_ref() != Some(&playground.setup) {
            playground.worker.request(playground.setup.clone());
            playground.asked = Some(playground.setup.clone());
            // A new drawing shows all its pixels.
            playground.steps = None;
        }
    }

    /// Asks for the playground's drawing and waits for it, at most
    /// `limit` (for tests); whether it arrived.
    pub fn wait_for_drawing(&mut self, limit: Duration) -> bool {
        self.ask_playground();
        match self.playground.worker.wait(limit) {
            Some(drawing) => {
                self.playground.drawing = Some(drawing);
                true
            }
            None => self.playground.worker.busy_for().is_none(),
        }
    }

    /// Asks for the current frame and waits for it, at most `limit`
    /// (for tests and screenshots); whether it arrived.
    pub fn wait_for_frame(&mut self, limit: Duration) -> bool {
        self.ask();
        match self.worker.wait(limit) {
            Some(frame) => {
                self.frame = Some(frame);
                self.texture = None;
                true
            }
            None => self.worker.busy_for().is_none(),
        }
    }

    /// Loads the PLY file at `path` and shows it.
    pub fn open(&mut self, path: &str) {
        match crate::meshes::load(std::path::Path::new(path)) {
            Ok(entry) => {
                self.message = Some(format!("loaded {}", entry.name));
                self.meshes.push(entry);
                self.selected = self.meshes.len() - 1;
            }
            Err(e) => self.message = Some(format!("cannot load {path}: {e}")),
        }
    }

    /// Saves the picture on screen as a PNG at `path`.
    pub fn save(&mut self, path: &str) {
        let Some(frame) = &self.frame else {
            self.message = Some("nothing drawn yet".to_owned());
            return;
        };
        let path = PathBuf::from(path);
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            let _ = std::fs::create_dir_all(dir);
        }
        self.message = Some(match frame.canvas.save_png(&path) {
            Ok(()) => format!("saved {}", path.display()),
            Err(e) => format!("cannot save {}: {e}", path.display()),
        });
    }

    /// Draws the window's contents into `ui`.
    pub fn show(&mut self, ui: &mut egui::Ui) {
        match self.scene {
            Scene::Pixels => {
                self.show_playground(ui);
                self.window_screenshot(ui);
                return;
            }
            Scene::Curves => {
                self.show_curves(ui);
                self.window_screenshot(ui);
                return;
            }
            Scene::Surfaces => {
                self.show_surfaces(ui);
                self.window_screenshot(ui);
                return;
            }
            Scene::Tessellation => {
                self.show_tessellation(ui);
                self.window_screenshot(ui);
                return;
            }
            Scene::Gpu => {
                self.show_gpu(ui);
                self.window_screenshot(ui);
                return;
            }
            Scene::Pipeline => {}
        }
        self.ask();
        if let Some(frame) = self.worker.poll() {
            self.frame = Some(frame);
            self.texture = None;
        }
        if self.worker.busy_for().is_some() {
            ui.ctx().request_repaint_after(Duration::from_millis(100));
        }
        egui::Panel::right("controls")
            .default_size(320.0)
            .show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| self.controls(ui));
            });
        egui::CentralPanel::default().show(ui, |ui| self.picture(ui));
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
