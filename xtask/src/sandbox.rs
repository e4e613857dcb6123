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
//! named here. Every process runs under a seccomp filter (built with
//! [`seccompiler`]) that denies the system calls with which one process
//! reads or changes another's memory (`ptrace`, `process_vm_readv`,
//! `process_vm_writev` and their kin): the test that holds a verdict
//! token cannot be read by the processes it starts. The sandbox has its
//! own process, network, IPC and user namespaces, no capabilities and no
//! terminal.
//!
//! **Limits.** Each process has the wall-clock limit, an address-space
//! limit per process, a file-size limit, no core files; where the machine
//! lets the grader make a memory and a pids cgroup (Linux, as root: CI,
//! Gradescope), the memory of all its processes together and their count
//! are limited as well. What the processes write into their writable
//! folders is measured while they run and stops them past
//! [`Limits::written_mib`]; `/tmp` is a tmpfs of that size.
//!
//! **Cleanup.** The process leads a process group of its own; when it ends
//! or is stopped, the group, the sandbox's process namespace and the
//! cgroup are killed, so nothing it started outlives it. Ctrl-C reaches
//! the grader alone, whose handler ([`stop_all_on_interrupt`]) kills every
//! running job before it exits.
//!
//! Where bubblewrap cannot run (macOS, Windows, a container that forbids
//! namespaces) the same runner runs the process unsandboxed, with the
//! scrubbed environment, the limits the platform has, and the process
//! group killed at the end; every report then says `unsandboxed`.

use std::collections::BTreeSet;
use std::ffi::{OsStr, OsString};
use std::fs::{self, File};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Mutex, Once, OnceLock};
use std::time::{Duration, Instant};

use anyhow::{Context, Result};

