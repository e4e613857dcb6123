//! The grader's file walks and reads, in one place: the files of a course
//! (never `target/`, `.git/` or the solutions, no link followed), a
//! bounded walk of what a job wrote, and the plain-file reads and writes
//! that staging a submission needs (no link followed at any component),
//! and which files are WGSL.

use std::fs::{self, File};
use std::path::{Component, Path, PathBuf};

use anyhow::{Context, Result};

/// Folders never copied, compared or deleted, at any depth: build output
/// and history.
pub const SKIPPED_FOLDERS: [&str; 2] = ["target", ".git"];

/// The solutions: skipped at the top of a course (a fixture course inside
/// the tooling may have a `reference/` of its own).
pub const SOLUTIONS: &str = "reference";

/// The most entries a walk of a writable folder visits: a job that makes
/// more files than this is stopped as one that writes too much.
pub const MAX_ENTRIES: usize = 20_000;

/// The most a file of a submission may hold to be read (a task file, a
/// grading file compared with the course's).
pub const MAX_SUBMITTED_FILE: u64 = 4 << 20;

/// Whether a file is WGSL (a shader piece a student writes).
#[must_use]
pub fn is_wgsl(file: impl AsRef<Path>) -> bool {
    file.as_ref().extension().is_some_and(|ext| ext == "wgsl")
}

/// Every file under `root`, relative to it and sorted, skipping
/// [`SKIPPED_FOLDERS`] at any depth and [`SOLUTIONS`] at the top. Symbolic links are neither listed nor
/// followed: one in a submission could point anywhere.
pub fn files_under(root: &Path) -> Result<Vec<PathBuf>> {
    fn walk(root: &Path, dir: &Path, files: &mut Vec<PathBuf>) -> Result<()> {
        let entries =
            fs::read_dir(dir).with_context(|| format!("cannot read {}", dir.display()))?;
        for entry in entries {
            let entry = entry.with_context(|| format!("cannot read {}", dir.display()))?;
            let path = entry.path();
            let kind = entry
                .file_type()
                .with_context(|| format!("cannot read {}", path.display()))?;
            if kind.is_dir() {
                let name = entry.file_name();
                let solutions = dir == root && name == SOLUTIONS;
                if !solutions && !SKIPPED_FOLDERS.iter().any(|s| name == *s) {
                    walk(root, &path, files)?;
                }
            } else if kind.is_file() {
                let relative = path.strip_prefix(root).unwrap_or(&path).to_path_buf();
                files.push(relative);
            }
        }
        Ok(())
    }
    let mut files = Vec::new();
    if root.is_dir() {
        walk(root, root, &mut files)?;
    }
    files.sort();
    Ok(files)
}

/// Whether `relative` under `root` is a plain file reached through plain
/// folders: `Err` names the first symbolic link (or other non-file) on
/// the way, for the report.
pub fn plain_file(root: &Path, relative: &Path) -> std::result::Result<(), String> {
    let mut path = root.to_path_buf();
    let parts: Vec<Component<'_>> = relative.components().collect();
    for (i, part) in parts.iter().enumerate() {
        let Component::Normal(name) = part else {
            return Err(format!("{} is not a plain path", relative.display()));
        };
        path.push(name);
        let shown = || {
            parts[..=i]
                .iter()
                .map(|c| c.as_os_str().to_string_lossy())
                .collect::<Vec<_>>()
                .join("/")
        };
        let meta =
            fs::symlink_metadata(&path).map_err(|_| format!("{} does not exist", shown()))?;
        if meta.file_type().is_symlink() {
            return Err(format!("{} is a symbolic link", shown()));
        }
        let last = i + 1 == parts.len();
        if last && !meta.is_file() {
            return Err(format!("{} is not a plain file", shown()));
        }
        if !last && !meta.is_dir() {
            return Err(format!("{} is not a folder", shown()));
        }
    }
    Ok(())
}

/// The contents of `relative` under `root` if it is a plain file reached
/// through plain folders ([`plain_file`]) and holds at most
/// [`MAX_SUBMITTED_FILE`] bytes; `None` otherwise (a link, a device, a
/// pipe, a flood: nothing the grader reads could block it or follow a
/// link out of the submission).
#[must_use]
pub fn read_plain(root: &Path, relative: &Path) -> Option<Vec<u8>> {
    use std::io::Read as _;
    plain_file(root, relative).ok()?;
    let file = File::open(root.join(relative)).ok()?;
    let mut bytes = Vec::new();
    file.take(MAX_SUBMITTED_FILE + 1)
        .read_to_end(&mut bytes)
        .ok()?;
    (bytes.len() as u64 <= MAX_SUBMITTED_FILE).then_some(bytes)
}

/// Writes `contents` to `path`, creating the folders it lies in.
pub fn write_file(path: &Path, contents: impl AsRef<[u8]>) -> Result<()> {
    if let Some(parent) = path.parent() {
        fs::create_dir_all(parent)
            .with_context(|| format!("cannot create {}", parent.display()))?;
    }
    fs::write(path, contents).with_context(|| format!("cannot write {}", path.display()))
}

/// The bytes of the files under `dir`, never following a link; `None`
/// past [`MAX_ENTRIES`] entries (a job making files without end).
#[must_use]
pub fn bytes_under(dir: &Path) -> Option<u64> {
    let mut total = 0;
    let mut seen = 0;
    walk(dir, &mut |_, meta| {
        seen += 1;
        total += meta.len();
        seen <= MAX_ENTRIES
    })
    .then_some(total)
}

/// Calls `visit` with every file and folder under `dir` (depth first,
/// links neither followed nor visited) until it returns `false`; whether
/// the walk went to its end.
pub fn walk(dir: &Path, visit: &mut dyn FnMut(&Path, &fs::Metadata) -> bool) -> bool {
    let Ok(entries) = fs::read_dir(dir) else {
        return true;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        let Ok(meta) = fs::symlink_metadata(&path) else {
            continue;
        };
        if meta.file_type().is_symlink() {
            continue;
        }
        if !visit(&path, &meta) {
            return false;
        }
        if meta.is_dir() && !walk(&path, visit) {
            return false;
        }
    }
    true
}

/// The files under `dir`, relative to it and sorted: no link followed, at
/// most [`MAX_ENTRIES`] looked at.
#[must_use]
pub fn listing(dir: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    let mut seen = 0;
    walk(dir, &mut |path, meta| {
        seen += 1;
        if meta.is_file()
            && let Ok(relative) = path.strip_prefix(dir)
        {
            files.push(relative.to_path_buf());
        }
        seen <= MAX_ENTRIES
    });
    files.sort();
    files
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn walks_follow_no_link_and_stop_at_their_bound() {
        let dir = std::env::temp_dir().join(format!("course-files-walk-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(dir.join("a/b")).unwrap();
        fs::write(dir.join("a/b/file"), "1234").unwrap();
        #[cfg(unix)]
        {
            std::os::unix::fs::symlink(".", dir.join("a/loop")).unwrap();
            std::os::unix::fs::symlink("..", dir.join("a/b/up")).unwrap();
        }
        assert_eq!(listing(&dir), [PathBuf::from("a/b/file")]);
        assert_eq!(bytes_under(&dir).map(|b| b >= 4), Some(true));
        for n in 0..=MAX_ENTRIES {
            File::create(dir.join(format!("f{n}"))).unwrap();
        }
        assert_eq!(bytes_under(&dir), None, "a walk past its bound says so");
        fs::remove_dir_all(&dir).unwrap();
    }
}
