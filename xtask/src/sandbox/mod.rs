//! The one runner of student code: every process that compiles or runs
//! it — the build of a stage, each test, the listing of a test
//! executable, the report's pipeline pictures — starts here, with the
//! same file system, environment, limits and cleanup.
//!
//! **An allowlist, not a blocklist.** Inside the bubblewrap sandbox a
//! process sees only what is bound for it:
//!
//! ```text
//! /usr /bin /lib* /etc/{ld.so.*,alternatives,vulkan,...}  read-only   the system's programs and libraries
//! <toolchain sysroot>, <CARGO_HOME>/{registry,git}        read-only   builds only: rustc, cargo, the sources of the dependencies
//! the course's files (no target/, .git/, reference/)      read-only   the stage, or the checkout graded in place
//! the test executable                                     read-only   tests only
//! the build folder | the scratch, pictures, snapshots     writable    builds | tests
//! /tmp                                                    writable    a tmpfs of its own, size-limited
//! /dev (null, zero, random ...; the GPU's for GPU topics), /proc of its own for builds, none for tests
//! ```
//!
//! Not `/`, not `$HOME`, not the course checkout's history or solutions,
//! not another checkout. The environment is an allowlist too
//! ([`Environment`]): nothing of the grader's reaches student code unless
//! named here. The sandbox has its own process, network, IPC and UTS
//! namespaces, no capabilities and no terminal.
//!
//! **Never root.** Where the grader is root, a test still runs as
//! `nobody`: bwrap makes its namespaces with root's privileges and
//! `setpriv` drops them before the test starts (see `command.rs` for why
//! a user namespace's mapping would not do). Builds stay the grader's
//! user: they are the compiler's processes, and write the shared build
//! folder.
//!
//! **Denied system calls.** Every process runs under seccomp filters
//! (built with [`seccompiler`], listed with a reason each in
//! `platform.rs`, as Flatpak does for bwrap) that deny what no test needs:
//! the calls with which one process reads or changes another's memory
//! (`ptrace`, `process_vm_readv`, …: the test that holds a verdict token
//! cannot be read by the processes it starts), making a user namespace,
//! mounting, the kernel's keyrings, modules, `bpf`, `perf_event_open`,
//! `userfaultfd`, `io_uring` and the machine's administration.
//!
//! **Limits.** Each process has the wall-clock limit, an address-space
//! limit per process, a file-size limit, no core files; where the machine
//! lets the grader make memory and pids cgroups — v1 or v2, as root or in
//! a delegated subtree (`cgroup.rs`) — the memory of all its processes
//! together and their count are limited as well, and the reports name the
//! hierarchy ([`Containment`]). What the processes write into their
//! writable folders is measured while they run and stops them past
//! [`Limits::written_mib`]; `/tmp` is a tmpfs of that size. A build has
//! 8 GiB ([`Limits::build`]): a `const` array past it stops rustc at
//! once; an endless `const` is refused before it is built
//! ([`const_eval`]).
//!
//! **The grade of record fails closed.** A student's own grade runs with
//! what the machine has and says what was missing; `--submission`, a
//! class and the Classroom workflow refuse to run student code unless
//! bubblewrap, its seccomp filters and the cgroups can all be had
//! ([`Policy`], [`enforce`]), or a tutor says `--unsandboxed-on-purpose`
//! (Gradescope's container, see `gradescope.rs`), which every report then
//! says.
//!
//! **Cleanup.** The process leads a process group of its own; when it ends
//! or is stopped, the group, the sandbox's process namespace and the
//! cgroup are killed, so nothing it started outlives it. Ctrl-C reaches
//! the grader alone, whose handler ([`stop_all_on_interrupt`]) kills every
//! running job before it exits.
//!
//! Where bubblewrap cannot run (macOS, Windows, a container that forbids
//! namespaces) the same runner runs the process unsandboxed, with the
//! scrubbed environment, the limits the platform has, as `nobody` where
//! the grader is root, and the process group killed at the end; every
//! report then says `unsandboxed`.

use std::collections::BTreeSet;
use std::ffi::OsString;
use std::fs::{self, File};
use std::path::{Path, PathBuf};
use std::process::Stdio;
use std::sync::{Mutex, Once, OnceLock};
use std::time::{Duration, Instant};

use anyhow::{Context, Result};

use crate::files::bytes_under;

mod cgroup;
mod command;
pub mod const_eval;
mod environment;
mod exit;
mod platform;

