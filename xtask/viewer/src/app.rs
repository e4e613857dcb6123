//! The window: the picture on the left, the controls and your stages on
//! the right, as in seed 004's Figure 2.

use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;

use canvas::Canvas;
use eframe::egui;
use egui::{Color32, RichText, TextureHandle, TextureOptions};
use scene::Mode;

use crate::meshes::MeshEntry;
use crate::render::{Frame, Settings};
use crate::stages::{Stages, Status};
use crate::worker::Worker;

/// The viewer's state.
pub struct ViewerApp {
    meshes: Vec<MeshEntry>,
    selected: usize,
    settings: Settings,
    worker: Worker,
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
    /// Whether the stage list says how long the frame took (off in
    /// snapshot tests, where the time would differ from run to run).
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
            meshes,
            selected: 0,
            settings: Settings::default(),
            worker: Worker::start(stages),
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
        if self.texture.is_some() && !self.screenshot_asked {
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

    /// Whether the stage list says how long each frame took.
    pub fn set_show_timing(&mut self, show: bool) {
        self.show_timing = show;
    }

    /// Reports a frame as slow (an endless loop?) after `limit`.
    pub fn set_slow_after(&mut self, limit: Duration) {
        self.worker.set_slow_after(limit);
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
            self.worker.request(
                Arc::clone(&self.meshes[self.selected].mesh),
                self.settings.clone(),
            );
            self.asked = Some(wanted);
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

    fn controls(&mut self, ui: &mut egui::Ui) {
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
            let colour = match stage.status {
                Status::Ok => Color32::LIGHT_GREEN,
                Status::Unused | Status::NotReached => Color32::GRAY,
                Status::NotYet(_) => Color32::YELLOW,
                Status::Missing | Status::Panicked(_) | Status::Failed(_) => Color32::LIGHT_RED,
            };
            ui.label(
                RichText::new(format!("{}: {}", stage.name, stage.status.describe())).color(colour),
            );
            ui.label(RichText::new(stage.source).small().weak());
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
        if let Some(busy) = self.worker.slow_for() {
            ui.label(
                RichText::new(format!(
                    "Your stages have been drawing this frame for {:.1} s: an endless loop? \
                     The window stays usable; fix the loop and restart the viewer.",
                    busy.as_secs_f64()
                ))
                .color(Color32::YELLOW),
            );
        }
        let Some(frame) = &self.frame else {
            ui.label("drawing …");
            return;
        };
        let texture = self
            .texture
            .get_or_insert_with(|| {
                ui.ctx().load_texture(
                    "picture",
                    colour_image(&frame.canvas),
                    TextureOptions::NEAREST,
                )
            })
            .clone();
        // The largest whole-pixel magnification that fits, so that every
        // pixel shows as a sharp square.
        let available = ui.available_size();
        let (w, h) = (
            frame.canvas.width().max(1) as f32,
            frame.canvas.height().max(1) as f32,
        );
        let scale = (available.x / w).min(available.y / h);
        let scale = if scale >= 1.0 { scale.floor() } else { scale };
        let size = egui::vec2(w * scale, h * scale);
        let response = ui.add(
            egui::Image::from_texture(egui::load::SizedTexture::new(texture.id(), size))
                .sense(egui::Sense::drag()),
        );
        if response.dragged() {
            let delta = response.drag_delta();
            self.settings.yaw = (self.settings.yaw - delta.x * 0.5).clamp(-180.0, 180.0);
            self.settings.pitch = (self.settings.pitch + delta.y * 0.5).clamp(-89.0, 89.0);
        }
        if response.hovered() {
            let scroll = ui.input(|i| i.smooth_scroll_delta.y);
            if scroll != 0.0 {
                self.settings.distance =
                    (self.settings.distance * (1.0 - scroll * 0.002)).clamp(1.0, 12.0);
            }
        }
    }
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
