//! The pipeline scene's state in the window: the meshes, the settings,
//! the frame on screen and the file fields.

use std::path::PathBuf;
use std::sync::Arc;

use scene::Mesh;

use super::draw::{Frame, Settings, frame_worker};
use crate::live::{Live, LiveScene};
use crate::meshes::MeshEntry;
use crate::stages::Stages;

/// The pipeline scene in the window.
pub(crate) struct MeshScene {
    pub(crate) meshes: Vec<MeshEntry>,
    pub(crate) selected: usize,
    pub(crate) settings: Settings,
    /// The frame on screen; a change of mesh or settings asks again.
    pub(crate) live: Live<(Arc<Mesh>, Settings), Frame, (usize, Settings)>,
    /// Where "Save PNG" writes.
    pub(crate) save_path: String,
    /// A PLY file to load.
    pub(crate) open_path: String,
    /// The last message for the user (saved, cannot load, ...).
    pub(crate) message: Option<String>,
    /// The scene outlines your clipped polygons over the picture.
    pub(crate) outline_clipped: bool,
}

impl MeshScene {
    /// The scene of `meshes` (at least one) drawn with `stages`.
    pub(crate) fn new(meshes: Vec<MeshEntry>, stages: Stages) -> Self {
        Self {
            meshes,
            selected: 0,
            settings: Settings::default(),
            live: Live::new(frame_worker(stages)),
            save_path: "target/view/picture.png".to_owned(),
            open_path: String::new(),
            message: None,
            outline_clipped: false,
        }
    }

    /// Selects the mesh called `name`, if there is one.
    pub(crate) fn select(&mut self, name: &str) -> bool {
        match self.meshes.iter().position(|m| m.name == name) {
            Some(index) => {
                self.selected = index;
                true
            }
            None => false,
        }
    }

    /// Loads the PLY file at `path` and shows it.
    pub(crate) fn open(&mut self, path: &str) {
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
    pub(crate) fn save(&mut self, path: &str) {
        let Some(frame) = &self.live.drawing else {
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
}

impl LiveScene for MeshScene {
    type Job = (Arc<Mesh>, Settings);
    type Drawing = Frame;
    type Key = (usize, Settings);

    /// Asks for a frame if the mesh or the settings changed since the
    /// last one.
    fn ask(&mut self) {
        let wanted = (self.selected, self.settings.clone());
        let mesh = &self.meshes[self.selected].mesh;
        let settings = &self.settings;
        self.live
            .ask(&wanted, || (Arc::clone(mesh), settings.clone()));
    }

    fn live(&mut self) -> &mut Live<(Arc<Mesh>, Settings), Frame, (usize, Settings)> {
        &mut self.live
    }
}
