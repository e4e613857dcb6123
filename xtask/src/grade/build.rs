//! Building a topic's test executables with cargo.
//!
//! `cargo test -p <package> --no-run --message-format=json-render-diagnostics`
//! prints one JSON message per line on stdout (the executables are in the
//! `compiler-artifact` ones) and renders the compiler's diagnostics on
//! stderr, where a failed build's errors are read from.
//!
//! The build compiles student code, so it is a job of the one runner
//! ([`crate::sandbox`]): it sees the toolchain, the dependencies' sources
//! and the course's files read-only, writes its build folder alone, has
//! no network (the dependencies are fetched before, outside it), and has
//! a time and a memory limit. A build over either fails with that reason
//! ("the build of 01-lines did not finish in 600 s") and is not tried
//! again topic by topic.

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::time::Duration;

use anyhow::{Context as _, Result, bail};

use crate::cargo::{self, cargo};
use crate::sandbox::{Jail, Job, Limits, Purpose};
use crate::topics::Topic;

/// At most this many compiler error blocks are shown for a topic.
const MAX_ERROR_BLOCKS: usize = 8;
/// At most this many lines of compiler errors are shown for a topic.
const MAX_ERROR_LINES: usize = 120;
/// What a build may take by default, the dependencies' first build
/// included (a cold build of the whole course takes some ten minutes on
/// two cores).
pub const DEFAULT_BUILD_TIME_LIMIT: Duration = Duration::from_secs(45 * 60);
/// The CPU time each compiler process may take: no crate of the course or
/// its dependencies takes a tenth of it, while an endless constant
/// evaluation in student code is stopped by it even within the
/// wall-clock limit of a build.
const COMPILER_CPU_LIMIT_S: u64 = 900;

/// What the graded code's programs and libraries may take on disk after a
/// build (the course's whole reference takes some 700 MiB): a large
/// initialised static in a task file is copied into every test program
/// that links it, and a class's build folder would keep every copy.
pub const GRADED_BUILD_BUDGET_MIB: u64 = 3072;

/// An integration-test executable: `tests/<name>.rs`.
#[derive(Debug, Clone)]
pub struct TestBinary {
    /// The test target's name, i.e. the file name without `.rs`.
    pub name: String,
    /// Where cargo put it.
    pub executable: PathBuf,
    /// The same tests built against the replaying crate, for a replayed
    /// topic (see `stage::replay`).
    pub replay: Option<PathBuf>,
}

/// What building a topic gave.
#[derive(Debug)]
pub enum Build {
    /// The test executables, sorted by name.
    Built(Vec<TestBinary>),
    /// The readable compiler errors, or the limit the build ran into.
    Failed(String),
}

/// Where and within what a course is built.
#[derive(Debug, Clone)]
pub struct Builder {
    /// The workspace (a stage, or a checkout graded in place).
    pub root: PathBuf,
    /// cargo's `--target-dir`.
    pub target_dir: PathBuf,
    /// Where cargo's output is kept (the report folder's `build/`).
    pub logs: PathBuf,
    /// The wall-clock limit of one cargo run.
    pub time_limit: Duration,
    /// Folders under the build folder that are not cargo's (a checkout's
    /// reports and stages): shown empty to the build.
    pub emptied: Vec<PathBuf>,
}

impl Builder {
    /// `args` with the stage's features package named too, where the
    /// workspace has one (see `stage::features`): every build of the
    /// grade gets the dependencies' features of the whole course.
    pub fn unified<'a>(&self, mut args: Vec<&'a str>) -> Vec<&'a str> {
        if crate::stage::features::is_in(&self.root) {
            args.extend(["--package", crate::stage::features::FEATURES_PACKAGE]);
        }
        args
    }

    /// Whether nothing was built into the build folder yet: the first
    /// build compiles every dependency too.
    #[must_use]
    pub fn is_first(&self) -> bool {
        std::fs::read_dir(self.target_dir.join("debug").join("deps"))
            .map_or(true, |mut entries| entries.next().is_none())
    }
}

/// How one cargo run of a build ended.
pub struct CargoRun {
    /// It succeeded.
    pub success: bool,
    /// cargo's JSON messages.
    pub stdout: String,
    /// Its rendered diagnostics.
    pub stderr: String,
    /// The limit it ran into, said for a student.
    pub stopped: Option<String>,
}