use crate::files::bytes_under;
use crate::grade::report::Exit;

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
            output: 64 << 20,
            cpu_s: 0,
        }
    }

    /// The limits of a build of student code: `time`, 8 GiB of memory
    /// (rustc on the whole course needs about 2), as many processes as a
    /// parallel build starts, its build folder's growth unmeasured (it is
    /// the dependencies' too) and 64 MiB of compiler messages.
    #[must_use]
    pub fn build(time: Duration) -> Self {
        Self {
            time,
            memory_mib: 8192,
            processes: 1024,
            written_mib: 0,
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
    /// [`course_entries`]).
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

/// The toolchain that builds student code: cargo and rustc of the
/// toolchain `cargo xtask` runs on, called directly (no rustup proxy,
/// which would need the home folder), and cargo's home for the sources of
/// the dependencies.
#[derive(Debug, Clone)]
pub struct Toolchain {
    /// The toolchain's root (`rustc --print sysroot`).
    pub sysroot: PathBuf,
    /// cargo's home: the registry and git sources.
    pub cargo_home: PathBuf,
}

impl Toolchain {
    /// The toolchain of this run: `$CARGO`'s (cargo sets it for `cargo
    /// xtask`), else `rustc --print sysroot`.
    pub fn find() -> Result<Self> {
        let from_cargo = std::env::var_os("CARGO")
            .map(PathBuf::from)
            .and_then(|cargo| Some(cargo.parent()?.parent()?.to_path_buf()))
            .filter(|root| root.join("bin").join(exe("rustc")).is_file());
        let sysroot = match from_cargo {
            Some(root) => root,
            None => {
                let output = Command::new("rustc")
                    .args(["--print", "sysroot"])
                    .output()
                    .context("cannot run `rustc --print sysroot`")?;
                anyhow::ensure!(output.status.success(), "`rustc --print sysroot` failed");
                PathBuf::from(String::from_utf8_lossy(&output.stdout).trim())
            }
        };
        let cargo_home = std::env::var_os("CARGO_HOME")
            .map(PathBuf::from)
            .or_else(|| home_dir().map(|home| home.join(".cargo")))
            .context("cannot tell cargo's home folder (set CARGO_HOME)")?;
        Ok(Self {
            sysroot,
            cargo_home,
        })
    }

    /// The cargo program.
    #[must_use]
    pub fn cargo(&self) -> PathBuf {
        self.sysroot.join("bin").join(exe("cargo"))
    }

    /// The rustc program.
    #[must_use]
    pub fn rustc(&self) -> PathBuf {
        self.sysroot.join("bin").join(exe("rustc"))
    }
}

fn exe(name: &str) -> String {
    format!("{name}{}", std::env::consts::EXE_SUFFIX)
}

fn home_dir() -> Option<PathBuf> {
    std::env::var_os(if cfg!(windows) { "USERPROFILE" } else { "HOME" }).map(PathBuf::from)
}

/// The environment of a job: built from nothing, never inherited.
pub struct Environment;

impl Environment {
    /// Variables of the grader's passed on because they choose a GPU driver
    /// or a property test's random cases, or tune a build without changing
    /// what it means; nothing else of the grader's environment (tokens,
    /// keys, paths of other courses) reaches student code.
    pub const PASSED_ON: &[&str] = &[
        "PROPTEST_RNG_SEED",
        "NODEVICE_SELECT",
        "LIBGL_ALWAYS_SOFTWARE",
        "CARGO_INCREMENTAL",
        "CARGO_BUILD_JOBS",
        "RUSTFLAGS",
    ];
    /// Prefixes of variables passed on: GPU drivers' and wgpu's choices.
    pub const PASSED_ON_PREFIXES: &[&str] = &["WGPU_", "VK_", "MESA_", "LP_"];
    /// What Windows programs need to run at all (there is no sandbox
    /// there, so they name nothing the process could not read anyway).
    pub const WINDOWS_SYSTEM: &[&str] = &[
        "SystemRoot",
        "SystemDrive",
        "windir",
        "ComSpec",
        "PATHEXT",
        "TEMP",
        "TMP",
        "USERPROFILE",
        "ProgramData",
        "ProgramFiles",
        "ProgramFiles(x86)",
        "NUMBER_OF_PROCESSORS",
        "PROCESSOR_ARCHITECTURE",
    ];

    /// The variables every job gets: the grader's [`Self::PASSED_ON`] ones,
    /// a `PATH` of the system's programs, a `HOME` and `TMPDIR` of its own
    /// (`home`), a UTF-8 locale.
    #[must_use]
    pub fn base(home: &Path, extra_path: Option<&Path>) -> Vec<(OsString, OsString)> {
        let mut env: Vec<(OsString, OsString)> = std::env::vars_os()
            .filter(|(name, _)| {
                let name = name.to_string_lossy();
                Self::PASSED_ON.contains(&name.as_ref())
                    || Self::PASSED_ON_PREFIXES.iter().any(|p| name.starts_with(p))
                    || (cfg!(windows)
                        && Self::WINDOWS_SYSTEM
                            .iter()
                            .any(|w| w.eq_ignore_ascii_case(&name)))
            })
            .collect();
        let mut path: Vec<PathBuf> = extra_path.map(Path::to_path_buf).into_iter().collect();
        if cfg!(windows) {
            // The system's programs, the linker's included, are found
            // through the user's PATH on Windows.
            path.extend(
                std::env::var_os("PATH")
                    .map_or_else(Vec::new, |p| std::env::split_paths(&p).collect::<Vec<_>>()),
            );
        } else {
            path.extend(
                ["/usr/local/bin", "/usr/bin", "/bin", "/usr/sbin", "/sbin"].map(PathBuf::from),
            );
        }
        let path = std::env::join_paths(path).unwrap_or_default();
        env.push(("PATH".into(), path));
        if !cfg!(windows) {
            env.push(("HOME".into(), home.into()));
        }
        env.push(("TMPDIR".into(), home.into()));
        env.push(("LANG".into(), "C.UTF-8".into()));
        env
    }
}

/// What held in a grading run beyond the sandbox itself.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, serde::Serialize)]
pub struct Containment {
    /// Every sandboxed process ran under the seccomp filter (wherever the
    /// sandbox runs on x86-64 or AArch64).
    pub seccomp: bool,
    /// The memory and the processes of all of a test's processes together
    /// were limited (a cgroup: Linux, as root).
    pub aggregate_limits: bool,
}

/// The sandbox of a grading run: bubblewrap where it runs, the seccomp
/// filter, the toolchain. Made once ([`Jail::get`]).
#[derive(Debug)]
pub struct Jail {
    /// `bwrap`, where it runs.
    pub bwrap: Option<PathBuf>,
    /// The compiled seccomp filter (raw `struct sock_filter`s), where one
    /// can be built for this machine's architecture.
    seccomp: Option<PathBuf>,
    /// cgroups can be made here (see [`Cgroup`]).
    cgroups: bool,
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
            Jail {
                bwrap,
                seccomp,
                cgroups: Cgroup::available(),
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
        Containment {
            seccomp: self.seccomp.is_some() && self.sandboxed(),
            aggregate_limits: self.cgroups,
        }
    }

    /// The toolchain builds use.
    pub fn toolchain(&self) -> Result<&Toolchain> {
        self.toolchain
            .as_ref()
            .context("cannot find the Rust toolchain (rustc --print sysroot)")
    }

    /// Runs `job` to its end or its limit.
    pub fn run(&self, job: &Job) -> Result<Ended> {
        for dir in &job.writable {
            fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
        }
        let stdout = create_log(&job.stdout)?;
        let stderr = match &job.stderr {
            Some(path) => create_log(path)?,
            // Both streams share one file description, so they interleave in order.
            None => stdout.try_clone().context("cannot share the log file")?,
        };
        let cgroup = if self.cgroups {
            Cgroup::new(&job.limits).ok()
        } else {
            None
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
            exit.written_limit = Some(job.limits.written_mib);
        }
        Ok(Ended { exit, duration })
    }

    /// The command line of `job`: the limits set by a small `sh` script
    /// (`ulimit`; joining the cgroup; the seccomp filter opened as fd 3)
    /// that `exec`s bwrap with the job's binds, which runs the program.
    fn command(&self, job: &Job, cgroup: Option<&Cgroup>) -> Result<Command> {
        let mut inner: Vec<OsString> = Vec::new();
        let home = job
            .writable
            .first()
            .cloned()
            .unwrap_or_else(|| PathBuf::from("/tmp"));
        let (program, extra_path) = match job.purpose {
            Purpose::Build => {
                let toolchain = self.toolchain()?;
                (toolchain.cargo(), Some(toolchain.sysroot.join("bin")))
            }
            Purpose::Run => (job.program.clone(), None),
        };
        let mut env = Environment::base(
            if self.sandboxed() {
                Path::new("/tmp")
            } else {
                &home
            },
            extra_path.as_deref(),
        );
        if job.purpose == Purpose::Build {
            let toolchain = self.toolchain()?;
            env.push(("RUSTC".into(), toolchain.rustc().into()));
            env.push(("CARGO_HOME".into(), toolchain.cargo_home.clone().into()));
            env.push(("CARGO_NET_OFFLINE".into(), "true".into()));
        }
        env.extend(job.env.iter().cloned());
        if let Some(bwrap) = &self.bwrap {
            inner.push(bwrap.into());
            inner.extend(self.bwrap_args(job)?);
            if self.seccomp.is_some() {
                inner.extend(["--seccomp".into(), "3".into()]);
            }
            inner.extend(["--chdir".into(), job.cwd.clone().into(), "--".into()]);
        }
        if self.bwrap.is_none() && job.purpose == Purpose::Run && running_as_root() {
            // Unsandboxed as root (Gradescope's container without
            // namespaces): student code runs as nobody, never as root.
            for dir in &job.writable {
                give_to_nobody(dir)?;
            }
            inner.extend(
                [
                    "setpriv",
                    &format!("--reuid={NOBODY}"),
                    &format!("--regid={NOBODY}"),
                    "--clear-groups",
                    "--",
                ]
                .map(OsString::from),
            );
        }
        inner.push(program.into());
        inner.extend(job.args.iter().cloned());
        let mut command = if cfg!(unix) {
            let mut command = Command::new("/bin/sh");
            command
                .arg("-c")
                .arg(self.limits_script(job, cgroup))
                .arg("sh")
                .args(&inner);
            command
        } else {
            let mut command = Command::new(&inner[0]);
            command.args(&inner[1..]);
            command
        };
        command.current_dir(&job.cwd).env_clear().envs(env);
        #[cfg(unix)]
        {
            use std::os::unix::process::CommandExt as _;
            command.process_group(0);
        }
        Ok(command)
    }

    /// The `sh` script that joins the cgroup, sets the per-process limits
    /// and `exec`s its arguments with the seccomp filter on fd 3. `ulimit
    /// -v` takes KiB, `-f` 512-byte blocks; a shell without one of them
    /// (macOS has no `-v`) runs the job without that cap.
    fn limits_script(&self, job: &Job, cgroup: Option<&Cgroup>) -> String {
        let mut script = String::new();
        for procs in cgroup.iter().flat_map(|c| c.procs_files()) {
            script += &format!("echo $$ > {} || exit 125; ", shell_quoted(&procs));
        }
        script += "ulimit -c 0 2>/dev/null; ";
        script += &format!("ulimit -v {} 2>/dev/null; ", job.limits.memory_mib * 1024);
        if job.limits.cpu_s > 0 {
            script += &format!("ulimit -t {} 2>/dev/null; ", job.limits.cpu_s);
        }
        // No file bigger than everything the job may write.
        if job.limits.written_mib > 0 {
            script += &format!("ulimit -f {} 2>/dev/null; ", job.limits.written_mib * 2048);
        }
        script += "exec \"$@\"";
        if let (Some(seccomp), true) = (&self.seccomp, self.sandboxed()) {
            script += &format!(" 3< {}", shell_quoted(seccomp));
        }
        script
    }

    /// bwrap's binds and options for `job` (see the module documentation).
    fn bwrap_args(&self, job: &Job) -> Result<Vec<OsString>> {
        let mut args = Args::default();
        for dir in SYSTEM_DIRS {
            args.system(Path::new(dir));
        }
        for file in SYSTEM_ETC {
            args.ro_try(&Path::new("/etc").join(file));
        }
        args.words(["--dev", "/dev"]);
        // Shared memory is files too: a small tmpfs of its own.
        args.words(["--size", SHM_BYTES, "--tmpfs", "/dev/shm"]);
        if job.gpu {
            for device in GPU_DEVICES {
                args.dev_try(Path::new(device));
            }
        }
        match job.purpose {
            Purpose::Build => {
                let toolchain = self.toolchain()?;
                args.words(["--proc", "/proc"]);
                args.ro(&toolchain.sysroot);
                for dir in ["registry", "git"] {
                    args.ro_try(&toolchain.cargo_home.join(dir));
                }
                args.ro_try(&toolchain.cargo_home.join("config.toml"));
            }
            Purpose::Run => {}
        }
        let tmp_bytes = if job.limits.written_mib > 0 {
            job.limits.written_mib << 20
        } else {
            1 << 30
        };
        args.words(["--size".to_owned(), tmp_bytes.to_string()]);
        args.words(["--tmpfs", "/tmp"]);
        for entry in course_entries(&job.course)? {
            args.ro(&entry);
        }
        for path in &job.read_only {
            args.ro(path);
        }
        for dir in &job.writable {
            args.rw(dir);
        }
        for dir in job.emptied.iter().filter(|d| d.is_dir()) {
            args.words([OsStr::new("--tmpfs"), dir.as_os_str()]);
            args.words([OsStr::new("--remount-ro"), dir.as_os_str()]);
        }
        // The sandbox's own root and `/dev` are tmpfs mounts bwrap makes,
        // writable up to half the memory: read-only once everything is
        // bound, so that `/tmp`, `/dev/shm` and the writable folders are
        // all a job can write.
        args.words(["--remount-ro", "/dev", "--remount-ro", "/"]);
        args.words([
            "--unshare-all",
            "--die-with-parent",
            "--new-session",
            "--cap-drop",
            "ALL",
        ]);
        Ok(args.0)
    }
}

/// The user and group student code runs as where the grader is root and
/// there is no sandbox: `nobody`, `nogroup`.
const NOBODY: u32 = 65534;

/// Whether the grader runs as root.
#[cfg(unix)]
fn running_as_root() -> bool {
    rustix::process::geteuid().is_root()
}

#[cfg(not(unix))]
fn running_as_root() -> bool {
    false
}

/// Makes `dir` (created if missing) and what is in it [`NOBODY`]'s, so that
/// a test run as nobody can write its scratch and picture folders.
#[cfg(unix)]
fn give_to_nobody(dir: &Path) -> Result<()> {
    fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    std::os::unix::fs::chown(dir, Some(NOBODY), Some(NOBODY))
        .with_context(|| format!("cannot give {} to nobody", dir.display()))?;
    crate::files::walk(dir, &mut |path, _| {
        let _ = std::os::unix::fs::lchown(path, Some(NOBODY), Some(NOBODY));
        true
    });
    Ok(())
}

#[cfg(not(unix))]
fn give_to_nobody(_: &Path) -> Result<()> {
    Ok(())
}

/// The system's folders shown read-only (a symbolic link, as `/bin` is on
/// a merged-`/usr` system, is shown as the same link).
const SYSTEM_DIRS: [&str; 8] = [
    "/usr",
    "/bin",
    "/sbin",
    "/lib",
    "/lib64",
    "/lib32",
    "/libx32",
    "/opt/homebrew",
];
/// What of `/etc` programs need: the dynamic linker's cache, the
/// alternatives system's links (`cc`), Vulkan's drivers, the names of
/// users and groups.
const SYSTEM_ETC: [&str; 9] = [
    "ld.so.cache",
    "ld.so.conf",
    "ld.so.conf.d",
    "alternatives",
    "vulkan",
    "passwd",
    "group",
    "nsswitch.conf",
    "localtime",
];
/// The size of a job's `/dev/shm`.
const SHM_BYTES: &str = "67108864";
/// A GPU's device files (Mesa's render nodes, NVIDIA's).
const GPU_DEVICES: [&str; 5] = [
    "/dev/dri",
    "/dev/nvidia0",
    "/dev/nvidiactl",
    "/dev/nvidia-uvm",
    "/dev/nvidia-modeset",
];

/// bwrap's arguments, built up.
#[derive(Default)]
struct Args(Vec<OsString>);

impl Args {
    fn words<S: AsRef<OsStr>>(&mut self, words: impl IntoIterator<Item = S>) {
        self.0
            .extend(words.into_iter().map(|w| w.as_ref().to_os_string()));
    }

    fn bind(&mut self, option: &str, path: &Path) {
        self.words([OsStr::new(option), path.as_os_str(), path.as_os_str()]);
    }

    fn ro(&mut self, path: &Path) {
        self.bind("--ro-bind", path);
    }

    fn ro_try(&mut self, path: &Path) {
        self.bind("--ro-bind-try", path);
    }

    fn rw(&mut self, path: &Path) {
        self.bind("--bind", path);
    }

    fn dev_try(&mut self, path: &Path) {
        self.bind("--dev-bind-try", path);
    }

    /// A system folder: bound, or its link made again; nothing if missing.
    fn system(&mut self, path: &Path) {
        match fs::symlink_metadata(path) {
            Ok(meta) if meta.file_type().is_symlink() => {
                if let Ok(target) = fs::read_link(path) {
                    self.words([
                        OsStr::new("--symlink"),
                        target.as_os_str(),
                        path.as_os_str(),
                    ]);
                }
            }
            Ok(meta) if meta.is_dir() => self.ro(path),
            _ => {}
        }
    }
}

/// What of a course a job sees: every entry at its top but its build
/// output (`target/`), its history (`.git/`) and its solutions
/// (`reference/`). A stage holds the edition's files alone; a checkout
/// graded in place keeps these three out of sight this way.
pub fn course_entries(root: &Path) -> Result<Vec<PathBuf>> {
    let mut entries = Vec::new();
    for entry in fs::read_dir(root).with_context(|| format!("cannot read {}", root.display()))? {
        let entry = entry.with_context(|| format!("cannot read {}", root.display()))?;
        let name = entry.file_name();
        if ["target", ".git", crate::files::SOLUTIONS]
            .iter()
            .any(|hidden| name == *hidden)
        {
            continue;
        }
        // A link at the top of a course is not followed out of it.
        if entry.file_type().is_ok_and(|kind| kind.is_symlink()) {
            continue;
        }
        entries.push(entry.path());
    }
    entries.sort();
    Ok(entries)
}

fn create_log(path: &Path) -> Result<File> {
    if let Some(parent) = path.parent() {
        fs::create_dir_all(parent)
            .with_context(|| format!("cannot create {}", parent.display()))?;
    }
    File::create(path).with_context(|| format!("cannot create the log {}", path.display()))
}

/// `path` quoted for `sh`.
fn shell_quoted(path: &Path) -> String {
    format!("'{}'", path.to_string_lossy().replace('\'', r"'\''"))
}

/// A memory and a pids cgroup (cgroup v1, which needs root) for one job:
/// all its processes together are limited, and all are found to kill.
/// Removed when dropped.
struct Cgroup {
    /// `/sys/fs/cgroup/memory/.../course-grader-<pid>-<n>`.
    memory: PathBuf,
    /// `/sys/fs/cgroup/pids/.../course-grader-<pid>-<n>`.
    pids: PathBuf,
}

/// Where cgroup v1 controllers are mounted.
const CGROUP_V1: &str = "/sys/fs/cgroup";

impl Cgroup {
    /// Whether this machine lets the grader make cgroups: one is made and
    /// removed again, once.
    fn available() -> bool {
        cfg!(target_os = "linux") && Cgroup::new(&Limits::test(Duration::from_secs(1), 64)).is_ok()
    }

    /// The folder of `controller` for this process's children: under the
    /// grader's own cgroup of that controller.
    fn parent(controller: &str) -> Option<PathBuf> {
        let own = fs::read_to_string("/proc/self/cgroup").ok()?;
        let path = own.lines().find_map(|line| {
            let mut parts = line.splitn(3, ':');
            let (_, controllers, path) = (parts.next()?, parts.next()?, parts.next()?);
            controllers
                .split(',')
                .any(|c| c == controller)
                .then(|| path.trim_start_matches('/').to_owned())
        })?;
        let dir = Path::new(CGROUP_V1).join(controller).join(path);
        dir.join("cgroup.procs").is_file().then_some(dir)
    }

    fn new(limits: &Limits) -> Result<Self> {
        static NEXT: AtomicU64 = AtomicU64::new(0);
        let name = format!(
            "course-grader-{}-{}",
            std::process::id(),
            NEXT.fetch_add(1, Ordering::Relaxed)
        );
        let memory = Self::parent("memory")
            .context("no memory cgroup")?
            .join(&name);
        let pids = Self::parent("pids").context("no pids cgroup")?.join(&name);
        fs::create_dir(&memory).context("cannot make a memory cgroup")?;
        let cgroup = Self {
            memory,
            pids: pids.clone(),
        };
        fs::create_dir(&pids).context("cannot make a pids cgroup")?;
        let bytes = (limits.memory_mib << 20).to_string();
        fs::write(cgroup.memory.join("memory.limit_in_bytes"), &bytes)
            .context("cannot limit the memory cgroup")?;
        // With swap, the same limit for memory and swap together.
        let _ = fs::write(cgroup.memory.join("memory.memsw.limit_in_bytes"), &bytes);
        fs::write(pids.join("pids.max"), limits.processes.to_string())
            .context("cannot limit the pids cgroup")?;
        Ok(cgroup)
    }

    fn procs_files(&self) -> [PathBuf; 2] {
        [
            self.memory.join("cgroup.procs"),
            self.pids.join("cgroup.procs"),
        ]
    }

    /// Whether the kernel had to stop a process of it for memory (or
    /// refused it memory).
    fn out_of_memory(&self) -> bool {
        let oom_kills = fs::read_to_string(self.memory.join("memory.oom_control"))
            .ok()
            .and_then(|text| {
                text.lines()
                    .find_map(|line| line.strip_prefix("oom_kill "))
                    .and_then(|n| n.trim().parse::<u64>().ok())
            })
            .unwrap_or(0);
        let failures = fs::read_to_string(self.memory.join("memory.failcnt"))
            .ok()
            .and_then(|n| n.trim().parse::<u64>().ok())
            .unwrap_or(0);
        oom_kills > 0 || failures > 0
    }

    /// Kills every process left in it, until none is.
    fn kill_all(&self) {
        for _ in 0..50 {
            let pids: Vec<i32> = self
                .procs_files()
                .iter()
                .filter_map(|procs| fs::read_to_string(procs).ok())
                .flat_map(|text| {
                    text.split_whitespace()
                        .filter_map(|pid| pid.parse().ok())
                        .collect::<Vec<i32>>()
                })
                .filter(|&pid| pid > 0)
                .collect();
            if pids.is_empty() {
                return;
            }
            for pid in pids {
                kill_pid(pid);
            }
            std::thread::sleep(Duration::from_millis(5));
        }
    }
}

impl Drop for Cgroup {
    fn drop(&mut self) {
        self.kill_all();
        let _ = fs::remove_dir(&self.memory);
        let _ = fs::remove_dir(&self.pids);
    }
}

/// The seccomp filter every sandboxed process runs under, compiled once
/// per run into a file bwrap reads (`--seccomp 3`): the system calls with
/// which a process reads, writes or takes over another's memory fail with
/// `EPERM`; every other is allowed. An architecture other than the one it
/// was compiled for is killed (seccompiler's own check), so the 32-bit
/// calls of an x86-64 machine cannot go round it.
#[cfg(all(
    target_os = "linux",
    any(target_arch = "x86_64", target_arch = "aarch64")
))]
fn seccomp_filter() -> Result<PathBuf> {
    use seccompiler::{BpfProgram, SeccompAction, SeccompFilter, TargetArch};
    let arch =
        TargetArch::try_from(std::env::consts::ARCH).map_err(|e| anyhow::anyhow!("{e:?}"))?;
    let mut denied: Vec<i64> = vec![
        libc::SYS_ptrace,
        libc::SYS_process_vm_readv,
        libc::SYS_process_vm_writev,
        libc::SYS_pidfd_getfd,
        libc::SYS_kcmp,
        libc::SYS_perf_event_open,
        libc::SYS_userfaultfd,
        libc::SYS_bpf,
    ];
    if cfg!(target_arch = "x86_64") {
        // The x32 ABI's numbers (bit 30 set) pass the architecture check.
        const X32: i64 = 0x4000_0000;
        denied.extend([X32 + 521, X32 + 539, X32 + 540]);
    }
    let rules = denied.into_iter().map(|call| (call, Vec::new())).collect();
    let filter = SeccompFilter::new(
        rules,
        SeccompAction::Allow,
        SeccompAction::Errno(libc::EPERM as u32),
        arch,
    )
    .map_err(|e| anyhow::anyhow!("{e}"))?;
    let program: BpfProgram = filter.try_into().map_err(|e| anyhow::anyhow!("{e}"))?;
    let mut bytes = Vec::with_capacity(program.len() * 8);
    for instruction in &program {
        bytes.extend_from_slice(&instruction.code.to_ne_bytes());
        bytes.push(instruction.jt);
        bytes.push(instruction.jf);
        bytes.extend_from_slice(&instruction.k.to_ne_bytes());
    }
    let dir = std::env::temp_dir().join(format!("course-grader-{}", std::process::id()));
    fs::create_dir_all(&dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let path = dir.join("seccomp.bpf");
    fs::write(&path, bytes).with_context(|| format!("cannot write {}", path.display()))?;
    Ok(path)
}

#[cfg(not(all(
    target_os = "linux",
    any(target_arch = "x86_64", target_arch = "aarch64")
)))]
fn seccomp_filter() -> Result<PathBuf> {
    anyhow::bail!("seccomp filters are built for Linux on x86-64 and AArch64 only")
}

