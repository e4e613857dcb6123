//! Comparing a submission's grading files with the official course's:
//! what was changed, is missing or was added, and which of its `src/`
//! files are not graded.

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

use anyhow::Result;
use serde::{Deserialize, Serialize};

use super::slashed;
use crate::edition as release;
use crate::edition::{Files, Source};
use crate::files::files_under;
use crate::stage::{self, is_student_file};
use crate::topics::{self, Topic};

/// What differs between a submission and the official course, in the
/// files that take part in grading (paths relative to the course root).
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
pub struct Integrity {
    /// The official course the submission was compared with.
    pub official: PathBuf,
    /// Official files whose copy in the submission differs.
    pub changed: Vec<PathBuf>,
    /// Official files the submission lacks.
    pub missing: Vec<PathBuf>,
    /// Grading files the submission has and the course does not (e.g. an
    /// extra test file); they are not used.
    pub added: Vec<PathBuf>,
    /// Files the submission's tests changed while they ran: official files
    /// in the stage or in the course itself (restored afterwards). The
    /// submission scores 0 and is flagged.
    #[serde(default)]
    pub tampered: Vec<PathBuf>,
    /// Files in the submission's `src/` folders that are not task files
    /// and differ from the course's (an edited `lib.rs`, an added module):
    /// not graded, the course's are used. Not a reason to flag.
    #[serde(default)]
    pub not_graded: Vec<PathBuf>,
}

impl Integrity {
    /// How many files differ.
    #[must_use]
    pub fn count(&self) -> usize {
        self.changed.len() + self.missing.len() + self.added.len() + self.tampered.len()
    }

    /// Whether anything differs: the submission is flagged.
    #[must_use]
    pub fn flagged(&self) -> bool {
        !(self.changed.is_empty()
            && self.missing.is_empty()
            && self.added.is_empty()
            && self.tampered.is_empty())
    }

    /// One line for people, e.g. "2 grading files differ from the official
    /// course (changed: exercises/01-lines/tests/dda.rs, ...)".
    #[must_use]
    pub fn summary(&self) -> String {
        let mut parts = Vec::new();
        for (what, files) in [
            ("changed", &self.changed),
            ("missing", &self.missing),
            ("added", &self.added),
            ("changed by its tests while grading", &self.tampered),
        ] {
            if files.is_empty() {
                continue;
            }
            let shown: Vec<String> = files.iter().take(5).map(|f| slashed(f)).collect();
            let more = files.len().saturating_sub(shown.len());
            let mut part = format!("{what}: {}", shown.join(", "));
            if more > 0 {
                let _ = write!(part, " and {more} more");
            }
            parts.push(part);
        }
        let count = self.count();
        format!(
            "{count} grading file(s) differ from the official course, which was used instead ({})",
            parts.join("; ")
        )
    }
}

/// Whether a path takes part in grading: the manifests, `.cargo/`, the
/// course library, the tooling, and every exercise file outside `src/`.
pub(super) fn is_grading_file(relative: &Path) -> bool {
    let Some(first) = relative.components().next() else {
        return false;
    };
    let first = first.as_os_str();
    let top_level = relative.components().count() == 1;
    // Not `Cargo.lock`: the stage builds with the course's, and cargo
    // rewrites a student's when it resolves for them.
    (top_level && first == "Cargo.toml")
        || first == ".cargo"
        || first == "crates"
        || first == "xtask"
        || (first == "exercises"
            && relative.components().count() >= 3
            && !is_student_file(relative))
}

/// The topics (folder names) of the official course that a submission
/// holds.
fn submitted_topics(official: &Path, submission: &Path) -> Result<Vec<Topic>> {
    Ok(topics::discover(official)?
        .into_iter()
        .filter(|topic| submission.join("exercises").join(&topic.name).is_dir())
        .collect())
}

