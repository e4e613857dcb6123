//! `cargo xtask test`: the project's own test command, proving what the
//! course promises:
//!
//! 1. the student stubs are exactly what `reference/` generates;
//! 2. every workspace test passes against the reference solutions;
//! 3. the reference solutions are clippy-clean (`-D warnings`, all targets,
//!    the benchmarks too);
//! 4. graded with `--reference`, every task gets full points;
//! 5. graded as shipped (the stubs), the course scores 0, compiles and the
//!    grader finishes;
//! 6. the stubs are clippy-clean;
//! 7. a do-nothing edition (each `todo!()` replaced by the cheapest body
//!    that compiles) scores 0 on every task;
//! 8. each planted shortcut (`xtask/tests/shortcuts/`: a simpler or
//!    copied algorithm in place of the one a task teaches) loses its
//!    points;
//! 9. no given function with a task's signature scores in that task's
//!    place;
//! 10. the student edition that `cargo xtask release` writes builds on its
//!     own: `cargo test` there fails only at `todo!()`, `cargo clippy
//!     --all-targets` is clean, `cargo xtask grade` works;
//! 11. the Windows build of the grader's unit tests and of topic 01's tests
//!     passes under Wine (see `wine`);
//! 12. the workspace (the benchmarks aside) is clippy-clean for macOS and
//!     Windows as well (`aarch64-apple-darwin`, `x86_64-pc-windows-gnu`),
//!     which no machine of the project runs.
//!
//! Steps 2 to 10 build in the stage (see `stage`), one build cache for the
//! reference, the stubs, the planted editions and the student edition:
//! switching between them rebuilds only the crates whose files differ.
//! Step 12 checks the stage for the other systems in the same build cache.
//!
//! Every step runs even when an earlier one failed, so that one CI log
//! shows everything that is wrong.

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail, ensure};

use crate::cargo;
use crate::grade::{self, GradeOptions, Report, TaskStatus, TestStatus};
use crate::stage::{self, DoNothingKeep, Overlay};
use crate::{classroom, release, setup, stubs, topics};

/// The shortcuts planted into the solutions, one file a topic
/// (`NN-topic.toml`), each of which must lose its points (see
/// [`shortcuts_lose_their_points`]).
const SHORTCUTS: &str = "xtask/tests/shortcuts";

/// The benchmark crate: built by `cargo xtask bench`, not by the tests.
const BENCH_PACKAGE: &str = "course-bench";

/// Runs the steps (all, or those numbered in `only`) and prints a
/// summary; fails if any step failed.
pub fn run(root: &Path, only: &[usize]) -> Result<()> {
    // GPU topics need a Vulkan driver; an error in the topics themselves
    // is reported by the steps below.
    if topics::discover(root).is_ok_and(|topics| topics.iter().any(|t| t.sheet.gpu)) {
        setup::ensure_vulkan();
    }
    // The viewer's window test runs under a virtual display.
    if root.join("xtask").join("viewer").is_dir() {
        setup::ensure_vulkan();
        setup::ensure_xvfb();
    }
    type Step<'a> = (&'a str, Box<dyn Fn() -> Result<String> + 'a>);
    let steps: Vec<Step<'_>> = vec![
        (
            "stubs are in sync with reference/",
            Box::new(|| stubs_in_sync(root)),
        ),
        (
            "workspace tests pass against the reference solutions",
            Box::new(|| workspace_tests(root)),
        ),
        (
            "reference solutions are clippy-clean",
            Box::new(|| clippy(root, Overlay::Reference)),
        ),
        (
            "reference solutions score full points",
            Box::new(|| reference_scores_full(root)),
        ),
        (
            "untouched stubs compile, score 0 and the grader finishes",
            Box::new(|| stubs_score_zero(root)),
        ),
        (
            "the stubs are clippy-clean",
            Box::new(|| clippy(root, Overlay::Own)),
        ),
        (
            "a do-nothing edition scores 0 on every task",
            Box::new(|| do_nothing_scores_zero(root)),
        ),
        (
            "planted shortcuts lose their points",
            Box::new(|| shortcuts_lose_their_points(root)),
        ),
        (
            "given code stands in for no task",
            Box::new(|| given_code_stands_in_for_no_task(root)),
        ),
        (
            "the student edition builds, fails only at todo!(), grades, and its Classroom workflow lints",
            Box::new(|| student_edition(root)),
        ),
        (
            "the Windows build of the grader's tests and of topic 01's runs under Wine",
            Box::new(|| crate::wine::tests_under_wine(root)),
        ),
        (
            "the workspace is clippy-clean for macOS and Windows",
            Box::new(|| clippy_for_other_systems(root)),
        ),
        (
            "the course's workflow for the hosted macOS and Windows runners lints",
            Box::new(|| platforms_workflow(root)),
        ),
    ];
    if let Some(unknown) = only.iter().find(|&&n| n == 0 || n > steps.len()) {
        bail!(
            "there is no step {unknown}: the steps are 1 to {}",
            steps.len()
        );
    }
    let mut results: Vec<(&str, Result<String>, Duration)> = Vec::new();
    for (number, (title, step)) in steps.iter().enumerate() {
        if !only.is_empty() && !only.contains(&(number + 1)) {
            continue;
        }
        println!();
        println!("==> [{}/{}] {title}", number + 1, steps.len());
        let started = Instant::now();
        let result = step();
        let elapsed = started.elapsed();
        match &result {
            Ok(summary) => println!("==> ok ({:.1} s): {summary}", elapsed.as_secs_f64()),
            Err(error) => println!("==> FAILED ({:.1} s): {error:#}", elapsed.as_secs_f64()),
        }
        results.push((title, result, elapsed));
    }
    println!();
    println!("==> summary");
    let mut failed = 0;
    for (title, result, elapsed) in &results {
        let (status, detail) = match result {
            Ok(summary) => ("ok  ", summary.clone()),
            Err(error) => {
                failed += 1;
                ("FAIL", format!("{error:#}"))
            }
        };
        let detail = detail.lines().next().unwrap_or_default().to_owned();
        println!(
            "  {status}  {:>7.1} s  {title}: {detail}",
            elapsed.as_secs_f64()
        );
    }
    if failed > 0 {
        bail!("{failed} of {} steps failed", results.len());
    }
    println!("all {} steps passed", results.len());
    Ok(())
}

