//! The window: the picture on the left, the controls and your stages on
//! the right, as in seed 004's Figure 2. Six scenes: your pipeline
//! ([`crate::render`]), the pixel playground ([`crate::playground`]), the
//! curve scene ([`crate::curves`]), the trimmed surface
//! ([`crate::surfaces`]), the tessellation ([`crate::tessellation`]) and
//! the GPU passes ([`crate::gpu_scene`]).

use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;

use canvas::Canvas;
use eframe::egui;
use egui::{Color32, RichText, TextureHandle, TextureOptions};
use scene::Mode;

use crate::curves::{self, CurveDrawing, CurveKind, CurveSetup, CurveWorker};
use crate::gpu_scene::{self, GpuDrawing, GpuSetup};
use crate::meshes::MeshEntry;
use crate::playground::{self, Cell, Drawing, PlaygroundWorker, Primitive, Setup};
use crate::render::{Frame, FrameWorker, Settings, frame_worker};
use crate::stages::{Stages, Status};
use crate::surfaces::{self, SurfaceDrawing, SurfaceSetup, TrimShape};
use crate::tessellation::{self as tess, TessDrawing, TessSetup};
use crate::worker::Worker;

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

    fn controls(&mut self, ui: &mut egui::Ui) {
        self.scene_switch(ui);
        ui.heading("Your pipeline");
        ui.label(
            "The mesh, transformed by the course; clipped, drawn and depth-tested by your code.",
        );
        ui.separator();
        let current = self.meshes[self.selected].name.clone();
        egui::ComboBox::from_label("Mesh")
            .selected_text(current)
            .show_ui(ui, |ui| {
                for (index, entry) in self.meshes.iter().enumerate() {
                    ui.selectable_value(&mut self.selected, index, &entry.name);
                }
            });
        ui.horizontal(|ui| {
            let label = ui.label("PLY file");
            ui.add(egui::TextEdit::singleline(&mut self.open_path).hint_text("path/to/mesh.ply"))
                .labelled_by(label.id);
            if ui.button("Open").clicked() {
                let path = self.open_path.clone();
                self.open(&path);
            }
        });
        ui.separator();
        ui.horizontal(|ui| {
            ui.radio_value(&mut self.settings.mode, Mode::Line, "Wireframe");
            ui.radio_value(&mut self.settings.mode, Mode::Fill, "Filled");
        });
        ui.checkbox(&mut self.settings.clip, "Clipping");
        ui.checkbox(
            &mut self.outline_clipped,
            "Outline your clipped polygons (drawn by the window, not by your lines)",
        )
        .on_hover_text(
            "Topic 04 on its own: the polygons your Sutherland–Hodgman returns, \
             outlined in yellow with the window's vector shapes. Shown by itself \
             when your lines or fill draw nothing yet.",
        );
        ui.checkbox(&mut self.settings.depth_test, "Depth test");
        ui.separator();
        ui.label("Camera (or drag the picture; scroll to zoom)");
        ui.add(egui::Slider::new(&mut self.settings.yaw, -180.0..=180.0).text("around"));
        ui.add(egui::Slider::new(&mut self.settings.pitch, -89.0..=89.0).text("above"));
        ui.add(egui::Slider::new(&mut self.settings.distance, 1.0..=12.0).text("distance"));
        egui::ComboBox::from_label("Pixels")
            .selected_text(format!("{0} × {0}", self.settings.width))
            .show_ui(ui, |ui| {
                for size in [100, 200, 400, 800] {
                    if ui
                        .selectable_label(self.settings.width == size, format!("{size} × {size}"))
                        .clicked()
                    {
                        self.settings.width = size;
                        self.settings.height = size;
                    }
                }
            });
        if ui.button("Reset camera").clicked() {
            let defaults = Settings::default();
            self.settings.yaw = defaults.yaw;
            self.settings.pitch = defaults.pitch;
            self.settings.distance = defaults.distance;
        }
        ui.separator();
        ui.horizontal(|ui| {
            let label = ui.label("Save as");
            ui.add(egui::TextEdit::singleline(&mut self.save_path))
                .labelled_by(label.id);
            if ui.button("Save PNG").clicked() {
                let path = self.save_path.clone();
                self.save(&path);
            }
        });
        if let Some(message) = &self.message {
            ui.label(message);
        }
        ui.separator();
        self.stage_list(ui);
    }

    fn stage_list(&self, ui: &mut egui::Ui) {
        ui.heading("Your stages");
        if !self.not_compiling.is_empty() {
            ui.label(
                RichText::new(format!(
                    "Not compiling, so left out: {}",
                    self.not_compiling.join(", ")
                ))
                .color(Color32::LIGHT_RED),
            );
        }
        let Some(frame) = &self.frame else {
            ui.label("drawing the first frame …");
            return;
        };
        for stage in &frame.stages {
            stage_label(ui, stage.name, stage.source, &stage.status);
        }
        let (total, drawn) = frame.polygons;
        let timing = self
            .worker
            .last_frame_time()
            .filter(|_| self.show_timing)
            .map_or_else(String::new, |t| {
                format!(" in {:.0} ms", t.as_secs_f64() * 1e3)
            });
        ui.label(format!("{drawn} of {total} polygons drawn{timing}"));
    }

    fn picture(&mut self, ui: &mut egui::Ui) {
        let slow = self.worker.slow_for();
        let Some(frame) = &self.frame else {
            ui.label("drawing …");
            slow_notice(ui, "Your stages have been drawing this frame", slow);
            return;
        };
        let texture = self
            .texture
            .get_or_insert_with(|| texture(ui, "picture", &frame.canvas))
            .clone();
        let response = magnified(ui, &texture, 0.0);
        // Topic 04 without topics 01 and 03: your clipped polygons as
        // outlines, when asked for or when nothing else draws them.
        let drew = frame.stages[1..=2].iter().any(|s| s.status == Status::Ok);
        if !frame.clipped.is_empty() && (self.outline_clipped || !drew) {
            outline_polygons(ui, response.rect, &frame.canvas, &frame.clipped);
            ui.label(
                RichText::new(
                    "Yellow: your clipped polygons, outlined by the window (not by your lines)",
                )
                .color(OUTLINE),
            );
        }
        let (around, above, zoom) = orbit(ui, &response);
        let settings = &mut self.settings;
        settings.yaw = (settings.yaw + around).clamp(-180.0, 180.0);
        settings.pitch = (settings.pitch + above).clamp(-89.0, 89.0);
        settings.distance = (settings.distance * zoom).clamp(1.0, 12.0);
        slow_notice(ui, "Your stages have been drawing this frame", slow);
    }
}

