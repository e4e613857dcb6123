//! What a tutor's review of the snapshots changes in a grade: a test that
//! failed only because its snapshot differs from the course's passes when
//! the tutor accepted that snapshot (`cargo xtask review`), and its task
//! gets its share of the points back, marked as reviewed in every report.
//!
//! The verdicts are applied to the grade as it came from the tests: a
//! review done again first takes back what an earlier one gave, so a
//! snapshot accepted and then rejected scores as it did before. A
//! submission whose tests changed the course's files scores 0 whatever
//! the review says.

use super::report::{self, Report, TaskStatus, TestStatus};

/// The snapshot a failed test's reason says it does not match (the
/// grader's own words, see `outcome`), if that is why it failed.
fn mismatched_snapshot(reason: &str) -> Option<&str> {
    let (_, rest) = reason.split_once(" does not match ")?;
    rest.split_whitespace().next()
}

/// Applies the review's verdicts to `report`: `accepted` are the official
/// snapshots' paths (as `review.json` names them) the tutor found the
/// student's right. Returns how many tests pass by review.
pub fn apply(report: &mut Report, accepted: &[String]) -> usize {
    let tampered = report
        .integrity
        .as_ref()
        .is_some_and(|i| !i.tampered.is_empty());
    let mut passing = 0;
    for topic in &mut report.topics {
        for task in &mut topic.tasks {
            for test in &mut task.tests {
                if test.reviewed.take().is_some() {
                    test.status = TestStatus::Failed;
                }
                let snapshot = test
                    .reason
                    .as_deref()
                    .and_then(mismatched_snapshot)
                    .filter(|s| accepted.iter().any(|a| a == s));
                if let Some(snapshot) = snapshot
                    && test.status == TestStatus::Failed
                    && !tampered
                {
                    test.status = TestStatus::Passed;
                    test.reviewed = Some(snapshot.to_owned());
                    passing += 1;
                }
            }
            task.passed = task
                .tests
                .iter()
                .filter(|t| t.status == TestStatus::Passed)
                .count();
            task.failed = task
                .tests
                .iter()
                .filter(|t| t.status == TestStatus::Failed)
                .count();
            let counted = task.passed + task.failed;
            if matches!(task.status, TaskStatus::Ok | TaskStatus::Fail) && counted > 0 && !tampered
            {
                task.score = report::round2(task.points * task.passed as f64 / counted as f64);
                task.status = if task.failed > 0 {
                    TaskStatus::Fail
                } else {
                    TaskStatus::Ok
                };
            }
        }
        topic.score = report::round2(topic.tasks.iter().map(|t| t.score).sum());
    }
    report.score = report::round2(report.topics.iter().map(|t| t.score).sum());
    passing
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grade::report::tests::{report_of, test};

    const SNAP: &str = "exercises/01-lines/tests/snapshots/midpoint__octants.snap";

    fn mismatch(name: &str) -> crate::grade::report::TestReport {
        let mut failed = test(name, TestStatus::Failed);
        failed.reason = Some(format!(
            "snapshot 'octants' does not match {SNAP} (yours is the .snap.new at the same path under the report's snapshots/)"
        ));
        failed
    }

    #[test]
    fn an_accepted_snapshot_gives_its_test_back_and_a_rejected_one_takes_it_again() {
        let tests = vec![
            test("a", TestStatus::Passed),
            mismatch("octants"),
            test("b", TestStatus::Failed),
            test("c", TestStatus::Passed),
        ];
        let mut report = report_of(4.0, tests);
        assert_eq!(report.score, 2.0);
        assert_eq!(apply(&mut report, &[SNAP.to_owned()]), 1);
        let task = &report.topics[0].tasks[0];
        assert_eq!((task.passed, task.failed, task.score), (3, 1, 3.0));
        assert_eq!(task.tests[1].reviewed.as_deref(), Some(SNAP));
        assert_eq!((report.topics[0].score, report.score), (3.0, 3.0));
        // Another snapshot accepted: this one is failed again.
        assert_eq!(apply(&mut report, &["other.snap".to_owned()]), 0);
        let task = &report.topics[0].tasks[0];
        assert_eq!((task.passed, task.failed, task.score), (2, 2, 2.0));
        assert_eq!(task.tests[1].status, TestStatus::Failed);
        assert_eq!(report.score, 2.0);
    }

    #[test]
    fn a_submission_that_tampered_gets_nothing_back() {
        let mut report = report_of(
            4.0,
            vec![mismatch("octants"), test("a", TestStatus::Failed)],
        );
        report.topics[0].tasks[0].score = 0.0;
        report.integrity = Some(crate::grade::submission::Integrity {
            tampered: vec!["exercises/01-lines/tests/dda.rs".into()],
            ..Default::default()
        });
        assert_eq!(apply(&mut report, &[SNAP.to_owned()]), 0);
        assert_eq!(report.topics[0].tasks[0].score, 0.0);
    }
}
