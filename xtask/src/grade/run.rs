//! Running one test in its own process, so that nothing the student's code
//! does (loop, overflow its stack, abort, exit, allocate without end) can
//! take the grader down with it: the test is a job of the one runner of
//! student code ([`crate::sandbox`]), which owns its sandbox, environment,
//! limits and cleanup. Here: the token the test must print, and reading
//! back what it printed.
//!
//! A test of a replayed topic (see the `transcript` crate) runs twice:
//!
//! ```text
//!   record: the test with the student's code, no token,   ──> transcript
//!           its pictures and snapshots thrown away             │ (read-only)
//!   replay: the same test built without the student's code, <──┘
//!           the token, the report's pictures and snapshots  ──> the verdict
//! ```
//!
//! The token never exists in a process that ran the student's code, so no
//! read of that process's memory can find it; what the first run prints is
//! shown as evidence of what the code did, never read for the verdict.

use std::ffi::OsString;
use std::fs::{self, File};
use std::io::{Read as _, Seek as _, SeekFrom};
use std::path::{Path, PathBuf};
use std::time::Duration;

use anyhow::{Context, Result};

mod transcript {
    //! The names the `transcript` crate reads.
    pub use wire::{RECORD_VAR, REPLAY_VAR};
}

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
pub use wire::VERDICT_FILE_VAR;

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
    /// For a GPU topic: the grade's folder of compiled shaders (see
    /// [`ShaderCache`]).
    pub shader_cache: Option<PathBuf>,
    /// Where stdout and stderr go.
    pub log: PathBuf,
    /// Where the run's secret token is written for the test to take (in
    /// the test's own scratch folder, which no other test can see).
    pub verdict_file: PathBuf,
    /// The same test built against the replaying crate: when set, the
    /// test runs twice (see the module documentation).
    pub replay: Option<PathBuf>,
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
    /// For a replayed test: the end of what the run of the student's code
    /// printed, shown beside the verdict's output, never read for it.
    pub evidence: Option<String>,
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
            evidence: None,
        }
    }
}

/// The environment variables that say where a test's pictures and pending
/// snapshots go (see `plan::test_env`): a recording run's go to its scratch.
const EVIDENCE_VARS: [(&str, &str); 2] = [
    ("TESTKIT_OUTPUT_DIR", "pictures"),
    ("INSTA_PENDING_DIR", "snapshots"),
];

/// The line before a recording run's output, where it is shown.
pub const EVIDENCE_HEADER: &str = "\n--- the run of your code (its output, shown as evidence; the verdict above is the replay's) ---";

/// The two caches of compiled shaders under a grade's shader folder.
///
/// Mesa's drivers (lavapipe, the software Vulkan driver of machines
/// without a GPU) keep the shaders they compiled in a folder: compiling a
/// test's shaders anew in every process costs lavapipe seconds, reading
/// them back milliseconds. What a driver reads from its cache it runs, so
/// the processes of the two sides never share one: the recordings of the
/// student's code share one folder, the replays (which hold the token)
/// another that no process of student code can reach. Each is a writable
/// folder of the jobs that use it, its bytes counted with theirs; Mesa
/// keeps it under [`ShaderCache::MAX_SIZE`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ShaderCache {
    /// The recordings' folder.
    Recorded,
    /// The replays' folder.
    Replayed,
}

impl ShaderCache {
    /// The size Mesa keeps each cache under (`MESA_SHADER_CACHE_MAX_SIZE`),
    /// well within a test's written bytes.
    pub const MAX_SIZE: &str = "128M";

    /// This side's folder under the grade's shader folder `shaders`.
    #[must_use]
    pub fn dir(self, shaders: &Path) -> PathBuf {
        shaders.join(match self {
            Self::Recorded => "recorded",
            Self::Replayed => "replayed",
        })
    }

    /// Gives the job of this side `writable` and `env` to use its cache.
    fn add_to(
        self,
        shaders: Option<&Path>,
        writable: &mut Vec<PathBuf>,
        env: &mut Vec<(OsString, OsString)>,
    ) {
        let Some(shaders) = shaders else {
            return;
        };
        let dir = self.dir(shaders);
        env.push(("MESA_SHADER_CACHE_DIR".into(), dir.clone().into()));
        env.push(("MESA_SHADER_CACHE_MAX_SIZE".into(), Self::MAX_SIZE.into()));
        writable.push(dir);
    }
}

/// A recorded or replayed run may take this many times the sheet's time
/// limit: writing down (or reading back) every value a task hands out is
/// the grader's cost, not the student's. A long line hands its callback
/// tens of millions of fragments; recorded, the run takes several times as
/// long as the drawing.
const REPLAY_TIME_FACTOR: u32 = 3;