impl Builder {
    /// Runs cargo with `args` in the workspace as a job of the runner.
    pub fn cargo(&self, what: &str, args: &[&str], env: &[(&str, &str)]) -> Result<CargoRun> {
        fetch(&self.root);
        let stdout = self.logs.join(format!("{what}.out"));
        let stderr = self.logs.join(format!("{what}.err"));
        let temporary = self.target_dir.join("tmp-build");
        let mut limits = Limits::build(self.time_limit);
        limits.output = 256 << 20;
        limits.cpu_s = COMPILER_CPU_LIMIT_S;
        let mut job_env: Vec<(OsString, OsString)> =
            vec![("CARGO_TARGET_DIR".into(), self.target_dir.clone().into())];
        job_env.extend(
            env.iter()
                .map(|(k, v)| (OsString::from(k), OsString::from(v))),
        );
        let job = Job {
            purpose: Purpose::Build,
            program: PathBuf::from("cargo"),
            args: args.iter().map(OsString::from).collect(),
            cwd: self.root.clone(),
            course: self.root.clone(),
            read_only: Vec::new(),
            writable: vec![temporary, self.target_dir.clone()],
            emptied: self.emptied.clone(),
            env: job_env,
            gpu: false,
            limits,
            stdout: stdout.clone(),
            stderr: Some(stderr.clone()),
        };
        let ended = Jail::get().run(&job)?;
        let read = |path: &Path| {
            std::fs::read(path)
                .map(|bytes| String::from_utf8_lossy(&bytes).into_owned())
                .unwrap_or_default()
        };
        let seconds = self.time_limit.as_secs();
        let stopped = if ended.exit.timed_out {
            Some(format!(
                "the build of {what} did not finish in {seconds} s (an endless constant evaluation?), and was stopped"
            ))
        } else if ended.exit.memory_limit.is_some()
            || ended.exit.signal == Some(9)
            || read(&stderr).contains("signal: 9, SIGKILL")
            || read(&stderr).contains("memory allocation of")
        {
            Some(format!(
                "the build of {what} took more than {} MiB of memory, and was stopped",
                limits_memory()
            ))
        } else if ended.exit.signal == Some(24) || read(&stderr).contains("(signal: 24, SIGXCPU") {
            Some(format!(
                "the build of {what} took the compiler more than {COMPILER_CPU_LIMIT_S} s of CPU time (an endless constant evaluation?), and was stopped"
            ))
        } else if ended.exit.signal == Some(25) || read(&stderr).contains("(signal: 25, SIGXFSZ") {
            Some(format!(
                "the build of {what} wrote a file larger than {} MiB, and was stopped",
                Limits::build(Duration::ZERO).file_mib
            ))
        } else if ended.exit.output_limit.is_some() {
            Some(format!(
                "the build of {what} printed without end, and was stopped"
            ))
        } else {
            None
        };
        let stdout = read(&stdout);
        let stopped = stopped.or_else(|| {
            over_budget(
                &stdout,
                &self.root,
                &self.target_dir,
                what,
                GRADED_BUILD_BUDGET_MIB,
            )
        });
        Ok(CargoRun {
            success: ended.success(),
            stdout,
            stderr: read(&stderr),
            stopped,
        })
    }
}

fn limits_memory() -> u64 {
    Limits::build(Duration::ZERO).memory_mib
}

/// Downloads what the workspace at `root` depends on (outside any sandbox:
/// the sandboxed build has no network), so that it builds offline. A
/// machine without a network may have everything already: a failure is a
/// warning, and the build says what is missing, if anything. The course's
/// manifests are the course's own, not a student's.
fn fetch(root: &Path) {
    static FETCHED: std::sync::Mutex<Vec<PathBuf>> = std::sync::Mutex::new(Vec::new());
    let mut fetched = FETCHED
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    if fetched.iter().any(|done| done == root) {
        return;
    }
    let mut command = cargo();
    command
        .current_dir(root)
        .args(["fetch", "--color", "never"]);
    match command.output() {
        Ok(output) if output.status.success() => fetched.push(root.to_path_buf()),
        Ok(output) => eprintln!(
            "warning: `{}` failed; building with what is already downloaded: {}",
            cargo::display(&command),
            String::from_utf8_lossy(&output.stderr).trim()
        ),
        Err(error) => eprintln!(
            "warning: cannot run `{}`: {error}",
            cargo::display(&command)
        ),
    }
}