/// Puts `child` into a job object that kills every process in it when it
/// is dropped (Windows, where there are no process groups to kill).
#[cfg(windows)]
fn contain(child: &Child) -> Option<win32job::Job> {
    use std::os::windows::io::AsRawHandle as _;
    let mut limits = win32job::ExtendedLimitInfo::new();
    limits.limit_kill_on_job_close();
    let job = win32job::Job::create_with_limit_info(&limits).ok()?;
    job.assign_process(child.as_raw_handle() as isize).ok()?;
    Some(job)
}

#[cfg(not(windows))]
fn contain(_: &Child) -> Option<()> {
    None
}

/// Kills what is left of the process group `pgid`; nothing left is fine.
#[cfg(unix)]
pub fn kill_group(pgid: u32) {
    use rustix::process::{Pid, Signal, kill_process_group};
    if let Some(pgid) = i32::try_from(pgid).ok().and_then(Pid::from_raw) {
        let _ = kill_process_group(pgid, Signal::KILL);
    }
}

/// Kills the process `pid`; one that is gone is fine.
#[cfg(unix)]
fn kill_pid(pid: i32) {
    use rustix::process::{Pid, Signal, kill_process};
    // Never 0 or below: those would name a whole group, or every process.
    if let Some(pid) = Pid::from_raw(pid).filter(|p| p.as_raw_nonzero().get() > 0) {
        let _ = kill_process(pid, Signal::KILL);
    }
}

