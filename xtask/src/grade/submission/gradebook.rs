//! The gradebook of a class: one row per submission, as CSV and JSON.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde::Serialize;

use super::Integrity;
use super::report::{self, Report};

/// One row of the gradebook.
#[derive(Debug, Serialize)]
pub(super) struct GradebookRow {
    pub(super) submission: String,
    /// Points of the tasks that are not bonuses.
    score: f64,
    max_score: f64,
    /// Bonus points, apart.
    bonus: f64,
    complete: bool,
    pub(super) flagged: bool,
    integrity: Option<String>,
    /// Per topic, its points (bonus apart).
    topics: Vec<(String, f64)>,
    /// Per task (`topic/task`), its points.
    tasks: Vec<(String, f64)>,
    /// The topics that could not be graded, each with why.
    not_graded: Vec<String>,
    report: PathBuf,
}

impl GradebookRow {
    pub(super) fn new(submission: String, report: &Report, out: &Path) -> Self {
        let integrity = report.integrity.as_ref();
        Self {
            submission,
            score: report::round2(report.topics.iter().map(|t| t.base_score()).sum()),
            max_score: report.max_score,
            bonus: report::round2(report.topics.iter().map(|t| t.bonus().0).sum()),
            complete: report.complete,
            flagged: integrity.is_some_and(Integrity::flagged),
            integrity: integrity.filter(|i| i.flagged()).map(Integrity::summary),
            topics: report
                .topics
                .iter()
                .map(|t| (t.name.clone(), t.base_score()))
                .collect(),
            tasks: report
                .topics
                .iter()
                .flat_map(|t| {
                    t.tasks
                        .iter()
                        .map(move |task| (format!("{}/{}", t.name, task.id), task.score))
                })
                .collect(),
            not_graded: report
                .topics
                .iter()
                .filter_map(|t| {
                    let why = match (&t.compile_error, t.errors.first()) {
                        (Some(_), _) => "does not compile".to_owned(),
                        (None, Some(error)) => error.lines().next().unwrap_or_default().to_owned(),
                        (None, None) => return None,
                    };
                    Some(format!("{}: {why}", t.name))
                })
                .collect(),
            report: out.join("report.html"),
        }
    }
}

/// The gradebook as CSV: one row per submission; columns by name (a
/// member without a topic leaves its cell empty, never shifts the others):
/// the points (bonus apart), then one per topic, one per task, and why a
/// topic was not graded.
pub(super) fn gradebook_csv(rows: &[GradebookRow]) -> String {
    // Every topic and task any member has, in the order first met.
    let mut topics: Vec<&str> = Vec::new();
    let mut tasks: Vec<&str> = Vec::new();
    for row in rows {
        for (name, _) in &row.topics {
            if !topics.contains(&name.as_str()) {
                topics.push(name);
            }
        }
        for (name, _) in &row.tasks {
            if !tasks.contains(&name.as_str()) {
                tasks.push(name);
            }
        }
    }
    let mut csv = String::from("submission,score,max_score,bonus,complete,flagged");
    for column in topics.iter().chain(&tasks) {
        csv.push(',');
        csv.push_str(&csv_field(column));
    }
    csv.push_str(",not_graded\n");
    let cell = |values: &[(String, f64)], column: &str| {
        values
            .iter()
            .find(|(name, _)| name == column)
            .map_or_else(String::new, |(_, score)| report::points(*score))
    };
    for row in rows {
        let _ = write!(
            csv,
            "{},{},{},{},{},{}",
            csv_field(&row.submission),
            report::points(row.score),
            report::points(row.max_score),
            report::points(row.bonus),
            row.complete,
            row.flagged
        );
        for topic in &topics {
            let _ = write!(csv, ",{}", cell(&row.topics, topic));
        }
        for task in &tasks {
            let _ = write!(csv, ",{}", cell(&row.tasks, task));
        }
        let _ = writeln!(csv, ",{}", csv_field(&row.not_graded.join("; ")));
    }
    csv
}

/// A CSV field, quoted when it holds a comma, a quote or a line break.
fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_owned()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gradebook_columns_go_by_name_not_by_position() {
        let row = |name: &str, topics: &[(&str, f64)], tasks: &[(&str, f64)]| GradebookRow {
            submission: name.to_owned(),
            score: topics.iter().map(|t| t.1).sum(),
            max_score: 5.0,
            bonus: 0.0,
            complete: true,
            flagged: false,
            integrity: None,
            topics: topics.iter().map(|(n, s)| ((*n).to_owned(), *s)).collect(),
            tasks: tasks.iter().map(|(n, s)| ((*n).to_owned(), *s)).collect(),
            not_graded: Vec::new(),
            report: PathBuf::new(),
        };
        let mut lacking = row("ben", &[("02-b", 1.0)], &[("02-b/y", 1.0)]);
        lacking.not_graded = vec!["01-a: the submission has no exercises/01-a".to_owned()];
        let csv = gradebook_csv(&[
            row(
                "anna",
                &[("01-a", 2.0), ("02-b", 3.0)],
                &[("01-a/x", 2.0), ("02-b/y", 3.0)],
            ),
            lacking,
        ]);
        assert_eq!(
            csv,
            "submission,score,max_score,bonus,complete,flagged,01-a,02-b,01-a/x,02-b/y,not_graded\n\
             anna,5,5,0,true,false,2,3,2,3,\n\
             ben,1,5,0,true,false,,1,,1,01-a: the submission has no exercises/01-a\n"
        );
    }

    #[test]
    fn csv_fields_are_quoted_only_when_needed() {
        assert_eq!(csv_field("anna"), "anna");
        assert_eq!(csv_field("a,b"), "\"a,b\"");
        assert_eq!(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
    }
}
