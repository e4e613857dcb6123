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
//! Each submission is graded into `<out>/<name>/`; the snapshots it
//! failed are in `<out>/<name>/snapshots/` (insta's `.snap.new` files, at
//! their paths in the course). One submission is graded in the course's
//! stage. A folder whose subfolders are checkouts is a class: up to
//! `--jobs` submissions (default: one per two CPUs) are graded side by side, each in a stage of its
//! own (a *slot*, see `stage::class_home`), all built into the one build
//! cache, so the dependencies are built once. The builds take turns (cargo
//! would make them anyway); while one submission builds, the others run
//! their tests, from hard links of their executables in their slot, with
//! at most `--jobs` tests running at once in all. `<out>/gradebook.csv`
//! and `gradebook.json` list the scores.
//!
//! A test sees its own stage and executables and nothing else of the
//! course's build output: not the other slots (a classmate's code), the
//! course's own stage (which may hold the solutions), the build cache or
//! the planted shortcuts of `cargo xtask test`. Without a sandbox nothing
//! hides them, and a class is graded one submission at a time, so that
//! what a submission's tests change is found and blamed on it.

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use anyhow::{Context, Result, bail};
use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;

use super::report::{self, Edition, Report, TaskStatus};
use super::{GradeOptions, Permits, table};
use crate::files::files_under;
use crate::release;
use crate::stage::{self, Files, Overlay, Source, is_student_file};
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

/// Whether `dir` looks like a course checkout.
fn is_checkout(dir: &Path) -> bool {
    // A link among a class's members is no member: it could name another.
    let linked = fs::symlink_metadata(dir).is_ok_and(|m| m.file_type().is_symlink());
    !linked && dir.join("exercises").is_dir() && dir.join("Cargo.toml").is_file()
}

/// A class slot: where one submission of a class is staged and its tests
/// run from.
struct Slot<'a> {
    /// The slot's folder (see `stage::class_home`).
    home: PathBuf,
    /// The one build cache of all slots.
    target_dir: PathBuf,
    /// Held while a slot syncs its stage and builds.
    turn: &'a Mutex<()>,
    /// The tests that may run at once, in all slots.
    permits: Arc<Permits>,
}

