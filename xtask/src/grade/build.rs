//! Building a topic's test executables with cargo.
//!
//! `cargo test -p <package> --no-run --message-format=json-render-diagnostics`
//! prints one JSON message per line on stdout (the executables are in the
//! `compiler-artifact` ones) and renders the compiler's diagnostics on
//! stderr, where a failed build's errors are read from.
//!
//! Where the tests run in a sandbox, so does the build ([`BuildSandbox`]):
//! compiling reads the student's files, and whatever a macro of a
//! dependency might read or write at compile time, it finds the file
//! system read-only, the solutions, the submissions and the reports
//! hidden, and no network; only the build's target folder is writable.
//! The dependencies are fetched before, outside it.

use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{Context, Result};
use serde::Deserialize;

use crate::cargo::{self, cargo};
use crate::topics::Topic;

/// At most this many compiler error blocks are shown for a topic.
const MAX_ERROR_BLOCKS: usize = 8;
/// At most this many lines of compiler errors are shown for a topic.
const MAX_ERROR_LINES: usize = 120;

/// An integration-test executable: `tests/<name>.rs`.
#[derive(Debug, Clone)]
pub struct TestBinary {
    /// The test target's name, i.e. the file name without `.rs`.
    pub name: String,
    /// Where cargo put it.
    pub executable: PathBuf,
}

/// What building a topic gave.
#[derive(Debug)]
pub enum Build {
    /// The test executables, sorted by name.
    Built(Vec<TestBinary>),
    /// The readable compiler errors.
    Failed(String),
}

/// The bubblewrap sandbox of a build: `/` read-only, `hidden` folders
/// empty, `target_dir` writable (the compiler's temporary files go to a
/// folder in it: `/tmp` stays read-only, and no tmpfs covers it, since the
/// course itself may live under `/tmp`), no network, its own process
/// namespace.
#[derive(Debug, Clone)]
pub struct BuildSandbox {
    /// The `bwrap` program.
    pub program: PathBuf,
    /// Folders shown empty (a hidden folder holding the workspace or the
    /// target folder is left alone).
    pub hidden: Vec<PathBuf>,
    /// cargo's `--target-dir`: the one folder the build writes.
    pub target_dir: PathBuf,
}

impl BuildSandbox {
    /// `cargo`, run offline inside the sandbox, in `cargo`'s folder.
    pub(crate) fn wrap(&self, cargo: &Command) -> Result<Command> {
        std::fs::create_dir_all(&self.target_dir)
            .with_context(|| format!("cannot create {}", self.target_dir.display()))?;
        let temporary = self.target_dir.join("tmp-build");
        std::fs::create_dir_all(&temporary)
            .with_context(|| format!("cannot create {}", temporary.display()))?;
        let cwd = cargo.get_current_dir().map(Path::to_path_buf);
        let mut command = Command::new(&self.program);
        command.args(["--ro-bind", "/", "/", "--dev", "/dev", "--proc", "/proc"]);
        let keeps = |dir: &Path| {
            cwd.as_deref().is_some_and(|c| c.starts_with(dir)) || self.target_dir.starts_with(dir)
        };
        // The target folder first, so that a hidden folder inside it (the
        // reports, under `target/grade`) is hidden too.
        command
            .arg("--bind")
            .arg(&self.target_dir)
            .arg(&self.target_dir);
        for dir in self.hidden.iter().filter(|d| d.exists() && !keeps(d)) {
            command.arg("--tmpfs").arg(dir);
        }
        command.args(["--unshare-all", "--die-with-parent", "--new-session"]);
        if let Some(cwd) = &cwd {
            command.arg("--chdir").arg(cwd);
            command.current_dir(cwd);
        }
        command.arg(cargo.get_program()).args(cargo.get_args());
        for (key, value) in cargo.get_envs() {
            match value {
                Some(value) => command.env(key, value),
                None => command.env_remove(key),
            };
        }
        command.env("CARGO_NET_OFFLINE", "true");
        command.env("TMPDIR", &temporary);
        Ok(command)
    }
}