fn stubs_in_sync(root: &Path) -> Result<String> {
    stubs::run(root, true)?;
    Ok("every student file is generated from its solution".to_owned())
}

fn workspace_tests(root: &Path) -> Result<String> {
    let staged = stage::stage(root, Overlay::Reference, None)?;
    cargo::run_visibly(staged.cargo().args([
        "test",
        "--workspace",
        "--no-fail-fast",
        "--exclude",
        BENCH_PACKAGE,
    ]))?;
    Ok("all tests pass with reference/ staged over the stubs".to_owned())
}

/// `cargo clippy` over the whole workspace, staged with `overlay`.
fn clippy(root: &Path, overlay: Overlay<'_>) -> Result<String> {
    let staged = stage::stage(root, overlay, None)?;
    cargo::run_visibly(staged.cargo().args([
        "clippy",
        "--workspace",
        "--all-targets",
        "--all-features",
        "--",
        "-D",
        "warnings",
    ]))?;
    Ok(match overlay {
        Overlay::Reference => "no warnings in the solutions, the benchmarks or the tooling",
        _ => "no warnings in the stubs, the benchmarks or the tooling",
    }
    .to_owned())
}

fn grade_into(root: &Path, overlay: Overlay<'_>, folder: &str) -> Result<Report> {
    let mut options = GradeOptions::new(root.to_path_buf());
    options.out = root.join("target").join("grade").join(folder);
    let report = grade::grade_staged(&options, overlay)?;
    let reference = matches!(overlay, Overlay::Reference);
    // Every stub fails at its todo!(): the table says enough there.
    grade::print_summary(&report, &options.out, reference);
    Ok(report)
}

fn reference_scores_full(root: &Path) -> Result<String> {
    let report = grade_into(root, Overlay::Reference, "reference")?;
    let mut problems = Vec::new();
    // The report's pipeline pictures, drawn with the solutions, are the
    // expected ones to the byte.
    let out = root.join("target").join("grade").join("reference");
    for picture in &report.pipeline {
        let same = match (&picture.yours, &picture.expected) {
            (Some(yours), Some(expected)) => {
                fs::read(out.join(yours)).ok() == fs::read(out.join(expected)).ok()
            }
            _ => false,
        };
        if !same {
            problems.push(format!(
                "the pipeline picture \"{}\" is not the expected one ({})",
                picture.what,
                picture.error.as_deref().unwrap_or("it differs")
            ));
        }
    }
    for topic in &report.topics {
        if topic.compile_error.is_some() {
            problems.push(format!("{} does not compile", topic.name));
        }
        problems.extend(
            topic
                .errors
                .iter()
                .map(|error| format!("{}: {error}", topic.name)),
        );
        for task in &topic.tasks {
            if task.status != TaskStatus::Ok {
                let why = task
                    .first_failure()
                    .and_then(|test| Some(format!("{}: {}", test.name, test.reason.as_deref()?)))
                    .or_else(|| task.error.clone())
                    .unwrap_or_else(|| format!("{:?}", task.status));
                problems.push(format!(
                    "{} / {}: {}",
                    topic.name,
                    task.id,
                    why.lines().next().unwrap_or_default()
                ));
            }
        }
    }
    if !problems.is_empty() {
        bail!(
            "the reference scores {} of {} points; {} problem(s):\n  {}",
            report.score,
            report.max_score,
            problems.len(),
            problems.join("\n  ")
        );
    }
    let page = report_in_chromium(root, &out, &report)?;
    let tests: usize = report
        .topics
        .iter()
        .flat_map(|t| &t.tasks)
        .map(|t| t.passed)
        .sum();
    Ok(format!(
        "{page}; {} of {} points, {tests} tests passed",
        report.score, report.max_score
    ))
}

fn stubs_score_zero(root: &Path) -> Result<String> {
    let report = grade_into(root, Overlay::Own, "stubs")?;
    let mut problems = Vec::new();
    // The pipeline is drawn with the stubs too: nothing drawn, and the
    // stages at `todo!()` named, never replaced by anything.
    for picture in &report.pipeline {
        let names_a_todo = picture.stages.iter().any(|s| s.contains("not written yet"));
        if picture.yours.is_none() || !names_a_todo {
            problems.push(format!(
                "the pipeline picture \"{}\" with the stubs: {}",
                picture.what,
                picture
                    .error
                    .clone()
                    .unwrap_or_else(|| format!("no stage at todo!() named: {:?}", picture.stages))
            ));
        }
    }
    for topic in &report.topics {
        if topic.compile_error.is_some() {
            problems.push(format!("{}: the stubs do not compile", topic.name));
        }
        problems.extend(
            topic
                .errors
                .iter()
                .map(|error| format!("{}: {error}", topic.name)),
        );
        for task in &topic.tasks {
            if task.status == TaskStatus::Error {
                problems.push(format!(
                    "{} / {}: {}",
                    topic.name,
                    task.id,
                    task.error.as_deref().unwrap_or_default()
                ));
            }
            for test in task
                .tests
                .iter()
                .filter(|test| test.status == TestStatus::Passed)
            {
                problems.push(format!(
                    "{} / {}: `{}` passes against the stub (scores {} points)",
                    topic.name, task.id, test.name, task.score
                ));
            }
        }
    }
    if !problems.is_empty() {
        bail!(
            "the stubs score {} of {} points; {} problem(s):\n  {}",
            report.score,
            report.max_score,
            problems.len(),
            problems.join("\n  ")
        );
    }
    let failed: Vec<_> = report
        .topics
        .iter()
        .flat_map(|t| &t.tasks)
        .flat_map(|t| &t.tests)
        .filter(|t| t.status == TestStatus::Failed)
        .collect();
    let todo = failed
        .iter()
        .filter(|t| {
            t.reason
                .as_deref()
                .is_some_and(|r| r.starts_with("not implemented yet"))
        })
        .count();
    Ok(format!(
        "0 of {} points in {:.1} s; {} tests fail, {todo} of them at a todo!()",
        report.max_score,
        report.duration_s,
        failed.len()
    ))
}