/// The colour of the clipped polygons' outlines.
const OUTLINE: Color32 = Color32::from_rgb(255, 215, 0);

/// Draws `polygons` (pixel coordinates of `canvas`, `y` up) as closed
/// outlines over the picture shown in `rect`, with egui's vector shapes.
fn outline_polygons(ui: &egui::Ui, rect: egui::Rect, canvas: &Canvas, polygons: &[Vec<[f32; 2]>]) {
    let (w, h) = (canvas.width() as f32, canvas.height() as f32);
    let scale = egui::vec2(rect.width() / w, rect.height() / h);
    let to_screen = |[x, y]: [f32; 2]| {
        egui::pos2(
            rect.left() + (x + 0.5) * scale.x,
            rect.top() + (h - y - 0.5) * scale.y,
        )
    };
    let painter = ui.painter_at(rect);
    for polygon in polygons {
        let points: Vec<egui::Pos2> = polygon.iter().map(|&p| to_screen(p)).collect();
        painter.add(egui::Shape::closed_line(
            points,
            egui::Stroke::new(1.0, OUTLINE),
        ));
    }
}

/// The room kept below a picture or the pixel grid for [`slow_notice`]:
/// the picture is laid out the same whether the notice shows or not, so
/// that it never moves under the pointer (a handle being dragged stays
/// where it was grabbed).
fn notice_room(ui: &egui::Ui) -> f32 {
    3.0 * ui.text_style_height(&egui::TextStyle::Body)
}

/// Below the picture: that the student's code has been drawing for long,
/// perhaps in an endless loop, and that the window still answers.
fn slow_notice(ui: &mut egui::Ui, what: &str, busy: Option<std::time::Duration>) {
    if let Some(busy) = busy {
        ui.label(
            RichText::new(format!(
                "{what} for {:.1} s: an endless loop? \
                 The window stays usable; fix the loop and restart the viewer.",
                busy.as_secs_f64()
            ))
            .color(Color32::YELLOW),
        );
    }
}

impl ViewerApp {
    /// The pixel playground: its controls on the right, the grid on the
    /// left.
    fn show_playground(&mut self, ui: &mut egui::Ui) {
        self.ask_playground();
        if let Some(drawing) = self.playground.worker.poll() {
            let count = drawing.yours.len();
            self.playground.steps = self.playground.steps.map(|s| s.min(count));
            self.playground.drawing = Some(drawing);
        }
        if self.playground.worker.busy_for().is_some() {
            ui.ctx().request_repaint_after(Duration::from_millis(100));
        }
        self.two_panels(ui, Self::playground_controls, Self::pixel_grid);
    }

    fn playground_controls(&mut self, ui: &mut egui::Ui) {
        ui.heading("Your pixels");
        ui.label("Your code draws one primitive; drag its handles. Beside it, the pixels of the course's definition, which the tests compare with.");
        ui.separator();
        let playground = &mut self.playground;
        egui::ComboBox::from_label("Primitive")
            .selected_text(playground.setup.primitive.label())
            .show_ui(ui, |ui| {
                for primitive in Primitive::ALL {
                    ui.selectable_value(
                        &mut playground.setup.primitive,
                        primitive,
                        primitive.label(),
                    );
                }
            });
        ui.add(egui::Slider::new(&mut playground.setup.size, Setup::SIZES).text("pixels across"));
        ui.separator();
        ui.label("# in both, + only yours, - only expected (the tests' legend)");
        let Some(drawing) = &playground.drawing else {
            ui.label("drawing …");
            return;
        };
        let (name, source) = drawing.stage;
        stage_label(ui, name, source, &drawing.status);
        ui.label(drawing.summary());
        ui.separator();
        let count = drawing.yours.len();
        ui.label(format!(
            "Step through your {count} pixels, in the order you plotted them"
        ));
        let mut shown = playground.steps.unwrap_or(count);
        ui.horizontal(|ui| {
            if ui.button("Back").clicked() {
                shown = shown.saturating_sub(1);
            }
            if ui.button("Next").clicked() {
                shown = (shown + 1).min(count);
            }
            if ui.button("All").clicked() {
                shown = count;
            }
        });
        ui.add(egui::Slider::new(&mut shown, 0..=count).text("pixels shown"));
        playground.steps = (shown < count).then_some(shown);
        if let Some(step) = shown.checked_sub(1).and_then(|k| drawing.yours.get(k)) {
            ui.label(RichText::new(format!("pixel {shown} of {count}")).strong());
            ui.label(&step.note);
        }
    }

