//! `cargo xtask grade --submission DIR`: grading a student's checkout, or a
//! folder of them, with the course's official tests.
//!
//! Only `exercises/*/src/` belongs to the student. Everything else that
//! takes part in grading — the course library (`crates/`), the tests and
//! snapshots, the task sheets (they hold the points), the manifests, the
//! tooling — is the course's. So a submission is never built where it
//! lies: its `src/` folders are laid over a copy of the official course,
//! the *stage* (see `stage`, which also stages the reference), and the
//! stage is graded.
//!
//! ```text
//!   official course ──(no target/, .git/, reference/)──┐
//!                                                      ├──sync──> stage ──grade──> report
//!   submission ──exercises/*/src/ only─────────────────┘
//! ```
//!
//! The grading files of the submission are compared with the official ones
//! first; a submission where any differ, are missing or were added is
//! *flagged* in every report (the table, `report.html`, `report.json`,
//! Gradescope's output). Nothing in the submission is ever written to.
//!
//! Each submission is graded into `<out>/<name>/`, in the one stage of the
//! course, whose build cache all submissions share; the snapshots it
//! failed are in `<out>/<name>/snapshots/` (insta's `.snap.new` files, at
//! their paths in the course). A folder whose subfolders are
//! checkouts is a class: each is graded in turn, and `<out>/gradebook.csv`
//! and `gradebook.json` list the scores.

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use serde::Serialize;

use super::report::{self, Edition, Report, TaskStatus};
use super::{GradeOptions, table};
use crate::release;
use crate::stage::{self, Files, Overlay, Source, files_under, is_student_file};
use crate::topics::{self, Topic};

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
fn is_grading_file(relative: &Path) -> bool {
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
            let same = fs::read(official.join(&file))
                .is_ok_and(|ours| fs::read(submission.join(&file)).is_ok_and(|t| t == ours));
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
        match fs::read(submission.join(file)) {
            Ok(bytes) => {
                if bytes != source.read()? {
                    integrity.changed.push(file.clone());
                }
            }
            Err(_) => integrity.missing.push(file.clone()),
        }
    }
    integrity.added = theirs
        .into_iter()
        .filter(|f| !ours.iter().any(|(file, _)| file == f))
        .collect();
    Ok(integrity)
}

/// Whether `dir` looks like a course checkout.
fn is_checkout(dir: &Path) -> bool {
    dir.join("exercises").is_dir() && dir.join("Cargo.toml").is_file()
}

/// Grades one submission against the official course at `official`:
/// compare, stage, grade the stage into `options.out`, keep its failed
/// snapshots, and print the table. The report files carry the
/// submission's path and its integrity.
pub fn grade_one(official: &Path, submission: &Path, options: &GradeOptions) -> Result<Report> {
    let integrity = check(official, submission)?;
    let mut options = options.clone();
    if options.topics.is_empty() {
        // An edition of some topics is graded on those alone.
        options.topics = submitted_topics(official, submission)?
            .into_iter()
            .map(|t| t.name)
            .collect();
    }
    let options = &options;
    // A task file that reaches other files at compile time is not
    // compiled: its stub is staged instead, and its topic scores 0.
    let mut files = stage::plan(official, Overlay::Submission(submission))?;
    let mut refused: Vec<(String, Vec<String>)> = Vec::new();
    for task_file in stage::task_files(official)? {
        let Ok(text) = fs::read_to_string(submission.join(&task_file)) else {
            continue;
        };
        let uses = super::forbidden::uses(&text);
        if uses.is_empty() {
            continue;
        }
        let topic = task_file
            .components()
            .nth(1)
            .map(|c| c.as_os_str().to_string_lossy().into_owned())
            .unwrap_or_default();
        let shown = task_file.display().to_string();
        refused.push((topic, uses.iter().map(|u| format!("{shown}:{u}")).collect()));
        files.retain(|(to, _)| *to != task_file);
        files.push((task_file.clone(), Source::File(official.join(&task_file))));
    }
    files.sort();
    let course_before = contents_of(official)?;
    let staged = stage::stage_plan(official, &files, options.target_dir.as_deref())?;
    let planned: Vec<(PathBuf, Vec<u8>)> = files
        .iter()
        .map(|(to, from)| Ok((to.clone(), from.read()?)))
        .collect::<Result<_>>()?;
    let mut in_stage = options.clone();
    in_stage.root.clone_from(&staged.root);
    in_stage.target_dir = Some(staged.target_dir.clone());
    let mut report = super::grade_tree(&in_stage, Edition::Student)?;
    for (topic, uses) in refused {
        refuse(&mut report, &topic, &uses);
    }
    let mut integrity = integrity;
    integrity.tampered = tampered(official, &course_before, &staged.root, &planned)?;
    if !integrity.tampered.is_empty() {
        zero_for_tampering(&mut report, &integrity.tampered);
        let in_course: Vec<String> = integrity
            .tampered
            .iter()
            .filter(|f| !f.starts_with("stage"))
            .map(|f| table::shown(&slashed(f)))
            .collect();
        if !in_course.is_empty() {
            eprintln!(
                "warning: the tests of {} changed files of the course itself; check them (e.g. `git status`): {}",
                table::shown(&submission.display().to_string()),
                in_course.join(", ")
            );
        }
    }
    report.root = submission.to_path_buf();
    report.integrity = Some(integrity);
    super::export::write_all(&report, &options.out)?;
    print!(
        "{}",
        table::render(
            &report,
            &options.out,
            table::Style::detect(),
            table::Details::EveryTask
        )
    );
    Ok(report)
}

