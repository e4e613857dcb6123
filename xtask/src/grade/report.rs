//! The grade report: topics → tasks → tests, as written to `report.json`.
//!
//! ```text
//! Report { schema, root, edition, score, max_score, duration_s, phases, complete, integrity, topics: [
//!   TopicReport { name, package, dir, time_limit_s, memory_limit_mib,
//!                 compile_error, errors, score, max_score, tasks: [
//!     TaskReport { id, title, points, bonus, score, status, error,
//!                  passed, failed, ignored, tests: [
//!       TestReport { name, status, reason, panic_location, minimal_input,
//!                    raster_diff, snapshot_diff, reviewed, snapshot_mismatches,
//!                    duration_s, exit, output, log, images_dir, images }
//! ]}]}]}
//! ```
//!
//! A task scores `points × passed / (passed + failed)`; ignored tests count
//! neither way. Scores are rounded to two decimals in the file.

use std::path::PathBuf;

use std::fmt::Write as _;

use serde::{Deserialize, Serialize};

pub use super::outcome::Exit;
pub use super::submission::Integrity;
pub use crate::sandbox::Containment;

/// Version of the `report.json` layout; bumped when a field changes meaning.
pub const SCHEMA: u32 = 1;

/// Which edition of the code was graded.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Edition {
    /// `exercises/*/src`: the student's code.
    Student,
    /// `--reference`: the tutor's solutions, staged over the stubs.
    Reference,
}

/// A path as JSON text: its lossy UTF-8 form.
fn lossy_path<S: serde::Serializer>(path: &std::path::Path, to: S) -> Result<S::Ok, S::Error> {
    to.serialize_str(&path.to_string_lossy())
}

/// Everything one `cargo xtask grade` found.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Report {
    /// [`SCHEMA`].
    pub schema: u32,
    /// The checkout that was graded (a path that is not UTF-8 is written
    /// lossily: a member's folder name may be anything a file system
    /// takes, and the report is still written).
    #[serde(serialize_with = "lossy_path")]
    pub root: PathBuf,
    /// Student code or reference solutions.
    pub edition: Edition,
    /// Points earned, over all topics graded.
    pub score: f64,
    /// Points possible (bonus points excluded).
    pub max_score: f64,
    /// Wall-clock seconds the grading took.
    pub duration_s: f64,
    /// Where those seconds went.
    #[serde(default)]
    pub phases: Phases,
    /// Every task of every topic was graded: no compile error, no test
    /// binary outside the task list, no task without tests.
    pub complete: bool,
    /// For a submission graded with `--submission`: how its grading files
    /// compare with the official course's (`None` for the checkout itself).
    pub integrity: Option<Integrity>,
    /// The builds and tests ran in the bubblewrap sandbox (see
    /// `crate::sandbox`); `false`: none was available, and nothing kept
    /// student code from the rest of the machine.
    pub sandboxed: bool,
    /// What else held (see `crate::sandbox`): the seccomp filter, and
    /// limits on all of a test's processes together.
    pub containment: Containment,
    /// Per topic, in course order.
    pub topics: Vec<TopicReport>,
    /// The shipped meshes drawn by the graded stages (see `pipeline`);
    /// empty when no topic of the viewer was graded.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub pipeline: Vec<super::pipeline::PipelinePicture>,
    /// What the tests left in the report folder that it does not keep, one
    /// line each with why: links and other entries that are no plain file,
    /// folders nested too deep, files past the grade's budget (see
    /// `files::Keeper`). Removed before the report was written.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub left_out: Vec<String>,
}

impl Report {
    /// What was graded, for titles: the folder name of the submission or
    /// checkout.
    #[must_use]
    pub fn name(&self) -> String {
        self.root.file_name().map_or_else(
            || self.root.display().to_string(),
            |name| name.to_string_lossy().into_owned(),
        )
    }
}

/// The wall-clock seconds of a grade's three phases, one after the other.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct Phases {
    /// Building the topics' test executables and the pipeline's viewer,
    /// and listing the tests.
    pub build_s: f64,
    /// Running the tests.
    pub tests_s: f64,
    /// Drawing the pipeline's pictures with the graded stages.
    pub pipeline_s: f64,
}

