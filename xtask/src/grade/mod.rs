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
//!   └─────────────────────> Report ──> table, report.json, results.json, junit.xml, report.html
//! ```
//!
//! What a grade promises: each test runs in a bubblewrap sandbox
//! ([`run::Sandbox`]) where one can be had, and a test passed only when it
//! exited with status 0 and printed the random token the grader made for
//! that run ([`outcome::judge`]; the test side is `crates/testkit-macros`),
//! so student code that prints a passing summary and exits has not passed.

mod build;
pub mod export;
mod forbidden;
mod html;
mod outcome;
pub mod pipeline;
pub mod report;
mod run;
pub mod submission;
mod table;

use std::collections::HashMap;
use std::ffi::OsString;
use std::fs;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};
use indicatif::{ProgressBar, ProgressStyle};

pub use report::{Edition, Report, TaskStatus, TestStatus};

use crate::stage;
pub use crate::stage::Overlay;
use crate::topics::{self, Topic};
use build::{Build, TestBinary};
use outcome::Exit;
use report::{TaskReport, TestReport, TopicReport};
use run::{Finished, TestCommand};

/// Where insta writes the snapshots a test failed (`.snap.new`), under the
/// report folder: the course's own stay untouched (and read-only in the
/// sandbox).
pub const PENDING_SNAPSHOTS: &str = "snapshots";

/// The excerpt of a failed test's output kept in the report.
const OUTPUT_EXCERPT_CHARS: usize = 4000;

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
    /// Submissions of a class graded at the same time, as `--jobs` gave
    /// it; `None`: one per two CPUs (see `submission`).
    pub submissions_at_once: Option<usize>,
    /// cargo's `--target-dir`; `None`: cargo's default for the workspace.
    pub target_dir: Option<PathBuf>,
    /// The wall-clock limit of each build of student code.
    pub build_time_limit: Duration,
    /// Where to keep the test executables once built (hard links), so
    /// that they run from there while the build folder builds another
    /// stage: a class slot's `bin/`. `None`: they run where cargo put them.
    pub keep_binaries: Option<PathBuf>,
    /// Shared with other grades running at the same time: at most its
    /// count of tests run at once across all of them.
    pub permits: Option<std::sync::Arc<Permits>>,
    /// Progress bars and spinners on stderr (off where several grades
    /// share the terminal).
    pub progress: bool,
}

/// A counting semaphore: the tests that may run at once, shared by the
/// submissions of a class graded side by side.
#[derive(Debug)]
pub struct Permits {
    free: Mutex<usize>,
    freed: std::sync::Condvar,
}

impl Permits {
    /// `count` permits (at least one).
    #[must_use]
    pub fn new(count: usize) -> Self {
        Self {
            free: Mutex::new(count.max(1)),
            freed: std::sync::Condvar::new(),
        }
    }

    /// Waits for a permit, which is given back when the guard drops.
    pub fn take(&self) -> PermitGuard<'_> {
        let mut free = self.free.lock().expect("no permit holder panics");
        while *free == 0 {
            free = self.freed.wait(free).expect("no permit holder panics");
        }
        *free -= 1;
        PermitGuard(self)
    }
}

/// A permit of [`Permits`], held while a test runs.
pub struct PermitGuard<'a>(&'a Permits);

impl Drop for PermitGuard<'_> {
    fn drop(&mut self) {
        *self.0.free.lock().expect("no permit holder panics") += 1;
        self.0.freed.notify_one();
    }
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
            submissions_at_once: None,
            target_dir: None,
            build_time_limit: build::DEFAULT_BUILD_TIME_LIMIT,
            keep_binaries: None,
            permits: None,
            progress: true,
        }
    }
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
        let mut report = grade_tree(options, Edition::Student)?;
        report.root = root;
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
        Overlay::Own | Overlay::Submission(_) | Overlay::DoNothing(_) => Edition::Student,
    };
    let mut report = grade_tree(&in_stage, edition)?;
    report.root = root;
    export::write_all(&report, &options.out)?;
    Ok(report)
}

/// Grades the course at `options.root` as it is, building it into
/// `options.target_dir`; writes no report files.
fn grade_tree(options: &GradeOptions, edition: Edition) -> Result<Report> {
    prepare(options, edition)?.finish()
}

