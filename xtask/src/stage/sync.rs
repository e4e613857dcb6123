//! Syncing a folder to hold exactly a tree's files, and claiming a
//! folder as the tooling's to rewrite.

use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};

use super::{STAGE_MARKER, Source};
use crate::files::{files_under, write_file};
/// Makes `dest` hold exactly `files` (besides [`crate::files::SKIPPED_FOLDERS`] and the
/// [`STAGE_MARKER`]): writes a file only when its contents differ, removes
/// the others and the folders they leave empty. Returns how many files
/// were written, and the files removed.
pub fn sync(files: &[(PathBuf, Source)], dest: &Path) -> Result<(usize, Vec<PathBuf>)> {
    fs::create_dir_all(dest).with_context(|| format!("cannot create {}", dest.display()))?;
    let mut written = 0;
    for (to, from) in files {
        let contents = from.read()?;
        let target = dest.join(to);
        if fs::read(&target).is_ok_and(|old| old == contents) {
            continue;
        }
        write_file(&target, &contents)?;
        written += 1;
    }
    let mut removed = Vec::new();
    let wanted: std::collections::HashSet<&Path> =
        files.iter().map(|(to, _)| to.as_path()).collect();
    for file in files_under(dest)? {
        if !wanted.contains(file.as_path()) && file != Path::new(STAGE_MARKER) {
            let path = dest.join(&file);
            fs::remove_file(&path).with_context(|| format!("cannot remove {}", path.display()))?;
            removed.push(file.clone());
            // Folders left empty go too (`remove_dir` refuses non-empty ones).
            let mut parent = path.parent();
            while let Some(dir) = parent.filter(|dir| *dir != dest) {
                if fs::remove_dir(dir).is_err() {
                    break;
                }
                parent = dir.parent();
            }
        }
    }
    Ok((written, removed))
}

/// Refuses to sync into `dir` unless it is empty, missing, or marked as
/// written by this tooling; then marks it.
pub fn claim(dir: &Path) -> Result<()> {
    if dir.exists() {
        let mut entries =
            fs::read_dir(dir).with_context(|| format!("cannot read {}", dir.display()))?;
        let empty = entries.next().is_none();
        if !empty && !dir.join(STAGE_MARKER).is_file() {
            bail!(
                "{} exists and was not written by `cargo xtask`; choose a new or empty folder",
                dir.display()
            );
        }
    }
    fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    fs::write(
        dir.join(STAGE_MARKER),
        "Written by `cargo xtask`: files here are replaced on the next run.\n",
    )
    .with_context(|| format!("cannot write in {}", dir.display()))
}
