//! `cargo xtask grade --submission DIR`: grading a student's checkout, or a
//! folder of them, with the course's official tests.
//!
//! Only `exercises/*/src/` belongs to the student. Everything else that
//! takes part in grading — the course library (`crates/`), the tests and
//! snapshots, the task sheets (they hold the points), the manifests, the
//! tooling — is the course's. So a submission is never built where it
//! lies: its `src/` folders are laid over a copy of the official course,
//! the *stage*, and the stage is graded.
//!
//! ```text
//!   official course ──copy (no target/, .git/, reference/)──┐
//!                                                           ├──> stage ──grade──> report
//!   submission ──exercises/*/src/ only──────────────────────┘
//! ```
//!
//! The grading files of the submission are compared with the official ones
//! first; a submission where any differ, are missing or were added is
//! *flagged* in every report (the table, `report.html`, `report.json`,
//! Gradescope's output). Nothing in the submission is ever written to.
//!
//! Each submission is graded into `<out>/<name>/` (its stage is
//! `<out>/<name>/stage/`, its build `<out>/.build/`). A folder whose
//! subfolders are checkouts is a class: each is graded in turn, and
//! `<out>/gradebook.csv` and `gradebook.json` list the scores.

use std::fmt::Write as _;
use std::fs;
use std::path::{Component, Path, PathBuf};

use anyhow::{Context, Result, bail};
use serde::Serialize;

use super::report::{self, Report};
use super::{GradeOptions, table};

/// Folders never copied or compared: build output, history, solutions.
const SKIPPED_FOLDERS: [&str; 3] = ["target", ".git", "reference"];

/// What differs between a submission and the official course, in the
/// files that take part in grading (paths relative to the course root).
#[derive(Debug, Clone, Default, Serialize)]
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
}

impl Integrity {
    /// Whether anything differs: the submission is flagged.
    #[must_use]
    pub fn flagged(&self) -> bool {
        !(self.changed.is_empty() && self.missing.is_empty() && self.added.is_empty())
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
        let count = self.changed.len() + self.missing.len() + self.added.len();
        format!(
            "{count} grading file(s) differ from the official course, which was used instead ({})",
            parts.join("; ")
        )
    }
}

/// Whether a path (relative to a course root) is the student's: inside
/// `exercises/<topic>/src/`.
fn is_student_file(relative: &Path) -> bool {
    let parts: Vec<Component<'_>> = relative.components().collect();
    parts.len() >= 3 && parts[0].as_os_str() == "exercises" && parts[2].as_os_str() == "src"
}

/// Whether a path takes part in grading: the manifests, `.cargo/`, the
/// course library, the tooling, and every exercise file outside `src/`.
fn is_grading_file(relative: &Path) -> bool {
    let Some(first) = relative.components().next() else {
        return false;
    };
    let first = first.as_os_str();
    let top_level = relative.components().count() == 1;
    (top_level && (first == "Cargo.toml" || first == "Cargo.lock"))
        || first == ".cargo"
        || first == "crates"
        || first == "xtask"
        || (first == "exercises"
            && relative.components().count() >= 3
            && !is_student_file(relative))
}

/// Every file under `root`, relative to it and sorted, skipping
/// [`SKIPPED_FOLDERS`] at any depth.
fn files_under(root: &Path) -> Result<Vec<PathBuf>> {
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
                if !SKIPPED_FOLDERS.iter().any(|s| entry.file_name() == *s) {
                    walk(root, &path, files)?;
                }
            } else if kind.is_file() {
                let relative = path.strip_prefix(root).unwrap_or(&path).to_path_buf();
                files.push(relative);
            }
            // Symbolic links are neither copied nor followed: a link in a
            // submission could point anywhere.
        }
        Ok(())
    }
    let mut files = Vec::new();
    walk(root, root, &mut files)?;
    files.sort();
    Ok(files)
}

/// Compares the submission's grading files with the official ones.
pub fn check(official: &Path, submission: &Path) -> Result<Integrity> {
    let theirs: Vec<PathBuf> = files_under(submission)?
        .into_iter()
        .filter(|f| is_grading_file(f))
        .collect();
    let ours: Vec<PathBuf> = files_under(official)?
        .into_iter()
        .filter(|f| is_grading_file(f))
        .collect();
    let mut integrity = Integrity {
        official: official.to_path_buf(),
        ..Integrity::default()
    };
    for file in &ours {
        let official_file = official.join(file);
        match fs::read(submission.join(file)) {
            Ok(bytes) => {
                let expected = fs::read(&official_file)
                    .with_context(|| format!("cannot read {}", official_file.display()))?;
                if bytes != expected {
                    integrity.changed.push(file.clone());
                }
            }
            Err(_) => integrity.missing.push(file.clone()),
        }
    }
    integrity.added = theirs
        .into_iter()
        .filter(|f| ours.binary_search(f).is_err())
        .collect();
    Ok(integrity)
}