#[cfg(not(unix))]
fn kill_pid(_: i32) {}

#[cfg(not(unix))]
pub fn kill_group(_: u32) {}

fn kill(child: &mut Child) -> Result<ExitStatus> {
    // It may have ended between `try_wait` and now; `wait` tells either way.
    let _ = child.kill();
    child.wait().context("cannot wait for a killed job")
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

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("xtask-sandbox-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn the_environment_is_built_not_inherited() {
        // SAFETY-free: the test reads the variables, it sets none; the
        // grader's own environment holds PATH and HOME, never passed on.
        let env = Environment::base(Path::new("/scratch"), None);
        let names: Vec<String> = env
            .iter()
            .map(|(name, _)| name.to_string_lossy().into_owned())
            .collect();
        for name in &names {
            assert!(
                ["PATH", "HOME", "TMPDIR", "LANG"].contains(&name.as_str())
                    || Environment::PASSED_ON.contains(&name.as_str())
                    || Environment::PASSED_ON_PREFIXES
                        .iter()
                        .any(|p| name.starts_with(p))
                    || cfg!(windows),
                "{name} is not on the allowlist"
            );
        }
        let home = env.iter().find(|(n, _)| n == "TMPDIR").unwrap();
        assert_eq!(home.1, "/scratch");
    }

    #[test]
    fn a_course_shows_neither_its_build_nor_its_history_nor_its_solutions() {
        let dir = scratch("course");
        for folder in ["target", ".git", "reference", "crates", "exercises"] {
            fs::create_dir_all(dir.join(folder)).unwrap();
        }
        fs::write(dir.join("Cargo.toml"), "").unwrap();
        #[cfg(unix)]
        std::os::unix::fs::symlink("/", dir.join("escape")).unwrap();
        let shown: Vec<String> = course_entries(&dir)
            .unwrap()
            .iter()
            .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
            .collect();
        assert_eq!(shown, ["Cargo.toml", "crates", "exercises"]);
        fs::remove_dir_all(&dir).unwrap();
    }
}