/// One topic (exercise crate).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct TopicReport {
    /// Folder name, e.g. `01-lines`.
    pub name: String,
    /// Cargo package name.
    pub package: String,
    /// The topic folder.
    pub dir: PathBuf,
    /// Per-test wall-clock limit used.
    pub time_limit_s: f64,
    /// Per-test address-space limit used (0: none).
    pub memory_limit_mib: u64,
    /// The compiler's errors when the topic did not build.
    pub compile_error: Option<String>,
    /// Problems with the topic's tests themselves (a test binary that is
    /// not a task, a listing that failed).
    pub errors: Vec<String>,
    /// Points earned in this topic.
    pub score: f64,
    /// Points possible in this topic (bonus excluded).
    pub max_score: f64,
    /// Per task, in the task sheet's order.
    pub tasks: Vec<TaskReport>,
}

impl TopicReport {
    /// Points earned in the tasks that are not bonuses (at most
    /// [`Self::max_score`]).
    #[must_use]
    pub fn base_score(&self) -> f64 {
        round2(
            self.tasks
                .iter()
                .filter(|t| !t.bonus)
                .map(|t| t.score)
                .sum(),
        )
    }

    /// Bonus points earned, and possible.
    #[must_use]
    pub fn bonus(&self) -> (f64, f64) {
        let bonus = || self.tasks.iter().filter(|t| t.bonus);
        (
            round2(bonus().map(|t| t.score).sum()),
            round2(bonus().map(|t| t.points).sum()),
        )
    }
}

/// How a task did.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TaskStatus {
    /// Every test passed.
    Ok,
    /// At least one test failed.
    Fail,
    /// The topic did not compile.
    CompileError,
    /// The task could not be graded (no tests).
    Error,
}

/// One task of a topic.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct TaskReport {
    /// Task id (= test binary name).
    pub id: String,
    /// Title from the task sheet.
    pub title: String,
    /// Full points.
    pub points: f64,
    /// Bonus task: its points are not part of `max_score`.
    pub bonus: bool,
    /// Points earned.
    pub score: f64,
    /// How it did.
    pub status: TaskStatus,
    /// Why it could not be graded, for [`TaskStatus::Error`].
    pub error: Option<String>,
    /// The sheet's hints (`cargo xtask hint`).
    pub hints: Vec<String>,
    /// Tests that passed.
    pub passed: usize,
    /// Tests that failed.
    pub failed: usize,
    /// `#[ignore]`d tests (not run, not counted).
    pub ignored: usize,
    /// Per test, in the order libtest lists them.
    pub tests: Vec<TestReport>,
}

/// How a test did.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TestStatus {
    /// Exit status 0 and the run's token (see [`super::outcome::judge`]).
    Passed,
    /// Anything else.
    Failed,
    /// `#[ignore]`d: not run.
    Ignored,
}

/// One test, run in its own process.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct TestReport {
    /// Full test name (`octants::steep_line`).
    pub name: String,
    /// How it did.
    pub status: TestStatus,
    /// Why it failed.
    pub reason: Option<String>,
    /// Where the final panic happened (`file:line:col`).
    pub panic_location: Option<String>,
    /// proptest's shrunk failing input.
    pub minimal_input: Option<String>,
    /// testkit's ASCII raster diff (expected vs yours).
    pub raster_diff: Option<String>,
    /// insta's diff of a mismatching snapshot (`-` stored, `+` yours).
    pub snapshot_diff: Option<String>,
    /// The snapshot a tutor accepted in review (`cargo xtask review`): the
    /// test failed only on it, and passes by that verdict.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reviewed: Option<String>,
    /// The official snapshots this failed test was found to differ from,
    /// as the grader recorded them after the run (see `grade::reviewed`):
    /// the only thing a tutor's review acts on, never the test's reason.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub snapshot_mismatches: Vec<SnapshotMismatch>,
    /// Wall-clock seconds.
    pub duration_s: f64,
    /// How the process ended.
    pub exit: Exit,
    /// The end of its output, for failed tests.
    pub output: Option<String>,
    /// The full output.
    pub log: Option<PathBuf>,
    /// `TESTKIT_OUTPUT_DIR` of the test.
    pub images_dir: Option<PathBuf>,
    /// Files the test wrote there (PNGs), relative to `images_dir`.
    pub images: Vec<PathBuf>,
}

