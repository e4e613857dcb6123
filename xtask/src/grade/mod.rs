//! `cargo xtask grade`: build each topic, run every test in its own process
//! within limits, and turn the results into points.
//!
//! Tests map to tasks by name: `exercises/NN-topic/tests/<task id>.rs` is
//! the test binary of that task, and a task scores
//! `points × passed / tests`. The pipeline:
//!
//! ```text
//! topics ──build──> test binaries ──--list──> tests ──run (--jobs at once)──> verdicts
//!   │ compile error: all its tasks fail, other topics go on            │
//!   └──────────────> outcomes + the grader's adjustments ──> Report ──> table, report.json,
//!                    (refused, absent, tampered: `adjustments`)         results.json, junit.xml,
//!                                                                       report.html
//! ```
//!
//! The report is made once ([`Graded::report`]) and never changed after:
//! the formats only read it.
//!
//! One module a stage of the pipeline: [`build`] (a job of the runner,
//! [`crate::sandbox`]), [`plan`] (the tests listed), [`pool`] (run
//! [`run`] by the workers), [`verdict`] (from finished tests to points),
//! and the report's formats ([`export`], [`html`], [`table`]); a
//! submission is staged first ([`submission`]).
//!
//! What a grade promises: each test runs in a bubblewrap sandbox
//! ([`crate::sandbox`]) where one can be had, and a test passed only when it
//! exited with status 0 and printed the random token the grader made for
//! that run ([`outcome::judge`]; the test side is `crates/testkit-macros`),
//! so student code that prints a passing summary and exits has not passed.
//! In a topic decided by replay, graded from a stage, that process is not
//! the one that ran the student's code ([`run`], `crates/transcript`): no
//! process that ran it ever holds a token.

mod adjustments;
mod build;
pub mod classroom;
mod events;
pub mod export;
mod flow;
mod forbidden;
pub(crate) mod html;
mod junit;
pub mod markup;
mod outcome;
pub mod pipeline;
mod plan;
mod pool;
pub mod report;
mod results_json;
pub mod reviewed;
mod run;
pub mod score;
pub mod submission;
pub(crate) mod table;
mod verdict;

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use anyhow::{Context, Result};

use adjustments::Adjustments;
#[cfg(feature = "staff")]
pub(crate) use events::Silent;
pub(crate) use events::{Events, Terminal};
#[cfg(feature = "staff")]
pub use pool::Permits;
pub use report::{Edition, Report, TaskStatus};

use crate::stage;
pub use crate::stage::Overlay;
use report::TopicReport;

/// Where insta writes the snapshots a test failed (`.snap.new`), under the
/// report folder: the course's own stay untouched (and read-only in the
/// sandbox).
pub const PENDING_SNAPSHOTS: &str = "snapshots";

/// What to grade and where to put the results.
#[derive(Debug, Clone)]
pub struct GradeOptions {
    /// The checkout whose `exercises/` are graded (a workspace root).
    pub root: PathBuf,
    /// Topics by folder name, short name, package or number; empty: all.
    pub topics: Vec<String>,
    /// Of a topic named here by its folder name, only these tasks are
    /// graded (`(topic, task)`; the report holds those alone): the
    /// self-test's plants are each judged by their own task. A topic not
    /// named here is graded whole.
    pub tasks: Vec<(String, String)>,
    /// Grade the reference solutions, staged over the stubs (see `stage`).
    pub reference: bool,
    /// Where the report files, logs and images go.
    pub out: PathBuf,
    /// Tests run at the same time.
    pub jobs: usize,
    /// cargo's `--target-dir`; `None`: cargo's default for the workspace.
    pub target_dir: Option<PathBuf>,
    /// The wall-clock limit of each build of student code.
    pub build_time_limit: Duration,
    /// Progress bars and spinners on stderr (off where several grades
    /// share the terminal).
    pub progress: bool,
    /// What containment student code needs before it runs: the grade of
    /// record fails closed (see [`crate::sandbox::Policy`]).
    pub sandbox: crate::sandbox::Policy,
}