pub use cgroup::CgroupVersion;
#[cfg(feature = "staff")]
pub use cgroup::delegate_script;
use cgroup::{Cgroup, Hierarchy};
pub use environment::{Environment, Toolchain};
pub use exit::Exit;
use platform::{contain, kill, kill_group, seccomp_filter, signal};

/// How often a running job is checked on.
const POLL_INTERVAL: Duration = Duration::from_millis(10);
/// The signal that ends a process writing a file past `ulimit -f`
/// (Linux's and macOS's number).
const SIGXFSZ: i32 = 25;
/// How often the bytes in a job's writable folders are counted.
const WRITTEN_INTERVAL: Duration = Duration::from_millis(250);
/// Shells and bwrap report death by signal `n` as exit code `128 + n`.
const SIGNAL_EXIT_BASE: i32 = 128;
/// The exit code after an interrupt (128 + SIGINT, as shells report it).
const INTERRUPTED_EXIT_CODE: i32 = SIGNAL_EXIT_BASE + 2;

/// The process groups of the jobs running now.
static RUNNING: Mutex<BTreeSet<u32>> = Mutex::new(BTreeSet::new());

/// Makes Ctrl-C (and SIGTERM) kill every running job's process group
/// before the grader exits; once per process, later calls do nothing.
pub fn stop_all_on_interrupt() {
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

/// What a job may use.
#[derive(Debug, Clone)]
pub struct Limits {
    /// Wall-clock time.
    pub time: Duration,
    /// Memory of all the job's processes together, in MiB (a cgroup, where
    /// the machine allows one); also each process's address space.
    pub memory_mib: u64,
    /// Processes (and threads) at once (a cgroup, where the machine allows one).
    pub processes: u64,
    /// Bytes in all its writable folders and its `/tmp` together, in MiB.
    pub written_mib: u64,
    /// The largest file any of its processes may write, in MiB (0: no
    /// limit); a process writing past it is ended by `SIGXFSZ`.
    pub file_mib: u64,
    /// Bytes of output (stdout and stderr) before it is stopped.
    pub output: u64,
    /// CPU seconds each process may take; 0: no limit but the time.
    pub cpu_s: u64,
}

impl Limits {
    /// The limits of one test: `time`, `memory_mib` (0: the default of
    /// 4 GiB), 256 processes, 1 GiB written, 64 MiB printed.
    #[must_use]
    pub fn test(time: Duration, memory_mib: u64) -> Self {
        Self {
            time,
            memory_mib: if memory_mib == 0 { 4096 } else { memory_mib },
            processes: 256,
            written_mib: 1024,
            file_mib: 1024,
            output: 64 << 20,
            cpu_s: 0,
        }
    }

    /// The limits of a build of student code: `time`, 8 GiB of memory
    /// (rustc on the whole course needs about 2; a `const` array past it
    /// stops rustc at once with "tried to allocate more memory than
    /// available to compiler"), as many processes as a
    /// parallel build starts, its build folder's growth unmeasured while
    /// it runs (it is the dependencies' too; the graded code's share is
    /// counted when it ends, see `grade::build`), no file over 1 GiB (the
    /// course's largest test program is some 40 MiB) and 64 MiB of
    /// compiler messages.
    #[must_use]
    pub fn build(time: Duration) -> Self {
        Self {
            time,
            memory_mib: 8192,
            processes: 1024,
            written_mib: 0,
            file_mib: 1024,
            output: 64 << 20,
            cpu_s: 0,
        }
    }
}

/// What a job is: it decides what of the toolchain and `/proc` it sees.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Purpose {
    /// cargo compiling student code: the toolchain and the registry, its
    /// own `/proc` (rustc finds itself through it).
    Build,
    /// A test executable or the viewer: no toolchain, no `/proc`.
    Run,
}