/// A do-nothing edition (every `todo!()` replaced by the cheapest body
/// that compiles) scores 0 on every task: no test pays for doing nothing.
fn do_nothing_scores_zero(root: &Path) -> Result<String> {
    // A body that does not compile (a return type without `Default`) keeps
    // its `todo!()`: the errors name the lines, a few rounds at most.
    let mut keep = DoNothingKeep::new();
    for round in 1.. {
        let staged = stage::stage(root, Overlay::DoNothing(&keep), None)?;
        let mut command = staged.cargo();
        // Every crate's errors at once, not just the first failing crate's.
        command.args([
            "check",
            "--workspace",
            "--lib",
            "--keep-going",
            "--message-format",
            "short",
        ]);
        let (compiles, output) = run_captured(&mut command)?;
        if compiles {
            break;
        }
        let mut new = 0;
        for (file, line) in error_lines(&output) {
            let lines = keep.entry(file).or_default();
            if !lines.contains(&line) {
                lines.push(line);
                new += 1;
            }
        }
        if new == 0 || round == 5 {
            bail!(
                "the do-nothing edition does not compile:\n{}",
                tail(&output, 30)
            );
        }
    }
    let report = grade_into(root, Overlay::DoNothing(&keep), "do-nothing")?;
    let mut problems = Vec::new();
    for topic in &report.topics {
        for task in topic.tasks.iter().filter(|t| t.score > 0.0) {
            let passing: Vec<&str> = task
                .tests
                .iter()
                .filter(|t| t.status == TestStatus::Passed)
                .map(|t| t.name.as_str())
                .collect();
            problems.push(format!(
                "{} / {}: {} of {} points for doing nothing ({} of {} tests pass: {})",
                topic.name,
                task.id,
                task.score,
                task.points,
                passing.len(),
                task.tests.len(),
                passing.join(", ")
            ));
        }
    }
    if !problems.is_empty() {
        bail!(
            "the do-nothing edition scores {} of {} points; {} task(s) pay for nothing (make each test also require what only a working body gives):\n  {}",
            report.score,
            report.max_score,
            problems.len(),
            problems.join("\n  ")
        );
    }
    let kept: usize = keep.values().map(Vec::len).sum();
    let reviewed = snapshots_review(root, &root.join("target").join("grade").join("do-nothing"))?;
    Ok(format!(
        "0 of {} points in {:.1} s ({kept} todo!() kept where no cheap body compiles); {reviewed}",
        report.max_score, report.duration_s
    ))
}

/// `cargo xtask review` on the grade in `graded`, whose snapshots differ
/// where the course has any (a do-nothing body draws nothing): cargo-insta
/// shows each one's diff, and the course's own snapshots stay as they
/// were.
fn snapshots_review(root: &Path, graded: &Path) -> Result<String> {
    let official = |review: &crate::review::Review| -> Vec<Option<Vec<u8>>> {
        review
            .pending
            .iter()
            .map(|file| fs::read(root.join(file.with_extension(""))).ok())
            .collect()
    };
    let Some(review) = crate::review::Review::prepare(root, graded)? else {
        return Ok("no snapshot differs, so none to review".to_owned());
    };
    let before = official(&review);
    let diffs = review.diffs()?;
    ensure!(
        diffs.len() == review.pending.len(),
        "the review shows {} of {} snapshots",
        diffs.len(),
        review.pending.len()
    );
    for (snapshot, diff) in &diffs {
        ensure!(
            diff.contains("-old snapshot") && diff.contains("+new results"),
            "the review of {} shows no diff:\n{}",
            snapshot.display(),
            tail(diff, 20)
        );
    }
    ensure!(
        official(&review) == before,
        "reviewing changed the course's snapshots"
    );
    Ok(format!(
        "`cargo xtask review` shows the diffs of its {} differing snapshots",
        diffs.len()
    ))
}

/// The planted shortcuts (see [`SHORTCUTS`]).
#[derive(serde::Deserialize)]
struct Shortcuts {
    #[serde(default)]
    shortcut: Vec<Shortcut>,
}

/// One shortcut: where it goes, how it is made, what it must cost.
#[derive(serde::Deserialize)]
pub(crate) struct Shortcut {
    what: String,
    /// Its topic (folder name).
    pub topic: String,
    /// Its solution file, in the topic's `src/`.
    pub file: String,
    task: String,
    function: Option<String>,
    body: Option<String>,
    #[serde(default)]
    replace: Vec<[String; 2]>,
    #[serde(default)]
    zero: bool,
    #[serde(default)]
    failing: Vec<String>,
}

impl Shortcut {
    /// What this shortcut keeps that it should lose, graded as `report`.
    fn problems(&self, report: &Report) -> Vec<String> {
        let task = report
            .topics
            .iter()
            .filter(|t| t.name == self.topic)
            .flat_map(|t| &t.tasks)
            .find(|t| t.id == self.task);
        let Some(task) = task else {
            return vec![format!(
                "{}: no task {} / {}",
                self.what, self.topic, self.task
            )];
        };
        let mut problems = Vec::new();
        if self.zero && task.score > 0.0 {
            problems.push(format!(
                "{} scores {} of {} points on {} / {}",
                self.what, task.score, task.points, self.topic, self.task
            ));
        }
        for name in &self.failing {
            let failed = task
                .tests
                .iter()
                .any(|t| &t.name == name && t.status == TestStatus::Failed);
            if !failed {
                problems.push(format!(
                    "{}: `{name}` of {} / {} does not fail",
                    self.what, self.topic, self.task
                ));
            }
        }
        problems
    }

    /// The solution file `source` with this shortcut planted.
    pub(crate) fn plant(&self, source: &str) -> Result<String> {
        let mut text = source.to_owned();
        if let (Some(function), Some(body)) = (&self.function, &self.body) {
            let at = [format!("fn {function}("), format!("fn {function}<")]
                .iter()
                .filter_map(|f| text.find(f.as_str()))
                .min()
                .with_context(|| format!("no `fn {function}` in {}", self.file))?;
            let begin = text[at..]
                .find(stubs::BEGIN_MARKER)
                .map(|n| at + n)
                .with_context(|| format!("`fn {function}` has no solution region"))?;
            let body_start = begin + text[begin..].find('\n').context("a marker line")? + 1;
            let end = text[body_start..]
                .find(stubs::END_MARKER)
                .map(|n| body_start + n)
                .context("a solution region without an end")?;
            let end_line = text[..end].rfind('\n').map_or(end, |n| n + 1);
            text.replace_range(body_start..end_line, body);
        }
        for [old, new] in &self.replace {
            let count = text.matches(old.as_str()).count();
            ensure!(
                count == 1,
                "`{old}` occurs {count} times in {}, not once",
                self.file
            );
            text = text.replacen(old.as_str(), new, 1);
        }
        Ok(text)
    }
}

