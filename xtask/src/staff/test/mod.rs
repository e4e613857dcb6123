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
//! 12. the code that differs between systems (the grader, the GPU library,
//!     the viewer, topic 10) is clippy-clean for macOS and
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

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};

use crate::cargo;
use crate::grade::{self, GradeOptions, Report};
use crate::stage::{self, Overlay};
use crate::{setup, topics};

mod browser;
pub(crate) mod disk;
mod edition;
mod platforms;
mod scores;
mod shortcuts;
mod stand_ins;

use edition::student_edition;
use platforms::{clippy_for_other_systems, platforms_workflow};
use scores::{do_nothing_scores_zero, reference_scores_full, stubs_score_zero};
use shortcuts::shortcuts_lose_their_points;
pub(crate) use shortcuts::{Shortcut, shortcuts};
use stand_ins::given_code_stands_in_for_no_task;

/// The shortcuts planted into the solutions, one file a topic
/// (`NN-topic.toml`), each of which must lose its points (see
/// [`shortcuts_lose_their_points`]).
pub(super) const SHORTCUTS: &str = "xtask/tests/shortcuts";

/// The stage's replay packages (`stage::replay`), as cargo's `--exclude`
/// pattern: the course's own code and tests again, built for grading.
pub(super) const REPLAY_PACKAGES: &str = "*-replay";

/// The benchmark crate: built by `cargo xtask bench`, not by the tests.
pub(super) const BENCH_PACKAGE: &str = crate::stage::features::BENCHMARKS;

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
        crate::staff::setup::ensure_xvfb();
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
            Box::new(|| crate::staff::wine::tests_under_wine(root)),
        ),
        (
            "the code that differs between systems is clippy-clean for macOS and Windows",
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
    let mut results: Vec<(&str, Result<String>, Duration, disk::Disk)> = Vec::new();
    for (number, (title, step)) in steps.iter().enumerate() {
        if !only.is_empty() && !only.contains(&(number + 1)) {
            continue;
        }
        println!();
        println!("==> [{}/{}] {title}", number + 1, steps.len());
        let started = Instant::now();
        let result = step();
        let elapsed = started.elapsed();
        let disk = disk::Disk::measure(root);
        let seconds = elapsed.as_secs_f64();
        match &result {
            Ok(summary) => println!("==> ok ({seconds:.1} s; {disk}): {summary}"),
            Err(error) => println!("==> FAILED ({seconds:.1} s; {disk}): {error:#}"),
        }
        results.push((title, result, elapsed, disk));
    }
    println!();
    println!("==> summary");
    let mut failed = 0;
    for (title, result, elapsed, disk) in &results {
        let (status, detail) = match result {
            Ok(summary) => ("ok  ", summary.clone()),
            Err(error) => {
                failed += 1;
                ("FAIL", format!("{error:#}"))
            }
        };
        let detail = detail.lines().next().unwrap_or_default().to_owned();
        println!(
            "  {status}  {:>7.1} s  [{disk}]  {title}: {detail}",
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
    crate::staff::stubs::run(root, true)?;
    Ok("every student file is generated from its solution".to_owned())
}

fn workspace_tests(root: &Path) -> Result<String> {
    let staged = stage::stage(root, Overlay::Reference, None)?;
    // With the stage's features package a member (see `stage::features`),
    // the dependencies get the features every grade of the stage builds
    // them with: the grades that follow find the topics' tests built.
    let tested = cargo::run_visibly(staged.cargo().args([
        "test",
        "--workspace",
        "--no-fail-fast",
        "--exclude",
        BENCH_PACKAGE,
        // The replay builds run only with a record (see `stage::replay`).
        "--exclude",
        REPLAY_PACKAGES,
    ]));
    // The grader's own tests copy fixture courses there, each with a build
    // folder of its own.
    disk::remove_build(
        &staged.target_dir.join("tmp"),
        "the scratch folders of the workspace's tests",
    );
    tested?;
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
        "--exclude",
        REPLAY_PACKAGES,
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

pub(super) fn grade_into(root: &Path, overlay: Overlay<'_>, folder: &str) -> Result<Report> {
    let mut options = GradeOptions::new(root.to_path_buf());
    options.out = root.join("target").join("grade").join(folder);
    let report = grade::grade_staged(&options, overlay)?;
    let reference = matches!(overlay, Overlay::Reference);
    // Every stub fails at its todo!(): the table says enough there.
    grade::print_summary(&report, &options.out, reference);
    Ok(report)
}

/// `items` in rounds, in order, so that no two items of a round `clash`:
/// a round is graded as one submission-like folder.
pub(super) fn rounds<T>(items: &[T], clash: impl Fn(&T, &T) -> bool) -> Vec<Vec<&T>> {
    let mut rounds: Vec<Vec<&T>> = Vec::new();
    for item in items {
        match rounds
            .iter_mut()
            .find(|round| round.iter().all(|other| !clash(other, item)))
        {
            Some(round) => round.push(item),
            None => rounds.push(vec![item]),
        }
    }
    rounds
}

/// Grades items planted a round at a time (made by [`rounds`]):
/// `plant` writes each item of a round into the round's submission-like
/// folder, `target/xtask/<scratch>`, which is graded as a submission of
/// the round's items' tasks (`task`: its topic and task) alone into
/// `target/grade/<out(round number)>`, its summary printed; `check` reads
/// the round's report. Returns how many rounds there were.
pub(super) fn grade_planted<T>(
    root: &Path,
    rounds: &[Vec<&T>],
    task: impl Fn(&T) -> (&str, &str),
    scratch: &str,
    out: impl Fn(usize) -> String,
    mut plant: impl FnMut(&Path, &T) -> Result<()>,
    mut check: impl FnMut(&[&T], &Report),
) -> Result<usize> {
    for (number, round) in rounds.iter().enumerate() {
        let planted = empty_folder(root.join("target").join("xtask").join(scratch))?;
        for item in round {
            plant(&planted, item)?;
        }
        let mut options = GradeOptions::new(root.to_path_buf());
        options.out = root.join("target").join("grade").join(out(number));
        options.tasks = round
            .iter()
            .map(|item| {
                let (topic, task) = task(item);
                (topic.to_owned(), task.to_owned())
            })
            .collect();
        options.topics = options
            .tasks
            .iter()
            .map(|(topic, _)| topic.clone())
            .collect();
        options.topics.sort();
        options.topics.dedup();
        let report = grade::grade_staged(&options, Overlay::Submission(&planted))?;
        grade::print_summary(&report, &options.out, false);
        check(round, &report);
    }
    Ok(rounds.len())
}

/// `folder`, emptied (what an earlier round left there goes).
pub(super) fn empty_folder(folder: PathBuf) -> Result<PathBuf> {
    crate::files::remove_tree(&folder)
        .with_context(|| format!("cannot clear {}", folder.display()))?;
    Ok(folder)
}

/// Runs `command` with its output captured and echoed; returns
/// (success, stdout and stderr).
pub(super) fn run_captured(command: &mut std::process::Command) -> Result<(bool, String)> {
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

/// The last `lines` lines of `text`.
pub(crate) fn tail(text: &str, lines: usize) -> String {
    let all: Vec<&str> = text.lines().collect();
    all[all.len().saturating_sub(lines)..].join("\n")
}