/// One process to run, and everything it may see.
#[derive(Debug, Clone)]
pub struct Job {
    /// Build or run.
    pub purpose: Purpose,
    /// The program (an absolute path; for a build, cargo is found by the
    /// runner).
    pub program: PathBuf,
    /// Its arguments.
    pub args: Vec<OsString>,
    /// The folder it starts in (shown read-only unless under a writable one).
    pub cwd: PathBuf,
    /// The course it works on: its files are shown read-only (see
    /// [`course_entries`](command::course_entries)).
    pub course: PathBuf,
    /// Further files and folders shown read-only (the test executable).
    pub read_only: Vec<PathBuf>,
    /// Folders it may write (created first).
    pub writable: Vec<PathBuf>,
    /// Folders shown empty although they lie under a writable one (a
    /// checkout's reports and stage under its build folder).
    pub emptied: Vec<PathBuf>,
    /// Its environment, beyond [`Environment::base`].
    pub env: Vec<(OsString, OsString)>,
    /// The GPU's device files are shown (GPU topics).
    pub gpu: bool,
    /// Its limits.
    pub limits: Limits,
    /// Where stdout goes.
    pub stdout: PathBuf,
    /// Where stderr goes; `None`: into the same file as stdout, in order.
    pub stderr: Option<PathBuf>,
}

/// How a job ended.
#[derive(Debug, Clone)]
pub struct Ended {
    /// Its exit, and which limit stopped it.
    pub exit: Exit,
    /// Wall-clock time it ran.
    pub duration: Duration,
}

impl Ended {
    /// It exited with status 0, stopped by no limit.
    #[must_use]
    pub fn success(&self) -> bool {
        self.exit.code == Some(0) && !self.exit.stopped()
    }
}

/// What held in a grading run beyond the sandbox itself.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(default)]
pub struct Containment {
    /// Every sandboxed process ran under the seccomp filter (wherever the
    /// sandbox runs on x86-64 or AArch64).
    pub seccomp: bool,
    /// The memory and the processes of all of a test's processes together
    /// were limited (a cgroup: Linux, as root or in a delegated subtree).
    pub aggregate_limits: bool,
    /// The cgroup hierarchy those limits were set on (`v1` or `v2`);
    /// `None` where they were not.
    pub cgroup: Option<CgroupVersion>,
    /// Tests ran as a user other than root: the grader's own where it is
    /// not root, else `nobody` (see `command.rs`). Builds of a grader that
    /// is root run as root, in the sandbox: the compiler's, not student
    /// code's, processes.
    pub unprivileged: bool,
    /// A tutor chose to grade for the record with less than the sandbox,
    /// its seccomp filter and its aggregate limits
    /// (`--unsandboxed-on-purpose`): what did not hold is named by the
    /// fields above.
    pub on_purpose: bool,
}

impl Containment {
    /// For a grade of record graded with less on purpose, the line every
    /// report says it in: what did not hold (`sandboxed`: whether
    /// bubblewrap ran); `None` for any other grade.
    #[must_use]
    pub fn on_purpose_note(&self, sandboxed: bool) -> Option<String> {
        if !self.on_purpose {
            return None;
        }
        let lacking: Vec<&str> = [
            (!sandboxed, "bubblewrap"),
            (!self.seccomp, "its seccomp filters"),
            (!self.aggregate_limits, "cgroups"),
        ]
        .into_iter()
        .filter_map(|(lacked, what)| lacked.then_some(what))
        .collect();
        Some(if lacking.is_empty() {
            "graded with --unsandboxed-on-purpose; everything held all the same".to_owned()
        } else {
            format!(
                "graded on purpose (--unsandboxed-on-purpose) without {}",
                lacking.join(", ")
            )
        })
    }
}

/// How a grading run treats containment it cannot fully have.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub enum Policy {
    /// A student's own grade: student code runs with whatever this machine
    /// has, and the reports say what was missing. It is the student's own
    /// code on the student's own machine.
    #[default]
    BestEffort,
    /// The grade of record (`--submission`, a class, the Classroom
    /// workflow): student code runs only inside bubblewrap, under the
    /// seccomp filter and in cgroups, else none of it runs — someone
    /// else's code, next to the tutor's files and tokens.
    Required,
    /// The grade of record with less, on purpose (`--unsandboxed-on-purpose`,
    /// and Gradescope's container, which is a sandbox of its own): graded as
    /// [`Policy::BestEffort`], and every report says so.
    OnPurpose,
}

/// The policy of this run, set once by [`enforce`].
static POLICY: OnceLock<Policy> = OnceLock::new();

/// Makes `policy` this run's: for [`Policy::Required`], fails with what is
/// missing and how to get it unless the sandbox, its seccomp filter and
/// its aggregate limits can all be had here. Called before any student code
/// runs; [`Jail::run`] refuses as well where the policy is not met.
pub fn enforce(policy: Policy) -> Result<()> {
    let policy = *POLICY.get_or_init(|| policy);
    if policy != Policy::Required {
        return Ok(());
    }
    let missing = Jail::get().missing();
    anyhow::ensure!(
        missing.is_empty(),
        "refusing to run student code for the record without its containment:\n  - {}\n\
         A grade of record runs someone else's code beside your files: it needs bubblewrap, \
         its seccomp filter and cgroups. Get what is missing, or grade anyway with \
         --unsandboxed-on-purpose (every report then says so).",
        missing.join("\n  - ")
    );
    Ok(())
}