impl GradeOptions {
    /// Grades `root`'s exercises, writing into `root/target/grade`.
    #[must_use]
    pub fn new(root: PathBuf) -> Self {
        let out = root.join("target").join("grade");
        Self {
            root,
            topics: Vec::new(),
            tasks: Vec::new(),
            reference: false,
            out,
            jobs: default_jobs(),
            target_dir: None,
            build_time_limit: build::DEFAULT_BUILD_TIME_LIMIT,
            progress: true,
            sandbox: crate::sandbox::Policy::BestEffort,
        }
    }
}

/// What the grader of a submission sets for its grade besides the
/// [`GradeOptions`] (see `submission`); a grade of the checkout itself or
/// of the reference sets nothing.
#[derive(Debug, Default)]
pub(crate) struct Setting {
    /// Topics of the assignment that the graded code does not hold (a
    /// submission without their folders): neither built nor run, each of
    /// their tasks an error that says so, scoring 0.
    pub(crate) absent: Vec<String>,
    /// The grade runs in a class's slot, beside the grades of the other
    /// slots (the staff's class).
    #[cfg(feature = "staff")]
    pub(crate) beside: Option<Beside>,
}

/// A grade in a class's slot, beside others: its test executables kept
/// apart, its tests counted with theirs.
#[cfg(feature = "staff")]
#[derive(Debug, Clone)]
pub(crate) struct Beside {
    /// Where the test executables are kept once built (hard links), so
    /// that they run from there while the build folder builds another
    /// slot's stage: the slot's `bin/`, removed when the grade is done.
    pub(crate) keep_binaries: PathBuf,
    /// Shared with the other slots: at most its count of tests run at
    /// once across all of them.
    pub(crate) permits: std::sync::Arc<Permits>,
}

/// One test per available CPU.
#[must_use]
pub fn default_jobs() -> usize {
    std::thread::available_parallelism().map_or(1, usize::from)
}

/// Grades, writes `report.json`, `results.json`, `junit.xml` and `report.html` into
/// `options.out`, and returns the report. Student code failing in any way
/// is part of the report; `Err` means grading itself could not run.
///
/// The student code is graded in the checkout itself; the reference
/// solutions in the stage (see `stage`), built in the stage's cache.
pub fn grade(options: &GradeOptions) -> Result<Report> {
    grade_with(options, &Terminal::new(options.progress))
}

/// [`grade`], telling `events` what it does.
fn grade_with(options: &GradeOptions, events: &dyn Events) -> Result<Report> {
    if options.reference {
        grade_staged_with(options, Overlay::Reference, events)
    } else {
        let root = std::path::absolute(&options.root)
            .with_context(|| format!("cannot find {}", options.root.display()))?;
        // A build folder shared with another copy of the course must not
        // run that copy's tests.
        let target_dir = build::target_dir_of(&root, options.target_dir.as_deref());
        stage::claim_checkout_build(&root, &target_dir)?;
        let report = grade_tree(options, Edition::Student, events)?.report(Adjustments {
            shown_root: Some(root),
            ..Adjustments::default()
        });
        export::write_all(&report, &options.out)?;
        Ok(report)
    }
}

/// Grades `options.root` staged with `overlay` (see `stage`), built in the
/// stage's cache unless `options.target_dir` says otherwise, and writes
/// the report files.
#[cfg(feature = "staff")]
pub fn grade_staged(options: &GradeOptions, overlay: Overlay<'_>) -> Result<Report> {
    grade_staged_with(options, overlay, &Terminal::new(options.progress))
}

/// [`grade_staged`], telling `events` what it does.
fn grade_staged_with(
    options: &GradeOptions,
    overlay: Overlay<'_>,
    events: &dyn Events,
) -> Result<Report> {
    let root = std::path::absolute(&options.root)
        .with_context(|| format!("cannot find {}", options.root.display()))?;
    let staged = stage::stage(&root, overlay, options.target_dir.as_deref())?;
    let mut in_stage = options.clone();
    in_stage.root.clone_from(&staged.root);
    in_stage.target_dir = Some(staged.target_dir.clone());
    let edition = match overlay {
        Overlay::Reference => Edition::Reference,
        Overlay::Own | Overlay::Submission(_) => Edition::Student,
        #[cfg(feature = "staff")]
        Overlay::Texts(_) => Edition::Student,
    };
    let report = grade_tree(&in_stage, edition, events)?.report(Adjustments {
        shown_root: Some(root),
        ..Adjustments::default()
    });
    export::write_all(&report, &options.out)?;
    Ok(report)
}