/// The target folder cargo builds `root` into.
#[must_use]
pub fn target_dir_of(root: &Path, target_dir: Option<&Path>) -> PathBuf {
    target_dir.map(Path::to_path_buf).unwrap_or_else(|| {
        std::env::var_os("CARGO_TARGET_DIR")
            .map(|dir| {
                let dir = PathBuf::from(dir);
                if dir.is_absolute() {
                    dir
                } else {
                    root.join(dir)
                }
            })
            .unwrap_or_else(|| root.join("target"))
    })
}

/// Builds the tests of all `topics` in one cargo run, which builds their
/// shared dependencies once, with the features of the whole set (as the
/// course's own `cargo test --workspace` does, so its artifacts serve).
/// `Err(None)` when the build fails: then each topic is built on its own
/// with [`build`], so that one topic's compile errors fail that topic
/// alone; `Err(Some(reason))` when it ran into a limit, which every topic
/// fails with (building them one by one would only run into it again).
pub fn build_all(
    builder: &Builder,
    topics: &[Topic],
) -> Result<std::result::Result<Vec<Vec<TestBinary>>, Option<String>>> {
    let mut args = cargo_test_args();
    for topic in topics {
        args.extend(["--package", &topic.package]);
    }
    let mut targets: Vec<String> = topics.iter().flat_map(|t| test_targets(&t.dir)).collect();
    targets.sort();
    targets.dedup();
    let args = builder.unified(only_tests(args, &targets));
    let names: Vec<&str> = topics.iter().map(|t| t.name.as_str()).collect();
    let run = builder.cargo(&names.join("+"), &args, &[])?;
    if let Some(stopped) = run.stopped {
        return Ok(Err(Some(stopped)));
    }
    if !run.success {
        return Ok(Err(None));
    }
    Ok(Ok(topics
        .iter()
        .map(|topic| test_binaries(&run.stdout, Some(&topic.dir)))
        .collect()))
}

/// `args` with `--test` for each of `targets`, the integration tests a
/// grade runs: not the libraries' own unit tests, which no task holds.
/// With no targets, `args` as they are (cargo builds every test).
fn only_tests<'a>(mut args: Vec<&'a str>, targets: &'a [String]) -> Vec<&'a str> {
    for target in targets {
        args.extend(["--test", target]);
    }
    args
}

/// `cargo test --no-run` with JSON messages.
fn cargo_test_args() -> Vec<&'static str> {
    vec![
        "test",
        "--no-run",
        "--color",
        "never",
        "--message-format=json-render-diagnostics",
    ]
}

/// Builds `topic`'s tests in the workspace.
pub fn build(builder: &Builder, topic: &Topic) -> Result<Build> {
    let mut args = cargo_test_args();
    args.extend(["--package", &topic.package]);
    let targets = test_targets(&topic.dir);
    let args = builder.unified(only_tests(args, &targets));
    let run = builder.cargo(&topic.name, &args, &[])?;
    if let Some(stopped) = run.stopped {
        return Ok(Build::Failed(stopped));
    }
    if !run.success {
        return Ok(Build::Failed(compiler_errors(&run.stderr)));
    }
    Ok(Build::Built(test_binaries(&run.stdout, None)))
}

/// Builds `topic`'s tests alone, as a build of all of `topics` (which
/// holds it) would: cargo chooses the dependencies' features by the
/// packages a build names, so the topic's test targets are named with
/// every topic's package, and the dependencies are built once, with the
/// features of the whole set, whichever topic comes first. (A test file
/// of the same name in another topic is built with it: found again when
/// that topic's turn comes.)
///
/// In a stage, whose features package (see `stage::features`) does what
/// naming every topic would, the topic is built on its own.
pub fn build_among(builder: &Builder, topics: &[Topic], topic: &Topic) -> Result<Build> {
    let targets = test_targets(&topic.dir);
    // A stage's features package does what naming the others would.
    if topics.len() < 2 || targets.is_empty() || crate::stage::features::is_in(&builder.root) {
        return build(builder, topic);
    }
    let mut args = cargo_test_args();
    for topic in topics {
        args.extend(["--package", &topic.package]);
    }
    for target in &targets {
        args.extend(["--test", target]);
    }
    let run = builder.cargo(&topic.name, &args, &[])?;
    if let Some(stopped) = run.stopped {
        return Ok(Build::Failed(stopped));
    }
    if !run.success {
        return Ok(Build::Failed(compiler_errors(&run.stderr)));
    }
    Ok(Build::Built(test_binaries(&run.stdout, Some(&topic.dir))))
}