/// What the evidence says when the record the run left was not a plain
/// file (a link, a folder), which is then not read.
pub const NOT_PLAIN_RECORD: &str =
    "[the record your code's run left was not a plain file (a link?): it was not read]";

/// Of a recording run's output, this much is kept in the log beside the
/// replay's.
const RECORDED_OUTPUT_KEPT: usize = 16 << 10;

impl TestCommand {
    /// Runs the test to its end or its limit: once with the token, or, for
    /// a replayed topic, recorded and then replayed with the token.
    pub fn run(&self) -> Result<Finished> {
        match &self.replay {
            None => self.run_with_token(&self.executable, None),
            Some(replay) => self.run_replayed(replay),
        }
    }

    /// Records the student's code, then replays the record (see the module
    /// documentation).
    fn run_replayed(&self, replay: &Path) -> Result<Finished> {
        let scratch = self
            .writable
            .first()
            .context("a test needs a scratch folder")?;
        let record_dir = scratch.with_extension("record");
        let transcript = record_dir.join("transcript");
        for dir in [scratch, &record_dir] {
            let _ = crate::files::remove_tree(dir);
            fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
        }
        let mut env: Vec<(OsString, OsString)> = self
            .env
            .iter()
            .map(|(key, value)| {
                let thrown_away = EVIDENCE_VARS
                    .iter()
                    .find(|(var, _)| key == var)
                    .map(|(_, dir)| scratch.join(dir).into_os_string());
                (key.clone(), thrown_away.unwrap_or_else(|| value.clone()))
            })
            .collect();
        env.push((transcript::RECORD_VAR.into(), transcript.clone().into()));
        let mut writable = vec![scratch.clone(), record_dir.clone()];
        ShaderCache::Recorded.add_to(self.shader_cache.as_deref(), &mut writable, &mut env);
        let recorded_log = self.log.with_extension("record.log");
        let mut limits = Limits::test(self.time_limit * REPLAY_TIME_FACTOR, self.memory_limit_mib);
        limits.output = OUTPUT_LIMIT;
        let job = Job {
            purpose: Purpose::Run,
            program: self.executable.clone(),
            args: self.test_args(),
            cwd: self.cwd.clone(),
            course: self.course.clone(),
            read_only: vec![self.executable.clone()],
            writable,
            emptied: Vec::new(),
            env,
            gpu: self.gpu,
            limits,
            stdout: recorded_log.clone(),
            stderr: None,
        };
        let recorded = Jail::get().run(&job)?;
        // What the student's code left in the scratch folder goes before
        // the grader writes there (the token's file): it is the grader's
        // own folder again, or the test is not run with the token. (Off
        // Unix, where students grade their own work, a virus scanner that
        // holds a file a moment is no reason to stop: the token's file is
        // still a new one.)
        if let Err(error) = crate::files::remove_tree(scratch)
            && cfg!(unix)
        {
            return Err(error);
        }
        let recorded_output = read_tail(&recorded_log)?;
        // Stopped by a limit or killed by a signal (a stack overflow, an
        // abort): nothing to replay, and its own output says why.
        if recorded.exit.stopped() || recorded.exit.signal.is_some() {
            let _ = crate::files::remove_tree(&record_dir);
            let _ = fs::rename(&recorded_log, &self.log);
            return Ok(Finished {
                exit: recorded.exit,
                duration: recorded.duration,
                output: recorded_output,
                token: String::new(),
                evidence: None,
            });
        }
        // The record is read only as the plain file the run left: a link
        // there would have the replay's sandbox bind whatever it names.
        let left = fs::symlink_metadata(&transcript).ok();
        let not_plain = left
            .as_ref()
            .is_some_and(|meta| !meta.file_type().is_file());
        if not_plain {
            crate::files::remove_tree(&transcript)?;
        }
        let replayed = self.run_with_token(replay, Some(&transcript));
        let _ = crate::files::remove_tree(&record_dir);
        self.move_replayed_snapshots();
        let mut replayed = replayed?;
        replayed.duration += recorded.duration;
        // The replay's tests are copies in its package: name the topic's.
        if let Ok(topic) = self.cwd.strip_prefix(&self.course)
            && let Some(name) = topic.file_name()
        {
            let copy = Path::new(crate::stage::replay::REPLAY_DIR).join(name);
            replayed.output = replayed.output.replace(
                &format!("{}/", copy.display()),
                &format!("{}/", topic.display()),
            );
        }
        // An exit of its own (not libtest's 0 or 101): the recording's
        // output says what the code did; the replay only that it ended.
        if replayed.exit.code != Some(0) && !matches!(recorded.exit.code, Some(0 | 101)) {
            replayed.exit = recorded.exit;
            replayed.output = recorded_output.clone();
            replayed.token = String::new();
        }
        // The recording's output beside the replay's, as evidence only.
        let mut start = recorded_output.len().saturating_sub(RECORDED_OUTPUT_KEPT);
        while !recorded_output.is_char_boundary(start) {
            start += 1;
        }
        let mut evidence = format!("{EVIDENCE_HEADER}\n{}", &recorded_output[start..]);
        if not_plain {
            evidence.push_str(&format!("\n{NOT_PLAIN_RECORD}"));
        }
        let _ = fs::OpenOptions::new()
            .append(true)
            .open(&self.log)
            .and_then(|mut log| std::io::Write::write_all(&mut log, evidence.as_bytes()));
        let _ = fs::remove_file(&recorded_log);
        replayed.evidence = Some(evidence);
        Ok(replayed)
    }

