//! Reading a file of a folder that someone else may change while it is
//! read (a shared drop folder, a folder tests write): one handle, opened
//! one folder at a time without following a link at any component, and
//! the bytes read from that handle alone.
//!
//! Checking a path first (`lstat` on every component) and opening it
//! afterwards leaves a gap: a watcher that swaps the file, or a folder on
//! its way, for a link between the two makes the grader read whatever the
//! link names (the solution, the tutor's notes). Here nothing is looked up
//! twice: each folder is opened relative to the handle of the one above
//! with `O_NOFOLLOW | O_DIRECTORY`, the file relative to the last with
//! `O_NOFOLLOW | O_NONBLOCK` (a named pipe cannot block the grader), and
//! what the handle is (`fstat`) decides whether it is read. What the
//! caller gets is a copy in memory: checked, staged and graded, never
//! read again from the folder.
//!
//! Off Unix the check-then-open of [`crate::files::read_plain`] is what
//! there is; the grade of record runs on Linux.

use std::path::{Component, Path};

/// The contents of `relative` under `root`, if every folder on the way is
/// a folder (not a link to one) and the file a plain file (not a link, a
/// pipe or a device) of at most `max` bytes. `Err` says what is in the way,
/// in words for the report; [`Missing`] when nothing is there at all.
pub fn read(root: &Path, relative: &Path, max: u64) -> Result<Vec<u8>, Refusal> {
    let parts = relative
        .components()
        .map(|part| match part {
            Component::Normal(name) => Ok(name),
            _ => Err(Refusal::Refused(format!(
                "{} is not a plain path",
                relative.display()
            ))),
        })
        .collect::<Result<Vec<_>, _>>()?;
    if parts.is_empty() {
        return Err(Refusal::Refused("an empty path".to_owned()));
    }
    imp::read(root, &parts, max)
}

/// Why [`read`] read nothing.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Refusal {
    /// Nothing is at the path (or a folder on the way is missing).
    Missing,
    /// Something is there that is not read, and why.
    Refused(String),
}

pub use Refusal::Missing;

/// `a/b` of the first `n` parts, for messages.
fn shown(parts: &[&std::ffi::OsStr], n: usize) -> String {
    parts[..n]
        .iter()
        .map(|p| p.to_string_lossy())
        .collect::<Vec<_>>()
        .join("/")
}

#[cfg(unix)]
mod imp {
    use std::ffi::OsStr;
    use std::io::Read as _;
    use std::os::fd::OwnedFd;
    use std::path::Path;

    use rustix::fs::{FileType, Mode, OFlags, fstat, open, openat};
    use rustix::io::Errno;

    use super::{Refusal, shown};

    pub(super) fn read(root: &Path, parts: &[&OsStr], max: u64) -> Result<Vec<u8>, Refusal> {
        let folder = OFlags::RDONLY | OFlags::DIRECTORY | OFlags::CLOEXEC;
        // The root is the caller's choice (the submission as the tutor
        // named it): opened as given.
        let mut dir: OwnedFd = open(root, folder, Mode::empty()).map_err(|e| match e {
            Errno::NOENT => Refusal::Missing,
            e => Refusal::Refused(format!("cannot open {}: {e}", root.display())),
        })?;
        for (i, name) in parts.iter().enumerate() {
            let last = i + 1 == parts.len();
            let flags = if last {
                OFlags::RDONLY | OFlags::NOFOLLOW | OFlags::NONBLOCK | OFlags::CLOEXEC
            } else {
                folder | OFlags::NOFOLLOW
            };
            let here = || shown(parts, i + 1);
            let opened = openat(&dir, *name, flags, Mode::empty()).map_err(|e| match e {
                Errno::NOENT => Refusal::Missing,
                // O_NOFOLLOW on the last part, O_DIRECTORY|O_NOFOLLOW on a
                // folder: a link is refused with ELOOP (or ENOTDIR).
                Errno::LOOP | Errno::MLINK => {
                    Refusal::Refused(format!("{} is a symbolic link", here()))
                }
                Errno::NOTDIR => {
                    Refusal::Refused(format!("{} is not a folder (a link, or a file)", here()))
                }
                e => Refusal::Refused(format!("cannot open {}: {e}", here())),
            })?;
            dir = opened;
        }
        let stat = fstat(&dir).map_err(|e| {
            Refusal::Refused(format!("cannot read {}: {e}", shown(parts, parts.len())))
        })?;
        if FileType::from_raw_mode(stat.st_mode) != FileType::RegularFile {
            return Err(Refusal::Refused(format!(
                "{} is not a plain file",
                shown(parts, parts.len())
            )));
        }
        let mut bytes = Vec::new();
        std::fs::File::from(dir)
            .take(max + 1)
            .read_to_end(&mut bytes)
            .map_err(|e| {
                Refusal::Refused(format!("cannot read {}: {e}", shown(parts, parts.len())))
            })?;
        if bytes.len() as u64 > max {
            return Err(Refusal::Refused(format!(
                "{} holds more than {max} bytes",
                shown(parts, parts.len())
            )));
        }
        Ok(bytes)
    }
}

