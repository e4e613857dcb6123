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
pub mod export;
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

use std::collections::HashMap;
use std::fs;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};
use indicatif::ProgressBar;

use adjustments::Adjustments;
#[cfg(feature = "staff")]
pub use pool::Permits;
pub use report::{Edition, Report, TaskStatus};

use crate::stage;
pub use crate::stage::Overlay;
use crate::topics;
use build::{Build, TestBinary};
use report::TopicReport;
use run::Finished;

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
    if options.reference {
        grade_staged(options, Overlay::Reference)
    } else {
        let root = std::path::absolute(&options.root)
            .with_context(|| format!("cannot find {}", options.root.display()))?;
        // A build folder shared with another copy of the course must not
        // run that copy's tests.
        let target_dir = build::target_dir_of(&root, options.target_dir.as_deref());
        stage::claim_checkout_build(&root, &target_dir)?;
        let report = grade_tree(options, Edition::Student)?.report(Adjustments {
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
pub fn grade_staged(options: &GradeOptions, overlay: Overlay<'_>) -> Result<Report> {
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
    let report = grade_tree(&in_stage, edition)?.report(Adjustments {
        shown_root: Some(root),
        ..Adjustments::default()
    });
    export::write_all(&report, &options.out)?;
    Ok(report)
}

/// Grades the course at `options.root` as it is, building it into
/// `options.target_dir`; makes no report yet.
fn grade_tree(options: &GradeOptions, edition: Edition) -> Result<Graded> {
    prepare(options, edition, Setting::default())?.finish()
}

/// A course built and its tests listed, ready to run: the first half of a
/// grade. Where the executables are kept apart (`Beside::keep_binaries`),
/// what the tests run from no longer depends on the build folder.
pub(crate) struct Prepared {
    options: GradeOptions,
    #[cfg(feature = "staff")]
    beside: Option<Beside>,
    edition: Edition,
    started: Instant,
    /// Seconds the builds took (and the listing of the tests).
    build_s: f64,
    root: PathBuf,
    out: PathBuf,
    plans: Vec<plan::Plan>,
    viewer: pipeline::Viewer,
}

/// Builds the course at `options.root` (every topic and the pipeline's
/// viewer, but the topics `setting` says are absent) and lists its tests.
pub(crate) fn prepare(
    options: &GradeOptions,
    edition: Edition,
    setting: Setting,
) -> Result<Prepared> {
    let started = Instant::now();
    let root = std::path::absolute(&options.root)
        .with_context(|| format!("cannot find {}", options.root.display()))?;
    let out = std::path::absolute(&options.out)
        .with_context(|| format!("cannot find {}", options.out.display()))?;
    let topics = topics::select(&root, &options.topics)?;
    if topics.is_empty() {
        bail!(
            "there are no topics in {}",
            root.join("exercises").display()
        );
    }
    fs::create_dir_all(&out).with_context(|| format!("cannot create {}", out.display()))?;
    if topics.iter().any(|topic| topic.sheet.gpu) {
        crate::setup::ensure_vulkan();
    }
    let spinner = |message: String| spinner(message, options.progress);
    // (What an earlier grade's tests left may be anything: removed by the
    // grader's bounded removal, never `fs::remove_dir_all`.)
    for stale in [
        out.join(PENDING_SNAPSHOTS),
        out.join("scratch"),
        out.join("build"),
    ] {
        crate::files::remove_tree(&stale)
            .with_context(|| format!("cannot clear {}", stale.display()))?;
    }

    // Build every topic first: cargo serialises builds anyway. All at
    // once when they compile, one by one to tell whose errors they are.
    let target_dir = build::target_dir_of(&root, options.target_dir.as_deref());
    let builder = build::Builder {
        root: root.clone(),
        logs: out.join("build"),
        time_limit: options.build_time_limit,
        // A checkout graded in place builds into its own `target/`, which
        // also holds its stages and reports: not cargo's, not shown.
        emptied: [
            target_dir.join("xtask"),
            target_dir.join("grade"),
            out.clone(),
        ]
        .into_iter()
        .filter(|dir| dir.starts_with(&target_dir))
        .collect(),
        target_dir,
    };
    let mut together: Option<std::vec::IntoIter<Vec<TestBinary>>> = None;
    let mut stopped: Option<String> = None;
    let held: Vec<topics::Topic> = topics
        .iter()
        .filter(|topic| !setting.absent.contains(&topic.name))
        .cloned()
        .collect();
    if held.len() > 1 {
        let spinner = spinner(format!("building {} topics", held.len()));
        match build::build_all(&builder, &held)? {
            Ok(all) => together = Some(all.into_iter()),
            Err(reason) => stopped = reason,
        }
        spinner.finish_and_clear();
    }
    let mut plans = Vec::new();
    for topic in &topics {
        for stale in [
            out.join("images").join(&topic.name),
            out.join("logs").join(&topic.name),
        ] {
            crate::files::remove_tree(&stale)
                .with_context(|| format!("cannot clear {}", stale.display()))?;
        }
        if setting.absent.contains(&topic.name) {
            plans.push(plan::absent(topic));
            continue;
        }
        let build = match (together.as_mut().and_then(Iterator::next), &stopped) {
            // (None found: built on its own, which says why.)
            (Some(binaries), _) if !binaries.is_empty() => Build::Built(binaries),
            (_, Some(reason)) => Build::Failed(reason.clone()),
            _ => {
                let spinner = spinner(format!("building {}", topic.name));
                let build = build::build(&builder, topic);
                spinner.finish_and_clear();
                build?
            }
        };
        let build = match (crate::stage::replay::package_dir(&root, topic), build) {
            (Some(package_dir), Build::Built(mut binaries)) => {
                let spinner = spinner(format!("building the replay of {}", topic.name));
                let built = build::add_replays(&builder, topic, &package_dir, &mut binaries);
                spinner.finish_and_clear();
                built?;
                Build::Built(binaries)
            }
            (_, build) => build,
        };
        #[cfg(feature = "staff")]
        let build = match (&setting.beside, build) {
            (Some(beside), Build::Built(binaries)) => Build::Built(keep_binaries(
                binaries,
                &beside.keep_binaries.join(&topic.name),
            )?),
            (_, build) => build,
        };
        plans.push(plan::plan(&root, &out, topic, build));
    }
    let compiled: Vec<&str> = plans
        .iter()
        .filter(|plan| plan.compile_error.is_none())
        .map(|plan| plan.topic.name.as_str())
        .collect();
    let graded: Vec<&str> = plans
        .iter()
        .filter(|plan| !plan.absent)
        .map(|plan| plan.topic.name.as_str())
        .collect();
    let viewer = pipeline::build_viewer(&builder, &graded, &compiled);
    #[cfg(feature = "staff")]
    let viewer = match (&setting.beside, viewer) {
        (Some(beside), pipeline::Viewer::Built(binary)) => {
            match keep_binary(&binary, &beside.keep_binaries.join("viewer")) {
                Ok(kept) => pipeline::Viewer::Built(kept),
                Err(error) => pipeline::Viewer::Failed(format!("{error:#}")),
            }
        }
        (_, viewer) => viewer,
    };
    Ok(Prepared {
        options: options.clone(),
        #[cfg(feature = "staff")]
        beside: setting.beside,
        edition,
        started,
        build_s: started.elapsed().as_secs_f64(),
        root,
        out,
        plans,
        viewer,
    })
}

/// Hard links `binaries` into `dir` (emptied first): cargo replaces an
/// executable it rebuilds with a new file, so the link keeps this build's.
#[cfg(feature = "staff")]
fn keep_binaries(binaries: Vec<TestBinary>, dir: &Path) -> Result<Vec<TestBinary>> {
    crate::files::remove_tree(dir).with_context(|| format!("cannot clear {}", dir.display()))?;
    binaries
        .into_iter()
        .map(|binary| {
            Ok(TestBinary {
                executable: keep_binary(&binary.executable, dir)?,
                replay: match &binary.replay {
                    Some(replay) => Some(keep_binary(replay, &dir.join("replay"))?),
                    None => None,
                },
                name: binary.name,
            })
        })
        .collect()
}

/// Hard links (or, across file systems, copies) `binary` into `dir`.
#[cfg(feature = "staff")]
fn keep_binary(binary: &Path, dir: &Path) -> Result<PathBuf> {
    fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let name = binary
        .file_name()
        .with_context(|| format!("{} has no file name", binary.display()))?;
    let kept = dir.join(name);
    let _ = fs::remove_file(&kept);
    if fs::hard_link(binary, &kept).is_err() {
        fs::copy(binary, &kept)
            .with_context(|| format!("cannot copy {} to {}", binary.display(), kept.display()))?;
    }
    Ok(kept)
}

impl Prepared {
    /// Runs the tests and draws the pipeline: the second half of a grade.
    pub(crate) fn finish(self) -> Result<Graded> {
        #[cfg(feature = "staff")]
        let kept = self.beside.as_ref().map(|b| b.keep_binaries.clone());
        let report = self.run();
        #[cfg(feature = "staff")]
        if let Some(kept) = kept {
            let _ = crate::files::remove_tree(&kept);
        }
        report
    }

    fn run(self) -> Result<Graded> {
        let Prepared {
            options,
            #[cfg(feature = "staff")]
            beside,
            edition,
            started,
            build_s,
            root,
            out,
            plans,
            viewer,
        } = self;
        let testing = Instant::now();
        let out = out.as_path();
        // Then run all tests of all topics in one pool.
        let mut jobs: Vec<(usize, usize)> = plans
            .iter()
            .enumerate()
            .flat_map(|(p, plan)| {
                let runnable = plan
                    .tests
                    .iter()
                    .enumerate()
                    .filter(|(_, test)| test.command.is_some());
                runnable.map(move |(t, _)| (p, t))
            })
            .collect();
        // First the first test of every task, then the second of every task,
        // and so on: the workers run tests of different tasks side by side,
        // so a task that loops costs one time limit, not one per worker.
        let mut rank: HashMap<(usize, usize), usize> = HashMap::new();
        let mut order: HashMap<(usize, usize), usize> = HashMap::new();
        for &(p, t) in &jobs {
            let task = (p, plans[p].tests[t].task);
            let next = rank.entry(task).or_insert(0);
            order.insert((p, t), *next);
            *next += 1;
        }
        jobs.sort_by_key(|&(p, t)| (order[&(p, t)], p, plans[p].tests[t].task, t));
        // What the tests write into the report folder is kept within one
        // budget for the whole grade, swept after each test (see
        // `files::Keeper`).
        let kept = pool::Kept {
            keeper: std::sync::Mutex::new(crate::files::Keeper::new(
                out,
                crate::files::KEPT_BUDGET,
            )),
            pending: out.join(PENDING_SNAPSHOTS),
        };
        let workers = pool::Workers {
            threads: options.jobs.max(1),
            progress: options.progress,
            #[cfg(feature = "staff")]
            permits: beside.map(|beside| beside.permits),
        };
        let results = pool::run_all(&plans, &jobs, &workers, &kept)?;
        let mut keeper = kept
            .keeper
            .into_inner()
            .unwrap_or_else(std::sync::PoisonError::into_inner);

        let mut finished: HashMap<(usize, usize), Finished> = HashMap::new();
        for (&(p, t), result) in jobs.iter().zip(results) {
            finished.insert((p, t), result);
        }
        let tests_s = testing.elapsed().as_secs_f64();
        let graded: Vec<String> = plans
            .iter()
            .filter(|plan| !plan.absent)
            .map(|plan| plan.topic.name.clone())
            .collect();
        let topics: Vec<TopicReport> = plans
            .into_iter()
            .enumerate()
            .map(|(p, plan)| verdict::topic_report(out, plan, |t| finished.remove(&(p, t))))
            .collect();
        let spinner = spinner(
            "drawing the pipeline with your stages".to_owned(),
            options.progress,
        );
        let graded: Vec<&str> = graded.iter().map(String::as_str).collect();
        let drawing = Instant::now();
        let pipeline = pipeline::draw_all(
            &pipeline::Plan {
                root: &root,
                out,
                graded: &graded,
            },
            &viewer,
        );
        spinner.finish_and_clear();
        // The builds' logs (the compiler's messages, which quote student
        // code) and what the listings of the tests and the viewer printed
        // into scratch, up to the output limit each, count to the same
        // budget.
        for folder in [out.join("build"), out.join("scratch")] {
            for log in crate::files::listing(&folder) {
                keeper.keep_log(&folder.join(log));
            }
        }
        let left_out = keeper.left_out();
        let phases = report::Phases {
            build_s: report::round2(build_s),
            tests_s: report::round2(tests_s),
            pipeline_s: report::round2(drawing.elapsed().as_secs_f64()),
        };
        Ok(Graded {
            root,
            edition,
            started,
            phases,
            topics,
            pipeline,
            left_out,
        })
    }
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

/// `cargo xtask grade`: grade, print the table and the failures.
pub fn run(options: &GradeOptions) -> Result<Report> {
    let report = grade(options)?;
    print!(
        "{}",
        table::render(
            &report,
            &options.out,
            table::Style::detect(),
            table::Details::EveryTask
        )
    );
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

fn spinner(message: String, shown: bool) -> ProgressBar {
    if !shown {
        return ProgressBar::hidden();
    }
    let spinner = ProgressBar::new_spinner().with_message(message);
    spinner.enable_steady_tick(Duration::from_millis(100));
    spinner
}