    fn pixel_grid(&mut self, ui: &mut egui::Ui) {
        let slow = self.playground.worker.slow_for();
        let playground = &mut self.playground;
        let n = playground.setup.size;
        let available = ui.available_size() - egui::vec2(0.0, notice_room(ui));
        let cell = (available.x.min(available.y) / n as f32).floor().max(4.0);
        let (response, painter) = ui.allocate_painter(
            egui::vec2(cell * n as f32, cell * n as f32),
            egui::Sense::drag(),
        );
        let origin = response.rect.left_top();
        playground.grid = Some((origin, cell));
        let top = n as f32 - 0.5;
        let to_screen = |p: glam::Vec2| {
            egui::pos2(origin.x + (p.x + 0.5) * cell, origin.y + (top - p.y) * cell)
        };
        let to_grid = |s: egui::Pos2| {
            glam::Vec2::new((s.x - origin.x) / cell - 0.5, top - (s.y - origin.y) / cell)
        };
        let setup = &playground.setup;
        let handles = setup.primitive.handles();
        if response.drag_started()
            && let Some(at) = response.interact_pointer_pos()
        {
            let at = to_grid(at);
            playground.dragging = nearest(
                (0..handles).map(|k| f64::from(setup.handles[k].distance(at))),
                1.0,
            );
        }
        if let (Some(k), Some(at)) = (playground.dragging, response.interact_pointer_pos())
            && response.dragged()
        {
            playground.setup.move_handle(k, to_grid(at));
        }
        if response.drag_stopped() {
            playground.dragging = None;
        }
        let setup = &playground.setup;
        let painter = &painter;
        let font = egui::FontId::monospace(cell * 0.6);
        if let Some(drawing) = &playground.drawing {
            let shown = playground.steps.unwrap_or(drawing.yours.len());
            let colours: std::collections::HashMap<canvas::Pixel, Color32> = drawing
                .yours
                .iter()
                .take(shown)
                .filter_map(|s| Some((s.pixel, s.colour.map(colour32)?)))
                .collect();
            // The legend's mark on a cell: a frame and its symbol.
            let mark = |rect: egui::Rect, width: f32, colour: Color32, symbol: &str| {
                painter.rect_stroke(
                    rect.shrink(1.5),
                    0.0,
                    egui::Stroke::new(width, colour),
                    egui::StrokeKind::Inside,
                );
                painter.text(
                    rect.center(),
                    egui::Align2::CENTER_CENTER,
                    symbol,
                    font.clone(),
                    colour,
                );
            };
            for (p, how) in drawing.cells(shown) {
                let rect =
                    egui::Rect::from_center_size(to_screen(p.centre()), egui::vec2(cell, cell));
                let ink = colours.get(&p).copied().unwrap_or(INK);
                match how {
                    Cell::Both => {
                        painter.rect_filled(rect.shrink(1.0), 0.0, ink);
                    }
                    Cell::OnlyYours => {
                        painter.rect_filled(rect.shrink(1.0), 0.0, ink);
                        mark(rect, 3.0, ONLY_YOURS, "+");
                    }
                    Cell::OnlyExpected => mark(rect, 2.0, ONLY_EXPECTED, "-"),
                    Cell::Empty => {
                        painter.rect_filled(rect.shrink(1.0), 0.0, EMPTY);
                    }
                }
            }
            if let Some(step) = shown.checked_sub(1).and_then(|k| drawing.yours.get(k))
                && shown < drawing.yours.len()
            {
                let rect = egui::Rect::from_center_size(
                    to_screen(step.pixel.centre()),
                    egui::vec2(cell, cell),
                );
                painter.rect_stroke(
                    rect,
                    0.0,
                    egui::Stroke::new(3.0, Color32::YELLOW),
                    egui::StrokeKind::Outside,
                );
            }
        }
        // The ideal primitive over the pixels.
        let ideal = egui::Stroke::new(2.0, IDEAL);
        let h = setup.handles;
        match setup.primitive {
            Primitive::DdaLine | Primitive::MidpointLine | Primitive::WuLine => {
                painter.line_segment([to_screen(h[0]), to_screen(h[1])], ideal);
            }
            Primitive::Circle => {
                painter.circle_stroke(to_screen(h[0]), setup.radius() as f32 * cell, ideal);
            }
            Primitive::Triangle => {
                let points: Vec<egui::Pos2> = h.iter().map(|&p| to_screen(p)).collect();
                painter.add(egui::Shape::closed_line(points, ideal));
            }
        }
        for (k, handle) in h.iter().take(handles).enumerate() {
            let centre = to_screen(*handle);
            painter.circle_filled(centre, (cell * 0.3).max(4.0), HANDLE);
            painter.text(
                centre,
                egui::Align2::CENTER_CENTER,
                k.to_string(),
                egui::FontId::proportional((cell * 0.35).max(8.0)),
                Color32::BLACK,
            );
        }
        slow_notice(ui, "Your code has been drawing", slow);
    }
}