/// An official snapshot a failed test compared its result with and found
/// different, as the grader recorded it (see `grade::reviewed`).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct SnapshotMismatch {
    /// The official snapshot's path in the course
    /// (`exercises/01-lines/tests/snapshots/dda__lines_in_all_octants.snap`).
    pub snapshot: String,
    /// The test's result as the grader captured it after the run: the body
    /// of its pending snapshot (without insta's header), which differs
    /// from the official body. What a tutor accepts or rejects.
    pub captured: String,
}

impl TestReport {
    /// What a failed test found beyond its reason and place, one line
    /// each after a line break: the shrunk input, the raster diff, the
    /// snapshot diff (empty when it found none of them).
    #[must_use]
    pub fn evidence(&self) -> String {
        let mut text = String::new();
        if let Some(input) = &self.minimal_input {
            let _ = write!(text, "\nminimal failing input: {input}");
        }
        if let Some(diff) = &self.raster_diff {
            let _ = write!(text, "\nraster diff (expected vs yours):\n{diff}");
        }
        if let Some(diff) = &self.snapshot_diff {
            let _ = write!(text, "\nsnapshot diff (- expected, + yours):\n{diff}");
        }
        text
    }
}

impl TaskReport {
    /// The failing test that tells the most, if any: one that ran before
    /// one not run (after a timeout), one that checks a rule before one
    /// that compares a whole picture, a literal, named test before a
    /// property's shrunk random case; otherwise in the order of the tests.
    #[must_use]
    pub fn first_failure(&self) -> Option<&TestReport> {
        self.tests
            .iter()
            .filter(|test| test.status == TestStatus::Failed)
            // A test that names its rule before one that compares a whole
            // picture (a snapshot, a reference image): the picture shows
            // where, the rule says why.
            .min_by_key(|test| {
                let picture = test.snapshot_diff.is_some() || !test.images.is_empty();
                (test.exit.not_run, picture, test.minimal_input.is_some())
            })
    }

    /// The full points, or 0 for a bonus task (for maxima).
    #[must_use]
    pub fn max_score(&self) -> f64 {
        if self.bonus { 0.0 } else { self.points }
    }
}

/// Rounds to two decimals, for the files.
#[must_use]
pub fn round2(x: f64) -> f64 {
    // `+ 0.0` turns −0 (the sum of nothing) into 0.
    (x * 100.0).round() / 100.0 + 0.0
}

/// `3` for 3.0, `1.5` for 1.5: points as the task sheet writes them.
#[must_use]
pub fn points(x: f64) -> String {
    if x.fract() == 0.0 {
        format!("{x:.0}")
    } else {
        format!("{x}")
    }
}

