//! Running one test in its own process, so that nothing the student's code
//! does (loop, overflow its stack, abort, exit, allocate without end) can
//! take the grader down with it.
//!
//! The child writes stdout and stderr into one log file (a pipe nobody reads
//! fast enough would block it); the grader polls it with `try_wait` and kills
//! it at the wall-clock limit or when the log grows past [`OUTPUT_LIMIT`].
//! On Unix the address space is capped with `ulimit -v` in a tiny `sh`
//! wrapper that then `exec`s the test, so the limit needs no unsafe code.
//! The test leads a process group of its own, and when it ends (or is
//! killed) the whole group is killed: a process it started and left
//! running does not outlive it. (A process that leaves the group with
//! `setsid` escapes this; closing that is the sandbox's work.) Because the
//! groups are not the terminal's, Ctrl-C reaches the grader alone: its
//! handler ([`stop_tests_on_interrupt`]) kills every running group, then
//! exits.

use std::collections::BTreeSet;
use std::ffi::OsString;
use std::fs::{self, File};
use std::io::{Read as _, Seek as _, SeekFrom};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::{Mutex, Once};
use std::time::{Duration, Instant};

use anyhow::{Context, Result};

use super::outcome::Exit;

/// A test that prints more than this is stopped: endless printing would
/// otherwise fill the disk before the time limit.
pub const OUTPUT_LIMIT: u64 = 64 << 20;
/// Of a test stopped at [`OUTPUT_LIMIT`], this much output is kept.
const FLOOD_KEPT: usize = 64 << 10;
/// Only the end of a long log is read back: the verdict is at the end.
const READ_BACK_LIMIT: u64 = 4 << 20;
/// How often a running test is checked on.
const POLL_INTERVAL: Duration = Duration::from_millis(10);
/// Shells and bwrap report death by signal `n` as exit code `128 + n`.
const SIGNAL_EXIT_BASE: i32 = 128;
/// The exit code after an interrupt (128 + SIGINT, as shells report it).
const INTERRUPTED_EXIT_CODE: i32 = SIGNAL_EXIT_BASE + 2;

/// The environment variable that names a test's token file (see
/// `crates/testkit-macros`, which reads it).
pub const VERDICT_FILE_VAR: &str = "TESTKIT_VERDICT_FILE";

/// The process groups of the tests running now.
static RUNNING: Mutex<BTreeSet<u32>> = Mutex::new(BTreeSet::new());

/// Makes Ctrl-C (and SIGTERM) kill every running test's process group
/// before the grader exits; once per process, later calls do nothing.
pub fn stop_tests_on_interrupt() {
    static INSTALL: Once = Once::new();
    INSTALL.call_once(|| {
        let installed = ctrlc::set_handler(|| {
            let groups = RUNNING.lock().map(|g| g.clone()).unwrap_or_default();
            for pgid in groups {
                kill_group(pgid);
            }
            eprintln!("\ninterrupted: the running tests were stopped");
            std::process::exit(INTERRUPTED_EXIT_CODE);
        });
        if let Err(error) = installed {
            eprintln!("warning: Ctrl-C will not stop running tests: {error}");
        }
    });
}

/// The bubblewrap sandbox a test runs in: the whole file system read-only,
/// the home folder and the `hidden` folders empty, only `writable` folders
/// writable, a `/tmp` of its own, no network, its own process namespace
/// (so every process it starts dies with it, and no other process is
/// visible, the grader's included), a new session (no terminal).
#[derive(Debug, Clone)]
pub struct Sandbox {
    /// The `bwrap` program.
    pub program: PathBuf,
    /// Folders shown read-only even inside the hidden home folder: the
    /// course being graded and its build.
    pub read_only: Vec<PathBuf>,
    /// Folders shown empty: solutions, other submissions, reports.
    pub hidden: Vec<PathBuf>,
    /// Folders the test may write (created first): its scratch folder,
    /// its pictures, pending snapshots.
    pub writable: Vec<PathBuf>,
}