impl ViewerApp {
    /// The curve scene: its controls on the right, the curve on the left.
    fn show_curves(&mut self, ui: &mut egui::Ui) {
        self.ask_curves();
        if let Some(drawing) = self.curves.worker.poll() {
            self.curves.drawing = Some(drawing);
        }
        if self.curves.worker.busy_for().is_some() {
            ui.ctx().request_repaint_after(Duration::from_millis(100));
        }
        self.two_panels(ui, Self::curve_controls, Self::curve_area);
    }

    fn curve_controls(&mut self, ui: &mut egui::Ui) {
        let curves = &mut self.curves;
        ui.heading("Your curve");
        ui.horizontal(|ui| {
            ui.radio_value(&mut curves.setup.kind, CurveKind::Bezier, "Bézier (07)");
            ui.radio_value(&mut curves.setup.kind, CurveKind::Nurbs, "NURBS (08)");
        });
        ui.label(match curves.setup.kind {
            CurveKind::Bezier => {
                "Your de Casteljau draws the curve and the construction of one point; drag the control points. Beside it, the curve of the definition (the Bernstein sum)."
            }
            CurveKind::Nurbs => {
                "Your NurbsCurve::point draws the curve over the clamped uniform knot vector, with its points at the knots; drag the control points, set the degree and the weights. Beside it, the curve of the definition (the Cox–de Boor sum)."
            }
        });
        ui.separator();
        let mut count = curves.setup.points.len();
        ui.add(
            egui::Slider::new(&mut count, curves::MIN_POINTS..=curves::MAX_POINTS)
                .text("control points"),
        );
        if count != curves.setup.points.len() {
            curves.setup.set_count(count);
        }
        match curves.setup.kind {
            CurveKind::Bezier => {
                ui.add(egui::Slider::new(&mut curves.setup.t, 0.0..=1.0).text("t"));
                ui.checkbox(&mut curves.construction, "Construction at t");
            }
            CurveKind::Nurbs => {
                let highest = curves.setup.points.len() - 1;
                ui.add(egui::Slider::new(&mut curves.setup.degree, 1..=highest).text("degree"));
                curves.setup.weights.resize(curves.setup.points.len(), 1.0);
                for (k, w) in curves.setup.weights.iter_mut().enumerate() {
                    ui.add(
                        egui::Slider::new(w, curves::WEIGHTS)
                            .logarithmic(true)
                            .text(format!("w{k}")),
                    );
                }
            }
        }
        ui.checkbox(&mut curves.definition, "The definition's curve");
        if ui.button("Reset").clicked() {
            let kind = curves.setup.kind;
            curves.setup = CurveSetup {
                kind,
                ..CurveSetup::default()
            };
        }
        ui.separator();
        ui.heading("Your stage");
        let stages = crate::stages::Stages::default();
        let Some(drawing) = &curves.drawing else {
            ui.label("drawing …");
            return;
        };
        let (name, source) = match drawing.setup.kind {
            CurveKind::Bezier => (stages.curve.name, stages.curve.source),
            CurveKind::Nurbs => (stages.nurbs.name, stages.nurbs.source),
        };
        stage_label(ui, name, source, &drawing.status);
        if let Some(deviation) = drawing.deviation {
            ui.label(format!(
                "largest distance from the definition: {deviation:.1e}"
            ));
        }
        if drawing.setup.kind == CurveKind::Bezier
            && let Some(point) = drawing.levels.last().filter(|l| l.len() == 1).map(|l| l[0])
        {
            ui.label(format!(
                "C({:.2}) = ({:.4}, {:.4})",
                drawing.setup.t, point.x, point.y
            ));
        }
        if drawing.setup.kind == CurveKind::Nurbs {
            let knots: Vec<String> = drawing
                .setup
                .knots()
                .iter()
                .map(|k| format!("{k:.2}"))
                .collect();
            ui.label(format!("knots: {}", knots.join(" ")));
        }
    }

    fn curve_area(&mut self, ui: &mut egui::Ui) {
        let slow = self.curves.worker.slow_for();
        let curves = &mut self.curves;
        let available = ui.available_size() - egui::vec2(0.0, notice_room(ui));
        let side = available.x.min(available.y).max(100.0);
        let (response, painter) = ui.allocate_painter(egui::vec2(side, side), egui::Sense::drag());
        let area = response.rect.shrink(side * 0.04);
        curves.area = Some(area);
        let to_unit = |s: egui::Pos2| {
            glam::DVec2::new(
                f64::from((s.x - area.left()) / area.width()),
                f64::from((area.bottom() - s.y) / area.height()),
            )
        };
        if response.drag_started()
            && let Some(at) = response.interact_pointer_pos()
        {
            let at = to_unit(at);
            curves.dragging = nearest(curves.setup.points.iter().map(|p| p.distance(at)), 0.05);
        }
        if let (Some(k), Some(at)) = (curves.dragging, response.interact_pointer_pos())
            && response.dragged()
            && let Some(p) = curves.setup.points.get_mut(k)
        {
            *p = to_unit(at).clamp(glam::DVec2::ZERO, glam::DVec2::ONE);
        }
        if response.drag_stopped() {
            curves.dragging = None;
        }
        painter.rect_filled(response.rect, 0.0, EMPTY);
        let screen = |p: glam::DVec2| unit_to_screen(area, p);
        let polyline = |points: &[glam::DVec2], stroke: egui::Stroke| {
            if points.len() >= 2 {
                painter.add(egui::Shape::line(
                    points.iter().map(|&p| screen(p)).collect(),
                    stroke,
                ));
            }
        };
        // The control polygon, as it is now (also while a drag waits for
        // its drawing).
        polyline(&curves.setup.points, egui::Stroke::new(1.5, Color32::GRAY));
        if let Some(drawing) = &curves.drawing {
            if curves.definition {
                polyline(&drawing.expected, egui::Stroke::new(5.0, DEFINITION));
            }
            polyline(&drawing.yours, egui::Stroke::new(2.0, Color32::WHITE));
            for &p in &drawing.knot_points {
                painter.circle_filled(screen(p), 4.5, LEVELS[1]);
            }
            if curves.construction && drawing.setup.kind == CurveKind::Bezier {
                for (k, level) in drawing.levels.iter().enumerate().skip(1) {
                    let colour = LEVELS[(k - 1) % LEVELS.len()];
                    polyline(level, egui::Stroke::new(1.5, colour));
                    for &p in level {
                        painter.circle_filled(screen(p), 3.5, colour);
                    }
                }
                if let Some(&[point]) = drawing.levels.last().map(Vec::as_slice)
                    && drawing.levels.len() == drawing.setup.points.len()
                {
                    painter.circle_filled(screen(point), 6.0, ONLY_YOURS);
                }
            }
        }
        for (k, &p) in curves.setup.points.iter().enumerate() {
            let centre = screen(p);
            painter.circle_filled(centre, 9.0, HANDLE);
            painter.text(
                centre,
                egui::Align2::CENTER_CENTER,
                k.to_string(),
                egui::FontId::proportional(11.0),
                Color32::BLACK,
            );
        }
        slow_notice(ui, "Your de Casteljau has been drawing", slow);
    }
}