/// The names of the integration-test targets of the package at `dir`:
/// cargo's `tests/<name>.rs` and `tests/<name>/main.rs`.
fn test_targets(dir: &Path) -> Vec<String> {
    let Ok(entries) = std::fs::read_dir(dir.join("tests")) else {
        return Vec::new();
    };
    let mut names: Vec<String> = entries
        .filter_map(|entry| {
            let entry = entry.ok()?;
            let name = entry.file_name().into_string().ok()?;
            let kind = entry.file_type().ok()?;
            if kind.is_file() {
                name.strip_suffix(".rs").map(str::to_owned)
            } else if kind.is_dir() && entry.path().join("main.rs").is_file() {
                Some(name)
            } else {
                None
            }
        })
        .collect();
    names.sort();
    names
}

/// Builds the replay package of `topic`, whose folder in the stage is
/// `package_dir` (see `stage::replay`), and pairs each of `binaries` with
/// its replaying twin. The package is the course's own code: a failure is
/// the course's, and stops the grade.
pub fn add_replays(
    builder: &Builder,
    topic: &Topic,
    package_dir: &Path,
    binaries: &mut [TestBinary],
) -> Result<()> {
    let package = crate::stage::replay::package_name(topic);
    let mut args = cargo_test_args();
    args.extend(["--package", &package]);
    let targets = test_targets(package_dir);
    let args = builder.unified(only_tests(args, &targets));
    let what = format!("{}{}", topic.name, crate::stage::replay::REPLAY_SUFFIX);
    let run = builder.cargo(&what, &args, &[])?;
    if !run.success {
        bail!(
            "the replay build of {} failed (the course's own code, not the graded one): {}",
            topic.name,
            run.stopped.unwrap_or_else(|| compiler_errors(&run.stderr))
        );
    }
    let replays = test_binaries(&run.stdout, Some(package_dir));
    for binary in binaries {
        let twin = replays
            .iter()
            .find(|replay| replay.name == binary.name)
            .with_context(|| {
                format!(
                    "the replay build of {} has no test `{}`",
                    topic.name, binary.name
                )
            })?;
        binary.replay = Some(twin.executable.clone());
    }
    Ok(())
}

/// The files cargo reports having made for the graded packages (those
/// under `<root>/exercises/`: the student's code, not the course's given
/// crates or replay builds), with their bytes on disk. Only files in the
/// build folder `build_dir` count: nothing else is ever removed for them.
fn graded_artifacts(messages: &str, root: &Path, build_dir: &Path) -> (Vec<PathBuf>, u64) {
    let graded = root.join("exercises");
    let mut files: Vec<PathBuf> = messages
        .lines()
        .filter_map(crate::cargo::Message::parse)
        .filter(|message| message.is_artifact())
        .filter(|message| {
            message
                .manifest_path
                .as_deref()
                .is_some_and(|manifest| manifest.starts_with(&graded))
        })
        .flat_map(|message| message.filenames.into_iter().chain(message.executable))
        .filter(|file| {
            file.starts_with(build_dir)
                && !file
                    .components()
                    .any(|c| c == std::path::Component::ParentDir)
        })
        .collect();
    files.sort();
    files.dedup();
    let bytes = files
        .iter()
        .filter_map(|file| std::fs::symlink_metadata(file).ok())
        .map(|metadata| metadata.len())
        .sum();
    (files, bytes)
}

/// Past `budget_mib` ([`GRADED_BUILD_BUDGET_MIB`]), the reason, once the
/// graded packages' files are removed again (the build folder is shared
/// by a class: they would stay there).
fn over_budget(
    messages: &str,
    root: &Path,
    build_dir: &Path,
    what: &str,
    budget_mib: u64,
) -> Option<String> {
    let (files, bytes) = graded_artifacts(messages, root, build_dir);
    if bytes <= budget_mib << 20 {
        return None;
    }
    for file in &files {
        let _ = std::fs::remove_file(file);
    }
    Some(format!(
        "the build of {what} made {} MiB of programs and libraries from the graded code, more than the {budget_mib} MiB a grade may keep (a large initialised static copied into every test program?); they were removed",
        bytes >> 20
    ))
}

