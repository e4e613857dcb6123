//! `class.html` and `class.json`: the class report of `cargo xtask grade
//! --submission CLASS`, written beside the gradebook for a tutor of many
//! students. It shows, per task, how the points are spread over the class
//! (a histogram drawn as inline SVG), how many members have full marks
//! and the mean; the failures that most members hit, each with links to
//! their `report.html`; each member's row of the gradebook; and the
//! submissions that could not be graded, with why. One page with no
//! script and nothing outside it, linked relative to the grade folder, so
//! that the folder can be zipped and mailed.
//!
//! ```text
//! Class { schema, class, graded, not_graded, mean_score, median_score, max_score,
//!         flagged, incomplete,
//!   tasks: [TaskStats { topic, task, title, points, bonus, members, mean,
//!                       full_marks, full_share, histogram: [Bin { from, to, count }] }],
//!   failures: [Failure { topic, task, test, reason, count, members: [Link] }],
//!   members: [Member { name, report, score, max_score, bonus, complete, flagged,
//!                      flag, not_graded }],
//!   ungraded: [Ungraded { name, why }] }
//! ```

use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use serde::Serialize;

use super::gradebook::GradebookRow;
use crate::grade::report::{self, Report, TaskReport, TaskStatus, TestStatus};

mod page;
#[cfg(test)]
mod tests;

use page::page;

/// Version of the `class.json` layout; bumped when a field changes meaning.
pub const SCHEMA: u32 = 1;

/// Most histogram bins a task gets: a task worth more points gets bins
/// of several points each.
const MAX_BINS: usize = 20;

/// How many of the commonest failures the page lists (`class.json` has
/// them all).
const FAILURES_SHOWN: usize = 30;

/// Up to how many members a failure names at once (more are behind a
/// click).
const WHO_SHOWN: usize = 6;

/// Up to how many topics not graded a member's notes list at once.
const NOT_GRADED_SHOWN: usize = 2;

/// A member of the class as grading left it: its name, its report folder
/// and its report, or why it could not be graded.
type Graded = (String, PathBuf, Result<Report>);

/// The class report's data, as written to `class.json`.
#[derive(Debug, Clone, Serialize)]
pub struct Class {
    /// [`SCHEMA`].
    pub schema: u32,
    /// The class folder: the folder that holds the graded submissions.
    pub class: Option<PathBuf>,
    /// Members graded.
    pub graded: usize,
    /// Members that could not be graded.
    pub not_graded: usize,
    /// Mean of the members' points (bonus apart); `None` when none was
    /// graded.
    pub mean_score: Option<f64>,
    /// Median of the members' points (bonus apart).
    pub median_score: Option<f64>,
    /// Points possible (the most of any member).
    pub max_score: f64,
    /// Members whose grading files differ from the course's.
    pub flagged: usize,
    /// Members with a topic or task that could not be graded.
    pub incomplete: usize,
    /// Per task, in course order (as first met in the members' reports).
    pub tasks: Vec<TaskStats>,
    /// The failures, the one most members hit first.
    pub failures: Vec<Failure>,
    /// Per graded member, its row of the gradebook, in the gradebook's
    /// order.
    pub members: Vec<Member>,
    /// The submissions that could not be graded.
    pub ungraded: Vec<Ungraded>,
}

/// How one task went across the class.
#[derive(Debug, Clone, Serialize)]
pub struct TaskStats {
    /// Topic folder name, e.g. `01-lines`.
    pub topic: String,
    /// Task id.
    pub task: String,
    /// Title from the task sheet.
    pub title: String,
    /// Full points.
    pub points: f64,
    /// A bonus task.
    pub bonus: bool,
    /// Members whose report has the task.
    pub members: usize,
    /// Mean points of those members.
    pub mean: f64,
    /// Members with full marks.
    pub full_marks: usize,
    /// `full_marks / members` (0 to 1).
    pub full_share: f64,
    /// The members by their points: bins from 0 to the full points.
    pub histogram: Vec<Bin>,
}

/// One bin of a histogram: the members with `from ≤ points < to`; the
/// last bin, where `from == to` (the task's points), is full marks.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Bin {
    /// Lowest points of the bin.
    pub from: f64,
    /// Points the bin stops short of (its own for the full-marks bin).
    pub to: f64,
    /// Members in the bin.
    pub count: usize,
}

/// A failure many members may share: one test failing with the same first
/// line of its reason, or a task or topic that could not be graded.
#[derive(Debug, Clone, Serialize)]
pub struct Failure {
    /// Topic folder name.
    pub topic: String,
    /// Task id; `None` for what concerns the whole topic (it does not
    /// compile, the submission lacks it).
    pub task: Option<String>,
    /// Test name; `None` for a task or topic that could not be graded.
    pub test: Option<String>,
    /// The first line of the reason.
    pub reason: String,
    /// Members that hit it.
    pub count: usize,
    /// Those members, with their reports.
    pub members: Vec<Link>,
}

