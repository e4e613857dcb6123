//! The window's screenshot (`--window-screenshot`): taken once the scene's
//! first picture shows, then the window closes.

use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;

use canvas::Canvas;
use eframe::egui;

use super::{Scene, ViewerApp};

impl ViewerApp {
    /// Saves a screenshot of the whole window to `path` once the first
    /// picture shows, then closes the window.
    pub fn screenshot_window_to(&mut self, path: PathBuf) {
        self.window_screenshot = Some(path);
    }

    /// Takes the screenshot [`Self::screenshot_window_to`] asked for.
    pub(super) fn window_screenshot(&mut self, ui: &egui::Ui) {
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
            Scene::Pipeline => !self.mesh.live.textures.is_empty(),
            Scene::Pixels => self.playground.live.drawing.is_some(),
            Scene::Curves => self.curves.live.drawing.is_some(),
            Scene::Surfaces => !self.surfaces.live.textures.is_empty(),
            Scene::Tessellation => self.tessellation.live.drawing.is_some(),
            Scene::Gpu => self.gpu.live.drawing.is_some(),
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
}

/// A `w × h` RGBA image, top row first, as a canvas (for saving as PNG).
pub(crate) fn canvas_image(w: usize, h: usize, bytes: Vec<u8>) -> Option<Canvas> {
    let image = image::RgbaImage::from_raw(u32::try_from(w).ok()?, u32::try_from(h).ok()?, bytes)?;
    Some(Canvas::from_image(&image))
}