/// The shortcuts of [`SHORTCUTS`], file by file in the order of their
/// names (none where the course has no such folder).
pub(crate) fn shortcuts(root: &Path) -> Result<Vec<Shortcut>> {
    let dir = root.join(SHORTCUTS);
    let Ok(entries) = fs::read_dir(&dir) else {
        return Ok(Vec::new());
    };
    let mut files: Vec<PathBuf> = entries
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    let mut all = Vec::new();
    for path in files {
        let text =
            fs::read_to_string(&path).with_context(|| format!("cannot read {}", path.display()))?;
        let shortcuts: Shortcuts =
            toml::from_str(&text).with_context(|| format!("cannot read {}", path.display()))?;
        all.extend(shortcuts.shortcut);
    }
    Ok(all)
}

/// Each shortcut of [`SHORTCUTS`] planted into its topic's solutions loses
/// what it must: all points of its task, or the tests named.
fn shortcuts_lose_their_points(root: &Path) -> Result<String> {
    if !root.join(SHORTCUTS).is_dir() {
        return Ok(format!(
            "no shortcuts to plant ({SHORTCUTS} does not exist)"
        ));
    }
    let shortcuts = Shortcuts {
        shortcut: shortcuts(root)?,
    };
    // A round is one submission-like folder: the solutions of its topics
    // with one shortcut planted in each, so that every shortcut is graded
    // alone, against the solutions of the other tasks.
    let rounds = one_per_topic(&shortcuts.shortcut, |s| &s.topic);
    let mut problems = Vec::new();
    let mut topics = std::collections::BTreeSet::new();
    let mut duration_s = 0.0;
    for (number, round) in rounds.iter().enumerate() {
        let planted = empty_folder(root.join("target").join("xtask").join("shortcuts"))?;
        for shortcut in round {
            let solutions = root.join("reference").join(&shortcut.topic);
            for file in stage::files_under(&solutions)? {
                let to = Path::new("exercises").join(&shortcut.topic).join(&file);
                let text = fs::read(solutions.join(&file))
                    .with_context(|| format!("cannot read {}", solutions.join(&file).display()))?;
                stage::write_file(&planted.join(to), text)?;
            }
            let file = Path::new("exercises")
                .join(&shortcut.topic)
                .join("src")
                .join(&shortcut.file);
            let solution = root
                .join("reference")
                .join(&shortcut.topic)
                .join("src")
                .join(&shortcut.file);
            let source = fs::read_to_string(&solution)
                .with_context(|| format!("cannot read {}", solution.display()))?;
            let text = shortcut
                .plant(&source)
                .with_context(|| format!("cannot plant {}", shortcut.what))?;
            stage::write_file(&planted.join(file), text)?;
        }
        let mut options = GradeOptions::new(root.to_path_buf());
        let folder = match number {
            0 => "shortcuts".to_owned(),
            n => format!("shortcuts-{}", n + 1),
        };
        options.out = root.join("target").join("grade").join(folder);
        options.topics = round.iter().map(|s| s.topic.clone()).collect();
        options.topics.dedup();
        topics.extend(options.topics.iter().cloned());
        let report = grade::grade_staged(&options, Overlay::Submission(&planted))?;
        grade::print_summary(&report, &options.out, false);
        duration_s += report.duration_s;
        for shortcut in round {
            problems.extend(shortcut.problems(&report));
        }
    }
    if !problems.is_empty() {
        bail!(
            "{} planted shortcut(s) keep points they should lose:\n  {}",
            problems.len(),
            problems.join("\n  ")
        );
    }
    Ok(format!(
        "{} shortcuts planted in {} topics ({} rounds), each loses what it must ({duration_s:.1} s)",
        shortcuts.shortcut.len(),
        topics.len(),
        rounds.len()
    ))
}

/// `items` in rounds that hold at most one item of each topic (named by
/// `topic`), in order: a round is graded as one submission-like folder.
fn one_per_topic<T>(items: &[T], topic: impl Fn(&T) -> &str) -> Vec<Vec<&T>> {
    let mut rounds: Vec<Vec<&T>> = Vec::new();
    for item in items {
        match rounds
            .iter_mut()
            .find(|round| round.iter().all(|other| topic(other) != topic(item)))
        {
            Some(round) => round.push(item),
            None => rounds.push(vec![item]),
        }
    }
    rounds
}

/// `folder`, emptied (what an earlier round left there goes).
fn empty_folder(folder: PathBuf) -> Result<PathBuf> {
    if folder.exists() {
        fs::remove_dir_all(&folder)
            .with_context(|| format!("cannot clear {}", folder.display()))?;
    }
    Ok(folder)
}

/// A given function with a task's signature, and how it gets into the
/// task's file.
struct StandIn {
    topic: String,
    task: String,
    /// The task file, relative to the course.
    file: PathBuf,
    /// The given function: `crates/canvas/src/lib.rs: round`.
    given: String,
    /// The stub with the given function planted in.
    planted: String,
}