/// A member and its report, relative to the class report.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Link {
    /// The member's folder name.
    pub name: String,
    /// Its `report.html`, relative to `class.html` (`/` separators).
    pub report: String,
}

/// A member's row of the gradebook.
#[derive(Debug, Clone, Serialize)]
pub struct Member {
    /// The member's folder name.
    pub name: String,
    /// Its `report.html`, relative to `class.html`.
    pub report: String,
    /// Points of the tasks that are not bonuses.
    pub score: f64,
    /// Points possible.
    pub max_score: f64,
    /// Bonus points, apart.
    pub bonus: f64,
    /// Every task was graded.
    pub complete: bool,
    /// Its grading files differ from the course's.
    pub flagged: bool,
    /// Why it is flagged.
    pub flag: Option<String>,
    /// The topics that could not be graded, each with why.
    pub not_graded: Vec<String>,
}

/// A submission that could not be graded.
#[derive(Debug, Clone, Serialize)]
pub struct Ungraded {
    /// The member's folder name.
    pub name: String,
    /// Why.
    pub why: String,
}

/// Writes `class.json` and `class.html` into `out`, the class's grade
/// folder, from each member's name, report folder and report (or why it
/// could not be graded), and the gradebook's rows.
pub fn write(out: &Path, graded: &[Graded], rows: &[GradebookRow]) -> Result<()> {
    let class = class_of(out, graded, rows);
    let json = serde_json::to_string_pretty(&class).context("cannot serialise the class report")?;
    for (file, contents) in [("class.json", json), ("class.html", page(&class))] {
        let path = out.join(file);
        fs::write(&path, contents).with_context(|| format!("cannot write {}", path.display()))?;
    }
    Ok(())
}

/// The class report's data: see [`write`].
fn class_of(out: &Path, graded: &[Graded], rows: &[GradebookRow]) -> Class {
    let reports: Vec<(Link, &Report)> = graded
        .iter()
        .filter_map(|(name, folder, result)| {
            let report = result.as_ref().ok()?;
            Some((link(out, name, &folder.join("report.html")), report))
        })
        .collect();
    let ungraded: Vec<Ungraded> = graded
        .iter()
        .filter_map(|(name, _, result)| {
            let error = result.as_ref().err()?;
            Some(Ungraded {
                name: name.clone(),
                why: format!("{error:#}"),
            })
        })
        .collect();
    summarise(out, &reports, rows, ungraded)
}

/// A member's report as a link relative to `out`, where the class report
/// lies.
fn link(out: &Path, name: &str, report: &Path) -> Link {
    let relative = report
        .strip_prefix(out)
        .map_or_else(|_| Path::new(name).join("report.html"), Path::to_path_buf);
    Link {
        name: name.to_owned(),
        report: relative
            .components()
            .map(|c| c.as_os_str().to_string_lossy().into_owned())
            .collect::<Vec<_>>()
            .join("/"),
    }
}

/// The class report's data from the members' reports (each with its link),
/// the gradebook's rows and the submissions not graded.
fn summarise(
    out: &Path,
    reports: &[(Link, &Report)],
    rows: &[GradebookRow],
    ungraded: Vec<Ungraded>,
) -> Class {
    let mut scores: Vec<f64> = rows.iter().map(|r| r.score).collect();
    scores.sort_by(f64::total_cmp);
    let mean_score =
        (!scores.is_empty()).then(|| report::round2(scores.iter().sum::<f64>() / len(&scores)));
    let median_score = (!scores.is_empty()).then(|| {
        let middle = scores.len() / 2;
        report::round2(if scores.len().is_multiple_of(2) {
            f64::midpoint(scores[middle - 1], scores[middle])
        } else {
            scores[middle]
        })
    });
    let class = reports
        .iter()
        .find_map(|(_, report)| report.root.parent())
        .map(Path::to_path_buf);
    Class {
        schema: SCHEMA,
        class,
        graded: rows.len(),
        not_graded: ungraded.len(),
        mean_score,
        median_score,
        max_score: rows.iter().map(|r| r.max_score).fold(0.0, f64::max),
        flagged: rows.iter().filter(|r| r.flagged).count(),
        incomplete: rows.iter().filter(|r| !r.complete).count(),
        tasks: task_stats(reports),
        failures: failures(reports),
        members: rows
            .iter()
            .map(|row| Member {
                report: link(out, &row.submission, Path::new(&row.report)).report,
                name: row.submission.clone(),
                score: row.score,
                max_score: row.max_score,
                bonus: row.bonus,
                complete: row.complete,
                flagged: row.flagged,
                flag: row.integrity.clone(),
                not_graded: row.not_graded.clone(),
            })
            .collect(),
        ungraded,
    }
}

/// `part / whole`, 0 for nothing.
fn ratio(part: usize, whole: usize) -> f64 {
    if whole == 0 {
        0.0
    } else {
        part as f64 / whole as f64
    }
}

/// A count as a float, for means.
fn len<T>(items: &[T]) -> f64 {
    items.len() as f64
}

