//! The report files: `report.json` (ours), `results.json` (Gradescope's
//! autograder format), `junit.xml` (for CI test viewers), `report.html`
//! (for people: see [`super::html`]) and `classroom/<task>.json` (GitHub
//! Classroom's, see [`crate::classroom`]).

use std::fmt::Write as _;
use std::fs;
use std::path::Path;

use anyhow::{Context, Result};
use serde::Serialize;

use super::report::{self, Report, TaskReport, TaskStatus, TestStatus, TopicReport};

/// Writes all the files into `out`.
pub fn write_all(report: &Report, out: &Path) -> Result<()> {
    let write = |name: &str, contents: String| {
        let path = out.join(name);
        fs::write(&path, contents).with_context(|| format!("cannot write {}", path.display()))
    };
    write(
        "report.json",
        serde_json::to_string_pretty(report).context("cannot serialise the report")?,
    )?;
    write(
        "results.json",
        serde_json::to_string_pretty(&gradescope(report))
            .context("cannot serialise results.json")?,
    )?;
    write("junit.xml", junit(report))?;
    write("report.html", super::html::page(report))?;
    let classroom = out.join("classroom");
    fs::create_dir_all(&classroom)
        .with_context(|| format!("cannot create {}", classroom.display()))?;
    for (id, result) in crate::classroom::results(report) {
        write(
            &format!("classroom/{id}.json"),
            serde_json::to_string_pretty(&result).context("cannot serialise a task's result")?,
        )?;
    }
    Ok(())
}

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
                output: task_summary(topic, task),
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

/// A task's result in plain text: counts, then the first failure.
pub fn task_summary(topic: &TopicReport, task: &TaskReport) -> String {
    let mut text = String::new();
    match task.status {
        TaskStatus::CompileError => {
            let _ = write!(
                text,
                "compile error:\n{}",
                topic.compile_error.as_deref().unwrap_or_default()
            );
        }
        TaskStatus::Error => {
            let _ = write!(
                text,
                "not graded: {}",
                task.error.as_deref().unwrap_or_default()
            );
        }
        TaskStatus::Ok | TaskStatus::Fail => {
            let _ = write!(
                text,
                "{} of {} tests passed",
                task.passed,
                task.passed + task.failed
            );
            if task.ignored > 0 {
                let _ = write!(text, " ({} ignored)", task.ignored);
            }
        }
    }
    if let Some(test) = task.first_failure() {
        let _ = write!(text, "\n\nfirst failing test: {}", test.name);
        if let Some(reason) = &test.reason {
            let _ = write!(text, "\nreason: {reason}");
        }
        if let Some(location) = &test.panic_location {
            let _ = write!(text, "\nat: {location}");
        }
        if let Some(input) = &test.minimal_input {
            let _ = write!(text, "\nminimal failing input: {input}");
        }
        if let Some(diff) = &test.raster_diff {
            let _ = write!(text, "\nraster diff (expected vs yours):\n{diff}");
        }
        if let Some(diff) = &test.snapshot_diff {
            let _ = write!(text, "\nsnapshot diff (- expected, + yours):\n{diff}");
        }
        let others = task.failed - 1;
        if others > 0 {
            let _ = write!(text, "\n\n{others} other test(s) of this task failed too");
        }
        if !task.hints.is_empty() {
            let _ = write!(
                text,
                "\nhints: `cargo xtask hint {}/{}` ({} of them, one more each time)",
                topic.name,
                task.id,
                task.hints.len()
            );
        }
    }
    text
}

/// Escapes text for an XML 1.0 attribute value: markup, quotes and line
/// breaks (which attribute normalisation would otherwise turn into spaces).
#[must_use]
pub fn xml_attr(text: &str) -> String {
    escape(text, true)
}

/// Escapes text for XML 1.0 element content; line breaks stay.
#[must_use]
pub fn xml_text(text: &str) -> String {
    escape(text, false)
}

/// Characters XML 1.0 cannot hold at all (control characters such as the
/// ESC of ANSI colours) become `?`.
fn escape(text: &str, attribute: bool) -> String {
    let mut escaped = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => escaped.push_str("&amp;"),
            '<' => escaped.push_str("&lt;"),
            '>' => escaped.push_str("&gt;"),
            '"' => escaped.push_str("&quot;"),
            '\'' => escaped.push_str("&apos;"),
            '\n' if attribute => escaped.push_str("&#10;"),
            '\r' if attribute => escaped.push_str("&#13;"),
            '\t' if attribute => escaped.push_str("&#9;"),
            '\n' | '\r' | '\t' => escaped.push(c),
            c if (c as u32) < 0x20 || matches!(c, '\u{fffe}' | '\u{ffff}') => escaped.push('?'),
            c => escaped.push(c),
        }
    }
    escaped
}