/// Every public function of the given code (library crates, and files of
/// exercise crates that hold no task) whose signature is a task's, planted
/// into that task's stub, scores 0 there (see `stubs::stand_ins`).
fn given_code_stands_in_for_no_task(root: &Path) -> Result<String> {
    let (stand_ins, given, uncallable) = find_stand_ins(root)?;
    if stand_ins.is_empty() {
        return Ok(format!(
            "none of the {given} public functions of the given code has a task's signature"
        ));
    }
    // A round holds at most one stand-in per topic, so that one that does
    // not compile where planted hides no other.
    let rounds = one_per_topic(&stand_ins, |s| &s.topic);
    let mut problems = Vec::new();
    let mut not_compiling = Vec::new();
    for (number, round) in rounds.iter().enumerate() {
        let planted = empty_folder(root.join("target").join("xtask").join("stand-ins"))?;
        for stand_in in round {
            stage::write_file(&planted.join(&stand_in.file), &stand_in.planted)?;
        }
        let mut options = GradeOptions::new(root.to_path_buf());
        options.out = root
            .join("target")
            .join("grade")
            .join(format!("stand-ins-{}", number + 1));
        options.topics = round.iter().map(|s| s.topic.clone()).collect();
        let report = grade::grade_staged(&options, Overlay::Submission(&planted))?;
        grade::print_summary(&report, &options.out, false);
        for stand_in in round {
            let topic = report.topics.iter().find(|t| t.name == stand_in.topic);
            let task = topic
                .into_iter()
                .flat_map(|t| &t.tasks)
                .find(|t| t.id == stand_in.task);
            match (topic, task) {
                (Some(topic), _) if topic.compile_error.is_some() => {
                    not_compiling.push(format!("{} in {}", stand_in.given, stand_in.topic));
                }
                (_, Some(task)) if task.score > 0.0 => problems.push(format!(
                    "{} scores {} of {} points in place of {} / {}",
                    stand_in.given, task.score, task.points, stand_in.topic, stand_in.task
                )),
                (_, Some(_)) => {}
                _ => problems.push(format!(
                    "{}: no task {} / {} in the report",
                    stand_in.given, stand_in.topic, stand_in.task
                )),
            }
        }
    }
    if !problems.is_empty() {
        bail!(
            "{} given function(s) solve a task (given code must not: replace them, or make the task's tests tell them apart):\n  {}",
            problems.len(),
            problems.join("\n  ")
        );
    }
    let mut summary = format!(
        "{} given function(s) with a task's signature planted in, each scores 0",
        stand_ins.len()
    );
    if !not_compiling.is_empty() {
        let _ = write!(
            summary,
            "; {} of them do not compile where planted as they are: {}",
            not_compiling.len(),
            not_compiling.join(", ")
        );
    }
    if uncallable > 0 {
        let _ = write!(summary, "; {uncallable} take parameters they drop");
    }
    Ok(summary)
}

/// The given code's public functions with a task's signature, planted into
/// the task's stub; also how many given functions there are, and how many
/// stand-ins could not be planted (a pattern such as `_` drops a value).
fn find_stand_ins(root: &Path) -> Result<(Vec<StandIn>, usize, usize)> {
    use stubs::stand_ins::{Function, plant, public_functions, stub_task};
    let read = |path: &Path| {
        fs::read_to_string(root.join(path))
            .with_context(|| format!("cannot read {}", root.join(path).display()))
    };
    let topics = topics::discover(root)?;
    let task_files = stage::task_files(root)?;
    // Given files: (crate dir, file relative to the course, package name).
    let mut given_files: Vec<(PathBuf, PathBuf, String)> = Vec::new();
    let libraries = root.join("crates");
    let mut crate_dirs: Vec<(PathBuf, String)> = topics
        .iter()
        .map(|t| (Path::new("exercises").join(&t.name), t.package.clone()))
        .collect();
    if libraries.is_dir() {
        for entry in fs::read_dir(&libraries).context("cannot read crates/")? {
            let dir = entry.context("cannot read crates/")?.path();
            let Ok(manifest) = fs::read_to_string(dir.join("Cargo.toml")) else {
                continue;
            };
            let manifest: toml::Table = toml::from_str(&manifest)
                .with_context(|| format!("cannot read {}/Cargo.toml", dir.display()))?;
            let package = manifest
                .get("package")
                .and_then(|p| p.get("name"))
                .and_then(|n| n.as_str())
                .unwrap_or_default()
                .to_owned();
            let relative = dir.strip_prefix(root).unwrap_or(&dir).to_path_buf();
            crate_dirs.push((relative, package));
        }
    }
    for (dir, package) in &crate_dirs {
        let src = root.join(dir).join("src");
        if !src.is_dir() {
            continue;
        }
        for file in stage::files_under(&src)? {
            let course_path = dir.join("src").join(&file);
            let is_rust = file.extension().is_some_and(|e| e == "rs");
            if is_rust && !task_files.contains(&course_path) {
                given_files.push((dir.clone(), course_path, package.clone()));
            }
        }
    }
    let mut given: Vec<(&(PathBuf, PathBuf, String), String, Function)> = Vec::new();
    for entry in &given_files {
        let text = read(&entry.1)?;
        for function in public_functions(&text) {
            given.push((entry, text.clone(), function));
        }
    }
    let mut found = Vec::new();
    let mut uncallable = 0;
    for topic in &topics {
        let crate_dir = Path::new("exercises").join(&topic.name);
        let manifest: toml::Table = toml::from_str(&read(&crate_dir.join("Cargo.toml"))?)
            .with_context(|| format!("cannot read {}/Cargo.toml", crate_dir.display()))?;
        let depends_on = |package: &str| {
            manifest
                .get("dependencies")
                .and_then(|d| d.as_table())
                .is_some_and(|d| d.contains_key(package))
        };
        for file in task_files.iter().filter(|f| f.starts_with(&crate_dir)) {
            let stub = read(file)?;
            for task_fn in public_functions(&stub) {
                let Some(task) = stub_task(&stub, &task_fn) else {
                    continue;
                };
                for ((dir, given_file, package), text, function) in &given {
                    if function.shape != task_fn.shape {
                        continue;
                    }
                    let module = module_path(
                        given_file
                            .strip_prefix(dir.join("src"))
                            .unwrap_or(given_file),
                    );
                    let reachable = *dir == crate_dir
                        || (depends_on(package) && public_chain(root, dir, &module));
                    let path = if *dir == crate_dir {
                        format!("crate{}::{}", prefixed(&module), function.name)
                    } else if reachable {
                        format!(
                            "{}{}::{}",
                            package.replace('-', "_"),
                            prefixed(&module),
                            function.name
                        )
                    } else {
                        format!("stand_in::{}", function.name)
                    };
                    let copy = (!reachable).then_some(text.as_str());
                    let Some(planted) = plant(&stub, &task_fn, &path, copy) else {
                        uncallable += 1;
                        continue;
                    };
                    found.push(StandIn {
                        topic: topic.name.clone(),
                        task: task.clone(),
                        file: file.clone(),
                        given: format!("{}: {}", given_file.display(), function.name),
                        planted,
                    });
                }
            }
        }
    }
    Ok((found, given.len(), uncallable))
}