/// Per task (in the order first met), how its points are spread.
fn task_stats(reports: &[(Link, &Report)]) -> Vec<TaskStats> {
    /// A task and each member's points in it.
    struct Tally<'a> {
        topic: &'a str,
        task: &'a TaskReport,
        scores: Vec<f64>,
    }
    let mut tallies: Vec<Tally<'_>> = Vec::new();
    for (_, report) in reports {
        for topic in &report.topics {
            for task in &topic.tasks {
                let found = tallies
                    .iter()
                    .position(|t| t.topic == topic.name && t.task.id == task.id);
                let index = found.unwrap_or_else(|| {
                    tallies.push(Tally {
                        topic: &topic.name,
                        task,
                        scores: Vec::new(),
                    });
                    tallies.len() - 1
                });
                tallies[index].scores.push(task.score);
            }
        }
    }
    tallies
        .into_iter()
        .map(
            |Tally {
                 topic,
                 task,
                 scores,
             }| {
                let full_marks = scores.iter().filter(|&&s| is_full(s, task.points)).count();
                TaskStats {
                    topic: topic.to_owned(),
                    task: task.id.clone(),
                    title: task.title.clone(),
                    points: task.points,
                    bonus: task.bonus,
                    members: scores.len(),
                    mean: report::round2(scores.iter().sum::<f64>() / len(&scores).max(1.0)),
                    full_marks,
                    full_share: (ratio(full_marks, scores.len()) * 1e4).round() / 1e4,
                    histogram: histogram(&scores, task.points),
                }
            },
        )
        .collect()
}

/// Whether `score` is the full `points` (scores are rounded to hundredths).
fn is_full(score: f64, points: f64) -> bool {
    score >= points - 0.005
}

/// The members' `scores` in bins from 0 to `points`: one a point (a
/// task worth more than [`MAX_BINS`] points gets wider ones), and one of
/// its own for full marks.
fn histogram(scores: &[f64], points: f64) -> Vec<Bin> {
    let points = points.max(0.0);
    let width = (points / MAX_BINS as f64).ceil().max(1.0);
    // Bins below full marks: [0, w), [w, 2w), ... up to the points.
    let below = (points / width - 1e-9).ceil().max(0.0) as usize;
    let mut bins: Vec<Bin> = (0..below)
        .map(|i| Bin {
            from: i as f64 * width,
            to: ((i + 1) as f64 * width).min(points),
            count: 0,
        })
        .collect();
    bins.push(Bin {
        from: points,
        to: points,
        count: 0,
    });
    for &score in scores {
        let index = if is_full(score, points) {
            below
        } else {
            // A hundredth's rounding error must not drop a score a bin.
            ((score.max(0.0) + 1e-9) / width).floor() as usize
        };
        bins[index.min(below)].count += 1;
    }
    bins
}

/// Every failure of any member, counted by the members that hit it, the
/// commonest first (ties by topic, task and test).
fn failures(reports: &[(Link, &Report)]) -> Vec<Failure> {
    let mut failures: Vec<Failure> = Vec::new();
    let mut hit =
        |topic: &str, task: Option<&str>, test: Option<&str>, reason: &str, who: &Link| {
            let reason = first_line(reason);
            let found = failures.iter_mut().find(|f| {
                f.topic == topic
                    && f.task.as_deref() == task
                    && f.test.as_deref() == test
                    && f.reason == reason
            });
            match found {
                Some(failure) => {
                    if !failure.members.contains(who) {
                        failure.members.push(who.clone());
                        failure.count += 1;
                    }
                }
                None => failures.push(Failure {
                    topic: topic.to_owned(),
                    task: task.map(str::to_owned),
                    test: test.map(str::to_owned),
                    reason,
                    count: 1,
                    members: vec![who.clone()],
                }),
            }
        };
    for (who, report) in reports {
        for topic in &report.topics {
            if topic.compile_error.is_some() {
                hit(&topic.name, None, None, "the topic does not compile", who);
            }
            for error in &topic.errors {
                hit(&topic.name, None, None, error, who);
            }
            for task in &topic.tasks {
                if task.status == TaskStatus::Error {
                    let why = task
                        .error
                        .as_deref()
                        .unwrap_or("the task could not be graded");
                    hit(&topic.name, Some(&task.id), None, why, who);
                }
                for test in task.tests.iter().filter(|t| t.status == TestStatus::Failed) {
                    let reason = test.reason.as_deref().unwrap_or("failed (no reason given)");
                    hit(&topic.name, Some(&task.id), Some(&test.name), reason, who);
                }
            }
        }
    }
    failures.sort_by(|a, b| {
        b.count
            .cmp(&a.count)
            .then_with(|| a.topic.cmp(&b.topic))
            .then_with(|| a.task.cmp(&b.task))
            .then_with(|| a.test.cmp(&b.test))
            .then_with(|| a.reason.cmp(&b.reason))
    });
    failures
}

/// The first line of `text` that says something, trimmed.
fn first_line(text: &str) -> String {
    text.lines()
        .map(str::trim)
        .find(|line| !line.is_empty())
        .unwrap_or_default()
        .to_owned()
}