#[cfg(not(unix))]
mod imp {
    use std::ffi::OsStr;
    use std::path::{Path, PathBuf};

    use super::{Refusal, shown};

    pub(super) fn read(root: &Path, parts: &[&OsStr], max: u64) -> Result<Vec<u8>, Refusal> {
        let relative: PathBuf = parts.iter().collect();
        if std::fs::symlink_metadata(root.join(&relative)).is_err() {
            return Err(Refusal::Missing);
        }
        crate::files::plain_file(root, &relative).map_err(Refusal::Refused)?;
        crate::files::read_plain(root, &relative)
            .filter(|bytes| bytes.len() as u64 <= max)
            .ok_or_else(|| Refusal::Refused(format!("cannot read {}", shown(parts, parts.len()))))
    }
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;
    use std::fs;
    use std::os::unix::fs::symlink;

    #[test]
    fn links_at_any_component_are_refused_and_plain_files_read() {
        let dir = std::env::temp_dir().join(format!("xtask-nofollow-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        let sub = dir.join("sub");
        fs::create_dir_all(sub.join("exercises/01-x/src")).unwrap();
        fs::create_dir_all(dir.join("solutions/src")).unwrap();
        fs::write(dir.join("solutions/src/dda.rs"), "the solution").unwrap();
        fs::write(sub.join("exercises/01-x/src/dda.rs"), "mine").unwrap();
        let read = |relative: &str| read(&sub, Path::new(relative), 100);
        assert_eq!(read("exercises/01-x/src/dda.rs"), Ok(b"mine".to_vec()));
        assert_eq!(read("exercises/01-x/src/none.rs"), Err(Missing));
        assert_eq!(read("exercises/02-y/src/dda.rs"), Err(Missing));
        // The file a link.
        symlink(
            dir.join("solutions/src/dda.rs"),
            sub.join("exercises/01-x/src/link.rs"),
        )
        .unwrap();
        assert!(
            matches!(read("exercises/01-x/src/link.rs"), Err(Refusal::Refused(why)) if why.contains("symbolic link"))
        );
        // A folder on the way a link.
        symlink(dir.join("solutions"), sub.join("exercises/03-z")).unwrap();
        assert!(matches!(
            read("exercises/03-z/src/dda.rs"),
            Err(Refusal::Refused(_))
        ));
        // Too big, and not a file.
        fs::write(sub.join("exercises/01-x/src/big.rs"), vec![b'x'; 101]).unwrap();
        assert!(
            matches!(read("exercises/01-x/src/big.rs"), Err(Refusal::Refused(why)) if why.contains("more than"))
        );
        assert!(
            matches!(read("exercises/01-x/src"), Err(Refusal::Refused(why)) if why.contains("not a plain file"))
        );
        assert!(matches!(
            read("../sub/exercises/01-x/src/dda.rs"),
            Err(Refusal::Refused(_))
        ));
        // A named pipe with no writer: opened without blocking, refused
        // (the grader's reads of a member's files go through here).
        let pipe = sub.join("exercises/01-x/src/pipe.rs");
        let made = std::process::Command::new("mkfifo").arg(&pipe).status();
        if made.is_ok_and(|status| status.success()) {
            assert!(
                matches!(read("exercises/01-x/src/pipe.rs"), Err(Refusal::Refused(why)) if why.contains("not a plain file"))
            );
        }
        let _ = fs::remove_dir_all(&dir);
    }
}