impl ViewerApp {
    /// The surface scene: its controls on the right, the picture and the
    /// parameter square on the left.
    fn show_surfaces(&mut self, ui: &mut egui::Ui) {
        self.surfaces.ask();
        self.surfaces.poll(ui);
        self.two_panels(ui, Self::surface_controls, Self::surface_picture);
    }

    fn surface_controls(&mut self, ui: &mut egui::Ui) {
        ui.heading("Your trimmed surface");
        ui.label(
            "The seed's hill, a bicubic Bézier patch whose control points you raise and lower: evaluated by your surface code, trimmed by your trim and tessellated, rasterized and lit by your render_surface.",
        );
        ui.separator();
        let setup = &mut self.surfaces.setup;
        ui.label("Control points: their heights (u to the right, v up)");
        egui::Grid::new("control net").show(ui, |ui| {
            for j in (0..4).rev() {
                for i in 0..4 {
                    ui.add(
                        egui::DragValue::new(&mut setup.heights[i][j])
                            .speed(0.01)
                            .range(surfaces::HEIGHTS)
                            .prefix(format!("P{i}{j} ")),
                    );
                }
                ui.end_row();
            }
        });
        ui.separator();
        trim_controls(ui, &mut setup.trim);
        ui.separator();
        ui.add(
            egui::Slider::new(&mut setup.level, 1..=surfaces::MAX_LEVEL).text("tessellation level"),
        );
        ui.checkbox(&mut setup.wireframe, "Wireframe");
        ui.label("Camera (or drag the picture; scroll to zoom)");
        ui.add(egui::Slider::new(&mut setup.yaw, -180.0..=180.0).text("around"));
        ui.add(egui::Slider::new(&mut setup.pitch, -89.0..=89.0).text("above"));
        ui.add(egui::Slider::new(&mut setup.distance, 0.8..=8.0).text("distance"));
        if ui.button("Reset").clicked() {
            *setup = SurfaceSetup::default();
        }
        ui.separator();
        ui.heading("Your stages");
        let Some(drawing) = &self.surfaces.drawing else {
            ui.label("drawing …");
            return;
        };
        let stages = Stages::default();
        let trim_source = drawing.setup.trim.shape.source();
        for (name, source, status) in [
            (stages.surface.name, stages.surface.source, &drawing.surface),
            (stages.trim.name, trim_source, &drawing.trim),
            (
                stages.surface_render.name,
                stages.surface_render.source,
                &drawing.render,
            ),
        ] {
            stage_label(ui, name, source, status);
        }
    }

    fn surface_picture(&mut self, ui: &mut egui::Ui) {
        let slow = self.surfaces.worker.slow_for();
        let surfaces = &mut self.surfaces;
        let Some(drawing) = &surfaces.drawing else {
            ui.label("drawing …");
            slow_notice(ui, "Your surface code has been drawing", slow);
            return;
        };
        if surfaces.textures.is_empty() {
            surfaces.textures = vec![
                texture(ui, "surface", &drawing.canvas),
                texture(ui, "parameter square", &drawing.uv_map),
            ];
        }
        let response = magnified(ui, &surfaces.textures[0], 140.0);
        let (around, above, zoom) = orbit(ui, &response);
        let setup = &mut surfaces.setup;
        setup.yaw = (setup.yaw + f64::from(around)).clamp(-180.0, 180.0);
        setup.pitch = (setup.pitch + f64::from(above)).clamp(-89.0, 89.0);
        setup.distance = (setup.distance * f64::from(zoom)).clamp(0.8, 8.0);
        ui.horizontal(|ui| {
            ui.add(egui::Image::from_texture(egui::load::SizedTexture::new(
                surfaces.textures[1].id(),
                egui::vec2(128.0, 128.0),
            )));
            ui.label(
                "The parameter square as your trim sees it: dark is cut away.\nu to the right, v up.",
            );
        });
        slow_notice(ui, "Your surface code has been drawing", slow);
    }
}