/// A course built and its tests listed, ready to run: the first half of a
/// grade. What the tests run from no longer depends on the build folder
/// where the executables are kept ([`GradeOptions::keep_binaries`]).
pub(crate) struct Prepared {
    options: GradeOptions,
    edition: Edition,
    started: Instant,
    root: PathBuf,
    out: PathBuf,
    plans: Vec<Plan>,
    viewer: pipeline::Viewer,
}

/// Builds the course at `options.root` (every topic and the pipeline's
/// viewer) and lists its tests.
pub(crate) fn prepare(options: &GradeOptions, edition: Edition) -> Result<Prepared> {
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
    for stale in [
        out.join(PENDING_SNAPSHOTS),
        out.join("scratch"),
        out.join("build"),
    ] {
        if stale.exists() {
            fs::remove_dir_all(&stale)
                .with_context(|| format!("cannot clear {}", stale.display()))?;
        }
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
    if topics.len() > 1 {
        let spinner = spinner(format!("building {} topics", topics.len()));
        match build::build_all(&builder, &topics)? {
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
            if stale.exists() {
                fs::remove_dir_all(&stale)
                    .with_context(|| format!("cannot clear {}", stale.display()))?;
            }
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
        let build = match (&options.keep_binaries, build) {
            (Some(keep), Build::Built(binaries)) => {
                Build::Built(keep_binaries(binaries, &keep.join(&topic.name))?)
            }
            (_, build) => build,
        };
        plans.push(plan(&root, &out, topic, build));
    }
    let compiled: Vec<&str> = plans
        .iter()
        .filter(|plan| plan.compile_error.is_none())
        .map(|plan| plan.topic.name.as_str())
        .collect();
    let graded: Vec<&str> = plans.iter().map(|plan| plan.topic.name.as_str()).collect();
    let viewer = pipeline::build_viewer(&builder, &graded, &compiled);
    let viewer = match (&options.keep_binaries, viewer) {
        (Some(keep), pipeline::Viewer::Built(binary)) => {
            match keep_binary(&binary, &keep.join("viewer")) {
                Ok(kept) => pipeline::Viewer::Built(kept),
                Err(error) => pipeline::Viewer::Failed(format!("{error:#}")),
            }
        }
        (_, viewer) => viewer,
    };
    Ok(Prepared {
        options: options.clone(),
        edition,
        started,
        root,
        out,
        plans,
        viewer,
    })
}

/// Hard links `binaries` into `dir` (emptied first): cargo replaces an
/// executable it rebuilds with a new file, so the link keeps this build's.
fn keep_binaries(binaries: Vec<TestBinary>, dir: &Path) -> Result<Vec<TestBinary>> {
    if dir.exists() {
        fs::remove_dir_all(dir).with_context(|| format!("cannot clear {}", dir.display()))?;
    }
    binaries
        .into_iter()
        .map(|binary| {
            Ok(TestBinary {
                executable: keep_binary(&binary.executable, dir)?,
                name: binary.name,
            })
        })
        .collect()
}

/// Hard links (or, across file systems, copies) `binary` into `dir`.
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
    pub(crate) fn finish(self) -> Result<Report> {
        let keep = self.options.keep_binaries.clone();
        let report = self.run();
        if let Some(keep) = keep {
            let _ = fs::remove_dir_all(keep);
        }
        report
    }

    fn run(self) -> Result<Report> {
        let Prepared {
            options,
            edition,
            started,
            root,
            out,
            plans,
            viewer,
        } = self;
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
        let results = run_all(
            &plans,
            &jobs,
            options.jobs.max(1),
            options.permits.as_deref(),
            options.progress,
        )?;

        let mut finished: HashMap<(usize, usize), Finished> = HashMap::new();
        for (&(p, t), result) in jobs.iter().zip(results) {
            finished.insert((p, t), result);
        }
        let topics: Vec<TopicReport> = plans
            .into_iter()
            .enumerate()
            .map(|(p, plan)| topic_report(out, plan, |t| finished.remove(&(p, t))))
            .collect();
        let spinner = spinner(
            "drawing the pipeline with your stages".to_owned(),
            options.progress,
        );
        let pipeline = pipeline::draw_all(&pipeline::Plan { root: &root, out }, &viewer);
        spinner.finish_and_clear();
        let report = Report {
            schema: report::SCHEMA,
            root,
            edition,
            score: report::round2(topics.iter().map(|t| t.score).sum()),
            max_score: report::round2(topics.iter().map(|t| t.max_score).sum()),
            duration_s: report::round2(started.elapsed().as_secs_f64()),
            complete: topics.iter().all(|topic| {
                topic.compile_error.is_none()
                    && topic.errors.is_empty()
                    && topic
                        .tasks
                        .iter()
                        .all(|task| task.status != TaskStatus::Error)
            }),
            integrity: None,
            sandboxed: crate::sandbox::Jail::get().sandboxed(),
            containment: crate::sandbox::Jail::get().containment(),
            topics,
            pipeline,
        };
        Ok(report)
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

/// A topic ready to run: its tests, or why there are none.
struct Plan {
    topic: Topic,
    compile_error: Option<String>,
    errors: Vec<String>,
    /// Per task (sheet order): an error that keeps it from being graded.
    task_errors: Vec<Option<String>>,
    tests: Vec<PlannedTest>,
}

struct PlannedTest {
    task: usize,
    name: String,
    /// `None` for ignored tests, which are not run.
    command: Option<TestCommand>,
    images_dir: PathBuf,
}

/// Sorts `tests` (libtest lists them alphabetically) in the order their
/// file `source` declares them: the order its author wrote them in,
/// named cases before the random ones, so that the first failure shown is
/// the first a reader of the file meets. Names not found go last.
fn in_declaration_order(tests: &mut [String], source: &str) {
    tests.sort_by_cached_key(|test| {
        let name = test.rsplit("::").next().unwrap_or(test);
        source.find(&format!("fn {name}(")).unwrap_or(usize::MAX)
    });
}

/// The tests of `topic` built as `build`, ready to run (each sees the
/// course at `root` and its own executable).
fn plan(root: &Path, out: &Path, topic: &Topic, build: Build) -> Plan {
    let mut plan = Plan {
        topic: topic.clone(),
        compile_error: None,
        errors: Vec::new(),
        task_errors: vec![None; topic.sheet.tasks.len()],
        tests: Vec::new(),
    };
    let binaries = match build {
        Build::Built(binaries) => binaries,
        Build::Failed(errors) => {
            plan.compile_error = Some(errors);
            return plan;
        }
    };
    let mut has_binary = vec![false; topic.sheet.tasks.len()];
    for TestBinary { name, executable } in binaries {
        let Some(task) = topic.sheet.tasks.iter().position(|task| task.id == name) else {
            plan.errors.push(format!(
                "test binary `tests/{name}.rs` is not a task of {} (the task sheet lists: {}); its tests were not run",
                topic.name,
                topic.sheet.task_ids()
            ));
            continue;
        };
        has_binary[task] = true;
        let listing = out
            .join("scratch")
            .join(&topic.name)
            .join(format!("list-{name}"));
        let list = |ignored| run::list_tests(&executable, &topic.dir, root, &listing, ignored);
        let listed = list(false).and_then(|all| Ok((all, list(true)?)));
        let (mut all, ignored) = match listed {
            Ok(lists) => lists,
            Err(error) => {
                plan.task_errors[task] = Some(format!(
                    "cannot list the tests of tests/{name}.rs: {error:#}"
                ));
                continue;
            }
        };
        if all.is_empty() {
            plan.task_errors[task] = Some(format!("tests/{name}.rs has no tests"));
        }
        if let Ok(source) = fs::read_to_string(topic.dir.join("tests").join(format!("{name}.rs"))) {
            in_declaration_order(&mut all, &source);
        }
        for test in all {
            let relative = test_path(&name, &test);
            let images_dir = out.join("images").join(&topic.name).join(&relative);
            let scratch = out.join("scratch").join(&topic.name).join(&relative);
            let pending = out.join(PENDING_SNAPSHOTS);
            let mut env = test_env(root, topic, &images_dir);
            env.push(("TMPDIR".into(), scratch.clone().into()));
            env.push(("INSTA_PENDING_DIR".into(), pending.clone().into()));
            let command = (!ignored.contains(&test)).then(|| TestCommand {
                executable: executable.clone(),
                name: test.clone(),
                cwd: topic.dir.clone(),
                course: root.to_path_buf(),
                writable: vec![scratch.clone(), images_dir.clone(), pending.clone()],
                gpu: topic.sheet.gpu,
                env,
                time_limit: Duration::from_secs_f64(topic.sheet.time_limit_s),
                memory_limit_mib: topic.sheet.memory_limit_mib,
                verdict_file: scratch.join(".testkit-verdict"),
                log: out
                    .join("logs")
                    .join(&topic.name)
                    .join(relative.with_extension("log")),
            });
            plan.tests.push(PlannedTest {
                task,
                name: test,
                command,
                images_dir,
            });
        }
    }
    for (task, has) in has_binary.iter().enumerate() {
        if !has {
            plan.task_errors[task] = Some(format!(
                "no tests: tests/{}.rs does not exist",
                topic.sheet.tasks[task].id
            ));
        }
    }
    plan
}

/// `dda/octants/steep_line` for test `octants::steep_line` of task `dda`:
/// unique across the topic, one folder per module.
fn test_path(task: &str, test: &str) -> PathBuf {
    let mut path = PathBuf::from(task);
    for part in test.split("::") {
        path.push(part);
    }
    path
}

fn test_env(root: &Path, topic: &Topic, images_dir: &Path) -> Vec<(OsString, OsString)> {
    vec![
        ("RUST_BACKTRACE".into(), "0".into()),
        ("RUST_LIB_BACKTRACE".into(), "0".into()),
        // A failing snapshot leaves `.snap.new` for `cargo insta review`,
        // never touching the official `.snap`.
        ("INSTA_UPDATE".into(), "new".into()),
        // Saves insta a `cargo metadata` in every test process.
        ("INSTA_WORKSPACE_ROOT".into(), root.into()),
        ("TESTKIT_OUTPUT_DIR".into(), images_dir.into()),
        ("PROPTEST_DISABLE_FAILURE_PERSISTENCE".into(), "1".into()),
        // A GPU test without an adapter fails instead of skipping.
        (crate::setup::GPU_REQUIRED_VAR.into(), "1".into()),
        // What `cargo test` sets for a test process.
        ("CARGO_MANIFEST_DIR".into(), topic.dir.clone().into()),
        ("CARGO_PKG_NAME".into(), topic.package.clone().into()),
    ]
}

fn spinner(message: String, shown: bool) -> ProgressBar {
    if !shown {
        return ProgressBar::hidden();
    }
    let spinner = ProgressBar::new_spinner().with_message(message);
    spinner.enable_steady_tick(Duration::from_millis(100));
    spinner
}

/// Runs the given tests `threads` at a time (and, with `permits`, only
/// while one is free), with a progress bar on stderr (hidden when stderr
/// is not a terminal or `progress` is off).
fn run_all(
    plans: &[Plan],
    jobs: &[(usize, usize)],
    threads: usize,
    permits: Option<&Permits>,
    progress: bool,
) -> Result<Vec<Finished>> {
    crate::sandbox::stop_all_on_interrupt();
    let bar = if progress {
        let bar = ProgressBar::new(jobs.len() as u64).with_style(
            ProgressStyle::with_template(
                "{spinner} [{elapsed}] {bar:30} {pos}/{len} tests  {wide_msg}",
            )
            .expect("a valid progress template"),
        );
        bar.enable_steady_tick(Duration::from_millis(100));
        bar
    } else {
        ProgressBar::hidden()
    };
    let next = AtomicUsize::new(0);
    let results: Mutex<Vec<Option<Result<Finished>>>> =
        Mutex::new((0..jobs.len()).map(|_| None).collect());
    // Fail fast: the tasks (plan, task) one of whose tests timed out; their
    // tests not started yet are not run.
    let timed_out: Mutex<std::collections::HashSet<(usize, usize)>> = Mutex::default();
    std::thread::scope(|scope| {
        for _ in 0..threads.min(jobs.len()) {
            scope.spawn(|| {
                loop {
                    let index = next.fetch_add(1, Ordering::Relaxed);
                    let Some(&(p, t)) = jobs.get(index) else {
                        break;
                    };
                    let plan = &plans[p];
                    let test = &plan.tests[t];
                    bar.set_message(format!("{} {}", plan.topic.name, test.name));
                    let command = test.command.as_ref().expect("only runnable tests are jobs");
                    let key = (p, test.task);
                    let skip = timed_out.lock().expect("no worker panics").contains(&key);
                    let result = if skip {
                        Ok(Finished::not_run())
                    } else {
                        let _permit = permits.map(Permits::take);
                        command.run()
                    };
                    if result.as_ref().is_ok_and(|f| f.exit.timed_out) {
                        timed_out.lock().expect("no worker panics").insert(key);
                    }
                    results.lock().expect("no worker panics")[index] = Some(result);
                    bar.inc(1);
                }
            });
        }
    });
    bar.finish_and_clear();
    results
        .into_inner()
        .expect("no worker panics")
        .into_iter()
        .map(|result| result.expect("every job ran"))
        .collect()
}

fn topic_report(
    out: &Path,
    plan: Plan,
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
    for (t, test) in plan.tests.into_iter().enumerate() {
        let task = &mut tasks[test.task];
        let report = match finished(t) {
            None => ignored_test(test.name),
            Some(run) => test_report(out, test, run, time_limit_s),
        };
        match report.status {
            TestStatus::Passed => task.passed += 1,
            TestStatus::Failed => task.failed += 1,
            TestStatus::Ignored => task.ignored += 1,
        }
        task.tests.push(report);
    }
    for task in &mut tasks {
        let counted = task.passed + task.failed;
        if task.status == TaskStatus::Ok && counted == 0 {
            task.status = TaskStatus::Error;
            task.error = Some(format!("all {} tests are #[ignore]d", task.ignored));
        }
        if task.status == TaskStatus::Ok {
            task.score = task.points * task.passed as f64 / counted as f64;
            if task.failed > 0 {
                task.status = TaskStatus::Fail;
            }
        }
        task.score = report::round2(task.score);
    }
    TopicReport {
        name: topic.name.clone(),
        package: topic.package.clone(),
        dir: topic.dir.clone(),
        time_limit_s,
        memory_limit_mib: topic.sheet.memory_limit_mib,
        compile_error: plan.compile_error,
        errors: plan.errors,
        score: report::round2(tasks.iter().map(|t| t.score).sum()),
        max_score: report::round2(tasks.iter().map(TaskReport::max_score).sum()),
        tasks,
    }
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
        duration_s: 0.0,
        exit: Exit::default(),
        output: None,
        log: None,
        images_dir: None,
        images: Vec::new(),
    }
}

fn test_report(out: &Path, test: PlannedTest, run: Finished, time_limit_s: f64) -> TestReport {
    let verdict = outcome::judge(&run.output, &run.exit, &run.token, time_limit_s);
    let status = if verdict.passed {
        TestStatus::Passed
    } else {
        TestStatus::Failed
    };
    // Never following a link, never without end: the folder is the test's.
    let images = crate::sandbox::files_under(&test.images_dir);
    let ran = !run.exit.not_run;
    let relative = |path: PathBuf| {
        path.strip_prefix(out)
            .map(Path::to_path_buf)
            .unwrap_or(path)
    };
    TestReport {
        name: test.name,
        status,
        reason: verdict.reason,
        panic_location: verdict.panic_location,
        minimal_input: verdict.minimal_input,
        raster_diff: verdict.raster_diff,
        snapshot_diff: verdict.snapshot_diff,
        duration_s: report::round2(run.duration.as_secs_f64()),
        exit: run.exit,
        output: (status == TestStatus::Failed).then(|| excerpt(&run.output)),
        log: test
            .command
            .filter(|_| ran)
            .map(|command| relative(command.log)),
        images_dir: (!images.is_empty()).then(|| relative(test.images_dir)),
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
    fn tests_are_graded_in_the_order_their_file_declares_them() {
        let source = "#[testkit::test]\nfn zero_length_line() {}\n\nproptest! {\n    #[testkit::test]\n    fn a_random_property(x in 0..3) {}\n}\n\nmod more {\n    #[test]\n    fn backwards() {}\n}\n";
        let mut tests: Vec<String> = [
            "a_random_property",
            "more::backwards",
            "unknown",
            "zero_length_line",
        ]
        .map(str::to_owned)
        .to_vec();
        in_declaration_order(&mut tests, source);
        assert_eq!(
            tests,
            [
                "zero_length_line",
                "a_random_property",
                "more::backwards",
                "unknown"
            ]
        );
    }

    #[test]
    fn test_paths_are_unique_per_task_and_nest_modules() {
        assert_eq!(
            test_path("dda", "octants::steep"),
            Path::new("dda/octants/steep")
        );
        assert_eq!(test_path("wu", "steep"), Path::new("wu/steep"));
    }

    #[test]
    fn excerpt_keeps_the_end_from_a_line_start() {
        let long = format!("{}\nlast line", "x".repeat(OUTPUT_EXCERPT_CHARS));
        let cut = excerpt(&long);
        assert!(cut.starts_with("[... "), "{cut}");
        assert!(cut.ends_with("\nlast line"), "{cut}");
        assert_eq!(excerpt(" short \n"), "short");
    }
}