/// Compares the submission's grading files with the official ones: those
/// of the whole course, or of the student edition of the topics it holds
/// (`cargo xtask release`), whichever it is closer to.
pub fn check(official: &Path, submission: &Path) -> Result<Integrity> {
    let course: Files = files_under(official)?
        .into_iter()
        .map(|file| {
            let source = Source::File(official.join(&file));
            (file, source)
        })
        .collect();
    let mut integrity = compare(official, &course, submission)?;
    let topics = submitted_topics(official, submission)?;
    if integrity.flagged() && !topics.is_empty() {
        let (edition, _) = release::edition_files(official, &topics)?;
        let against_edition = compare(official, &edition, submission)?;
        if against_edition.count() < integrity.count() {
            integrity = against_edition;
        }
    }
    let tasks = stage::task_files(official)?;
    for file in files_under(submission)? {
        if is_student_file(&file) && !tasks.contains(&file) {
            let same = fs::read(official.join(&file)).is_ok_and(|ours| {
                crate::files::read_plain(submission, &file).is_some_and(|t| same_text(&t, &ours))
            });
            if !same {
                integrity.not_graded.push(file);
            }
        }
    }
    Ok(integrity)
}

/// Compares the submission's grading files with `expected`.
fn compare(official: &Path, expected: &Files, submission: &Path) -> Result<Integrity> {
    let theirs: Vec<PathBuf> = files_under(submission)?
        .into_iter()
        .filter(|f| is_grading_file(f))
        .collect();
    let ours: Vec<&(PathBuf, Source)> = expected
        .iter()
        .filter(|(file, _)| is_grading_file(file))
        .collect();
    let mut integrity = Integrity {
        official: official.to_path_buf(),
        ..Integrity::default()
    };
    for (file, source) in &ours {
        let official_bytes = source.read()?;
        // Read without following a link, and within a size: a grading
        // file that is a link, a pipe or a flood counts as changed.
        if fs::symlink_metadata(submission.join(file)).is_err() {
            integrity.missing.push(file.clone());
        } else if !crate::files::read_plain(submission, file)
            .is_some_and(|t| same_text(&t, &official_bytes))
        {
            integrity.changed.push(file.clone());
        }
    }
    integrity.added = theirs
        .into_iter()
        .filter(|f| !ours.iter().any(|(file, _)| file == f))
        .collect();
    Ok(integrity)
}

/// Whether two files hold the same text, line endings aside: a checkout
/// made on Windows with `core.autocrlf` has every line end in `\r\n`
/// (where the course's `.gitattributes` is not honoured, e.g. a zip), and
/// grades as the same files with `\n`.
fn same_text(theirs: &[u8], ours: &[u8]) -> bool {
    theirs == ours || without_cr(theirs) == without_cr(ours)
}

/// `bytes` with each `\r\n` made `\n`.
fn without_cr(bytes: &[u8]) -> Vec<u8> {
    let mut out = Vec::with_capacity(bytes.len());
    for (i, &byte) in bytes.iter().enumerate() {
        if !(byte == b'\r' && bytes.get(i + 1) == Some(&b'\n')) {
            out.push(byte);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grading_files_are_everything_the_grader_builds_or_reads() {
        for file in [
            "Cargo.toml",
            ".cargo/config.toml",
            "crates/testkit/src/raster.rs",
            "xtask/src/main.rs",
            "exercises/01-lines/README.md",
            "exercises/01-lines/tasks.toml",
            "exercises/01-lines/Cargo.toml",
            "exercises/01-lines/tests/dda.rs",
            "exercises/01-lines/tests/snapshots/dda__x.snap",
        ] {
            assert!(is_grading_file(Path::new(file)), "{file}");
        }
        for file in [
            "README.md",
            "Cargo.lock",
            "notes.txt",
            "exercises/01-lines/src/dda.rs",
            "exercises/README.md",
        ] {
            assert!(!is_grading_file(Path::new(file)), "{file}");
        }
    }

    #[test]
    fn text_is_the_same_whatever_its_line_endings() {
        assert!(same_text(b"a\r\nb\r\n", b"a\nb\n"));
        assert!(same_text(b"a\nb", b"a\nb"));
        assert!(!same_text(b"a\r\nc\r\n", b"a\nb\n"));
        // A lone carriage return is a change, not a line ending.
        assert!(!same_text(b"a\rb", b"ab"));
    }
}