    /// Moves the pending snapshots the replay wrote under its package's
    /// path (`replay/<topic>/tests/snapshots/`) to where the topic's own
    /// would be (`exercises/<topic>/tests/snapshots/`), for the review.
    fn move_replayed_snapshots(&self) {
        let Some((_, pending)) = self.env.iter().find(|(key, _)| key == "INSTA_PENDING_DIR") else {
            return;
        };
        let pending = Path::new(pending);
        let Ok(topic) = self.cwd.strip_prefix(&self.course) else {
            return;
        };
        let Some(name) = topic.file_name() else {
            return;
        };
        let from = pending.join(crate::stage::replay::REPLAY_DIR).join(name);
        let mut folders = vec![from.clone()];
        while let Some(folder) = folders.pop() {
            let Ok(entries) = fs::read_dir(&folder) else {
                continue;
            };
            for entry in entries.flatten() {
                let path = entry.path();
                match entry.file_type() {
                    Ok(kind) if kind.is_dir() => folders.push(path),
                    Ok(kind) if kind.is_file() => {
                        let Ok(relative) = path.strip_prefix(&from) else {
                            continue;
                        };
                        let to = pending.join(topic).join(relative);
                        if let Some(parent) = to.parent() {
                            let _ = fs::create_dir_all(parent);
                        }
                        let _ = fs::rename(&path, &to);
                    }
                    _ => {}
                }
            }
        }
    }

    /// libtest's arguments: this one test, its output not captured.
    fn test_args(&self) -> Vec<OsString> {
        ["--exact", &self.name, "--nocapture", "--test-threads=1"]
            .map(OsString::from)
            .to_vec()
    }

    /// Runs `executable`'s test with the token (replaying `transcript`,
    /// when given, read-only).
    fn run_with_token(&self, executable: &Path, transcript: Option<&Path>) -> Result<Finished> {
        let token = new_token()?;
        if let Some(parent) = self.verdict_file.parent() {
            fs::create_dir_all(parent)
                .with_context(|| format!("cannot create {}", parent.display()))?;
        }
        // A new file, never one found there: a link left in the folder by
        // a test's code is not followed (removed, it is the link that goes).
        let _ = fs::remove_file(&self.verdict_file);
        crate::files::write_new(&self.verdict_file, token.as_bytes())?;
        let mut env = self.env.clone();
        env.push((VERDICT_FILE_VAR.into(), self.verdict_file.clone().into()));
        let mut read_only = vec![executable.to_path_buf()];
        let mut writable = self.writable.clone();
        if let Some(transcript) = transcript {
            env.push((transcript::REPLAY_VAR.into(), transcript.into()));
            if fs::symlink_metadata(transcript).is_ok_and(|meta| meta.is_file()) {
                read_only.push(transcript.to_path_buf());
            }
            // A test of a topic not replayed runs the student's code with
            // the token, and keeps no cache.
            ShaderCache::Replayed.add_to(self.shader_cache.as_deref(), &mut writable, &mut env);
        }
        let time_limit = if transcript.is_some() {
            self.time_limit * REPLAY_TIME_FACTOR
        } else {
            self.time_limit
        };
        let mut limits = Limits::test(time_limit, self.memory_limit_mib);
        limits.output = OUTPUT_LIMIT;
        let job = Job {
            purpose: Purpose::Run,
            program: executable.to_path_buf(),
            args: self.test_args(),
            cwd: self.cwd.clone(),
            course: self.course.clone(),
            read_only,
            writable,
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
            evidence: None,
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