/// Builds the stage: the official course without its solutions, with the
/// submission's `exercises/*/src/` in place of the stubs.
pub fn stage(official: &Path, submission: &Path, stage: &Path) -> Result<()> {
    if stage.exists() {
        fs::remove_dir_all(stage).with_context(|| format!("cannot clear {}", stage.display()))?;
    }
    let copy = |from: &Path, to: &Path| -> Result<()> {
        if let Some(parent) = to.parent() {
            fs::create_dir_all(parent)
                .with_context(|| format!("cannot create {}", parent.display()))?;
        }
        fs::copy(from, to)
            .map(drop)
            .with_context(|| format!("cannot copy {} to {}", from.display(), to.display()))
    };
    for file in files_under(official)? {
        if !is_student_file(&file) {
            copy(&official.join(&file), &stage.join(&file))?;
        }
    }
    // The student's folders replace the stubs whole, so that a module the
    // student added comes along and a stub they deleted stays deleted.
    let exercises = official.join("exercises");
    let topics =
        fs::read_dir(&exercises).with_context(|| format!("cannot read {}", exercises.display()))?;
    for topic in topics {
        let topic = topic.with_context(|| format!("cannot read {}", exercises.display()))?;
        let relative = Path::new("exercises").join(topic.file_name()).join("src");
        let theirs = submission.join(&relative);
        if !theirs.is_dir() {
            // Nothing handed in for this topic: the stubs stay.
            for file in files_under(&official.join(&relative))? {
                copy(
                    &official.join(&relative).join(&file),
                    &stage.join(&relative).join(&file),
                )?;
            }
            continue;
        }
        for file in files_under(&theirs)? {
            copy(&theirs.join(&file), &stage.join(&relative).join(&file))?;
        }
    }
    Ok(())
}

/// Whether `dir` looks like a course checkout.
fn is_checkout(dir: &Path) -> bool {
    dir.join("exercises").is_dir() && dir.join("Cargo.toml").is_file()
}

/// Grades one submission against the official course at `official`:
/// compare, stage under `<options.out>/stage`, grade the stage into
/// `options.out`, and print the table. The report files are written again
/// with the submission's path and its integrity.
///
/// `build` is cargo's target folder for the stage. Submissions share one
/// (the stages have the official lock file, so dependencies are built
/// once for a whole class), and it must not contain the stage: cargo
/// records the sources of a package inside its target folder relative to
/// that folder, and would take one submission's files for another's.
pub fn grade_one(
    official: &Path,
    submission: &Path,
    options: &GradeOptions,
    build: &Path,
) -> Result<Report> {
    let integrity = check(official, submission)?;
    let stage_dir = options.out.join("stage");
    stage(official, submission, &stage_dir)?;
    let mut staged = options.clone();
    staged.root.clone_from(&stage_dir);
    staged.target_dir = Some(build.to_path_buf());
    let mut report = super::grade(&staged)?;
    report.root = submission.to_path_buf();
    report.integrity = Some(integrity);
    super::export::write_all(&report, &options.out)?;
    print!(
        "{}",
        table::render(&report, &options.out, table::Style::detect(), true)
    );
    Ok(report)
}

/// One row of the gradebook.
#[derive(Debug, Serialize)]
struct GradebookRow {
    submission: String,
    score: f64,
    max_score: f64,
    complete: bool,
    flagged: bool,
    integrity: Option<String>,
    topics: Vec<(String, f64)>,
    report: PathBuf,
}