/// Grades one submission against the official course at `official`:
/// compare, stage (in the course's stage, or in `slot`), grade the stage
/// into `options.out`, keep its failed snapshots. The report files carry
/// the submission's path and its integrity.
fn grade_one(
    official: &Path,
    submission: &Path,
    options: &GradeOptions,
    slot: Option<&Slot<'_>>,
) -> Result<Report> {
    let integrity = check(official, submission)?;
    let mut options = options.clone();
    // The assignment is the official course's topics, whatever the
    // submission holds: a topic it lacks scores 0, with the reason.
    let all_topics = topics::discover(official)?;
    if options.topics.is_empty() {
        options.topics = all_topics.iter().map(|t| t.name.clone()).collect();
    }
    let options = &options;
    // A task file that reaches other files at compile time is not
    // compiled: its stub is staged instead, and its topic scores 0. (The
    // sandbox shows the build nothing but the stage; this says why
    // early, and in words.)
    let mut files = stage::plan(official, Overlay::Submission(submission))?;
    let mut refused: Vec<(String, Vec<String>)> = Vec::new();
    let mut unreadable: Vec<(String, String)> = Vec::new();
    let topic_of = |task_file: &Path| {
        task_file
            .components()
            .nth(1)
            .map(|c| c.as_os_str().to_string_lossy().into_owned())
            .unwrap_or_default()
    };
    for task_file in stage::task_files(official)? {
        match crate::files::plain_file(submission, &task_file) {
            Ok(()) => {}
            Err(why)
                if fs::symlink_metadata(submission.join(&task_file)).is_err()
                    && !why.contains("symbolic link") =>
            {
                continue;
            }
            Err(why) => {
                unreadable.push((
                    topic_of(&task_file),
                    format!(
                        "{}: not graded ({why}); the stub was used",
                        slashed(&task_file)
                    ),
                ));
                continue;
            }
        }
        let Some(text) = crate::files::read_plain(submission, &task_file)
            .and_then(|bytes| String::from_utf8(bytes).ok())
        else {
            continue;
        };
        // WGSL reaches no files; Rust may, by macros.
        let uses = if crate::stubs::is_wgsl(&task_file) {
            Vec::new()
        } else {
            super::forbidden::uses(&text)
        };
        if uses.is_empty() {
            continue;
        }
        let shown = task_file.display().to_string();
        refused.push((
            topic_of(&task_file),
            uses.iter().map(|u| format!("{shown}:{u}")).collect(),
        ));
        files.retain(|(to, _)| *to != task_file);
        files.push((task_file.clone(), Source::File(official.join(&task_file))));
    }
    files.sort();
    let course_before = contents_of(official)?;
    let planned: Vec<(PathBuf, Vec<u8>)> = files
        .iter()
        .map(|(to, from)| Ok((to.clone(), from.read()?)))
        .collect::<Result<_>>()?;
    let mut in_stage = options.clone();
    let (staged, prepared) = match slot {
        None => {
            let target_dir = options
                .target_dir
                .clone()
                .unwrap_or_else(|| submissions_build(official));
            let staged = stage::stage_plan(official, &files, Some(&target_dir))?;
            in_stage.root.clone_from(&staged.root);
            in_stage.target_dir = Some(staged.target_dir.clone());
            let prepared = super::prepare(&in_stage, Edition::Student)?;
            (staged, prepared)
        }
        Some(slot) => {
            let _turn = slot.turn.lock().expect("no slot panics while building");
            let staged = stage::stage_slot(&slot.home, &files, &slot.target_dir)?;
            in_stage.keep_binaries = Some(slot.home.join("bin"));
            in_stage.permits = Some(Arc::clone(&slot.permits));
            in_stage.progress = false;
            in_stage.root.clone_from(&staged.root);
            in_stage.target_dir = Some(slot.target_dir.clone());
            let prepared = super::prepare(&in_stage, Edition::Student)?;
            (staged, prepared)
        }
    };
    let mut report = prepared.finish()?;
    for (topic, uses) in refused {
        refuse(&mut report, &topic, &uses);
    }
    for topic in &mut report.topics {
        if !submission.join("exercises").join(&topic.name).is_dir() {
            topic.errors.push(format!(
                "the submission has no exercises/{}: its tasks score 0",
                topic.name
            ));
            report.complete = false;
        }
        for (_, why) in unreadable.iter().filter(|(t, _)| *t == topic.name) {
            topic.errors.push(why.clone());
            report.complete = false;
        }
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
    Ok(report)
}

/// The table of a graded submission, as `cargo xtask grade` prints it.
fn table_of(report: &Report, out: &Path) -> String {
    table::render(
        report,
        out,
        table::Style::detect(),
        table::Details::EveryTask,
    )
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
    /// Points of the tasks that are not bonuses.
    score: f64,
    max_score: f64,
    /// Bonus points, apart.
    bonus: f64,
    complete: bool,
    flagged: bool,
    integrity: Option<String>,
    /// Per topic, its points (bonus apart).
    topics: Vec<(String, f64)>,
    /// Per task (`topic/task`), its points.
    tasks: Vec<(String, f64)>,
    /// The topics that could not be graded, each with why.
    not_graded: Vec<String>,
    report: PathBuf,
}

impl GradebookRow {
    fn new(submission: String, report: &Report, out: &Path) -> Self {
        let integrity = report.integrity.as_ref();
        Self {
            submission,
            score: report::round2(report.topics.iter().map(|t| t.base_score()).sum()),
            max_score: report.max_score,
            bonus: report::round2(report.topics.iter().map(|t| t.bonus().0).sum()),
            complete: report.complete,
            flagged: integrity.is_some_and(Integrity::flagged),
            integrity: integrity.filter(|i| i.flagged()).map(Integrity::summary),
            topics: report
                .topics
                .iter()
                .map(|t| (t.name.clone(), t.base_score()))
                .collect(),
            tasks: report
                .topics
                .iter()
                .flat_map(|t| {
                    t.tasks
                        .iter()
                        .map(move |task| (format!("{}/{}", t.name, task.id), task.score))
                })
                .collect(),
            not_graded: report
                .topics
                .iter()
                .filter_map(|t| {
                    let why = match (&t.compile_error, t.errors.first()) {
                        (Some(_), _) => "does not compile".to_owned(),
                        (None, Some(error)) => error.lines().next().unwrap_or_default().to_owned(),
                        (None, None) => return None,
                    };
                    Some(format!("{}: {why}", t.name))
                })
                .collect(),
            report: out.join("report.html"),
        }
    }
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
        (name, one)
    };
    if is_checkout(&dir) {
        let (_, one) = out_for(&dir);
        let report = grade_one(official, &dir, &one, None)?;
        print!("{}", table_of(&report, &one.out));
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
    let graded = grade_class(official, &submissions, options, out_for)?;
    let mut rows = Vec::new();
    let mut not_graded = Vec::new();
    for (name, out, result) in graded {
        let report = match result {
            Ok(report) => report,
            Err(error) => {
                not_graded.push(format!("{}: {error:#}", table::shown(&name)));
                continue;
            }
        };
        rows.push(GradebookRow::new(name, &report, &out));
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
    if !not_graded.is_empty() {
        bail!(
            "{} submission(s) could not be graded and are not in the gradebook:\n{}",
            not_graded.len(),
            not_graded.join("\n")
        );
    }
    Ok(())
}

/// A graded member of a class: its name, its report folder and its report
/// (or why it could not be graded).
type Graded = (String, PathBuf, Result<Report>);

/// Grades the `submissions` of a class, up to `options.jobs` side by side
/// in class slots (one at a time without a sandbox), printing each one's
/// table as it is done; (name, report folder, report) of each, in the
/// order given.
fn grade_class(
    official: &Path,
    submissions: &[PathBuf],
    options: &GradeOptions,
    out_for: impl Fn(&Path) -> (String, GradeOptions) + Sync,
) -> Result<Vec<Graded>> {
    let sandboxed = crate::sandbox::Jail::get().sandboxed();
    // Side by side, a submission's tests run while another builds. A grade
    // keeps two CPUs busy on its own (cargo's build, `--jobs` tests): on a
    // machine with two, one at a time was the faster (`BENCHMARKS.md`).
    let wanted = options
        .submissions_at_once
        .unwrap_or_else(|| (super::default_jobs() / 2).max(1));
    let slots = if sandboxed {
        wanted.clamp(1, submissions.len())
    } else {
        1
    };
    // No other `cargo xtask` builds into the cache while the slots do.
    let _stage = stage::lock(official)?;
    let target_dir = options
        .target_dir
        .clone()
        .unwrap_or_else(|| submissions_build(official));
    // Every slot's folder exists before the first test runs, so that each
    // slot's sandbox hides all the others (`stage::hidden_beside` hides
    // what it finds).
    for index in 0..slots {
        let home = stage::class_home(official, index);
        fs::create_dir_all(&home).with_context(|| format!("cannot create {}", home.display()))?;
    }
    let turn = Mutex::new(());
    let permits = Arc::new(Permits::new(options.jobs));
    let bar = ProgressBar::new(submissions.len() as u64).with_style(
        ProgressStyle::with_template(
            "{spinner} [{elapsed}] {bar:30} {pos}/{len} submissions  {wide_msg}",
        )
        .expect("a valid progress template"),
    );
    bar.enable_steady_tick(Duration::from_millis(100));
    if slots > 1 {
        bar.println(format!(
            "grading {} submissions, {slots} at a time",
            submissions.len()
        ));
    }
    let busy: Mutex<Vec<String>> = Mutex::new(vec![String::new(); slots]);
    let next = AtomicUsize::new(0);
    let done = AtomicUsize::new(0);
    let results: Mutex<Vec<Option<Graded>>> =
        Mutex::new((0..submissions.len()).map(|_| None).collect());
    std::thread::scope(|scope| {
        for index in 0..slots {
            let (turn, permits, target_dir) = (&turn, &permits, &target_dir);
            let (bar, busy, next, done, results, out_for) =
                (&bar, &busy, &next, &done, &results, &out_for);
            scope.spawn(move || {
                let slot = Slot {
                    home: stage::class_home(official, index),
                    target_dir: target_dir.clone(),
                    turn,
                    permits: Arc::clone(permits),
                };
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(submission) = submissions.get(i) else {
                        break;
                    };
                    let (name, one) = out_for(submission);
                    {
                        let mut busy = busy.lock().expect("no slot panics");
                        busy[index].clone_from(&name);
                        bar.set_message(
                            busy.iter()
                                .filter(|b| !b.is_empty())
                                .cloned()
                                .collect::<Vec<_>>()
                                .join(", "),
                        );
                    }
                    let result = grade_one(official, submission, &one, Some(&slot));
                    let n = done.fetch_add(1, Ordering::Relaxed) + 1;
                    let shown = match &result {
                        Ok(report) => table_of(report, &one.out),
                        Err(error) => format!("error: {error:#}\n"),
                    };
                    bar.suspend(|| {
                        println!("==> [{n}/{}] {}", submissions.len(), table::shown(&name));
                        print!("{shown}");
                    });
                    bar.inc(1);
                    results.lock().expect("no slot panics")[i] = Some((name, one.out, result));
                }
                busy.lock().expect("no slot panics")[index].clear();
            });
        }
    });
    bar.finish_and_clear();
    Ok(results
        .into_inner()
        .expect("no slot panics")
        .into_iter()
        .map(|result| result.expect("every submission was graded"))
        .collect())
}

/// The build cache of submissions: never the one the solutions are built
/// in, so that nothing a submission's build can read was compiled from
/// them.
fn submissions_build(official: &Path) -> PathBuf {
    stage::home(official).join("submissions-build")
}

/// The gradebook as CSV: one row per submission; columns by name (a
/// member without a topic leaves its cell empty, never shifts the others):
/// the points (bonus apart), then one per topic, one per task, and why a
/// topic was not graded.
fn gradebook_csv(rows: &[GradebookRow]) -> String {
    // Every topic and task any member has, in the order first met.
    let mut topics: Vec<&str> = Vec::new();
    let mut tasks: Vec<&str> = Vec::new();
    for row in rows {
        for (name, _) in &row.topics {
            if !topics.contains(&name.as_str()) {
                topics.push(name);
            }
        }
        for (name, _) in &row.tasks {
            if !tasks.contains(&name.as_str()) {
                tasks.push(name);
            }
        }
    }
    let mut csv = String::from("submission,score,max_score,bonus,complete,flagged");
    for column in topics.iter().chain(&tasks) {
        csv.push(',');
        csv.push_str(&csv_field(column));
    }
    csv.push_str(",not_graded\n");
    let cell = |values: &[(String, f64)], column: &str| {
        values
            .iter()
            .find(|(name, _)| name == column)
            .map_or_else(String::new, |(_, score)| report::points(*score))
    };
    for row in rows {
        let _ = write!(
            csv,
            "{},{},{},{},{},{}",
            csv_field(&row.submission),
            report::points(row.score),
            report::points(row.max_score),
            report::points(row.bonus),
            row.complete,
            row.flagged
        );
        for topic in &topics {
            let _ = write!(csv, ",{}", cell(&row.topics, topic));
        }
        for task in &tasks {
            let _ = write!(csv, ",{}", cell(&row.tasks, task));
        }
        let _ = writeln!(csv, ",{}", csv_field(&row.not_graded.join("; ")));
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

    #[test]
    fn gradebook_columns_go_by_name_not_by_position() {
        let row = |name: &str, topics: &[(&str, f64)], tasks: &[(&str, f64)]| GradebookRow {
            submission: name.to_owned(),
            score: topics.iter().map(|t| t.1).sum(),
            max_score: 5.0,
            bonus: 0.0,
            complete: true,
            flagged: false,
            integrity: None,
            topics: topics.iter().map(|(n, s)| ((*n).to_owned(), *s)).collect(),
            tasks: tasks.iter().map(|(n, s)| ((*n).to_owned(), *s)).collect(),
            not_graded: Vec::new(),
            report: PathBuf::new(),
        };
        let mut lacking = row("ben", &[("02-b", 1.0)], &[("02-b/y", 1.0)]);
        lacking.not_graded = vec!["01-a: the submission has no exercises/01-a".to_owned()];
        let csv = gradebook_csv(&[
            row(
                "anna",
                &[("01-a", 2.0), ("02-b", 3.0)],
                &[("01-a/x", 2.0), ("02-b/y", 3.0)],
            ),
            lacking,
        ]);
        assert_eq!(
            csv,
            "submission,score,max_score,bonus,complete,flagged,01-a,02-b,01-a/x,02-b/y,not_graded\n\
             anna,5,5,0,true,false,2,3,2,3,\n\
             ben,1,5,0,true,false,,1,,1,01-a: the submission has no exercises/01-a\n"
        );
    }

    #[test]
    fn csv_fields_are_quoted_only_when_needed() {
        assert_eq!(csv_field("anna"), "anna");
        assert_eq!(csv_field("a,b"), "\"a,b\"");
        assert_eq!(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
    }
}