impl Sandbox {
    /// `bwrap` and its options, up to the program it runs.
    pub(crate) fn command(&self, cwd: &Path) -> Command {
        let mut command = Command::new(&self.program);
        // No `/proc`: neither the grader nor another test is visible, and a
        // test cannot read its own memory or first environment through
        // `/proc/self` (see `crates/testkit-macros`). The root's bind would
        // show the host's `/proc`, so an empty one covers it.
        command.args(["--ro-bind", "/", "/", "--dev", "/dev", "--tmpfs", "/proc"]);
        command.args(["--tmpfs", "/tmp"]);
        if let Some(home) = std::env::var_os("HOME").filter(|h| Path::new(h) != Path::new("/")) {
            command.arg("--tmpfs").arg(home);
        }
        for dir in &self.read_only {
            command.arg("--ro-bind").arg(dir).arg(dir);
        }
        for dir in self.hidden.iter().filter(|d| d.exists()) {
            command.arg("--tmpfs").arg(dir);
        }
        // A folder to show inside one just hidden is shown again.
        for dir in &self.read_only {
            if self.hidden.iter().any(|h| dir.starts_with(h) && dir != h) {
                command.arg("--ro-bind").arg(dir).arg(dir);
            }
        }
        for dir in &self.writable {
            command.arg("--bind").arg(dir).arg(dir);
        }
        command
            .args(["--unshare-all", "--die-with-parent", "--new-session"])
            .arg("--chdir")
            .arg(cwd);
        command
    }
}

/// One test to run.
#[derive(Debug, Clone)]
pub struct TestCommand {
    /// The test executable built by cargo.
    pub executable: PathBuf,
    /// The test's full name as `--list` prints it (`octants::steep`).
    pub name: String,
    /// The package folder: cargo runs tests there.
    pub cwd: PathBuf,
    /// Extra environment variables.
    pub env: Vec<(OsString, OsString)>,
    /// Environment variables to remove.
    pub env_remove: Vec<&'static str>,
    /// Wall-clock limit.
    pub time_limit: Duration,
    /// Address-space limit in MiB; 0 for none.
    pub memory_limit_mib: u64,
    /// Where stdout and stderr go.
    pub log: PathBuf,
    /// Where the run's secret token is written for the test to take (in
    /// the test's own scratch folder, which no other test can see).
    pub verdict_file: PathBuf,
    /// The sandbox, or `None` to run unsandboxed.
    pub sandbox: Option<Sandbox>,
}

/// A finished test process.
#[derive(Debug, Clone)]
pub struct Finished {
    /// How it ended.
    pub exit: Exit,
    /// Wall-clock time it ran.
    pub duration: Duration,
    /// Its output (the end of it, when long), lossily decoded.
    pub output: String,
    /// The secret a passed test prints (see [`super::outcome::judge`]).
    pub token: String,
}

impl Finished {
    /// A test that was not started (see [`Exit::not_run`]).
    #[must_use]
    pub fn not_run() -> Self {
        Self {
            exit: Exit {
                not_run: true,
                ..Exit::default()
            },
            duration: Duration::ZERO,
            output: String::new(),
            token: String::new(),
        }
    }
}

/// The largest file a test may write, in the 512-byte blocks of
/// `ulimit -f`: 1 GiB, far above any picture, far below a full disk.
const FILE_SIZE_LIMIT_BLOCKS: u64 = 2 << 20;

impl TestCommand {
    /// The `sh` script that sets the limits and `exec`s the test: `ulimit
    /// -v` takes KiB; `-c 0` keeps aborts from writing core files; `-f`
    /// caps file sizes. A shell without one of them (macOS has no `-v`)
    /// runs the test without that cap. (No `ulimit -u`: it counts every
    /// thread of the user's, the browser's too, so a test would fail for
    /// what else runs; the process namespace and the time limit end a fork
    /// bomb instead.)
    fn limits_script(&self) -> String {
        let mut script = String::from("ulimit -c 0 2>/dev/null; ");
        if self.memory_limit_mib > 0 {
            script += &format!("ulimit -v {} 2>/dev/null; ", self.memory_limit_mib * 1024);
        }
        script += &format!("ulimit -f {FILE_SIZE_LIMIT_BLOCKS} 2>/dev/null; ");
        script += "exec \"$0\" \"$@\"";
        script
    }

