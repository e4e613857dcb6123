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
//! and `gradebook.json` list the scores (see `gradebook`: each member's row
//! is kept in its folder, so a member graded again updates them, and
//! shards of a class graded on several machines merge). A class graded
//! again keeps the members whose grade was made from the same files (see
//! `resume`), so an interrupted class goes on where it stopped.
//!
//! A test sees its own stage and executables and nothing else of the
//! course's build output: not the other slots (a classmate's code), the
//! course's own stage (which may hold the solutions), the build cache or
//! the planted shortcuts of `cargo xtask test`. Without a sandbox nothing
//! hides them, and a class is graded one submission at a time, so that
//! what a submission's tests change is found and blamed on it.

use std::fs;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use anyhow::{Context, Result, bail};

use super::report::{self, Edition, Report, TaskStatus};
use super::{GradeOptions, Permits, table};
use crate::stage::{self, Overlay, Source};
use crate::topics;

mod class;
mod gradebook;
mod integrity;
mod resume;
mod tampering;

use class::grade_class;
use gradebook::Class;
pub(crate) use gradebook::GradebookRow;
use integrity::is_grading_file;
pub use integrity::{Integrity, check};
pub use resume::Shard;
use tampering::{contents_of, tampered, zero_for_tampering};

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
    // A topic it lacks is neither built nor run: the course's stubs of it
    // would only fail, at the cost of a build and a `todo!()` per test.
    options.absent = all_topics
        .iter()
        .filter(|topic| !submission.join("exercises").join(&topic.name).is_dir())
        .map(|topic| topic.name.clone())
        .collect();
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
        let uses = if crate::files::is_wgsl(&task_file) {
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
            topic.errors.push(super::plan::absent_reason(&topic.name));
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

/// A graded member in one line: its points, bonus, flag, the topics that
/// did not compile, and where its report is.
fn one_line(report: &Report, out: &Path) -> String {
    let base: f64 = report.topics.iter().map(|t| t.base_score()).sum();
    let bonus: f64 = report.topics.iter().map(|t| t.bonus().0).sum();
    let mut line = format!(
        "{} / {} points",
        report::points(report::round2(base)),
        report::points(report.max_score)
    );
    if bonus > 0.0 {
        line.push_str(&format!(
            " (+{} bonus)",
            report::points(report::round2(bonus))
        ));
    }
    let broken: Vec<&str> = report
        .topics
        .iter()
        .filter(|t| t.compile_error.is_some())
        .map(|t| t.name.as_str())
        .collect();
    if !broken.is_empty() {
        line.push_str(&format!(" · does not compile: {}", broken.join(", ")));
    }
    if report.integrity.as_ref().is_some_and(Integrity::flagged) {
        line.push_str(" · FLAGGED: grading files changed");
    }
    line.push_str(&format!(" · {}", out.join("report.html").display()));
    line
}

/// The build cache of submissions: never the one the solutions are built
/// in, so that nothing a submission's build can read was compiled from
/// them.
pub(crate) fn submissions_build(official: &Path) -> PathBuf {
    stage::home(official).join("submissions-build")
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

/// `--submission DIR`: one checkout, or a folder of checkouts (a class);
/// of a class only the members of `shard`, where one is given.
pub fn run(
    official: &Path,
    dir: &Path,
    options: &GradeOptions,
    shard: Option<Shard>,
) -> Result<()> {
    let dir = dir
        .canonicalize()
        .with_context(|| format!("cannot find the submission {}", dir.display()))?;
    let out_for = |submission: &Path| {
        let mut one = options.clone();
        one.out = options.out.join(member_name(submission));
        (member_name(submission), one)
    };
    if is_checkout(&dir) {
        let (name, one) = out_for(&dir);
        let report = grade_one(official, &dir, &one, None)?;
        print!("{}", table_of(&report, &one.out));
        // A member graded again into its class's folder: its row there,
        // and the class's gradebook, follow.
        if options.out.join("gradebook.json").is_file() {
            GradebookRow::new(name, &report).save(&one.out)?;
            resume::save(
                &one.out,
                &resume::fingerprint(resume::tree_hash(official)?, &dir)?,
            )?;
            let class = write_class(&options.out)?;
            println!(
                "the gradebook of {} member(s) in {} now holds this grade",
                class.rows.len(),
                options.out.display()
            );
        }
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
    let whole = submissions.len();
    if let Some(shard) = shard {
        submissions.retain(|s| shard.holds(&member_name(s)));
        println!(
            "shard {}/{}: {} of the class's {whole} member(s)",
            shard.index,
            shard.count,
            submissions.len()
        );
    }
    // Members graded before from the same files keep their grade.
    let course = resume::tree_hash(official)?;
    let mut to_grade = Vec::new();
    let mut fingerprints = Vec::new();
    for submission in &submissions {
        let fingerprint = resume::fingerprint(course, submission)?;
        if !resume::is_current(&out_for(submission).1.out, &fingerprint) {
            to_grade.push(submission.clone());
            fingerprints.push(fingerprint);
        }
    }
    if to_grade.len() < submissions.len() {
        println!(
            "{} of {} member(s) were graded before from the same files: kept (their report folders in {})",
            submissions.len() - to_grade.len(),
            submissions.len(),
            options.out.display()
        );
    }
    fs::create_dir_all(&options.out)
        .with_context(|| format!("cannot create {}", options.out.display()))?;
    let graded = grade_class(official, &to_grade, options, out_for)?;
    for ((name, out, result), fingerprint) in graded.into_iter().zip(&fingerprints) {
        match result {
            Ok(report) => {
                GradebookRow::new(name, &report).save(&out)?;
                resume::save(&out, fingerprint)?;
            }
            Err(error) => gradebook::save_not_graded(&out, &format!("{error:#}"))?,
        }
    }
    let class = write_class(&options.out)?;
    report_class(&class, &options.out)
}

/// After a member's report changed (a review's verdicts): its row in the
/// gradebook of its class, where its report folder `member_out` is in a
/// class's folder. Whether there was a class to update.
pub fn update_class_row(member_out: &Path, report: &Report) -> Result<bool> {
    let Some(class_out) = member_out.parent() else {
        return Ok(false);
    };
    if !class_out.join("gradebook.json").is_file()
        || !member_out.join(gradebook::ROW_FILE).is_file()
    {
        return Ok(false);
    }
    GradebookRow::new(member_name(member_out), report).save(member_out)?;
    write_class(class_out)?;
    Ok(true)
}

/// `cargo xtask gradebook merge PARTS... --out DIR`.
pub fn merge(parts: &[PathBuf], out: &Path) -> Result<()> {
    gradebook::merge(parts, out)?;
    let class = write_class(out)?;
    report_class(&class, out)
}

/// Writes the gradebook of the class whose members' folders are in `out`
/// and the class's report (`class.html`, `class.json`, see
/// `grade::class_report`), each member's report read from its folder.
fn write_class(out: &Path) -> Result<Class> {
    let class = Class::read(out)?;
    class.write(out)?;
    let mut graded = Vec::new();
    for row in &class.rows {
        let folder = out.join(&row.submission);
        let path = folder.join("report.json");
        let report = fs::read_to_string(&path)
            .with_context(|| format!("cannot read {}", path.display()))
            .and_then(|text| {
                serde_json::from_str::<Report>(&text)
                    .with_context(|| format!("cannot read {}", path.display()))
            });
        graded.push((row.submission.clone(), folder, report));
    }
    for (name, why) in &class.not_graded {
        graded.push((name.clone(), out.join(name), Err(anyhow::anyhow!("{why}"))));
    }
    super::class_report::write(out, &graded, &class.rows)?;
    Ok(class)
}

/// Prints where the gradebook of `class` is, who is flagged, and fails
/// when a member could not be graded.
fn report_class(class: &Class, out: &Path) -> Result<()> {
    println!();
    println!(
        "gradebook of {} submission(s): {} (also gradebook.json)",
        class.rows.len(),
        out.join("gradebook.csv").display()
    );
    let flagged: Vec<&str> = class
        .rows
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
    if !class.not_graded.is_empty() {
        let lines: Vec<String> = class
            .not_graded
            .iter()
            .map(|(name, why)| format!("{}: {why}", table::shown(name)))
            .collect();
        bail!(
            "{} submission(s) could not be graded and are not in the gradebook:\n{}",
            lines.len(),
            lines.join("\n")
        );
    }
    Ok(())
}

/// A member's name: its checkout's folder name.
fn member_name(submission: &Path) -> String {
    submission.file_name().map_or_else(
        || "submission".to_owned(),
        |n| n.to_string_lossy().into_owned(),
    )
}

/// A relative path with `/` separators, for messages.
fn slashed(path: &Path) -> String {
    path.components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect::<Vec<_>>()
        .join("/")
}
