//! From finished tests to the report of a topic: each test's verdict
//! ([`super::outcome::judge`]), its pictures, and each task's points.

use std::path::Path;

use super::outcome::{self, Exit};
use super::plan::{Plan, PlannedTest};
use super::report::{self, TaskReport, TaskStatus, TestReport, TestStatus, TopicReport};
use super::run::Finished;

/// The excerpt of a failed test's output kept in the report.
const OUTPUT_EXCERPT_CHARS: usize = 4000;

pub(super) fn topic_report(
    out: &Path,
    plan: &Plan,
    mut finished: impl FnMut(usize) -> Option<Finished>,
) -> TopicReport {
    let topic = &plan.topic;
    let time_limit_s = topic.sheet.time_limit_s;
    let mut tasks: Vec<TaskReport> = topic
        .sheet
        .tasks
        .iter()
        .zip(&plan.task_errors)
        .map(|(task, error)| TaskReport {
            id: task.id.clone(),
            title: task.title.clone(),
            points: task.points,
            bonus: task.bonus,
            score: 0.0,
            status: if plan.compile_error.is_some() {
                TaskStatus::CompileError
            } else if error.is_some() {
                TaskStatus::Error
            } else {
                TaskStatus::Ok
            },
            error: if plan.compile_error.is_some() {
                None
            } else {
                error.clone()
            },
            hints: task.hints.clone(),
            passed: 0,
            failed: 0,
            ignored: 0,
            tests: Vec::new(),
        })
        .collect();
    for (t, test) in plan.tests.iter().enumerate() {
        let task = &mut tasks[test.task];
        let mut report = match finished(t) {
            None => ignored_test(test.name.clone()),
            Some(run) => test_report(out, test, run, time_limit_s),
        };
        if report.exit.timed_out
            && let Some(reason) = &mut report.reason
            && let Some(comment) = test_comment(&topic.dir, &task.id, &report.name)
        {
            reason.push_str(&format!("; the test says: \"{comment}\""));
        }
        task.tests.push(report);
    }
    // What a tutor's review may act on, recorded by the grader itself.
    super::reviewed::record_mismatches(out, topic, &mut tasks);
    for task in &mut tasks {
        super::score::recount(task);
        if task.status == TaskStatus::Ok && task.passed + task.failed == 0 {
            task.status = TaskStatus::Error;
            task.error = Some(format!("all {} tests are #[ignore]d", task.ignored));
        }
    }
    let mut topic = TopicReport {
        name: topic.name.clone(),
        package: topic.package.clone(),
        dir: topic.dir.clone(),
        time_limit_s,
        memory_limit_mib: topic.sheet.memory_limit_mib,
        compile_error: plan.compile_error.clone(),
        errors: plan.errors.clone(),
        score: 0.0,
        max_score: 0.0,
        tasks,
    };
    super::score::topic_totals(&mut topic);
    topic
}

/// The comment that explains a test, from the course's test file of its
/// task (`tests/<task>.rs` in the topic's folder, the grader's copy): the
/// doc comment above `fn <test>` or else the comment that opens its body.
/// A timeout says what the test expected (a line across the whole `i32`
/// range, finished only by a walk that starts at the viewport), where
/// "timed out" alone suggests an endless loop.
fn test_comment(topic_dir: &Path, task: &str, test: &str) -> Option<String> {
    let relative = Path::new("tests").join(format!("{task}.rs"));
    let source = crate::files::read_plain(topic_dir, &relative)?;
    comment_of(&String::from_utf8_lossy(&source), test)
}

/// See [`test_comment`]: at most 400 characters, the lines joined.
fn comment_of(source: &str, test: &str) -> Option<String> {
    let lines: Vec<&str> = source.lines().map(str::trim).collect();
    let signature = format!("fn {test}(");
    let at = lines.iter().position(|line| line.contains(&signature))?;
    let above = lines[..at]
        .iter()
        .rev()
        .skip_while(|line| line.starts_with("#["))
        .map_while(|line| line.strip_prefix("///"))
        .collect::<Vec<_>>();
    let words: Vec<&str> = if above.is_empty() {
        // The body opens on the first line ending in `{` (a signature may
        // run over several lines).
        let body = lines[at..].iter().position(|line| line.ends_with('{'))? + at + 1;
        lines[body..]
            .iter()
            .map_while(|line| line.strip_prefix("//"))
            .collect()
    } else {
        above.into_iter().rev().collect()
    };
    let text = words
        .iter()
        .map(|line| line.trim())
        .collect::<Vec<_>>()
        .join(" ");
    let text = text.trim();
    (!text.is_empty()).then(|| match text.char_indices().nth(400) {
        Some((cut, _)) => format!("{}…", &text[..cut]),
        None => text.to_owned(),
    })
}