impl ViewerApp {
    /// The tessellation scene: its controls on the right, the triangles
    /// on the left.
    fn show_tessellation(&mut self, ui: &mut egui::Ui) {
        self.tessellation.ask();
        self.tessellation.poll(ui);
        self.two_panels(ui, Self::tessellation_controls, Self::tessellation_picture);
    }

    fn tessellation_controls(&mut self, ui: &mut egui::Ui) {
        ui.heading("Your tessellation");
        ui.label(
            "A surface of Bézier or rational patches cut into triangles by your topic 09 code, drawn by the topic's given renderer.",
        );
        ui.separator();
        let setup = &mut self.tessellation.setup;
        egui::ComboBox::from_label("Surface")
            .selected_text(setup.surface.label())
            .show_ui(ui, |ui| {
                for surface in tess::Surface::ALL {
                    ui.selectable_value(&mut setup.surface, surface, surface.label());
                }
            });
        ui.horizontal(|ui| {
            for method in tess::Method::ALL {
                ui.radio_value(&mut setup.method, method, method.label());
            }
        });
        match setup.method {
            tess::Method::Uniform => {
                ui.add(
                    egui::Slider::new(&mut setup.level, 1..=tess::MAX_LEVEL).text("cells per side"),
                );
            }
            tess::Method::PerPatch => {
                ui.add(
                    egui::Slider::new(&mut setup.tolerance, 1e-4..=0.1)
                        .logarithmic(true)
                        .text("chord tolerance"),
                );
            }
            tess::Method::FullyAdaptive => {
                ui.add(
                    egui::Slider::new(&mut setup.level, 1..=tess::MAX_LEVEL)
                        .text("start: cells per side"),
                );
                let before = setup.test;
                egui::ComboBox::from_label("Edge test")
                    .selected_text(setup.test.label())
                    .show_ui(ui, |ui| {
                        for test in tess::Test::ALL {
                            ui.selectable_value(&mut setup.test, test, test.label());
                        }
                    });
                if setup.test != before {
                    setup.thresholds = setup.test.default_thresholds();
                }
                ui.add(
                    egui::Slider::new(&mut setup.thresholds[0], 1e-3..=1.0)
                        .logarithmic(true)
                        .text("threshold"),
                );
                if setup.test == tess::Test::OneEdgeComplementary {
                    ui.add(
                        egui::Slider::new(&mut setup.thresholds[1], 1e-3..=1.0)
                            .logarithmic(true)
                            .text("t2"),
                    );
                }
                ui.add(
                    egui::Slider::new(&mut setup.depth, 0..=tess::MAX_DEPTH).text("most halvings"),
                );
            }
        }
        ui.separator();
        ui.horizontal(|ui| {
            ui.radio_value(&mut setup.look, tess::Look::Shaded, "Shaded");
            ui.radio_value(&mut setup.look, tess::Look::Wireframe, "Wireframe");
            ui.radio_value(&mut setup.look, tess::Look::Both, "Both");
        });
        ui.label("View (or drag the picture)");
        ui.add(egui::Slider::new(&mut setup.yaw, -180.0..=180.0).text("turn"));
        ui.add(egui::Slider::new(&mut setup.pitch, -180.0..=180.0).text("tilt"));
        if ui.button("Reset").clicked() {
            *setup = TessSetup::default();
        }
        ui.separator();
        ui.heading("Your stage");
        let Some(drawing) = &self.tessellation.drawing else {
            ui.label("drawing …");
            return;
        };
        let named = Stages::default();
        if drawing.decomposition != Status::Unused {
            let stage = &named.decompose;
            stage_label(ui, stage.name, stage.source, &drawing.decomposition);
        }
        stage_label(
            ui,
            named.tessellate.name,
            drawing.setup.method.source(),
            &drawing.status,
        );
        if let Some(result) = &drawing.result {
            ui.label(format!(
                "{} vertices, {} triangles",
                result.vertices, result.triangles
            ));
        }
    }

    fn tessellation_picture(&mut self, ui: &mut egui::Ui) {
        let slow = self.tessellation.worker.slow_for();
        let scene = &mut self.tessellation;
        let Some(result) = scene.drawing.as_ref().and_then(|d| d.result.as_ref()) else {
            ui.label(match &scene.drawing {
                None => "tessellating …",
                Some(_) => "no triangles: your stage did not make a mesh (see the panel)",
            });
            slow_notice(ui, "Your tessellation has been running", slow);
            return;
        };
        if scene.textures.is_empty() {
            scene.textures = vec![texture(ui, "tessellation", &result.canvas)];
        }
        let response = magnified(ui, &scene.textures[0], 0.0);
        // Turn and tilt; the renderer fits the mesh, so no zoom.
        let (around, above, _) = orbit(ui, &response);
        let setup = &mut scene.setup;
        setup.yaw = (setup.yaw + f64::from(around)).clamp(-180.0, 180.0);
        setup.pitch = (setup.pitch - f64::from(above)).clamp(-180.0, 180.0);
        slow_notice(ui, "Your tessellation has been running", slow);
    }
}

impl ViewerApp {
    /// The GPU scene: its controls on the right, the picture on the left.
    fn show_gpu(&mut self, ui: &mut egui::Ui) {
        self.gpu.ask();
        self.gpu.poll(ui);
        self.two_panels(ui, Self::gpu_controls, Self::gpu_picture);
    }

