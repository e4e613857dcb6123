//! Running one test in its own process, so that nothing the student's code
//! does (loop, overflow its stack, abort, exit, allocate without end) can
//! take the grader down with it: the test is a job of the one runner of
//! student code ([`crate::sandbox`]), which owns its sandbox, environment,
//! limits and cleanup. Here: the token the test must print, and reading
//! back what it printed.

use std::ffi::OsString;
use std::fs::{self, File};
use std::io::{Read as _, Seek as _, SeekFrom};
use std::path::{Path, PathBuf};
use std::time::Duration;

use anyhow::{Context, Result};

use super::outcome::Exit;
use crate::sandbox::{Jail, Job, Limits, Purpose};

/// A test that prints more than this is stopped: endless printing would
/// otherwise fill the disk before the time limit.
pub const OUTPUT_LIMIT: u64 = 64 << 20;
/// Of a test stopped at [`OUTPUT_LIMIT`], this much output is kept.
const FLOOD_KEPT: usize = 64 << 10;
/// Only the end of a long log is read back: the verdict is at the end.
const READ_BACK_LIMIT: u64 = 4 << 20;
/// How long listing a test executable's tests may take.
const LIST_TIME_LIMIT: Duration = Duration::from_secs(60);

/// The environment variable that names a test's token file (see
/// `crates/testkit-macros`, which reads it).
pub const VERDICT_FILE_VAR: &str = "TESTKIT_VERDICT_FILE";

/// One test to run.
#[derive(Debug, Clone)]
pub struct TestCommand {
    /// The test executable built by cargo.
    pub executable: PathBuf,
    /// The test's full name as `--list` prints it (`octants::steep`).
    pub name: String,
    /// The package folder: cargo runs tests there.
    pub cwd: PathBuf,
    /// The course the test belongs to (the stage, or the checkout graded
    /// in place): shown read-only.
    pub course: PathBuf,
    /// Its environment (besides what every job gets).
    pub env: Vec<(OsString, OsString)>,
    /// Wall-clock limit.
    pub time_limit: Duration,
    /// Memory limit in MiB (all its processes together where the machine
    /// allows, each process's address space everywhere); 0: the default.
    pub memory_limit_mib: u64,
    /// Folders it may write: its scratch folder first, its pictures,
    /// pending snapshots.
    pub writable: Vec<PathBuf>,
    /// The GPU's device files are shown.
    pub gpu: bool,
    /// Where stdout and stderr go.
    pub log: PathBuf,
    /// Where the run's secret token is written for the test to take (in
    /// the test's own scratch folder, which no other test can see).
    pub verdict_file: PathBuf,
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

impl TestCommand {
    /// Runs the test to its end or its limit.
    pub fn run(&self) -> Result<Finished> {
        let token = new_token()?;
        if let Some(parent) = self.verdict_file.parent() {
            fs::create_dir_all(parent)
                .with_context(|| format!("cannot create {}", parent.display()))?;
        }
        fs::write(&self.verdict_file, &token)
            .with_context(|| format!("cannot write {}", self.verdict_file.display()))?;
        let mut env = self.env.clone();
        env.push((VERDICT_FILE_VAR.into(), self.verdict_file.clone().into()));
        let mut limits = Limits::test(self.time_limit, self.memory_limit_mib);
        limits.output = OUTPUT_LIMIT;
        let job = Job {
            purpose: Purpose::Run,
            program: self.executable.clone(),
            args: ["--exact", &self.name, "--nocapture", "--test-threads=1"]
                .map(OsString::from)
                .to_vec(),
            cwd: self.cwd.clone(),
            course: self.course.clone(),
            read_only: vec![self.executable.clone()],
            writable: self.writable.clone(),
            emptied: Vec::new(),
            env,
            gpu: self.gpu,
            limits,
            stdout: self.log.clone(),
            stderr: None,
        };
        let ended = Jail::get().run(&job)?;
        // Its scratch folder goes with it (the token file too, which a test
        // that never started its body leaves behind): what a test wrote
        // there is not kept, so a class leaves no gigabytes behind.
        if let Some(scratch) = self.writable.first() {
            let _ = crate::files::remove_tree(scratch);
        }
        let _ = fs::remove_file(&self.verdict_file);
        let mut output = read_tail(&self.log)?;
        if ended.exit.output_limit.is_some() {
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
            exit: ended.exit,
            duration: ended.duration,
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

/// Lists a test executable's tests (all, or the `#[ignore]`d ones), by
/// running it as any test is run: in the sandbox, within limits, its
/// output in `scratch`.
pub fn list_tests(
    executable: &Path,
    cwd: &Path,
    course: &Path,
    scratch: &Path,
    ignored: bool,
) -> Result<Vec<String>> {
    let mut args: Vec<OsString> = ["--list", "--format", "terse"].map(OsString::from).to_vec();
    if ignored {
        args.push("--ignored".into());
    }
    let stdout = scratch.join(if ignored { "ignored.out" } else { "list.out" });
    let stderr = stdout.with_extension("err");
    let job = Job {
        purpose: Purpose::Run,
        program: executable.to_path_buf(),
        args,
        cwd: cwd.to_path_buf(),
        course: course.to_path_buf(),
        read_only: vec![executable.to_path_buf()],
        writable: vec![scratch.to_path_buf()],
        emptied: Vec::new(),
        env: Vec::new(),
        gpu: false,
        limits: Limits::test(LIST_TIME_LIMIT, 0),
        stdout: stdout.clone(),
        stderr: Some(stderr.clone()),
    };
    let ended = Jail::get().run(&job)?;
    let listed = read_tail(&stdout)?;
    anyhow::ensure!(
        ended.success(),
        "`{} --list` failed ({:?}): {}",
        executable.display(),
        ended.exit,
        read_tail(&stderr).unwrap_or_default().trim()
    );
    Ok(listed
        .lines()
        .filter_map(|line| line.strip_suffix(": test"))
        .map(str::to_owned)
        .collect())
}