/// One `<testsuite>` per topic, one `<testcase>` per test; a topic that did
/// not compile has one errored case per task.
#[must_use]
pub fn junit(report: &Report) -> String {
    let mut suites = String::new();
    let (mut all_tests, mut all_failures, mut all_errors) = (0, 0, 0);
    for topic in &report.topics {
        let mut cases = String::new();
        let (mut tests, mut failures, mut errors, mut skipped) = (0, 0, 0, 0);
        let mut time = 0.0;
        let mut case = |class: &str, name: &str, time: f64, body: &str| {
            let _ = write!(
                cases,
                "    <testcase classname=\"{}\" name=\"{}\" time=\"{time:.3}\"",
                xml_attr(class),
                xml_attr(name)
            );
            if body.is_empty() {
                cases.push_str("/>\n");
            } else {
                let _ = write!(cases, ">\n{body}    </testcase>\n");
            }
        };
        for error in &topic.errors {
            tests += 1;
            errors += 1;
            let body = format!(
                "      <error message=\"{}\" type=\"test layout\"/>\n",
                xml_attr(error)
            );
            case(&topic.name, "test layout", 0.0, &body);
        }
        for task in &topic.tasks {
            let class = format!("{}.{}", topic.name, task.id);
            let not_graded = match task.status {
                TaskStatus::CompileError => Some((
                    "compile error",
                    topic.compile_error.as_deref().unwrap_or_default(),
                )),
                TaskStatus::Error => {
                    Some(("not graded", task.error.as_deref().unwrap_or_default()))
                }
                TaskStatus::Ok | TaskStatus::Fail => None,
            };
            if let Some((message, details)) = not_graded {
                tests += 1;
                errors += 1;
                let body = format!(
                    "      <error message=\"{}\" type=\"{message}\">{}</error>\n",
                    xml_attr(&format!(
                        "{message}: {}",
                        details.lines().next().unwrap_or_default()
                    )),
                    xml_text(details)
                );
                case(&class, &task.id, 0.0, &body);
            }
            for test in &task.tests {
                tests += 1;
                time += test.duration_s;
                let body = match test.status {
                    TestStatus::Passed => String::new(),
                    TestStatus::Ignored => {
                        skipped += 1;
                        "      <skipped/>\n".to_owned()
                    }
                    TestStatus::Failed => {
                        failures += 1;
                        let reason = test.reason.as_deref().unwrap_or("failed");
                        format!(
                            "      <failure message=\"{}\" type=\"{}\">{}</failure>\n      <system-out>{}</system-out>\n",
                            xml_attr(reason),
                            xml_attr(reason.split(':').next().unwrap_or("failed")),
                            xml_text(&failure_details(test)),
                            xml_text(test.output.as_deref().unwrap_or_default())
                        )
                    }
                };
                case(&class, &test.name, test.duration_s, &body);
            }
        }
        let _ = write!(
            suites,
            "  <testsuite name=\"{}\" tests=\"{tests}\" failures=\"{failures}\" errors=\"{errors}\" skipped=\"{skipped}\" time=\"{time:.3}\">\n{cases}  </testsuite>\n",
            xml_attr(&topic.name)
        );
        all_tests += tests;
        all_failures += failures;
        all_errors += errors;
    }
    format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"cargo xtask grade\" tests=\"{all_tests}\" failures=\"{all_failures}\" errors=\"{all_errors}\" time=\"{:.3}\">\n{suites}</testsuites>\n",
        report.duration_s
    )
}

fn failure_details(test: &report::TestReport) -> String {
    let mut text = test.reason.clone().unwrap_or_default();
    if let Some(location) = &test.panic_location {
        let _ = write!(text, "\nat {location}");
    }
    if let Some(input) = &test.minimal_input {
        let _ = write!(text, "\nminimal failing input: {input}");
    }
    if let Some(diff) = &test.raster_diff {
        let _ = write!(text, "\nraster diff (expected vs yours):\n{diff}");
    }
    if let Some(diff) = &test.snapshot_diff {
        let _ = write!(text, "\nsnapshot diff (- expected, + yours):\n{diff}");
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn xml_escape_handles_markup_quotes_and_control_characters() {
        assert_eq!(
            xml_attr("a<b & \"c\" 'd'>\n\x1b[31m"),
            "a&lt;b &amp; &quot;c&quot; &apos;d&apos;&gt;&#10;?[31m"
        );
        assert_eq!(xml_text("x < y\n\tz\u{0}"), "x &lt; y\n\tz?");
    }
}