    fn command(&self) -> Command {
        let args = [
            OsString::from("--exact"),
            OsString::from(&self.name),
            OsString::from("--nocapture"),
            OsString::from("--test-threads=1"),
        ];
        let mut command = if let Some(sandbox) = &self.sandbox {
            let mut command = sandbox.command(&self.cwd);
            let script = self.limits_script();
            command
                .args(["sh", "-c"])
                .arg(script)
                .arg(&self.executable)
                .args(args);
            command
        } else if cfg!(unix) {
            let script = self.limits_script();
            let mut command = Command::new("sh");
            command
                .arg("-c")
                .arg(script)
                .arg(&self.executable)
                .args(args);
            command
        } else {
            let mut command = Command::new(&self.executable);
            command.args(args);
            command
        };
        command.current_dir(&self.cwd).stdin(Stdio::null());
        #[cfg(unix)]
        {
            use std::os::unix::process::CommandExt as _;
            command.process_group(0);
        }
        for name in &self.env_remove {
            command.env_remove(name);
        }
        command.envs(self.env.iter().map(|(k, v)| (k, v)));
        command.env(VERDICT_FILE_VAR, &self.verdict_file);
        command
    }

    /// Runs the test to its end or its limit.
    pub fn run(&self) -> Result<Finished> {
        if let Some(parent) = self.log.parent() {
            fs::create_dir_all(parent)
                .with_context(|| format!("cannot create {}", parent.display()))?;
        }
        for dir in self.sandbox.iter().flat_map(|s| &s.writable) {
            fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
        }
        let token = new_token()?;
        if let Some(parent) = self.verdict_file.parent() {
            fs::create_dir_all(parent)
                .with_context(|| format!("cannot create {}", parent.display()))?;
        }
        fs::write(&self.verdict_file, &token)
            .with_context(|| format!("cannot write {}", self.verdict_file.display()))?;
        let log = File::create(&self.log)
            .with_context(|| format!("cannot create the log {}", self.log.display()))?;
        // Both streams share one file description, so they interleave in order.
        let log_err = log.try_clone().context("cannot share the log file")?;
        let start = Instant::now();
        let mut child = self
            .command()
            .stdout(log)
            .stderr(log_err)
            .spawn()
            .with_context(|| format!("cannot start {}", self.executable.display()))?;
        if let Ok(mut running) = RUNNING.lock() {
            running.insert(child.id());
        }
        let mut exit = Exit::default();
        let status = loop {
            if let Some(status) = child.try_wait().context("cannot wait for a test")? {
                break status;
            }
            if start.elapsed() >= self.time_limit {
                exit.timed_out = true;
                break kill(&mut child)?;
            }
            if fs::metadata(&self.log).is_ok_and(|m| m.len() > OUTPUT_LIMIT) {
                exit.output_limit = Some(OUTPUT_LIMIT);
                break kill(&mut child)?;
            }
            std::thread::sleep(POLL_INTERVAL);
        };
        let duration = start.elapsed();
        kill_group(child.id());
        // A test that never started its body leaves the token behind.
        let _ = fs::remove_file(&self.verdict_file);
        if let Ok(mut running) = RUNNING.lock() {
            running.remove(&child.id());
        }
        exit.code = status.code();
        exit.signal = signal(&status);
        if self.sandbox.is_some()
            && let Some(code) = exit
                .code
                .filter(|c| (SIGNAL_EXIT_BASE + 1..SIGNAL_EXIT_BASE + 65).contains(c))
        {
            // bwrap reports a test killed by signal n as exit code 128 + n.
            exit.code = None;
            exit.signal = Some(code - SIGNAL_EXIT_BASE);
        }
        let mut output = read_tail(&self.log)?;
        if exit.output_limit.is_some() {
            // Keep the disk free: only the end of a flood is worth reading.
            let mut start = output.len().saturating_sub(FLOOD_KEPT);
            while !output.is_char_boundary(start) {
                start += 1;
            }
            output = format!(
                "[the test printed more than {} MiB; the last {} KiB are kept]\n{}",
                OUTPUT_LIMIT >> 20,
                FLOOD_KEPT >> 10,
                &output[start..]
            );
            // Into a new file renamed over the log: a process of the test
            // that is still dying may write on into the old one (its file
            // description keeps the old inode and offset), never into this.
            let cut = self.log.with_extension("cut");
            fs::write(&cut, &output)
                .and_then(|()| fs::rename(&cut, &self.log))
                .with_context(|| format!("cannot write {}", self.log.display()))?;
        }
        Ok(Finished {
            exit,
            duration,
            output,
            token,
        })
    }
}