impl TaskReport {
    /// Its result in plain text: counts, then the first failure (`topic`
    /// is the topic it belongs to).
    #[must_use]
    pub fn summary(&self, topic: &TopicReport) -> String {
        let task = self;
        let mut text = String::new();
        match task.status {
            TaskStatus::CompileError => {
                let _ = write!(
                    text,
                    "compile error:\n{}",
                    topic.compile_error.as_deref().unwrap_or_default()
                );
            }
            TaskStatus::Error => {
                let _ = write!(
                    text,
                    "not graded: {}",
                    task.error.as_deref().unwrap_or_default()
                );
            }
            TaskStatus::Ok | TaskStatus::Fail => {
                let _ = write!(
                    text,
                    "{} of {} tests passed",
                    task.passed,
                    task.passed + task.failed
                );
                if task.ignored > 0 {
                    let _ = write!(text, " ({} ignored)", task.ignored);
                }
            }
        }
        if let Some(test) = task.first_failure() {
            let _ = write!(text, "\n\nfirst failing test: {}", test.name);
            if let Some(reason) = &test.reason {
                let _ = write!(text, "\nreason: {reason}");
            }
            if let Some(location) = &test.panic_location {
                let _ = write!(text, "\nat: {location}");
            }
            text.push_str(&test.evidence());
            let others = task.failed - 1;
            if others > 0 {
                let _ = write!(text, "\n\n{others} other test(s) of this task failed too");
            }
            if !task.hints.is_empty() {
                let _ = write!(
                    text,
                    "\nhints: `cargo xtask hint {}/{}` ({} of them, one more each time)",
                    topic.name,
                    task.id,
                    task.hints.len()
                );
            }
        }
        text
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// A test of `status`, its reason naming it.
    pub(crate) fn test(name: &str, status: TestStatus) -> TestReport {
        TestReport {
            name: name.to_owned(),
            status,
            reason: Some(format!("{name} failed")),
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

    /// The report of one topic with one task of `points` and `tests`,
    /// scored as the grader scores them.
    pub(crate) fn report_of(points: f64, tests: Vec<TestReport>) -> Report {
        let passed = tests
            .iter()
            .filter(|t| t.status == TestStatus::Passed)
            .count();
        let failed = tests
            .iter()
            .filter(|t| t.status == TestStatus::Failed)
            .count();
        let score = crate::grade::score::task_score(points, passed, passed + failed);
        let mut task = task("t", points, false, score);
        (task.passed, task.failed, task.tests) = (passed, failed, tests);
        let topic = TopicReport {
            name: "01-x".to_owned(),
            package: "x".to_owned(),
            dir: PathBuf::from("exercises/01-x"),
            time_limit_s: 10.0,
            memory_limit_mib: 4096,
            compile_error: None,
            errors: Vec::new(),
            score,
            max_score: points,
            tasks: vec![task],
        };
        Report {
            schema: SCHEMA,
            root: PathBuf::from("anna"),
            edition: Edition::Student,
            score,
            max_score: points,
            duration_s: 1.0,
            phases: Default::default(),
            complete: true,
            integrity: None,
            sandboxed: true,
            containment: Containment::default(),
            topics: vec![topic],
            pipeline: Vec::new(),
            left_out: Vec::new(),
        }
    }

    fn task(id: &str, points: f64, bonus: bool, score: f64) -> TaskReport {
        TaskReport {
            id: id.to_owned(),
            title: id.to_owned(),
            points,
            bonus,
            score,
            status: if score == points {
                TaskStatus::Ok
            } else {
                TaskStatus::Fail
            },
            error: None,
            hints: Vec::new(),
            passed: 0,
            failed: 0,
            ignored: 0,
            tests: Vec::new(),
        }
    }

    #[test]
    fn a_topics_bonus_is_counted_apart_from_its_points() {
        // 3 of 4 points lost, a 3-point bonus earned: the score (7 of 7
        // in total) must not read as full points.
        let topic = TopicReport {
            name: "01-x".to_owned(),
            package: "x".to_owned(),
            dir: PathBuf::from("exercises/01-x"),
            time_limit_s: 10.0,
            memory_limit_mib: 4096,
            compile_error: None,
            errors: Vec::new(),
            score: 7.0,
            max_score: 7.0,
            tasks: vec![
                task("a", 3.0, false, 3.0),
                task("b", 4.0, false, 1.0),
                task("bonus", 3.0, true, 3.0),
            ],
        };
        assert_eq!(topic.base_score(), 4.0);
        assert_eq!(topic.bonus(), (3.0, 3.0));
    }

    #[test]
    fn the_first_failure_shown_is_a_named_test_that_ran() {
        let mut shrunk = test("a_property", TestStatus::Failed);
        shrunk.minimal_input = Some("x = 3".to_owned());
        let mut skipped = test("b_not_run", TestStatus::Failed);
        skipped.exit.not_run = true;
        // A whole picture compared: where, but not which rule.
        let mut picture = test("b_picture", TestStatus::Failed);
        picture.images = vec![PathBuf::from("yours.png")];
        let named = test("c_literal", TestStatus::Failed);
        let later = test("d_literal", TestStatus::Failed);
        let mut task = TaskReport {
            tests: vec![
                shrunk,
                skipped,
                test("passed", TestStatus::Passed),
                picture,
                named,
                later,
            ],
            id: "task".to_owned(),
            title: "A task".to_owned(),
            points: 1.0,
            bonus: false,
            score: 0.0,
            status: TaskStatus::Fail,
            error: None,
            hints: Vec::new(),
            passed: 1,
            failed: 5,
            ignored: 0,
        };
        assert_eq!(task.first_failure().unwrap().name, "c_literal");
        task.tests
            .retain(|t| t.name != "c_literal" && t.name != "d_literal");
        assert_eq!(task.first_failure().unwrap().name, "a_property");
        task.tests.retain(|t| t.name != "a_property");
        assert_eq!(task.first_failure().unwrap().name, "b_picture");
        task.tests.retain(|t| t.name != "b_picture");
        assert_eq!(task.first_failure().unwrap().name, "b_not_run");
    }
}
