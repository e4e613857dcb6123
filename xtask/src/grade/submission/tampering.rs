//! What a submission's tests changed while they ran (it then scores 0:
//! see `grade::adjustments`).

use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result};

use super::is_grading_file;
use crate::files::files_under;
use crate::stage;

/// Every grading file of the course at `root` with its contents.
pub(super) fn contents_of(root: &Path) -> Result<Vec<(PathBuf, Vec<u8>)>> {
    files_under(root)?
        .into_iter()
        .filter(|file| is_grading_file(file))
        .map(|file| {
            let bytes = fs::read(root.join(&file))
                .with_context(|| format!("cannot read {}", root.join(&file).display()))?;
            Ok((file, bytes))
        })
        .collect()
}

/// What the tests changed while they ran: grading files of the course at
/// `official` that differ from `before` (left as they are, for the tutor
/// to look at: the grader never rewrites the course), and files of the
/// stage that differ from its plan (the next sync puts them back).
/// Pending snapshots, which insta writes beside the official ones, are
/// the one thing tests may add (and cargo a lock file, where the course
/// has none).
pub(super) fn tampered(
    official: &Path,
    before: &[(PathBuf, Vec<u8>)],
    stage_root: &Path,
    plan: &[(PathBuf, Vec<u8>)],
) -> Result<Vec<PathBuf>> {
    let mut changed = Vec::new();
    for (file, bytes) in before {
        if fs::read(official.join(file)).ok().as_deref() != Some(bytes.as_slice()) {
            changed.push(file.clone());
        }
    }
    for file in files_under(official)?
        .into_iter()
        .filter(|f| is_grading_file(f))
    {
        if !before.iter().any(|(f, _)| *f == file) {
            changed.push(file);
        }
    }
    let is_pending = |file: &Path| {
        let name = file.to_string_lossy();
        name.ends_with(".snap.new") || name.ends_with(".pending-snap")
    };
    // Cargo's own files: the lock file, which staging trims to the staged
    // packages and cargo may write, and the stage's marker.
    let cargos =
        |file: &Path| file == Path::new("Cargo.lock") || file == Path::new(stage::STAGE_MARKER);
    for (file, bytes) in plan {
        if !cargos(file)
            && fs::read(stage_root.join(file)).ok().as_deref() != Some(bytes.as_slice())
        {
            changed.push(Path::new("stage").join(file));
        }
    }
    for file in files_under(stage_root)? {
        let planned = plan.iter().any(|(f, _)| *f == file);
        if !planned && !is_pending(&file) && !cargos(&file) {
            changed.push(Path::new("stage").join(file));
        }
    }
    changed.sort();
    changed.dedup();
    Ok(changed)
}