/// 128 random bits from the operating system, in hex: a token no test can
/// guess, fresh for every run.
fn new_token() -> Result<String> {
    let mut bytes = [0_u8; 16];
    getrandom::fill(&mut bytes)
        .map_err(|e| anyhow::anyhow!("no random numbers for a token: {e}"))?;
    Ok(bytes.iter().map(|b| format!("{b:02x}")).collect())
}

/// Kills what is left of the process group `pgid` (the test's own, see
/// [`TestCommand::command`]); nothing left is fine.
#[cfg(unix)]
fn kill_group(pgid: u32) {
    let _ = Command::new("sh")
        .arg("-c")
        .arg(format!("kill -KILL -{pgid} 2>/dev/null"))
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status();
}

#[cfg(not(unix))]
fn kill_group(_: u32) {}

fn kill(child: &mut Child) -> Result<ExitStatus> {
    // It may have ended between `try_wait` and now; `wait` tells either way.
    let _ = child.kill();
    child.wait().context("cannot wait for a killed test")
}

#[cfg(unix)]
fn signal(status: &ExitStatus) -> Option<i32> {
    use std::os::unix::process::ExitStatusExt as _;
    status.signal()
}

#[cfg(not(unix))]
fn signal(_: &ExitStatus) -> Option<i32> {
    None
}

/// The log, or its last [`READ_BACK_LIMIT`] bytes.
fn read_tail(path: &Path) -> Result<String> {
    let mut file = File::open(path).with_context(|| format!("cannot read {}", path.display()))?;
    let len = file.metadata().map(|m| m.len()).unwrap_or(0);
    if len > READ_BACK_LIMIT {
        file.seek(SeekFrom::Start(len - READ_BACK_LIMIT))
            .with_context(|| format!("cannot read {}", path.display()))?;
    }
    let mut bytes = Vec::new();
    file.read_to_end(&mut bytes)
        .with_context(|| format!("cannot read {}", path.display()))?;
    Ok(String::from_utf8_lossy(&bytes).into_owned())
}

/// Lists a test executable's tests: all, and the `#[ignore]`d ones.
pub fn list_tests(executable: &Path, cwd: &Path, ignored: bool) -> Result<Vec<String>> {
    let mut command = Command::new(executable);
    command
        .args(["--list", "--format", "terse"])
        .current_dir(cwd)
        .stdin(Stdio::null());
    if ignored {
        command.arg("--ignored");
    }
    let output = command
        .output()
        .with_context(|| format!("cannot run {} --list", executable.display()))?;
    anyhow::ensure!(
        output.status.success(),
        "`{} --list` failed ({}): {}",
        executable.display(),
        output.status,
        String::from_utf8_lossy(&output.stderr).trim()
    );
    Ok(String::from_utf8_lossy(&output.stdout)
        .lines()
        .filter_map(|line| line.strip_suffix(": test"))
        .map(str::to_owned)
        .collect())
}
