//! `cargo xtask test`: the project's own test command, proving what the
//! course promises (DESIGN.md, property 2):
//!
//! 1. the student stubs are exactly what `reference/` generates;
//! 2. every workspace test passes against the reference solutions;
//! 3. graded with `--reference`, every task gets full points;
//! 4. graded as shipped (the stubs), the course scores 0, compiles and the
//!    grader finishes.
//!
//! Every step runs even when an earlier one failed, so that one CI log
//! shows everything that is wrong.

use std::path::Path;
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail, ensure};

use crate::cargo::{self, cargo};
use crate::grade::{self, GradeOptions, Report, TaskStatus, TestStatus};
use crate::{setup, stubs, topics};

/// The benchmark crate: built by `cargo xtask bench`, not by the tests.
const BENCH_PACKAGE: &str = "course-bench";

/// Runs the four steps and prints a summary; fails if any step failed.
pub fn run(root: &Path) -> Result<()> {
    // GPU topics need a Vulkan driver; an error in the topics themselves
    // is reported by the steps below.
    if topics::discover(root).is_ok_and(|topics| topics.iter().any(|t| t.sheet.gpu)) {
        setup::ensure_vulkan();
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
            "reference solutions score full points",
            Box::new(|| reference_scores_full(root)),
        ),
        (
            "untouched stubs compile, score 0 and the grader finishes",
            Box::new(|| stubs_score_zero(root)),
        ),
    ];
    let mut results: Vec<(&str, Result<String>, Duration)> = Vec::new();
    for (number, (title, step)) in steps.iter().enumerate() {
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
    let topics = topics::discover(root)?;
    let features: Vec<String> = topics
        .iter()
        .map(|t| format!("{}/reference", t.package))
        .collect();
    let mut command = cargo();
    command.current_dir(root).args([
        "test",
        "--workspace",
        "--no-fail-fast",
        "--exclude",
        BENCH_PACKAGE,
    ]);
    if !features.is_empty() {
        command.args(["--features", &features.join(",")]);
    }
    println!("$ {}", cargo::display(&command));
    let status = command
        .status()
        .with_context(|| format!("cannot run `{}`", cargo::display(&command)))?;
    ensure!(
        status.success(),
        "`{}` failed ({status})",
        cargo::display(&command)
    );
    Ok(format!(
        "all tests pass with {}",
        if features.is_empty() {
            "no topics".to_owned()
        } else {
            features.join(", ")
        }
    ))
}

fn grade_into(root: &Path, reference: bool, folder: &str) -> Result<Report> {
    let mut options = GradeOptions::new(root.to_path_buf());
    options.reference = reference;
    options.out = root.join("target").join("grade").join(folder);
    let report = grade::grade(&options)?;
    // Every stub fails at its todo!(): the table says enough there.
    grade::print_summary(&report, &options.out, reference);
    Ok(report)
}

fn reference_scores_full(root: &Path) -> Result<String> {
    let report = grade_into(root, true, "reference")?;
    let mut problems = Vec::new();
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
    let tests: usize = report
        .topics
        .iter()
        .flat_map(|t| &t.tasks)
        .map(|t| t.passed)
        .sum();
    Ok(format!(
        "{} of {} points, {tests} tests passed",
        report.score, report.max_score
    ))
}

fn stubs_score_zero(root: &Path) -> Result<String> {
    let report = grade_into(root, false, "stubs")?;
    let mut problems = Vec::new();
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
