//! GitHub Classroom's per-task results: what its grading reporter
//! (`classroom-resources/autograding-grading-reporter`) reads, one file a
//! task, `classroom/<step id>.json` beside the grader's other reports, in
//! the shape `classroom-resources/autograding-command-grader` gives its
//! `result` output (there base64-encoded, which the workflow does), but
//! with the task's partial score: the reporter adds up the tests' scores.
//! The workflow that reads them is the staff's to write (`cargo xtask
//! release --classroom`).

use serde::Serialize;

use crate::grade::report::{Report, TaskStatus};

/// The workflow's step id of a task, also the name of its result file:
/// `task-01-lines-dda`.
#[must_use]
pub fn step_id(topic: &str, task: &str) -> String {
    format!("task-{topic}-{task}")
}

/// One task's result in the reporter's shape.
#[derive(Debug, Serialize)]
pub struct TaskResult {
    version: u32,
    status: &'static str,
    /// The task's points; 0 for a bonus, which Classroom's total (that
    /// knows no bonus) then leaves out.
    max_score: f64,
    tests: Vec<TaskTest>,
}

#[derive(Debug, Serialize)]
struct TaskTest {
    name: String,
    status: &'static str,
    score: f64,
    message: String,
    test_code: String,
    filename: String,
    line_no: u32,
    duration: u64,
}

/// The results of every task in `report`, with their step ids.
#[must_use]
pub fn results(report: &Report) -> Vec<(String, TaskResult)> {
    let mut results = Vec::new();
    for topic in &report.topics {
        for task in &topic.tasks {
            let status = match task.status {
                TaskStatus::Ok => "pass",
                TaskStatus::Fail | TaskStatus::CompileError => "fail",
                TaskStatus::Error => "error",
            };
            let tests = task.passed + task.failed;
            results.push((
                step_id(&topic.name, &task.id),
                TaskResult {
                    version: 1,
                    status,
                    max_score: task.max_score(),
                    tests: vec![TaskTest {
                        name: format!(
                            "{} / {}: {} ({} of {tests} tests passed)",
                            topic.name, task.id, task.title, task.passed
                        ),
                        status,
                        score: task.score,
                        message: task.summary(topic),
                        test_code: format!("cargo xtask grade {}", topic.name),
                        filename: String::new(),
                        line_no: 0,
                        duration: 0,
                    }],
                },
            ));
        }
    }
    results
}
