//! The formula of a grade, written once: a task's points are shared
//! equally by its tests that count (passed or failed; an ignored test does
//! not), a topic's score is the sum of its tasks' and a report's the sum
//! of its topics'. Every place that decides or changes a grade — the
//! verdicts, a tutor's review, a refused or tampered submission — sets the
//! tasks and then asks for the sums here.

use super::report::{Report, TaskReport, TaskStatus, TestStatus, TopicReport, round2};

/// The score of a task worth `points` of whose `counted` tests `passed`
/// passed; 0 when none counts.
#[must_use]
pub fn task_score(points: f64, passed: usize, counted: usize) -> f64 {
    if counted == 0 {
        0.0
    } else {
        round2(points * passed as f64 / counted as f64)
    }
}

/// Counts a task's tests again and, for a task whose tests ran (status ok
/// or failed), sets its status and score from them; a task that did not
/// compile, or whose tests could not run, keeps its status and score.
pub fn recount(task: &mut TaskReport) {
    let count = |status| task.tests.iter().filter(|t| t.status == status).count();
    (task.passed, task.failed, task.ignored) = (
        count(TestStatus::Passed),
        count(TestStatus::Failed),
        count(TestStatus::Ignored),
    );
    if matches!(task.status, TaskStatus::Ok | TaskStatus::Fail) {
        task.score = task_score(task.points, task.passed, task.passed + task.failed);
        task.status = if task.failed > 0 {
            TaskStatus::Fail
        } else {
            TaskStatus::Ok
        };
    }
}

/// A topic's score and maximum from its tasks (bonus tasks count in the
/// score, not in the maximum).
pub fn topic_totals(topic: &mut TopicReport) {
    topic.score = round2(topic.tasks.iter().map(|t| t.score).sum());
    topic.max_score = round2(topic.tasks.iter().map(TaskReport::max_score).sum());
}

/// Every topic's totals, then the report's from its topics.
pub fn totals(report: &mut Report) {
    for topic in &mut report.topics {
        topic_totals(topic);
    }
    report.score = round2(report.topics.iter().map(|t| t.score).sum());
    report.max_score = round2(report.topics.iter().map(|t| t.max_score).sum());
}

#[cfg(test)]
mod tests {
    use super::task_score;

    #[test]
    fn a_tasks_points_are_shared_by_the_tests_that_count() {
        assert_eq!(task_score(4.0, 6, 8), 3.0);
        assert_eq!(task_score(3.0, 1, 3), 1.0);
        assert_eq!(task_score(2.0, 2, 3), 1.33);
        assert_eq!(task_score(5.0, 0, 0), 0.0);
        assert_eq!(task_score(5.0, 0, 7), 0.0);
    }
}