/// The module a source file is, relative to its crate's `src`
/// (`raster/dda.rs` → `["raster", "dda"]`, `lib.rs` → `[]`).
fn module_path(file: &Path) -> Vec<String> {
    let mut parts: Vec<String> = file
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    if let Some(last) = parts.pop() {
        let stem = last.strip_suffix(".rs").unwrap_or(&last);
        if !matches!(stem, "lib" | "mod" | "main") {
            parts.push(stem.to_owned());
        }
    }
    parts
}

/// `::a::b` for `["a", "b"]`.
fn prefixed(module: &[String]) -> String {
    module.iter().map(|m| format!("::{m}")).collect()
}

/// Whether every module of `module` is declared `pub mod` by its parent,
/// so that another crate can name it.
fn public_chain(root: &Path, crate_dir: &Path, module: &[String]) -> bool {
    let src = root.join(crate_dir).join("src");
    let mut parent = src.join("lib.rs");
    let mut folder = src.clone();
    for name in module {
        let text = fs::read_to_string(&parent).unwrap_or_default();
        let masked = stubs::quiet::mask(&text);
        if !masked.contains(&format!("pub mod {name};")) {
            return false;
        }
        folder = folder.join(name);
        parent = if folder.join("mod.rs").is_file() {
            folder.join("mod.rs")
        } else {
            folder.with_extension("rs")
        };
    }
    true
}

/// `(file, line)` of each error in cargo's `--message-format short`
/// output that lies in a task file (`exercises/…`).
fn error_lines(output: &str) -> Vec<(PathBuf, usize)> {
    output
        .lines()
        .filter_map(|line| {
            let (place, _) = line.split_once(": error")?;
            let mut parts = place.rsplitn(3, ':');
            let _column = parts.next()?;
            let number = parts.next()?.parse().ok()?;
            let file = parts.next()?;
            file.starts_with("exercises/")
                .then(|| (PathBuf::from(file), number))
        })
        .collect()
}

/// The panic messages of the failed tests in `cargo test` output that are
/// not a `todo!()`'s, by test name.
fn failures_not_at_todo(output: &str) -> Vec<String> {
    let mut failures = Vec::new();
    let mut current: Option<(String, bool)> = None;
    let mut finish = |current: &mut Option<(String, bool)>| {
        if let Some((name, at_todo)) = current.take()
            && !at_todo
        {
            failures.push(name);
        }
    };
    for line in output.lines() {
        if let Some(name) = line
            .strip_prefix("---- ")
            .and_then(|rest| rest.strip_suffix(" stdout ----"))
        {
            finish(&mut current);
            current = Some((name.to_owned(), false));
        } else if line == "failures:" || line.starts_with("test result:") {
            finish(&mut current);
        } else if let Some((_, at_todo)) = current.as_mut() {
            *at_todo |= line.contains("not yet implemented");
        }
    }
    finish(&mut current);
    failures
}

/// Runs `command` with its output captured and echoed; returns
/// (success, stdout and stderr).
fn run_captured(command: &mut std::process::Command) -> Result<(bool, String)> {
    println!("$ {}", cargo::display(command));
    let output = command
        .output()
        .with_context(|| format!("cannot run `{}`", cargo::display(command)))?;
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
    Ok((output.status.success(), text))
}

fn student_edition(root: &Path) -> Result<String> {
    let home = stage::home(root);
    let release_dir = home.join("release");
    // Released as for GitHub Classroom, whose workflow is checked below.
    let course = classroom::CourseRepo {
        repository: "course-author/rasterization".to_owned(),
        reference: Some("v1".to_owned()),
    };
    let release = release::write(root, &release_dir, &[], Some(&course))?;
    println!(
        "wrote the edition to {} ({} topics; course library: {})",
        release_dir.display(),
        release.topics.len(),
        release.crates.join(", ")
    );
    ensure!(
        !release_dir.join("reference").exists() && !release_dir.join("xtask/bench").exists(),
        "the edition holds reference/ or the benchmarks"
    );
    // Its text files stay LF in a Windows checkout too.
    ensure!(
        fs::read(release_dir.join(".gitattributes")).ok()
            == fs::read(root.join(".gitattributes")).ok(),
        "the edition does not hold the course's .gitattributes"
    );
    // Built in the stage, where the stubs were just graded: only what the
    // edition changes is rebuilt.
    let staged = stage::stage_in(&home, &release_dir, Overlay::Own, None)?;
    let in_edition = |args: &[&str]| {
        let mut command = staged.cargo();
        command.env("NO_COLOR", "1").args(args);
        command
    };

    let (_, output) = run_captured(&mut in_edition(&["test", "--no-fail-fast"]))?;
    ensure!(
        !output.contains("error: could not compile") && output.contains("test result:"),
        "`cargo test` does not build in the edition:\n{}",
        tail(&output, 40)
    );
    let not_todo = failures_not_at_todo(&output);
    ensure!(
        not_todo.is_empty(),
        "{} test(s) fail in the edition other than at a todo!(): {}",
        not_todo.len(),
        not_todo.join(", ")
    );
    let failed = output.matches(" stdout ----").count();

    let (clean, output) = run_captured(&mut in_edition(&[
        "clippy",
        "--all-targets",
        "--",
        "-D",
        "warnings",
    ]))?;
    ensure!(
        clean,
        "`cargo clippy --all-targets` is not clean in the edition:\n{}",
        tail(&output, 40)
    );

    // The grader of this checkout on the edition (the edition's own
    // `cargo xtask` is this code, and clippy has just checked it builds).
    let first = release
        .topics
        .first()
        .context("the edition has no topics")?;
    let exe = std::env::current_exe().context("cannot find the xtask program")?;
    let mut grade = std::process::Command::new(exe);
    grade
        .env("CARGO_TARGET_DIR", &staged.target_dir)
        .env("NO_COLOR", "1")
        .arg("--root")
        .arg(&staged.root)
        .args(["grade", first]);
    let (graded, output) = run_captured(&mut grade)?;
    ensure!(
        graded,
        "`cargo xtask grade {first}` fails in the edition:\n{}",
        tail(&output, 40)
    );
    let report_path = staged.root.join("target/grade/report.json");
    let report: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(&report_path)
            .with_context(|| format!("cannot read {}", report_path.display()))?,
    )
    .with_context(|| format!("cannot parse {}", report_path.display()))?;
    ensure!(
        report["score"].as_f64() == Some(0.0),
        "`cargo xtask grade {first}` in the edition scores {} instead of 0",
        report["score"]
    );
    let workflow = classroom_workflow(
        &home,
        &release_dir,
        &staged.root.join("target/grade/classroom"),
    )?;
    Ok(format!(
        "{} topics: `cargo test` fails {failed} test(s), all at a todo!(); clippy clean; `cargo xtask grade {first}` scores 0; {workflow}",
        release.topics.len()
    ))
}

