//! `cargo xtask grade --submission DIR`: grading a student's checkout, or a
//! folder of them, with the course's official tests.
//!
//! Only the task files belong to the student: the files of
//! `exercises/*/src/` the official course names as tasks (see
//! `stage::task_files`), each read once through a handle that follows no
//! link ([`take_task_files`]). Everything else that takes part in
//! grading — the given code beside them, the course library (`crates/`),
//! the tests and snapshots, the task sheets (they hold the points), the
//! manifests, the tooling — is the course's. So a submission is never
//! built where it lies: its task files are laid over a copy of the
//! official course, the *stage* (see `stage`, which also stages the
//! reference), and the stage is graded.
//!
//! ```text
//!   official course ──(no target/, .git/, reference/)──┐
//!                                                      ├──sync──> stage ──grade──> report
//!   submission ──its task files only, read once────────┘
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

use super::adjustments::Adjustments;
use super::report::{self, Edition, Report};
use super::{GradeOptions, Permits, table};
use crate::stage::{self, Overlay, Source};
use crate::topics;

mod class;
mod gradebook;
mod integrity;
pub(crate) mod nofollow;
mod resume;
mod tampering;

use class::grade_class;
use gradebook::Class;
pub(crate) use gradebook::GradebookRow;
use integrity::is_grading_file;
pub use integrity::{Integrity, check};
pub use resume::Shard;
use tampering::{contents_of, tampered};

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
    let (files, taken) = staged_files(official, submission)?;
    let (refused, unreadable) = (taken.refused, taken.unreadable);
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
    let graded = prepared.finish()?;
    let mut integrity = integrity;
    integrity.tampered = tampered(official, &course_before, &staged.root, &planned)?;
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
    let absent = options
        .absent
        .iter()
        .map(|name| (name.clone(), super::plan::absent_reason(name)));
    let report = graded.report(Adjustments {
        shown_root: Some(submission.to_path_buf()),
        refused,
        topic_errors: absent.chain(unreadable).collect(),
        tampered: integrity.tampered.clone(),
        integrity: Some(integrity),
    });
    super::export::write_all(&report, &options.out)?;
    Ok(report)
}

/// A submission's task files as the grader took them.
#[derive(Debug, Default)]
struct Taken {
    /// Every task file of the course (see `stage::task_files`): the
    /// submission's copy, read once, or the official stub where the
    /// submission's is missing, unreadable or refused.
    files: stage::Files,
    /// Per topic, the uses of what a task file may not do (see
    /// `forbidden`): the topic is not compiled.
    refused: Vec<(String, Vec<String>)>,
    /// Per topic, the task files not read and why (a link, a pipe, a
    /// flood): their stubs were used.
    unreadable: Vec<(String, String)>,
}

/// Takes the task files of `submission`: the files the official course at
/// `official` names as tasks (`stage::task_files`), nothing else of it.
/// Each is read once, through a handle opened without following a link at
/// any component ([`nofollow`]); that copy in memory is what is checked
/// for forbidden constructs and what is staged, so a file swapped for a
/// link to a solution after this read changes nothing. Every other file
/// of the submission (given code, `lib.rs`, its manifests) is the
/// course's in the stage.
fn take_task_files(official: &Path, submission: &Path) -> Result<Taken> {
    let mut taken = Taken::default();
    let topic_of = |task_file: &Path| {
        task_file
            .components()
            .nth(1)
            .map(|c| c.as_os_str().to_string_lossy().into_owned())
            .unwrap_or_default()
    };
    let stub = |task_file: &Path| {
        (
            task_file.to_path_buf(),
            Source::File(official.join(task_file)),
        )
    };
    for task_file in stage::task_files(official)? {
        let bytes = match nofollow::read(submission, &task_file, crate::files::MAX_SUBMITTED_FILE) {
            Ok(bytes) => bytes,
            Err(nofollow::Missing) => {
                taken.files.push(stub(&task_file));
                continue;
            }
            Err(nofollow::Refusal::Refused(why)) => {
                taken.unreadable.push((
                    topic_of(&task_file),
                    format!(
                        "{}: not graded ({why}); the stub was used",
                        slashed(&task_file)
                    ),
                ));
                taken.files.push(stub(&task_file));
                continue;
            }
        };
        // A task file that reaches other files at compile time (or uses a
        // known soundness hole, see `forbidden`) is not compiled: its stub
        // is staged instead, and its topic scores 0. WGSL reaches no
        // files; Rust may, by macros. Text that is not UTF-8 is staged as
        // it is, and does not compile.
        let uses = match std::str::from_utf8(&bytes) {
            Ok(text) if !crate::files::is_wgsl(&task_file) => super::forbidden::uses(text),
            _ => Vec::new(),
        };
        if uses.is_empty() {
            taken.files.push((task_file, Source::Text(bytes)));
        } else {
            let shown = task_file.display().to_string();
            taken.refused.push((
                topic_of(&task_file),
                uses.iter().map(|u| format!("{shown}:{u}")).collect(),
            ));
            taken.files.push(stub(&task_file));
        }
    }
    Ok(taken)
}