/// The integration-test executables among cargo's JSON messages, of the
/// package in `package_dir` when given.
fn test_binaries(messages: &str, package_dir: Option<&Path>) -> Vec<TestBinary> {
    let mut binaries: Vec<TestBinary> = messages
        .lines()
        .filter_map(crate::cargo::Message::parse)
        .filter(|message| message.is_artifact())
        .filter(|message| {
            package_dir.is_none_or(|dir| {
                message
                    .manifest_path
                    .as_deref()
                    .and_then(Path::parent)
                    .is_some_and(|parent| parent == dir)
            })
        })
        .filter_map(|message| {
            let target = message.target?;
            let is_test = target.kind.iter().any(|kind| kind == "test")
                && message.profile.is_some_and(|profile| profile.test);
            is_test.then_some(TestBinary {
                name: target.name,
                executable: message.executable?,
                replay: None,
            })
        })
        .collect();
    binaries.sort_by(|a, b| a.name.cmp(&b.name));
    binaries.dedup_by(|a, b| a.name == b.name);
    binaries
}

/// The `error` blocks of cargo's rendered diagnostics, without warnings and
/// progress lines; the tail of stderr when there are none (cargo's own
/// errors, e.g. a broken `Cargo.toml`).
fn compiler_errors(stderr: &str) -> String {
    let mut blocks: Vec<Vec<&str>> = Vec::new();
    let mut summaries = Vec::new();
    // Inside an error block: its lines are kept until a blank line ends it.
    let mut in_error = false;
    let mut after_blank = false;
    for line in stderr.lines() {
        if line.trim().is_empty() {
            after_blank = true;
            continue;
        }
        let blank = std::mem::take(&mut after_blank);
        if in_error && blank && line == "Caused by:" {
            // cargo's own errors explain themselves after a blank line.
            blocks.last_mut().expect("in a block").extend(["", line]);
        } else if line.starts_with("error: could not compile") {
            summaries.push(line);
            in_error = false;
        } else if line.starts_with("error") {
            blocks.push(vec![line]);
            in_error = true;
        } else if blank || line.starts_with("warning") || is_cargo_status(line) {
            in_error = false;
        } else if in_error {
            blocks.last_mut().expect("in a block").push(line);
        }
    }
    if blocks.is_empty() {
        if !summaries.is_empty() {
            return summaries.join("\n");
        }
        let lines: Vec<&str> = stderr.lines().collect();
        return lines[lines.len().saturating_sub(30)..]
            .join("\n")
            .trim()
            .to_owned();
    }
    let total = blocks.len();
    let mut text = String::new();
    let mut lines = 0;
    let mut shown = 0;
    for block in &blocks {
        if shown == MAX_ERROR_BLOCKS || (shown > 0 && lines + block.len() > MAX_ERROR_LINES) {
            break;
        }
        text.push_str(&block.join("\n"));
        text.push_str("\n\n");
        lines += block.len() + 1;
        shown += 1;
    }
    if shown < total {
        text.push_str(&format!("... and {} more error(s)\n", total - shown));
    }
    for summary in summaries {
        text.push_str(summary);
        text.push('\n');
    }
    text.trim_end().to_owned()
}