    fn gpu_controls(&mut self, ui: &mut egui::Ui) {
        ui.heading("Your GPU passes");
        ui.label(
            "Patches tessellated and drawn on the GPU by your topic 10 code: control pass, primitive generator, evaluation pass, shading, trimming and wireframe.",
        );
        ui.separator();
        let setup = &mut self.gpu.setup;
        egui::ComboBox::from_label("Surface")
            .selected_text(setup.surface.label())
            .show_ui(ui, |ui| {
                for surface in gpu_scene::GpuSurface::ALL {
                    ui.selectable_value(&mut setup.surface, surface, surface.label());
                }
            });
        ui.horizontal(|ui| {
            ui.radio_value(
                &mut setup.levels,
                gpu_scene::Levels::Uniform,
                "Uniform levels",
            );
            ui.radio_value(&mut setup.levels, gpu_scene::Levels::Adaptive, "Adaptive");
        });
        match setup.levels {
            gpu_scene::Levels::Uniform => {
                ui.add(egui::Slider::new(&mut setup.level, 1.0..=64.0).text("level"));
            }
            gpu_scene::Levels::Adaptive => {
                ui.add(
                    egui::Slider::new(&mut setup.pixels_per_segment, 2.0..=100.0)
                        .text("pixels per segment"),
                );
            }
        }
        ui.horizontal(|ui| {
            ui.radio_value(&mut setup.spacing, gpu_scene::Spacing::Equal, "equal");
            ui.radio_value(
                &mut setup.spacing,
                gpu_scene::Spacing::FractionalEven,
                "fractional even",
            );
            ui.radio_value(
                &mut setup.spacing,
                gpu_scene::Spacing::FractionalOdd,
                "fractional odd",
            );
        });
        ui.separator();
        trim_controls(ui, &mut setup.trim);
        ui.separator();
        ui.checkbox(&mut setup.wireframe, "Wireframe");
        ui.label("Camera (or drag the picture; scroll to zoom)");
        ui.add(egui::Slider::new(&mut setup.yaw, -180.0..=180.0).text("around"));
        ui.add(egui::Slider::new(&mut setup.pitch, -89.0..=89.0).text("above"));
        ui.add(egui::Slider::new(&mut setup.distance, 0.8..=10.0).text("distance"));
        if ui.button("Reset").clicked() {
            *setup = GpuSetup::default();
        }
        ui.separator();
        ui.heading("Your stages");
        let Some(drawing) = &self.gpu.drawing else {
            ui.label("drawing on the GPU …");
            return;
        };
        for stage in &drawing.stages {
            stage_label(ui, stage.name, stage.source, &stage.status);
        }
        if drawing.canvas.is_some() {
            ui.label(format!("{} triangles", drawing.triangles));
        }
        if self.show_timing {
            ui.label(RichText::new(format!("device: {}", drawing.device)).small());
        }
    }

    fn gpu_picture(&mut self, ui: &mut egui::Ui) {
        let slow = self.gpu.worker.slow_for();
        let scene = &mut self.gpu;
        let Some(canvas) = scene.drawing.as_ref().and_then(|d| d.canvas.as_ref()) else {
            ui.label(match &scene.drawing {
                None => "drawing on the GPU …",
                Some(_) => "nothing drawn: a stage it needs did not run (see the panel)",
            });
            slow_notice(ui, "Your GPU passes have been running", slow);
            return;
        };
        if scene.textures.is_empty() {
            scene.textures = vec![texture(ui, "gpu", canvas)];
        }
        let response = magnified(ui, &scene.textures[0], 0.0);
        let (around, above, zoom) = orbit(ui, &response);
        let setup = &mut scene.setup;
        setup.yaw = (setup.yaw + around).clamp(-180.0, 180.0);
        setup.pitch = (setup.pitch + above).clamp(-89.0, 89.0);
        setup.distance = (setup.distance * zoom).clamp(0.8, 10.0);
        slow_notice(ui, "Your GPU passes have been running", slow);
    }
}

/// A picture at the largest whole-pixel magnification that fits (every
/// pixel a sharp square), `reserve` points kept free below it, sensing
/// drags (to orbit the camera).
fn magnified(ui: &mut egui::Ui, texture: &TextureHandle, reserve: f32) -> egui::Response {
    let [w, h] = texture.size().map(|s| s.max(1) as f32);
    let available = ui.available_size() - egui::vec2(0.0, notice_room(ui) + reserve);
    let scale = (available.x / w).min(available.y / h);
    let scale = if scale >= 1.0 { scale.floor() } else { scale };
    ui.add(
        egui::Image::from_texture(egui::load::SizedTexture::new(
            texture.id(),
            egui::vec2(w * scale, h * scale),
        ))
        .sense(egui::Sense::drag()),
    )
}

/// How a drag over a picture and the scroll wheel move an orbiting
/// camera: degrees around and above (half a degree a point, the picture
/// following the pointer), and the factor for its distance.
fn orbit(ui: &egui::Ui, response: &egui::Response) -> (f32, f32, f32) {
    let delta = if response.dragged() {
        response.drag_delta()
    } else {
        egui::Vec2::ZERO
    };
    let scroll = if response.hovered() {
        ui.input(|i| i.smooth_scroll_delta.y)
    } else {
        0.0
    };
    (-delta.x * 0.5, delta.y * 0.5, 1.0 - scroll * 0.002)
}

/// A canvas as a texture, drawn without smoothing.
fn texture(ui: &egui::Ui, name: &str, canvas: &Canvas) -> TextureHandle {
    ui.ctx()
        .load_texture(name, colour_image(canvas), TextureOptions::NEAREST)
}

