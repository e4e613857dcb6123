//! Planning a topic's tests: each test of each task's executable, listed
//! by running the executable (a job of the runner, as a test is), in the
//! order its file declares them, with the folders and environment it gets.

use std::ffi::OsString;
use std::fs;
use std::path::{Path, PathBuf};
use std::time::Duration;

use super::PENDING_SNAPSHOTS;
use super::build::{Build, TestBinary};
use super::run::{self, TestCommand};
use crate::topics::Topic;

/// Where a grade's GPU tests keep the shaders the driver compiled, in the
/// grade's folder (see [`run::ShaderCache`]); removed with
/// the scratch folders.
pub(super) const SHADER_CACHE: &str = "shader-cache";

/// A topic ready to run: its tests, or why there are none.
pub(super) struct Plan {
    pub(super) topic: Topic,
    pub(super) compile_error: Option<String>,
    pub(super) errors: Vec<String>,
    /// Per task (sheet order): an error that keeps it from being graded.
    pub(super) task_errors: Vec<Option<String>>,
    pub(super) tests: Vec<PlannedTest>,
    /// The graded code does not hold the topic: nothing was built or run.
    pub(super) absent: bool,
}

pub(super) struct PlannedTest {
    pub(super) task: usize,
    pub(super) name: String,
    /// `None` for ignored tests, which are not run.
    pub(super) command: Option<TestCommand>,
    pub(super) images_dir: PathBuf,
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
pub(super) fn plan(root: &Path, out: &Path, topic: &Topic, build: Build) -> Plan {
    let mut plan = Plan {
        topic: topic.clone(),
        compile_error: None,
        errors: Vec::new(),
        task_errors: vec![None; topic.sheet.tasks.len()],
        tests: Vec::new(),
        absent: false,
    };
    let binaries = match build {
        Build::Built(binaries) => binaries,
        Build::Failed(errors) => {
            plan.compile_error = Some(errors);
            return plan;
        }
    };
    let mut has_binary = vec![false; topic.sheet.tasks.len()];
    for TestBinary {
        name,
        executable,
        replay,
    } in binaries
    {
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
        // The replay's list where there is one: that build holds no
        // student code.
        let listed_from = replay.as_ref().unwrap_or(&executable);
        let list = |ignored| run::list_tests(listed_from, &topic.dir, root, &listing, ignored);
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
                shader_cache: topic.sheet.gpu.then(|| out.join(SHADER_CACHE)),
                env,
                time_limit: Duration::from_secs_f64(topic.sheet.time_limit_s),
                memory_limit_mib: topic.sheet.memory_limit_mib,
                verdict_file: scratch.join(".testkit-verdict"),
                replay: replay.clone(),
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

/// Why the tasks of topic `name` score 0 in code that does not hold it.
pub(super) fn absent_reason(name: &str) -> String {
    format!("the submission has no exercises/{name}: its tasks score 0")
}

/// A topic the graded code does not hold: each task an error, no tests.
pub(super) fn absent(topic: &Topic) -> Plan {
    let why = absent_reason(&topic.name);
    Plan {
        topic: topic.clone(),
        compile_error: None,
        errors: Vec::new(),
        task_errors: vec![Some(why); topic.sheet.tasks.len()],
        tests: Vec::new(),
        absent: true,
    }
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
        // No "XDG_RUNTIME_DIR is invalid" from Mesa's device-select layer
        // in every log (as `.cargo/config.toml` sets it for `cargo test`).
        ("NODEVICE_SELECT".into(), "1".into()),
        // What `cargo test` sets for a test process.
        ("CARGO_MANIFEST_DIR".into(), topic.dir.clone().into()),
        ("CARGO_PKG_NAME".into(), topic.package.clone().into()),
    ]
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
}