/// Opens the report of `out` in a headless Chromium, as a reader would
/// from the folder (no server): the summary names every topic, and every
/// comparison of pictures became one magnified view with its switch (its
/// pictures load from the folder, and its script ran). A screenshot is
/// kept in `target/xtask/report.png`. Required under CI; elsewhere a
/// missing Chromium is a note.
fn report_in_chromium(root: &Path, out: &Path, report: &Report) -> Result<String> {
    let Some(chromium) = setup::chromium() else {
        ensure!(
            std::env::var_os("CI").is_none(),
            "no Chromium to check report.html in (Debian: apt-get install chromium)"
        );
        println!("note: report.html is not checked: no Chromium here");
        return Ok("report.html not checked (no Chromium)".to_owned());
    };
    let page = out.join("report.html");
    let url = format!("file://{}", page.display());
    let profile = stage::home(root).join("chromium-profile");
    let _ = fs::remove_dir_all(&profile);
    let screenshot = stage::home(root).join("report.png");
    let browse = |extra: &[String]| -> Result<std::process::Output> {
        let mut command = std::process::Command::new("timeout");
        command
            .arg("120")
            .arg(&chromium)
            .args([
                "--headless",
                "--no-sandbox",
                "--disable-gpu",
                "--disable-quic",
                "--no-first-run",
                "--disable-background-networking",
                "--disable-component-update",
                "--disable-sync",
                "--hide-scrollbars",
                "--virtual-time-budget=20000",
            ])
            .arg(format!("--user-data-dir={}", profile.display()))
            .args(extra)
            .arg(&url);
        println!("$ {}", cargo::display(&command));
        command
            .output()
            .with_context(|| format!("cannot run {}", chromium.display()))
    };
    let dumped = browse(&["--dump-dom".to_owned()])?;
    ensure!(
        dumped.status.success(),
        "Chromium could not open report.html: {}",
        tail(&String::from_utf8_lossy(&dumped.stderr), 10)
    );
    let dom = String::from_utf8_lossy(&dumped.stdout);
    ensure!(dom.contains("id=\"summary\""), "report.html has no summary");
    for topic in &report.topics {
        ensure!(
            dom.contains(&format!("href=\"#topic-{}\"", topic.name)),
            "the summary of report.html does not link {}",
            topic.name
        );
    }
    let comparisons: usize = report
        .topics
        .iter()
        .flat_map(|t| &t.tasks)
        .flat_map(|t| &t.tests)
        .map(|t| {
            let mut folders: Vec<_> = t.images.iter().map(|i| i.parent()).collect();
            folders.sort();
            folders.dedup();
            folders.len()
        })
        .sum();
    let boxes = dom.matches("class=\"compare\"").count();
    let shown = dom.matches("data-scale=\"").count();
    ensure!(
        boxes == comparisons && shown == boxes,
        "report.html: {comparisons} comparisons of pictures, {boxes} on the page, {shown} of them shown magnified"
    );
    let shot = browse(&[
        "--window-size=1280,2400".to_owned(),
        format!("--screenshot={}", screenshot.display()),
    ])?;
    ensure!(
        shot.status.success() && screenshot.is_file(),
        "Chromium could not take a screenshot of report.html"
    );
    Ok(format!(
        "report.html in Chromium: a summary of {} topics, {boxes} comparisons shown magnified (screenshot {})",
        report.topics.len(),
        screenshot.display()
    ))
}

/// The course's workflow that grades the solutions and draws the viewer's
/// picture on GitHub's hosted macOS and Windows runners (course only).
const PLATFORMS_WORKFLOW: &str = ".github/workflows/platforms.yml";

/// Checks [`PLATFORMS_WORKFLOW`] with actionlint, and that it runs on both
/// systems the project has no machine of.
fn platforms_workflow(root: &Path) -> Result<String> {
    let file = root.join(PLATFORMS_WORKFLOW);
    let text = fs::read_to_string(&file)
        .with_context(|| format!("the course has no {PLATFORMS_WORKFLOW}"))?;
    for runner in ["macos-latest", "windows-latest"] {
        ensure!(
            text.contains(runner),
            "{PLATFORMS_WORKFLOW} does not run on {runner}"
        );
    }
    let findings = setup::actionlint(&stage::home(root).join("tools"), &file)
        .context("cannot lint the hosted-runner workflow")?;
    ensure!(
        findings.is_empty(),
        "actionlint finds fault with {PLATFORMS_WORKFLOW}:\n{}",
        findings.join("\n")
    );
    Ok(format!(
        "{PLATFORMS_WORKFLOW}: macOS and Windows, actionlint finds nothing"
    ))
}