/// One stage in a panel: `name: status` in the status's colour, its
/// source below.
fn stage_label(ui: &mut egui::Ui, name: &str, source: &str, status: &Status) {
    ui.label(RichText::new(format!("{name}: {}", status.describe())).color(status_colour(status)));
    ui.label(RichText::new(source).small().weak());
}

/// The trim's shape and parameters (the surface and GPU scenes).
fn trim_controls(ui: &mut egui::Ui, trim: &mut surfaces::TrimSetup) {
    egui::ComboBox::from_label("Trim")
        .selected_text(trim.shape.label())
        .show_ui(ui, |ui| {
            for shape in TrimShape::ALL {
                ui.selectable_value(&mut trim.shape, shape, shape.label());
            }
        });
    if trim.shape != TrimShape::None {
        ui.add(egui::Slider::new(&mut trim.centre.x, 0.0..=1.0).text("centre u"));
        ui.add(egui::Slider::new(&mut trim.centre.y, 0.0..=1.0).text("centre v"));
    }
    match trim.shape {
        TrimShape::None => {}
        TrimShape::Rectangle => {
            ui.add(egui::Slider::new(&mut trim.size.x, 0.01..=0.5).text("half width"));
            ui.add(egui::Slider::new(&mut trim.size.y, 0.01..=0.5).text("half height"));
        }
        TrimShape::Circle => {
            ui.add(egui::Slider::new(&mut trim.size.x, 0.01..=0.7).text("radius"));
        }
        TrimShape::Ellipse => {
            ui.add(egui::Slider::new(&mut trim.size.x, 0.01..=0.7).text("radius in u"));
            ui.add(egui::Slider::new(&mut trim.size.y, 0.01..=0.7).text("radius in v"));
        }
        TrimShape::NewtonQuadratic | TrimShape::NewtonCubic | TrimShape::Nested => {
            ui.add(egui::Slider::new(&mut trim.scale, 0.1..=2.0).text("scale"));
            ui.add(egui::Slider::new(&mut trim.iterations, 1..=30).text("Newton steps"));
            ui.add(
                egui::Slider::new(&mut trim.epsilon, 1e-4..=0.1)
                    .logarithmic(true)
                    .text("ε"),
            );
        }
    }
}

/// The handle a drag picks up: the nearest of those at `distances` from
/// the pointer, if it is nearer than `reach`.
fn nearest(distances: impl Iterator<Item = f64>, reach: f64) -> Option<usize> {
    distances
        .enumerate()
        .filter(|(_, d)| *d < reach)
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(k, _)| k)
}

/// A point of the unit square on screen, in `area` (y up).
fn unit_to_screen(area: egui::Rect, p: glam::DVec2) -> egui::Pos2 {
    egui::pos2(
        area.left() + p.x as f32 * area.width(),
        area.bottom() - p.y as f32 * area.height(),
    )
}

/// A stage's status in its colour.
fn status_colour(status: &Status) -> Color32 {
    match status {
        Status::Ok => Color32::LIGHT_GREEN,
        Status::Unused | Status::NotReached => Color32::GRAY,
        Status::NotYet(_) => Color32::YELLOW,
        Status::Missing | Status::Panicked(_) | Status::Failed(_) => Color32::LIGHT_RED,
    }
}

/// The definition's curve, under yours.
const DEFINITION: Color32 = Color32::from_rgb(70, 110, 70);
/// The levels of the construction, one colour each.
const LEVELS: [Color32; 4] = [
    Color32::from_rgb(90, 170, 255),
    Color32::from_rgb(255, 170, 60),
    Color32::from_rgb(190, 120, 255),
    Color32::from_rgb(80, 220, 200),
];

/// A pixel you plotted (where your code gives it no colour).
const INK: Color32 = Color32::from_rgb(200, 200, 210);
/// A pixel of the grid nothing covers.
const EMPTY: Color32 = Color32::from_rgb(38, 38, 44);
/// The mark of a pixel only you plotted.
const ONLY_YOURS: Color32 = Color32::from_rgb(255, 60, 60);
/// The mark of a pixel only the definition has.
const ONLY_EXPECTED: Color32 = Color32::from_rgb(90, 170, 255);
/// The ideal primitive.
const IDEAL: Color32 = Color32::from_rgb(255, 220, 90);
/// The handles.
const HANDLE: Color32 = Color32::from_rgb(255, 255, 255);

/// A canvas colour on screen.
fn colour32(c: canvas::Rgba) -> Color32 {
    let [r, g, b, _] = c.to_rgba8();
    Color32::from_rgb(r, g, b)
}

/// A `w × h` RGBA image, top row first, as a canvas (for saving as PNG).
fn canvas_image(w: usize, h: usize, bytes: Vec<u8>) -> Option<Canvas> {
    let image = image::RgbaImage::from_raw(u32::try_from(w).ok()?, u32::try_from(h).ok()?, bytes)?;
    Some(Canvas::from_image(&image))
}

/// The canvas as an egui image (y up on the canvas, y down on screen).
fn colour_image(canvas: &Canvas) -> egui::ColorImage {
    let image = canvas.to_image();
    egui::ColorImage::from_rgba_unmultiplied(
        [image.width() as usize, image.height() as usize],
        image.as_raw(),
    )
}

impl eframe::App for ViewerApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.show(ui);
    }
}