/// Grades the course at `options.root` as it is, building it into
/// `options.target_dir`; makes no report yet.
fn grade_tree(options: &GradeOptions, edition: Edition, events: &dyn Events) -> Result<Graded> {
    flow::prepare(options, edition, Setting::default(), events)?.finish(events)
}

/// A grade whose tests have run and whose pipeline is drawn, before its
/// report is made: the outcomes, which [`Graded::report`] turns into the
/// report with the grader's [`Adjustments`].
pub(crate) struct Graded {
    root: PathBuf,
    edition: Edition,
    started: Instant,
    phases: report::Phases,
    /// Each topic's tasks with their tests' outcomes and scores.
    topics: Vec<TopicReport>,
    pipeline: Vec<pipeline::PipelinePicture>,
    left_out: Vec<String>,
}

impl Graded {
    /// The report, made once: the adjustments applied to the topics, then
    /// every total summed ([`score::totals`]). Nothing changes a report
    /// after this.
    pub(crate) fn report(self, adjustments: Adjustments) -> Report {
        let Graded {
            root,
            edition,
            started,
            phases,
            mut topics,
            pipeline,
            left_out,
        } = self;
        adjustments.apply(&mut topics);
        let mut report = Report {
            schema: report::SCHEMA,
            root: adjustments.shown_root.unwrap_or(root),
            edition,
            score: 0.0,
            max_score: 0.0,
            duration_s: report::round2(started.elapsed().as_secs_f64()),
            phases,
            complete: topics.iter().all(|topic| {
                topic.compile_error.is_none()
                    && topic.errors.is_empty()
                    && topic
                        .tasks
                        .iter()
                        .all(|task| task.status != TaskStatus::Error)
            }),
            integrity: adjustments.integrity,
            sandboxed: crate::sandbox::Jail::get().sandboxed(),
            containment: crate::sandbox::Jail::get().containment(),
            topics,
            pipeline,
            left_out,
        };
        score::totals(&mut report);
        report
    }
}

/// `cargo xtask grade`: grade, print the table (each topic's rows as soon
/// as its tests have ended) and the failures.
pub fn run(options: &GradeOptions) -> Result<Report> {
    let terminal = Terminal::with_rows(options.progress);
    let report = grade_with(options, &terminal)?;
    let style = table::Style::detect();
    let details = table::Details::EveryTask;
    if terminal.rows_shown() == report.topics.len() {
        let layout = table::Layout::of(&report);
        print!(
            "{}{}",
            layout.total(&report, style),
            table::below_table(&report, &options.out, style, details)
        );
    } else {
        print!("{}", table::render(&report, &options.out, style, details));
    }
    Ok(report)
}

/// Prints the table of a report (for `cargo xtask test`), with each
/// failing task's first failure when `details` is set.
pub fn print_summary(report: &Report, out: &Path, details: bool) {
    let details = if details {
        table::Details::EveryTask
    } else {
        table::Details::None
    };
    print!(
        "{}",
        table::render(report, out, table::Style::detect(), details)
    );
}

/// Text of many lines for the terminal, each line escaped as the grader
/// escapes every text from a submission (see `table::shown`), the later
/// ones indented under the first.
#[must_use]
pub fn escaped_lines(text: &str) -> String {
    table::continued(text, "  ")
}

/// One screen for `cargo xtask watch`: the table and the first failing
/// task's first failure.
#[must_use]
pub fn one_screen(report: &Report, out: &Path) -> String {
    table::render(
        report,
        out,
        table::Style::detect(),
        table::Details::FirstTask,
    )
}