/// Every grading file of the course at `root` with its contents.
fn contents_of(root: &Path) -> Result<Vec<(PathBuf, Vec<u8>)>> {
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
fn tampered(
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
    for (file, bytes) in plan {
        if fs::read(stage_root.join(file)).ok().as_deref() != Some(bytes.as_slice()) {
            changed.push(Path::new("stage").join(file));
        }
    }
    let cargos =
        |file: &Path| file == Path::new("Cargo.lock") || file == Path::new(stage::STAGE_MARKER);
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

/// Scores every topic of a submission whose tests changed official files 0.
fn zero_for_tampering(report: &mut Report, files: &[PathBuf]) {
    let shown: Vec<String> = files.iter().take(5).map(|f| slashed(f)).collect();
    let reason = format!(
        "scored 0: its tests changed official files while grading ({}{})",
        shown.join(", "),
        if files.len() > shown.len() {
            ", ..."
        } else {
            ""
        }
    );
    for topic in &mut report.topics {
        topic.errors.push(reason.clone());
        for task in &mut topic.tasks {
            task.score = 0.0;
        }
        topic.score = 0.0;
    }
    report.score = 0.0;
    report.complete = false;
}

/// Scores the topic `name` 0 as not compiled, for the forbidden `uses` of
/// its task files.
fn refuse(report: &mut Report, name: &str, uses: &[String]) {
    let Some(topic) = report.topics.iter_mut().find(|t| t.name == name) else {
        return;
    };
    let reason = format!(
        "not compiled: task code may not reach other files at compile time\n{}",
        uses.join("\n")
    );
    topic.compile_error = Some(match topic.compile_error.take() {
        Some(more) => format!("{reason}\n\n{more}"),
        None => reason,
    });
    for task in &mut topic.tasks {
        task.status = TaskStatus::CompileError;
        task.score = 0.0;
        task.error = None;
        task.tests.clear();
        (task.passed, task.failed, task.ignored) = (0, 0, 0);
    }
    topic.score = 0.0;
    report.score = report::round2(report.topics.iter().map(|t| t.score).sum());
    report.complete = false;
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
    let out_for = |submission: &Path| {
        let name = submission.file_name().map_or_else(
            || "submission".to_owned(),
            |n| n.to_string_lossy().into_owned(),
        );
        let mut one = options.clone();
        one.out = options.out.join(&name);
        // No test sees the solutions, a submission or another's report.
        one.hidden.extend([
            official.join(stage::SOLUTIONS),
            dir.clone(),
            options.out.clone(),
        ]);
        (name, one)
    };
    if is_checkout(&dir) {
        let (_, one) = out_for(&dir);
        grade_one(official, &dir, &one)?;
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
        println!(
            "==> [{}/{}] {}",
            i + 1,
            submissions.len(),
            table::shown(&name)
        );
        let report = grade_one(official, submission, &one)?;
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
        println!(
            "flagged (grading files changed): {}",
            table::shown(&flagged.join(", "))
        );
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
    fn grading_files_are_everything_the_grader_builds_or_reads() {
        for file in [
            "Cargo.toml",
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
            "Cargo.lock",
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
