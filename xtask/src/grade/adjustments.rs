//! What the grader decided about the graded code besides the outcomes of
//! its tests — a topic refused before it was built, a topic the
//! submission does not hold, task files it could not read, official files
//! its tests changed — and the folder the report names. They are applied
//! to the topics once, when the report is made ([`crate::grade::Graded`]),
//! before its totals are summed: a report is never changed after it is
//! made.

use std::path::PathBuf;

use super::report::{TaskStatus, TopicReport};
use super::submission::{Integrity, slashed};

/// The grader's decisions beyond the tests' outcomes (none by default: a
/// student's own grade).
#[derive(Debug, Default)]
pub(crate) struct Adjustments {
    /// The folder the report names as the one graded (the checkout, or the
    /// submission) rather than the stage its tests ran in.
    pub shown_root: Option<PathBuf>,
    /// Topics not compiled because their task files reach other files at
    /// compile time, each with the uses found (see `forbidden`).
    pub refused: Vec<(String, Vec<String>)>,
    /// Errors of a topic, by topic name: its folder is missing from the
    /// submission, or a task file could not be read.
    pub topic_errors: Vec<(String, String)>,
    /// Official files (or files of the stage) its tests changed while
    /// they ran: every task scores 0.
    pub tampered: Vec<PathBuf>,
    /// How the submission's grading files compare with the official ones.
    pub integrity: Option<Integrity>,
}

impl Adjustments {
    /// Applies them to `topics`: refused topics lose their tests, errors
    /// are added, and a submission whose tests tampered scores 0.
    pub(crate) fn apply(&self, topics: &mut [TopicReport]) {
        for (name, uses) in &self.refused {
            if let Some(topic) = topics.iter_mut().find(|t| t.name == *name) {
                refuse(topic, uses);
            }
        }
        for (name, error) in &self.topic_errors {
            if let Some(topic) = topics.iter_mut().find(|t| t.name == *name) {
                topic.errors.push(error.clone());
            }
        }
        if !self.tampered.is_empty() {
            let reason = tampering_reason(&self.tampered);
            for topic in topics {
                topic.errors.push(reason.clone());
                for task in &mut topic.tasks {
                    task.score = 0.0;
                }
            }
        }
    }
}

/// A topic not compiled for `uses` of what task code may not do: each
/// task a compile error, with no tests.
fn refuse(topic: &mut TopicReport, uses: &[String]) {
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
}

/// Why a submission whose tests changed `files` scores 0 (the first five
/// named).
fn tampering_reason(files: &[PathBuf]) -> String {
    let shown: Vec<String> = files.iter().take(5).map(|f| slashed(f)).collect();
    format!(
        "scored 0: its tests changed official files while grading ({}{})",
        shown.join(", "),
        if files.len() > shown.len() {
            ", ..."
        } else {
            ""
        }
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grade::report::TestStatus;
    use crate::grade::report::tests::{report_of, test};

    /// One topic, `01-x`, with one task of 4 points whose two tests passed.
    fn topics() -> Vec<TopicReport> {
        let tests = vec![test("a", TestStatus::Passed), test("b", TestStatus::Passed)];
        report_of(4.0, tests).topics
    }

    #[test]
    fn none_change_nothing() {
        let mut adjusted = topics();
        Adjustments::default().apply(&mut adjusted);
        let json = |topics: &[TopicReport]| serde_json::to_value(topics).unwrap();
        assert_eq!(json(&adjusted), json(&topics()));
    }

    #[test]
    fn a_refused_topic_is_not_compiled_and_its_tests_are_gone() {
        let mut adjusted = topics();
        Adjustments {
            refused: vec![("01-x".into(), vec!["src/a.rs:3: include_str!".into()])],
            ..Adjustments::default()
        }
        .apply(&mut adjusted);
        let task = &adjusted[0].tasks[0];
        assert_eq!(
            (task.status, task.score, task.tests.len(), task.passed),
            (TaskStatus::CompileError, 0.0, 0, 0)
        );
        let error = adjusted[0].compile_error.as_deref().unwrap();
        assert!(error.contains("include_str!"), "{error}");
    }

    #[test]
    fn tampering_scores_every_task_zero_and_names_the_files() {
        let mut adjusted = topics();
        Adjustments {
            tampered: vec![PathBuf::from("exercises/01-x/tests/a.rs")],
            topic_errors: vec![("01-x".into(), "a task file could not be read".into())],
            ..Adjustments::default()
        }
        .apply(&mut adjusted);
        assert_eq!(adjusted[0].tasks[0].score, 0.0);
        assert_eq!(adjusted[0].errors.len(), 2, "{:?}", adjusted[0].errors);
        assert!(adjusted[0].errors[1].contains("exercises/01-x/tests/a.rs"));
    }
}