/// cargo's progress lines: a verb right-aligned in 12 columns
/// (`   Compiling lines v0.1.0`).
fn is_cargo_status(line: &str) -> bool {
    let (Some(verb), Some(b' ')) = (line.get(..12), line.as_bytes().get(12)) else {
        return false;
    };
    let verb = verb.trim_start();
    verb.starts_with(|c: char| c.is_ascii_uppercase())
        && verb.chars().all(|c| c.is_ascii_alphabetic())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn test_targets_are_the_files_and_folders_cargo_builds_as_tests() {
        let dir = std::env::temp_dir().join(format!("test-targets-{}", std::process::id()));
        let tests = dir.join("tests");
        for folder in ["common", "images", "walk"] {
            std::fs::create_dir_all(tests.join(folder)).unwrap();
        }
        for file in [
            "dda.rs",
            "wu.rs",
            "common/mod.rs",
            "walk/main.rs",
            "notes.txt",
        ] {
            std::fs::write(tests.join(file), "").unwrap();
        }
        assert_eq!(test_targets(&dir), ["dda", "walk", "wu"]);
        std::fs::remove_dir_all(&dir).unwrap();
        assert!(test_targets(&dir).is_empty());
    }

    #[test]
    fn test_executables_are_the_test_targets_built_for_testing() {
        let messages = r#"{"reason":"compiler-artifact","target":{"kind":["lib"],"name":"lines"},"profile":{"test":false},"executable":null}
{"reason":"compiler-artifact","target":{"kind":["lib"],"name":"lines"},"profile":{"test":true},"executable":"/t/lines-1"}
{"reason":"compiler-artifact","target":{"kind":["test"],"name":"wu"},"profile":{"test":true},"executable":"/t/wu-2"}
{"reason":"compiler-artifact","target":{"kind":["test"],"name":"dda"},"profile":{"test":true},"executable":"/t/dda-3"}
{"reason":"build-script-executed"}
not json
{"reason":"build-finished","success":true}"#;
        let binaries = test_binaries(messages, None);
        let names: Vec<&str> = binaries.iter().map(|b| b.name.as_str()).collect();
        assert_eq!(names, ["dda", "wu"]);
        assert_eq!(binaries[0].executable, Path::new("/t/dda-3"));
    }

    #[test]
    fn the_graded_code_s_programs_past_the_budget_are_removed_with_the_reason() {
        let dir = std::env::temp_dir().join(format!("budget-{}", std::process::id()));
        let deps = dir.join("target").join("debug").join("deps");
        std::fs::create_dir_all(&deps).unwrap();
        let sized = |name: &str, bytes: u64| {
            let path = deps.join(name);
            std::fs::File::create(&path)
                .unwrap()
                .set_len(bytes)
                .unwrap();
            path
        };
        // Two test programs of the graded package, 3 MiB in all, and a
        // dependency's library of 5 MiB that is no part of the count.
        let dda = sized("dda-1", 2 << 20);
        let wu = sized("wu-2", 1 << 20);
        let glam = sized("libglam-3.rlib", 5 << 20);
        // (JSON written by serde: Windows paths hold backslashes.)
        let message = |manifest: &Path, file: &Path| {
            serde_json::json!({
                "reason": "compiler-artifact",
                "manifest_path": manifest,
                "filenames": [file],
                "executable": null,
            })
            .to_string()
        };
        let graded = dir.join("exercises").join("01-lines").join("Cargo.toml");
        // A file outside the build folder named as an artifact (cargo never
        // does) is neither counted nor removed.
        let outside = dir.join("notes.txt");
        std::fs::File::create(&outside)
            .unwrap()
            .set_len(4 << 20)
            .unwrap();
        let messages = [
            message(&graded, &dda),
            message(&graded, &wu),
            message(&graded, &outside),
            message(Path::new("/registry/glam/Cargo.toml"), &glam),
        ]
        .join("\n");
        let build = dir.join("target");
        assert_eq!(graded_artifacts(&messages, &dir, &build).1, 3 << 20);
        assert_eq!(over_budget(&messages, &dir, &build, "01-lines", 3), None);
        assert!(dda.exists() && wu.exists());
        let reason = over_budget(&messages, &dir, &build, "01-lines", 2).unwrap();
        assert!(
            reason.contains("3 MiB") && reason.contains("2 MiB"),
            "{reason}"
        );
        assert!(
            !dda.exists() && !wu.exists(),
            "the graded programs are removed"
        );
        assert!(glam.exists(), "the dependencies' are not");
        assert!(
            outside.exists(),
            "nothing outside the build folder is removed"
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn compiler_errors_keep_error_blocks_only() {
        let stderr = "   Compiling lines v0.1.0 (/w/exercises/01-lines)
warning: unused variable: `a`
 --> src/dda.rs:1:8
  |
1 | fn f(a: u32) {}
  |      ^ help: prefix it

error[E0308]: mismatched types
 --> src/dda.rs:3:5
  |
3 |     1.0
  |     ^^^ expected `u32`, found floating-point number
  |
help: change the type
  |
3 +     1
  |

For more information about this error, try `rustc --explain E0308`.
warning: `lines` (lib) generated 1 warning
error: could not compile `lines` (lib) due to 1 previous error; 1 warning emitted
";
        assert_eq!(
            compiler_errors(stderr),
            "error[E0308]: mismatched types
 --> src/dda.rs:3:5
  |
3 |     1.0
  |     ^^^ expected `u32`, found floating-point number
  |
help: change the type
  |
3 +     1
  |

error: could not compile `lines` (lib) due to 1 previous error; 1 warning emitted"
        );
        assert_eq!(
            compiler_errors(
                "error: failed to parse manifest at `/w/Cargo.toml`\n\nCaused by:\n  bad\n"
            ),
            "error: failed to parse manifest at `/w/Cargo.toml`\n\nCaused by:\n  bad"
        );
    }
}
