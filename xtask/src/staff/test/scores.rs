//! What the grader pays (steps 4, 5 and 7): the solutions full points,
//! the untouched stubs and a do-nothing edition nothing, and the snapshot
//! review of the diffs the do-nothing edition leaves.

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail, ensure};

use crate::grade::TaskStatus;
use crate::grade::report::TestStatus;
use crate::stage::{self, Overlay, TaskTexts};

use super::browser::report_in_chromium;
use super::edition::error_lines;
use super::{grade_into, run_captured, tail};

pub(super) fn reference_scores_full(root: &Path) -> Result<String> {
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

pub(super) fn stubs_score_zero(root: &Path) -> Result<String> {
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

/// The task files of the do-nothing edition: each `todo!()` replaced by
/// the cheapest body that compiles (`staff::stubs::do_nothing`), except on
/// the lines listed per task file.
fn do_nothing_edition(root: &Path, keep: &BTreeMap<PathBuf, Vec<usize>>) -> Result<TaskTexts> {
    stage::task_files(root)?
        .into_iter()
        .map(|task_file| {
            let path = root.join(&task_file);
            let stub = fs::read_to_string(&path)
                .with_context(|| format!("cannot read {}", path.display()))?;
            let lines = keep.get(&task_file).map_or(&[][..], Vec::as_slice);
            let (text, _) = crate::staff::stubs::do_nothing(&stub, lines);
            Ok((task_file, text))
        })
        .collect()
}

/// A do-nothing edition (every `todo!()` replaced by the cheapest body
/// that compiles) scores 0 on every task: no test pays for doing nothing.
pub(super) fn do_nothing_scores_zero(root: &Path) -> Result<String> {
    // A body that does not compile (a return type without `Default`) keeps
    // its `todo!()`: the errors name the lines, a few rounds at most.
    let mut keep: BTreeMap<PathBuf, Vec<usize>> = BTreeMap::new();
    let mut texts = TaskTexts::new();
    for round in 1.. {
        texts = do_nothing_edition(root, &keep)?;
        let staged = stage::stage(root, Overlay::Texts(&texts), None)?;
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
    let report = grade_into(root, Overlay::Texts(&texts), "do-nothing")?;
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
pub(super) fn snapshots_review(root: &Path, graded: &Path) -> Result<String> {
    let official = |review: &crate::staff::review::Review| -> Vec<Option<Vec<u8>>> {
        review
            .pending
            .iter()
            .map(|file| fs::read(root.join(file.with_extension(""))).ok())
            .collect()
    };
    let Some(review) = crate::staff::review::Review::prepare(root, graded)? else {
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