/// Checks the edition's GitHub Classroom workflow: actionlint finds
/// nothing (required under CI; elsewhere a missing Node.js is a note), it
/// reports every task of the edition, and the grade just written in
/// `results` has a result file for each task it names of the graded topic.
fn classroom_workflow(home: &Path, edition: &Path, results: &Path) -> Result<String> {
    let file = edition.join(classroom::WORKFLOW);
    let text = fs::read_to_string(&file)
        .with_context(|| format!("the edition has no {}", classroom::WORKFLOW))?;
    let linted = match setup::actionlint(&home.join("tools"), &file) {
        Ok(findings) => {
            ensure!(
                findings.is_empty(),
                "actionlint finds fault with the Classroom workflow:\n{}",
                findings.join("\n")
            );
            "actionlint finds nothing"
        }
        Err(error) if std::env::var_os("CI").is_none() => {
            println!("note: the Classroom workflow is not linted: {error:#}");
            "not linted (no actionlint)"
        }
        Err(error) => return Err(error.context("cannot lint the Classroom workflow")),
    };
    let names_step = |id: &str| text.contains(&format!("id: {id}\n"));
    let mut tasks = 0;
    for topic in topics::discover(edition)? {
        for task in &topic.sheet.tasks {
            let id = classroom::step_id(&topic.name, &task.id);
            ensure!(
                names_step(&id),
                "the Classroom workflow does not report {id}"
            );
            tasks += 1;
        }
    }
    let written: Vec<String> = fs::read_dir(results)
        .with_context(|| format!("the grade wrote no {}", results.display()))?
        .filter_map(|entry| {
            let path = entry.ok()?.path();
            Some(path.file_stem()?.to_string_lossy().into_owned())
        })
        .collect();
    ensure!(!written.is_empty(), "the grade wrote no Classroom results");
    for id in &written {
        ensure!(
            names_step(id),
            "the grade wrote a Classroom result {id} that the workflow does not report"
        );
    }
    Ok(format!(
        "the Classroom workflow reports {tasks} tasks, {} of them written by the grade, {linted}",
        written.len()
    ))
}

/// The systems students use besides Linux, with the target cargo checks
/// for each: no machine of the project runs them.
const OTHER_SYSTEMS: [(&str, &str); 2] = [
    ("macOS", "aarch64-apple-darwin"),
    ("Windows", "x86_64-pc-windows-gnu"),
];

/// `cargo clippy` over the workspace (the solutions staged, all targets)
/// for macOS and Windows: the code behind `cfg(windows)` and `cfg(unix)`,
/// wgpu's Metal and DX12 backends, eframe's and notify's platform code. A
/// check links nothing, so no cross linker is needed; a target that is
/// missing is installed with rustup. The benchmarks are left out: criterion
/// compiles C (`alloca`) for the target, which needs a cross compiler, and
/// students never build them. The other targets' artifacts lie in their
/// own folders of the stage's cache.
fn clippy_for_other_systems(root: &Path) -> Result<String> {
    for (_, target) in OTHER_SYSTEMS {
        setup::rustup_target(target)?;
    }
    // In the stage's own cache: the host's build scripts and procedural
    // macros, built by the steps before, serve the other targets too.
    let staged = stage::stage(root, Overlay::Reference, None)?;
    for (_, target) in OTHER_SYSTEMS {
        cargo::run_visibly(staged.cargo().args([
            "clippy",
            "--workspace",
            "--all-targets",
            "--all-features",
            "--exclude",
            BENCH_PACKAGE,
            "--target",
            target,
            "--",
            "-D",
            "warnings",
        ]))?;
    }
    let systems: Vec<String> = OTHER_SYSTEMS
        .iter()
        .map(|(system, target)| format!("{system} ({target})"))
        .collect();
    Ok(format!(
        "no warnings in the solutions or the tooling for {}",
        systems.join(" and ")
    ))
}

/// The last `lines` lines of `text`.
fn tail(text: &str, lines: usize) -> String {
    let all: Vec<&str> = text.lines().collect();
    all[all.len().saturating_sub(lines)..].join("\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shortcut(function: Option<&str>, body: Option<&str>, replace: &[[&str; 2]]) -> Shortcut {
        Shortcut {
            what: "a shortcut".to_owned(),
            topic: "01-x".to_owned(),
            file: "x.rs".to_owned(),
            task: "x".to_owned(),
            function: function.map(str::to_owned),
            body: body.map(str::to_owned),
            replace: replace.iter().map(|p| p.map(str::to_owned)).collect(),
            zero: true,
            failing: Vec::new(),
        }
    }

    #[test]
    fn a_shortcut_replaces_its_functions_region_or_substitutes_once() {
        let source = "\
pub fn a() -> u32 {
    // BEGIN SOLUTION x: one
    1
    // END SOLUTION
}

pub fn b<T>() -> u32 {
    // BEGIN SOLUTION x: two
    let two = 2;
    two
    // END SOLUTION
}
";
        let planted = shortcut(Some("b"), Some("    3\n"), &[])
            .plant(source)
            .unwrap();
        assert!(
            planted.contains("// BEGIN SOLUTION x: two\n    3\n    // END SOLUTION"),
            "{planted}"
        );
        assert!(
            planted.contains("    1\n"),
            "only b's region changes: {planted}"
        );
        let planted = shortcut(None, None, &[["let two = 2;", "let two = 4;"]])
            .plant(source)
            .unwrap();
        assert!(planted.contains("let two = 4;"), "{planted}");
        // What is not there, or there twice, is an error, not a silent no-op.
        assert!(
            shortcut(None, None, &[["three", "3"]])
                .plant(source)
                .is_err()
        );
        assert!(
            shortcut(None, None, &[["SOLUTION", "x"]])
                .plant(source)
                .is_err()
        );
        assert!(shortcut(Some("c"), Some("0"), &[]).plant(source).is_err());
    }

    #[test]
    fn the_courses_shortcuts_are_read_and_each_file_holds_its_topics() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
        let shortcuts = shortcuts(&root).unwrap();
        assert!(shortcuts.len() >= 29, "{} shortcuts", shortcuts.len());
        for entry in fs::read_dir(root.join(SHORTCUTS)).unwrap().flatten() {
            let path = entry.path();
            let Some(topic) = path
                .file_stem()
                .filter(|_| path.extension().is_some_and(|e| e == "toml"))
            else {
                continue;
            };
            let text = fs::read_to_string(&path).unwrap();
            let file: Shortcuts = toml::from_str(&text).unwrap();
            assert!(!file.shortcut.is_empty(), "{}", path.display());
            assert!(
                file.shortcut.iter().all(|s| *s.topic == *topic),
                "{} holds another topic's shortcut",
                path.display()
            );
        }
    }

    #[test]
    fn failures_at_a_todo_are_told_from_other_failures() {
        let output = "\
running 3 tests
test a ... FAILED
test b ... FAILED
test c ... ok

failures:

---- a stdout ----

thread 'a' panicked at src/dda.rs:3:5:
not yet implemented: dda: draw the line

---- b stdout ----

thread 'b' panicked at tests/dda.rs:9:5:
assertion `left == right` failed

failures:
    a
    b

test result: FAILED. 1 passed; 2 failed
";
        assert_eq!(failures_not_at_todo(output), ["b"]);
    }
}
