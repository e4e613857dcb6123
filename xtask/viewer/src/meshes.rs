//! The meshes the viewer shows: the shipped ones and PLY files.

use std::path::Path;
use std::sync::Arc;

use scene::Mesh;

/// A mesh the viewer can show: a shipped one or a PLY file.
pub struct MeshEntry {
    /// Its name: the file name.
    pub name: String,
    /// The mesh.
    pub mesh: Arc<Mesh>,
}

/// The shipped meshes (`scene::data::MESHES`); those that cannot be read
/// are left out with a message.
#[must_use]
pub fn shipped_meshes() -> (Vec<MeshEntry>, Vec<String>) {
    let mut meshes = Vec::new();
    let mut problems = Vec::new();
    for name in scene::data::MESHES {
        match scene::ply::load(scene::data::path(name)) {
            Ok(mesh) => meshes.push(MeshEntry {
                name: (*name).to_owned(),
                mesh: Arc::new(mesh),
            }),
            Err(e) => problems.push(format!("{name}: {e}")),
        }
    }
    (meshes, problems)
}

/// The mesh in the PLY file at `path`, named by its file name.
///
/// # Errors
/// When the file cannot be read or is not a PLY mesh.
pub fn load(path: &Path) -> Result<MeshEntry, scene::PlyError> {
    let mesh = scene::ply::load(path)?;
    let name = path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    Ok(MeshEntry {
        name,
        mesh: Arc::new(mesh),
    })
}
