//! Gradescope's `results.json`, the autograder's output format: one test
//! entry per task, with its points and its summary.

use std::fmt::Write as _;

use serde::Serialize;

use super::report::{self, Report, TaskStatus};

/// Gradescope's `results.json`: one entry per task, and a failed entry
/// worth no points when the submission is flagged, so that the flag shows
/// in Gradescope's list of tests and not only in its text.
#[derive(Debug, Serialize)]
pub struct Gradescope {
    score: f64,
    max_score: f64,
    /// Seconds the grading took.
    execution_time: f64,
    /// Shown to the student at once (Gradescope can hold results back
    /// until the due date: set it there, per assignment).
    visibility: &'static str,
    output: String,
    tests: Vec<GradescopeTest>,
    /// Kept by Gradescope with the result, for scripts.
    extra_data: GradescopeExtra,
}

#[derive(Debug, Serialize)]
struct GradescopeExtra {
    submission: String,
    flagged: bool,
    sandboxed: bool,
}

#[derive(Debug, Serialize)]
struct GradescopeTest {
    name: String,
    score: f64,
    max_score: f64,
    status: &'static str,
    visibility: &'static str,
    output: String,
}

/// The report in Gradescope's shape.
#[must_use]
pub fn gradescope(report: &Report) -> Gradescope {
    let mut output = format!(
        "{}: {} of {} points; {} edition",
        report.name(),
        report::points(report.score),
        report::points(report.max_score),
        match report.edition {
            report::Edition::Student => "student",
            report::Edition::Reference => "reference",
        }
    );
    if let Some(integrity) = report.integrity.as_ref().filter(|i| i.flagged()) {
        let _ = write!(output, "\nFLAGGED: {}", integrity.summary());
    }
    let mut tests = Vec::new();
    let flagged = report.integrity.as_ref().filter(|i| i.flagged());
    if let Some(integrity) = flagged {
        tests.push(GradescopeTest {
            name: "Integrity: grading files differ from the course (flagged)".to_owned(),
            score: 0.0,
            max_score: 0.0,
            status: "failed",
            visibility: "visible",
            output: integrity.summary(),
        });
    }
    if !report.sandboxed {
        let _ = write!(output, "\nunsandboxed: the tests ran without bubblewrap");
    }
    if let Some(note) = report.containment.on_purpose_note(report.sandboxed) {
        let _ = write!(output, "\n{note}");
    }
    for topic in &report.topics {
        for error in &topic.errors {
            let _ = write!(output, "\n{}: {error}", topic.name);
        }
        for task in &topic.tasks {
            tests.push(GradescopeTest {
                name: format!("{} / {}: {}", topic.name, task.id, task.title),
                score: task.score,
                max_score: task.max_score(),
                status: if task.status == TaskStatus::Ok {
                    "passed"
                } else {
                    "failed"
                },
                visibility: "visible",
                output: task.summary(topic),
            });
        }
    }
    Gradescope {
        score: report.score,
        max_score: report.max_score,
        execution_time: report::round2(report.duration_s),
        visibility: "visible",
        output,
        extra_data: GradescopeExtra {
            submission: report.name(),
            flagged: flagged.is_some(),
            sandboxed: report.sandboxed,
        },
        tests,
    }
}