/// The files of the stage of `submission`: the edition of the official
/// course with the submission's task files as [`take_task_files`] took
/// them (each read once, held in memory), and what it found. Nothing of
/// the submission is left to be read later: no staged file is a path
/// into it.
fn staged_files(official: &Path, submission: &Path) -> Result<(stage::Files, Taken)> {
    let taken = take_task_files(official, submission)?;
    let mut files = stage::plan(official, Overlay::Submission(submission))?;
    files.retain(|(to, _)| !taken.files.iter().any(|(task_file, _)| task_file == to));
    files.extend(taken.files.iter().cloned());
    files.sort();
    // As staged: what the integrity check compares the stage with.
    let files = stage::replay::with_graded_data(&files);
    Ok((files, taken))
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
#[cfg(feature = "staff")]
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
#[cfg(feature = "staff")]
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
            .map(|(name, why)| format!("{}: {}", table::shown(name), table::continued(why, "  ")))
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
pub(crate) fn slashed(path: &Path) -> String {
    path.components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect::<Vec<_>>()
        .join("/")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The course this tooling ships with.
    fn course() -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
    }

    #[test]
    fn the_course_markers_name_exactly_the_files_with_a_solution() {
        // In an edition (no `reference/`) the task files are found by the
        // stubs' markers; here, where `reference/` says which they are,
        // both must agree, and the given files that mention `todo!()` in
        // their doc comments are not tasks.
        let root = course();
        if !root.join("reference").is_dir() {
            eprintln!("not run: an edition has no reference/ to compare its markers with");
            return;
        }
        for topic in topics::discover(&root).unwrap() {
            let ids: Vec<&str> = topic.sheet.tasks.iter().map(|t| t.id.as_str()).collect();
            let src = topic.dir.join("src");
            for file in crate::files::files_under(&src).unwrap() {
                let text = fs::read_to_string(src.join(&file)).unwrap();
                let solved = root
                    .join("reference")
                    .join(&topic.name)
                    .join("src")
                    .join(&file)
                    .is_file();
                assert_eq!(
                    crate::stubs::holds_task_stub(&file, &text, &ids),
                    solved,
                    "exercises/{}/src/{}",
                    topic.name,
                    file.display()
                );
            }
        }
        for given in [
            "exercises/06-csg/src/raster.rs",
            "exercises/10-gpu-tessellation/src/wgsl.rs",
        ] {
            let text = fs::read_to_string(root.join(given)).unwrap();
            assert!(
                text.contains("todo!()"),
                "{given} no longer mentions todo!()"
            );
        }
    }

    /// An edition of one topic (no `reference/`): a task file `classify.rs`
    /// and a given file `raster.rs` whose doc comment mentions `todo!()`.
    fn edition(dir: &Path) -> PathBuf {
        let official = dir.join("official");
        let topic = official.join("exercises/06-x");
        let write = |path: PathBuf, text: &str| crate::files::write_file(&path, text).unwrap();
        write(topic.join("Cargo.toml"), "[package]\nname = \"x\"\n");
        write(
            topic.join("tasks.toml"),
            "[[tasks]]\nid = \"classify\"\ntitle = \"Classify\"\npoints = 3\n",
        );
        write(
            topic.join("src/lib.rs"),
            "pub mod classify;\npub mod raster;\n",
        );
        write(
            topic.join("src/raster.rs"),
            "//! Given: a stage at `todo!()` is named on screen.\npub fn raster() -> u8 { 1 }\n",
        );
        write(
            topic.join("src/classify.rs"),
            "pub fn classify() -> u8 {\n    todo!(\"classify: say inside or outside\")\n}\n",
        );
        official
    }

    #[test]
    fn a_modified_given_file_changes_nothing_and_task_files_are_read_once() {
        let dir = std::env::temp_dir().join(format!("xtask-taken-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        let official = edition(&dir);
        let classify = PathBuf::from("exercises/06-x/src/classify.rs");
        let raster = PathBuf::from("exercises/06-x/src/raster.rs");
        assert_eq!(
            stage::task_files(&official).unwrap(),
            std::slice::from_ref(&classify)
        );
        let submission = dir.join("anna");
        let write = |path: PathBuf, text: &str| crate::files::write_file(&path, text).unwrap();
        write(
            submission.join(&classify),
            "pub fn classify() -> u8 { 2 }\n",
        );
        write(
            submission.join(&raster),
            "//! Mine now: todo!(\"classify: x\")\npub fn raster() -> u8 { 42 }\n",
        );
        let taken = take_task_files(&official, &submission).unwrap();
        assert!(taken.refused.is_empty() && taken.unreadable.is_empty());
        // Only the task file is the student's; raster.rs stays the course's.
        let files: Vec<&PathBuf> = taken.files.iter().map(|(to, _)| to).collect();
        assert_eq!(files, [&classify]);
        let checked = Source::Text(b"pub fn classify() -> u8 { 2 }\n".to_vec());
        assert_eq!(taken.files[0].1, checked);
        // A watcher swaps the task file for a link to a solution after the
        // check: what was taken is what is staged and graded.
        let solution = dir.join("solution.rs");
        write(solution.clone(), "pub fn classify() -> u8 { 1 }\n");
        fs::remove_file(submission.join(&classify)).unwrap();
        #[cfg(unix)]
        {
            std::os::unix::fs::symlink(&solution, submission.join(&classify)).unwrap();
            assert_eq!(
                taken.files[0].1.read().unwrap(),
                b"pub fn classify() -> u8 { 2 }\n"
            );
            // Taken again, the link is refused and the stub staged.
            let again = take_task_files(&official, &submission).unwrap();
            assert_eq!(again.unreadable.len(), 1, "{:?}", again.unreadable);
            assert!(again.unreadable[0].1.contains("symbolic link"));
            assert_eq!(again.files[0].1, Source::File(official.join(&classify)));
        }
        let _ = fs::remove_dir_all(&dir);
    }

    #[test]
    #[cfg_attr(
        windows,
        ignore = "stages with `cargo metadata`; there is no cargo where the Windows build runs (Wine)"
    )]
    fn a_submissions_tool_configuration_is_never_staged_nor_read_later() {
        // insta reads `insta.yaml`, `.config/insta.yaml` or `.insta.yaml`
        // in the workspace root, proptest `proptest-regressions/` beside
        // a test: a submission's are not the course's, and stay behind.
        let dir = std::env::temp_dir().join(format!("xtask-staged-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        let submission = dir.join("anna");
        // A little course of its own, whose stub names its task file
        // wherever this test runs (in a stage the course's own files are
        // the solutions, and an edition has no fixtures).
        let tiny = dir.join("tiny");
        let dda = PathBuf::from("exercises/01-tiny/src/ops.rs");
        let write = |path: PathBuf, text: &str| crate::files::write_file(&path, text).unwrap();
        write(
            tiny.join("Cargo.toml"),
            "[workspace]\nresolver = \"3\"\nmembers = [\"exercises/*\"]\n",
        );
        write(
            tiny.join("exercises/01-tiny/Cargo.toml"),
            "[package]\nname = \"tiny\"\nversion = \"0.1.0\"\nedition = \"2024\"\n",
        );
        write(
            tiny.join("exercises/01-tiny/tasks.toml"),
            "[[tasks]]\nid = \"double\"\ntitle = \"Doubling\"\npoints = 1\n",
        );
        write(tiny.join("exercises/01-tiny/src/lib.rs"), "pub mod ops;\n");
        write(
            tiny.join(&dda),
            "pub fn double(x: i32) -> i32 {\n    let _ = x;\n    todo!(\"double: twice x\")\n}\n",
        );
        write(submission.join(&dda), "// mine\n");
        for config in ["insta.yaml", ".config/insta.yaml", ".insta.yaml"] {
            write(submission.join(config), "behavior:\n  force_pass: true\n");
        }
        write(
            submission.join("exercises/01-tiny/tests/proptest-regressions/double.txt"),
            "cc 0\n",
        );
        let (files, _) = staged_files(&tiny, &submission).unwrap();
        for (to, from) in &files {
            let name = to.to_string_lossy();
            assert!(
                !name.contains("insta.yaml") && !name.contains("proptest-regressions"),
                "{name} is staged"
            );
            assert!(
                !matches!(from, Source::File(path) if path.starts_with(&submission)),
                "{name} would be read from the submission later"
            );
        }
        let staged = files
            .iter()
            .find(|(to, _)| *to == dda)
            .map(|(_, from)| from);
        assert_eq!(staged, Some(&Source::Text(b"// mine\n".to_vec())));
        let _ = fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_task_file_using_the_soundness_hole_is_refused_and_its_stub_staged() {
        let dir = std::env::temp_dir().join(format!("xtask-taken-hole-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        let official = edition(&dir);
        let classify = PathBuf::from("exercises/06-x/src/classify.rs");
        let submission = dir.join("ben");
        crate::files::write_file(
            &submission.join(&classify),
            "fn t<'a, 'b, T>(_: &'a &'b (), v: &'b T) -> &'a T { v }\npub fn classify() -> u8 { 0 }\n",
        )
        .unwrap();
        let taken = take_task_files(&official, &submission).unwrap();
        assert_eq!(taken.refused.len(), 1);
        assert!(
            taken.refused[0].1[0].contains("rust-lang/rust#25860"),
            "{:?}",
            taken.refused
        );
        assert_eq!(taken.files[0].1, Source::File(official.join(&classify)));
        let _ = fs::remove_dir_all(&dir);
    }
}