fn policy() -> Policy {
    POLICY.get().copied().unwrap_or_default()
}

/// The sandbox of a grading run: bubblewrap where it runs, the seccomp
/// filter, the toolchain. Made once ([`Jail::get`]).
#[derive(Debug)]
pub struct Jail {
    /// `bwrap`, where it runs.
    pub bwrap: Option<PathBuf>,
    /// The compiled seccomp filters (raw `struct sock_filter`s), where they
    /// can be built for this machine's architecture.
    seccomp: Option<platform::Filters>,
    /// The hierarchy cgroups can be made on here (see [`Cgroup`]), or why
    /// none can.
    cgroups: std::result::Result<Hierarchy, String>,
    /// The toolchain, where one was found (builds need it).
    toolchain: Option<Toolchain>,
}

impl Jail {
    /// The sandbox of this run: found (and bubblewrap installed, see
    /// `setup::sandbox`) on first use.
    pub fn get() -> &'static Jail {
        static JAIL: OnceLock<Jail> = OnceLock::new();
        JAIL.get_or_init(|| {
            let bwrap = crate::setup::sandbox();
            let seccomp = bwrap.as_ref().and_then(|_| match seccomp_filter() {
                Ok(path) => Some(path),
                Err(error) => {
                    eprintln!(
                        "warning: no seccomp filter ({error:#}): a test's child could read its memory"
                    );
                    None
                }
            });
            let cgroups = Hierarchy::detect()
                .context("neither cgroup hierarchy has the memory and pids controllers here")
                .and_then(|hierarchy| Cgroup::available(&hierarchy).map(|()| hierarchy))
                .map_err(|error| format!("{error:#}"));
            Jail {
                bwrap,
                seccomp,
                cgroups,
                toolchain: Toolchain::find().ok(),
            }
        })
    }

    /// Whether jobs run in bubblewrap.
    #[must_use]
    pub fn sandboxed(&self) -> bool {
        self.bwrap.is_some()
    }

    /// What held beyond the sandbox itself, for the reports.
    #[must_use]
    pub fn containment(&self) -> Containment {
        let cgroup = self.cgroups.as_ref().ok().map(Hierarchy::version);
        Containment {
            seccomp: self.seccomp.is_some() && self.sandboxed(),
            aggregate_limits: cgroup.is_some(),
            cgroup,
            unprivileged: command::tests_run_unprivileged(),
            on_purpose: policy() == Policy::OnPurpose,
        }
    }

    /// What of the grade of record's containment cannot be had here, each
    /// with how to get it; empty where all can.
    #[must_use]
    pub fn missing(&self) -> Vec<String> {
        let mut missing = Vec::new();
        if !self.sandboxed() {
            missing.push(format!(
                "bubblewrap cannot run here{}: install it (`apt-get install bubblewrap`) where it \
                 may make namespaces (as root, or a user where the kernel allows unprivileged user \
                 namespaces; not a container that forbids them)",
                if std::env::var_os(crate::setup::NO_SANDBOX_VAR).is_some() {
                    format!(" ({} is set)", crate::setup::NO_SANDBOX_VAR)
                } else {
                    String::new()
                }
            ));
        } else if self.seccomp.is_none() {
            missing.push(
                "no seccomp filter: it is built for Linux on x86-64 and AArch64 only".to_owned(),
            );
        }
        if let Err(why) = &self.cgroups {
            missing.push(format!(
                "no cgroup for the memory and processes of a test together: {why} \
                 (grade as root, e.g. with sudo, or in a delegated cgroup v2 scope: \
                 systemd-run --user --scope -p Delegate=yes cargo xtask grade ...)"
            ));
        }
        missing
    }

    /// The toolchain builds use.
    pub fn toolchain(&self) -> Result<&Toolchain> {
        self.toolchain
            .as_ref()
            .context("cannot find the Rust toolchain (rustc --print sysroot)")
    }

    /// Runs `job` to its end or its limit.
    pub fn run(&self, job: &Job) -> Result<Ended> {
        if policy() == Policy::Required {
            let missing = self.missing();
            anyhow::ensure!(
                missing.is_empty(),
                "student code is not run for the record without {}",
                missing.join("; ")
            );
        }
        for dir in &job.writable {
            fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
        }
        let stdout = create_log(&job.stdout)?;
        let stderr = match &job.stderr {
            Some(path) => create_log(path)?,
            // Both streams share one file description, so they interleave in order.
            None => stdout.try_clone().context("cannot share the log file")?,
        };
        let cgroup = match &self.cgroups {
            Ok(hierarchy) => Some(Cgroup::new(hierarchy, &job.limits)),
            Err(_) => None,
        };
        let cgroup = match cgroup {
            Some(Ok(cgroup)) => Some(cgroup),
            // Promised for the record, it must hold for every job.
            Some(Err(error)) if policy() == Policy::Required => {
                return Err(error.context("cannot make the cgroup of a job"));
            }
            Some(Err(_)) | None => None,
        };
        let mut command = self.command(job, cgroup.as_ref())?;
        command.stdin(Stdio::null()).stdout(stdout).stderr(stderr);
        let started = Instant::now();
        let mut child = command
            .spawn()
            .with_context(|| format!("cannot start {}", job.program.display()))?;
        // Windows: the process and all it starts are one job object,
        // killed when the job is dropped below.
        let _job_object = contain(&child);
        if let Ok(mut running) = RUNNING.lock() {
            running.insert(child.id());
        }
        let mut exit = Exit::default();
        let mut counted = Instant::now();
        let logs: Vec<&Path> = std::iter::once(job.stdout.as_path())
            .chain(job.stderr.as_deref())
            .collect();
        let status = loop {
            if let Some(status) = child.try_wait().context("cannot wait for a job")? {
                break status;
            }
            if started.elapsed() >= job.limits.time {
                exit.timed_out = true;
                break kill(&mut child)?;
            }
            let printed: u64 = logs
                .iter()
                .map(|log| fs::metadata(log).map_or(0, |m| m.len()))
                .sum();
            if printed > job.limits.output {
                exit.output_limit = Some(job.limits.output);
                break kill(&mut child)?;
            }
            if job.limits.written_mib > 0 && counted.elapsed() >= WRITTEN_INTERVAL {
                counted = Instant::now();
                let written = job
                    .writable
                    .iter()
                    .map(|d| bytes_under(d))
                    .sum::<Option<u64>>();
                if written.is_none_or(|bytes| bytes > job.limits.written_mib << 20) {
                    exit.written_limit = Some(job.limits.written_mib);
                    break kill(&mut child)?;
                }
            }
            std::thread::sleep(POLL_INTERVAL);
        };
        let duration = started.elapsed();
        kill_group(child.id());
        #[cfg(windows)]
        drop(_job_object);
        if let Some(cgroup) = &cgroup {
            if cgroup.out_of_memory() {
                exit.memory_limit = Some(job.limits.memory_mib);
            }
            if cgroup.out_of_processes() {
                exit.process_limit = Some(job.limits.processes);
            }
            cgroup.kill_all();
        }
        drop(cgroup);
        if let Ok(mut running) = RUNNING.lock() {
            running.remove(&child.id());
        }
        exit.code = status.code();
        exit.signal = signal(&status);
        if let Some(code) = exit
            .code
            .filter(|c| (SIGNAL_EXIT_BASE + 1..SIGNAL_EXIT_BASE + 65).contains(c))
            .filter(|_| self.sandboxed())
        {
            // bwrap reports a process killed by signal n as exit code 128 + n.
            exit.code = None;
            exit.signal = Some(code - SIGNAL_EXIT_BASE);
        }
        // A file past the size limit (`ulimit -f`) ends its writer with
        // SIGXFSZ before the count of the written bytes sees it.
        if exit.signal == Some(SIGXFSZ) && job.limits.written_mib > 0 {
            // (A build's compiler ended so is reported by cargo: see
            // `grade::build`.)
            exit.written_limit = Some(job.limits.written_mib);
        }
        Ok(Ended { exit, duration })
    }
}

fn create_log(path: &Path) -> Result<File> {
    if let Some(parent) = path.parent() {
        fs::create_dir_all(parent)
            .with_context(|| format!("cannot create {}", parent.display()))?;
    }
    File::create(path).with_context(|| format!("cannot create the log {}", path.display()))
}

#[cfg(all(test, unix))]
mod tests;