/// Downloads what the workspace at `root` depends on (outside any sandbox:
/// the sandboxed build has no network), so that it builds offline. A
/// machine without a network may have everything already: a failure is a
/// warning, and the build says what is missing, if anything.
fn fetch(root: &Path) {
    let mut command = cargo();
    command
        .current_dir(root)
        .args(["fetch", "--color", "never"]);
    match command.output() {
        Ok(output) if output.status.success() => {}
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

/// `cargo test --no-run` for `root`, in `sandbox` when given.
fn build_command(
    root: &Path,
    target_dir: Option<&Path>,
    sandbox: Option<&BuildSandbox>,
) -> Result<Command> {
    let command = cargo_test(root, target_dir);
    match sandbox {
        Some(sandbox) => {
            fetch(root);
            sandbox.wrap(&command)
        }
        None => Ok(command),
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

#[derive(Deserialize)]
struct Message {
    reason: String,
    #[serde(default)]
    manifest_path: Option<PathBuf>,
    #[serde(default)]
    target: Option<Target>,
    #[serde(default)]
    profile: Option<Profile>,
    #[serde(default)]
    executable: Option<PathBuf>,
}

#[derive(Deserialize)]
struct Target {
    name: String,
    kind: Vec<String>,
}

#[derive(Deserialize)]
struct Profile {
    test: bool,
}

/// Builds the tests of all `topics` in one cargo run, which builds their
/// shared dependencies once, with the features of the whole set (as the
/// course's own `cargo test --workspace` does, so its artifacts serve).
/// `None` when the build fails: then each topic is built on its own with
/// [`build`], so that one topic's compile errors fail that topic alone.
pub fn build_all(
    root: &Path,
    topics: &[Topic],
    target_dir: Option<&Path>,
    sandbox: Option<&BuildSandbox>,
) -> Result<Option<Vec<Vec<TestBinary>>>> {
    let mut command = build_command(root, target_dir, sandbox)?;
    for topic in topics {
        command.args(["--package", &topic.package]);
    }
    let output = command
        .output()
        .with_context(|| format!("cannot run `{}`", cargo::display(&command)))?;
    if !output.status.success() {
        return Ok(None);
    }
    let stdout = String::from_utf8_lossy(&output.stdout);
    Ok(Some(
        topics
            .iter()
            .map(|topic| test_binaries(&stdout, Some(&topic.dir)))
            .collect(),
    ))
}

/// `cargo test --no-run` with JSON messages, in `root`.
fn cargo_test(root: &Path, target_dir: Option<&Path>) -> Command {
    let mut command = cargo();
    command
        .current_dir(root)
        .args(["test", "--no-run", "--color", "never"])
        .arg("--message-format=json-render-diagnostics");
    if let Some(dir) = target_dir {
        command.arg("--target-dir").arg(dir);
    }
    command
}

/// Builds `topic`'s tests in the workspace at `root`.
pub fn build(
    root: &Path,
    topic: &Topic,
    target_dir: Option<&Path>,
    sandbox: Option<&BuildSandbox>,
) -> Result<Build> {
    let mut command = build_command(root, target_dir, sandbox)?;
    command.args(["--package", &topic.package]);
    let output = command
        .output()
        .with_context(|| format!("cannot run `{}`", cargo::display(&command)))?;
    let stderr = String::from_utf8_lossy(&output.stderr);
    if !output.status.success() {
        return Ok(Build::Failed(compiler_errors(&stderr)));
    }
    let stdout = String::from_utf8_lossy(&output.stdout);
    Ok(Build::Built(test_binaries(&stdout, None)))
}

/// The integration-test executables among cargo's JSON messages, of the
/// package in `package_dir` when given.
fn test_binaries(messages: &str, package_dir: Option<&Path>) -> Vec<TestBinary> {
    let mut binaries: Vec<TestBinary> = messages
        .lines()
        .filter_map(|line| serde_json::from_str::<Message>(line).ok())
        .filter(|message| message.reason == "compiler-artifact")
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