fn ignored_test(name: String) -> TestReport {
    TestReport {
        name,
        status: TestStatus::Ignored,
        reason: None,
        panic_location: None,
        minimal_input: None,
        raster_diff: None,
        snapshot_diff: None,
        reviewed: None,
        snapshot_mismatches: Vec::new(),
        duration_s: 0.0,
        exit: Exit::default(),
        output: None,
        log: None,
        images_dir: None,
        images: Vec::new(),
    }
}

fn test_report(out: &Path, test: &PlannedTest, run: Finished, time_limit_s: f64) -> TestReport {
    let verdict = outcome::judge(&run.output, &run.exit, &run.token, time_limit_s);
    let status = if verdict.passed {
        TestStatus::Passed
    } else {
        TestStatus::Failed
    };
    // Never following a link, never without end: the folder is the test's.
    let images = crate::files::listing(&test.images_dir);
    let ran = !run.exit.not_run;
    let relative = |path: &Path| {
        path.strip_prefix(out)
            .map_or_else(|_| path.to_path_buf(), Path::to_path_buf)
    };
    TestReport {
        name: test.name.clone(),
        status,
        reason: verdict.reason,
        panic_location: verdict.panic_location,
        minimal_input: verdict.minimal_input,
        raster_diff: verdict.raster_diff,
        snapshot_diff: verdict.snapshot_diff,
        reviewed: None,
        snapshot_mismatches: Vec::new(),
        duration_s: report::round2(run.duration.as_secs_f64()),
        exit: run.exit,
        output: (status == TestStatus::Failed).then(|| match &run.evidence {
            None => excerpt(&run.output),
            Some(evidence) => format!("{}\n{}", excerpt(&run.output), excerpt(evidence)),
        }),
        log: test
            .command
            .as_ref()
            .filter(|_| ran)
            .map(|command| relative(&command.log)),
        images_dir: (!images.is_empty()).then(|| relative(&test.images_dir)),
        images,
    }
}

/// The end of a long output, cut at a line start.
fn excerpt(output: &str) -> String {
    let output = output.trim();
    if output.len() <= OUTPUT_EXCERPT_CHARS {
        return output.to_owned();
    }
    let mut start = output.len() - OUTPUT_EXCERPT_CHARS;
    while !output.is_char_boundary(start) {
        start += 1;
    }
    let start = output[start..]
        .find('\n')
        .map_or(start, |nl| start + nl + 1);
    format!("[... {} bytes cut ...]\n{}", start, &output[start..])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn excerpt_keeps_the_end_from_a_line_start() {
        let long = format!("{}\nlast line", "x".repeat(OUTPUT_EXCERPT_CHARS));
        let cut = excerpt(&long);
        assert!(cut.starts_with("[... "), "{cut}");
        assert!(cut.ends_with("\nlast line"), "{cut}");
        assert_eq!(excerpt(" short \n"), "short");
    }
}

#[cfg(test)]
mod comment_tests {
    use super::comment_of;

    const SOURCE: &str = "
/// A line across the whole range:
/// only a walk from the viewport ends.
#[testkit::test]
fn documented() {
    assert!(true);
}

#[testkit::test]
fn commented() {
    // Billions of columns: only an implementation that starts at the
    // viewport finishes within the time limit.
    let x = 1;
}

proptest! {
    #[testkit::test]
    fn property(a in 0..3,
    ) {
        // Each case small.
    }
}

#[testkit::test]
fn silent() {
    let x = 1; // not an opening comment
}
";

    #[test]
    fn a_tests_doc_comment_or_opening_comment_is_found() {
        assert_eq!(
            comment_of(SOURCE, "documented").as_deref(),
            Some("A line across the whole range: only a walk from the viewport ends.")
        );
        assert_eq!(
            comment_of(SOURCE, "commented").as_deref(),
            Some(
                "Billions of columns: only an implementation that starts at the viewport \
                 finishes within the time limit."
            )
        );
        assert_eq!(
            comment_of(SOURCE, "property").as_deref(),
            Some("Each case small.")
        );
        assert_eq!(comment_of(SOURCE, "silent"), None);
        assert_eq!(comment_of(SOURCE, "absent"), None);
    }
}