/// `--submission DIR`: one checkout, or a folder of checkouts (a class).
pub fn run(official: &Path, dir: &Path, options: &GradeOptions) -> Result<()> {
    let dir = dir
        .canonicalize()
        .with_context(|| format!("cannot find the submission {}", dir.display()))?;
    let build = options
        .target_dir
        .clone()
        .unwrap_or_else(|| options.out.join(".build"));
    let out_for = |submission: &Path| {
        let name = submission.file_name().map_or_else(
            || "submission".to_owned(),
            |n| n.to_string_lossy().into_owned(),
        );
        let mut one = options.clone();
        one.out = options.out.join(&name);
        (name, one)
    };
    if is_checkout(&dir) {
        let (_, one) = out_for(&dir);
        grade_one(official, &dir, &one, &build)?;
        return Ok(());
    }
    let mut submissions: Vec<PathBuf> = fs::read_dir(&dir)
        .with_context(|| format!("cannot read {}", dir.display()))?
        .filter_map(|entry| entry.ok().map(|e| e.path()))
        .filter(|path| is_checkout(path))
        .collect();
    submissions.sort();
    if submissions.is_empty() {
        bail!(
            "{} is neither a course checkout (with exercises/ and Cargo.toml) nor a folder of them",
            dir.display()
        );
    }
    let mut rows = Vec::new();
    for (i, submission) in submissions.iter().enumerate() {
        let (name, one) = out_for(submission);
        println!("==> [{}/{}] {name}", i + 1, submissions.len());
        let report = grade_one(official, submission, &one, &build)?;
        let integrity = report.integrity.as_ref();
        rows.push(GradebookRow {
            submission: name,
            score: report.score,
            max_score: report.max_score,
            complete: report.complete,
            flagged: integrity.is_some_and(Integrity::flagged),
            integrity: integrity.filter(|i| i.flagged()).map(Integrity::summary),
            topics: report
                .topics
                .iter()
                .map(|t| (t.name.clone(), t.score))
                .collect(),
            report: one.out.join("report.html"),
        });
    }
    let csv = gradebook_csv(&rows);
    let json = serde_json::to_string_pretty(&rows).context("cannot serialise the gradebook")?;
    for (file, contents) in [("gradebook.csv", csv), ("gradebook.json", json)] {
        let path = options.out.join(file);
        fs::write(&path, contents).with_context(|| format!("cannot write {}", path.display()))?;
    }
    println!();
    println!(
        "gradebook of {} submission(s): {} (also gradebook.json)",
        rows.len(),
        options.out.join("gradebook.csv").display()
    );
    let flagged: Vec<&str> = rows
        .iter()
        .filter(|r| r.flagged)
        .map(|r| r.submission.as_str())
        .collect();
    if !flagged.is_empty() {
        println!("flagged (grading files changed): {}", flagged.join(", "));
    }
    Ok(())
}

/// The gradebook as CSV: one row per submission, one column per topic.
fn gradebook_csv(rows: &[GradebookRow]) -> String {
    let mut csv = String::from("submission,score,max_score,complete,flagged");
    if let Some(first) = rows.first() {
        for (topic, _) in &first.topics {
            csv.push(',');
            csv.push_str(&csv_field(topic));
        }
    }
    csv.push('\n');
    for row in rows {
        let _ = write!(
            csv,
            "{},{},{},{},{}",
            csv_field(&row.submission),
            report::points(row.score),
            report::points(row.max_score),
            row.complete,
            row.flagged
        );
        for (_, score) in &row.topics {
            let _ = write!(csv, ",{}", report::points(*score));
        }
        csv.push('\n');
    }
    csv
}

/// A CSV field, quoted when it holds a comma, a quote or a line break.
fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_owned()
    }
}

/// A relative path with `/` separators, for messages.
fn slashed(path: &Path) -> String {
    path.components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect::<Vec<_>>()
        .join("/")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_exercise_sources_are_the_students() {
        assert!(is_student_file(Path::new("exercises/01-lines/src/dda.rs")));
        assert!(is_student_file(Path::new(
            "exercises/01-lines/src/sub/x.rs"
        )));
        assert!(!is_student_file(Path::new(
            "exercises/01-lines/tests/dda.rs"
        )));
        assert!(!is_student_file(Path::new("exercises/src/x.rs")));
    }

    #[test]
    fn grading_files_are_everything_the_grader_builds_or_reads() {
        for file in [
            "Cargo.toml",
            "Cargo.lock",
            ".cargo/config.toml",
            "crates/testkit/src/raster.rs",
            "xtask/src/main.rs",
            "exercises/01-lines/README.md",
            "exercises/01-lines/Cargo.toml",
            "exercises/01-lines/tests/dda.rs",
            "exercises/01-lines/tests/snapshots/dda__x.snap",
        ] {
            assert!(is_grading_file(Path::new(file)), "{file}");
        }
        for file in [
            "README.md",
            "notes.txt",
            "exercises/01-lines/src/dda.rs",
            "exercises/README.md",
        ] {
            assert!(!is_grading_file(Path::new(file)), "{file}");
        }
    }

    #[test]
    fn csv_fields_are_quoted_only_when_needed() {
        assert_eq!(csv_field("anna"), "anna");
        assert_eq!(csv_field("a,b"), "\"a,b\"");
        assert_eq!(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
    }
}
