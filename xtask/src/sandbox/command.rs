//! The command line of a job: the `sh` script that sets its limits and
//! `exec`s bwrap, bwrap's binds (the system's folders, the toolchain, the
//! course, the job's own folders), and running student code as `nobody`
//! where the grader is root, in the sandbox or without one.
//!
//! **Never root inside.** bwrap started by root maps root to root in its
//! user namespace, so a test would run as the host's uid 0: a way out of
//! the sandbox would be a way to root. A user namespace mapping another
//! uid inside to root outside (`--uid 65534`) only renames it — the
//! kernel still checks files against uid 0. So for a grader that is root
//! the test's sandbox has no user namespace at all (bwrap's privileges do
//! its mounts), keeps `CAP_SETUID` and `CAP_SETGID` alone, and runs
//! `setpriv` to become `nobody` for real before `exec`ing the test: from
//! then on the process has no capability and cannot get one back
//! (`no_new_privs`). Its writable folders are given to `nobody` first.

use std::ffi::{OsStr, OsString};
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{Context, Result};

use super::{Cgroup, Environment, Jail, Job, Purpose};

impl Jail {
    /// The command line of `job`: the limits set by a small `sh` script
    /// (`ulimit`; joining the cgroup; the seccomp filter opened as fd 3)
    /// that `exec`s bwrap with the job's binds, which runs the program.
    pub(super) fn command(&self, job: &Job, cgroup: Option<&Cgroup>) -> Result<Command> {
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
            if let Some(seccomp) = &self.seccomp {
                for (fd, _) in (SECCOMP_FD..).zip(seccomp.files()) {
                    inner.extend(["--add-seccomp-fd".into(), fd.to_string().into()]);
                }
            }
            inner.extend(["--chdir".into(), job.cwd.clone().into(), "--".into()]);
        }
        if as_nobody(job) {
            // As root, in the sandbox or without one (Gradescope's
            // container without namespaces): student code runs as nobody,
            // never as root.
            for dir in &job.writable {
                give_to_nobody(dir)?;
            }
            // No supplementary group but, for a GPU topic, those that may
            // open the GPU's device files (`render`, `video`).
            let groups = if job.gpu { gpu_groups() } else { Vec::new() };
            let groups = if groups.is_empty() {
                "--clear-groups".to_owned()
            } else {
                let ids: Vec<String> = groups.iter().map(u32::to_string).collect();
                format!("--groups={}", ids.join(","))
            };
            inner.extend(
                [
                    "setpriv",
                    &format!("--reuid={NOBODY}"),
                    &format!("--regid={NOBODY}"),
                    &groups,
                    // Nothing inheritable either: the process keeps no
                    // capability of its own across the `exec`.
                    "--inh-caps=-all",
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
        if job.limits.file_mib > 0 {
            script += &format!("ulimit -f {} 2>/dev/null; ", job.limits.file_mib * 2048);
        }
        script += "exec \"$@\"";
        if let (Some(seccomp), true) = (&self.seccomp, self.sandboxed()) {
            for (fd, filter) in (SECCOMP_FD..).zip(seccomp.files()) {
                script += &format!(" {fd}< {}", shell_quoted(filter));
            }
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
        // Shared memory is files too: a small tmpfs of its own, which
        // everyone may write (as `/dev/shm` always is), nobody included.
        args.words([
            "--perms", "1777", "--size", SHM_BYTES, "--tmpfs", "/dev/shm",
        ]);
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
        args.words(["--perms".to_owned(), "1777".to_owned()]);
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
        if as_nobody(job) {
            // Every namespace but the user's (see the module
            // documentation), and of root's capabilities only the two
            // that `setpriv` needs to become nobody and then drops.
            args.words([
                "--unshare-ipc",
                "--unshare-pid",
                "--unshare-net",
                "--unshare-uts",
                "--unshare-cgroup-try",
                "--cap-drop",
                "ALL",
                "--cap-add",
                "CAP_SETUID",
                "--cap-add",
                "CAP_SETGID",
            ]);
        } else {
            args.words(["--unshare-all", "--cap-drop", "ALL"]);
        }
        args.words(["--die-with-parent", "--new-session"]);
        Ok(args.0)
    }
}

/// The user and group student code runs as where the grader is root:
/// `nobody`, `nogroup`.
const NOBODY: u32 = 65534;

/// The first file descriptor the seccomp filters are opened on for bwrap
/// (`--add-seccomp-fd`): after stdin, stdout and stderr.
const SECCOMP_FD: u32 = 3;

/// Whether `job` runs as [`NOBODY`]: student code (a test, the viewer) of
/// a grader that is root. A build stays the grader's: the compiler and
/// cargo, which write the shared build folder.
fn as_nobody(job: &Job) -> bool {
    job.purpose == Purpose::Run && running_as_root()
}

/// Whether tests run as a user other than root (the grader's own, or
/// [`NOBODY`]) — on Unix always; elsewhere as whoever runs the grader.
#[must_use]
pub(super) fn tests_run_unprivileged() -> bool {
    cfg!(unix)
}

/// Whether the grader runs as root.
#[cfg(unix)]
fn running_as_root() -> bool {
    rustix::process::geteuid().is_root()
}

#[cfg(not(unix))]
fn running_as_root() -> bool {
    false
}

/// The groups that own the GPU's device files ([`GPU_DEVICES`] and what is
/// in `/dev/dri`), root's excepted: a GPU topic's tests, run as
/// [`NOBODY`], are in them, so that they may open a render node that only
/// its group may (`crw-rw---- root render`), as the grader could.
#[cfg(unix)]
fn gpu_groups() -> Vec<u32> {
    use std::os::unix::fs::MetadataExt as _;
    let dri = fs::read_dir("/dev/dri")
        .into_iter()
        .flatten()
        .flatten()
        .map(|entry| entry.path());
    let mut groups: Vec<u32> = GPU_DEVICES
        .iter()
        .map(PathBuf::from)
        .chain(dri)
        .filter_map(|path| fs::metadata(path).ok())
        .filter(|meta| !meta.is_dir())
        .map(|meta| meta.gid())
        .filter(|&gid| gid != 0)
        .collect();
    groups.sort_unstable();
    groups.dedup();
    groups
}

#[cfg(not(unix))]
fn gpu_groups() -> Vec<u32> {
    Vec::new()
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
struct Args(Vec<OsString>, std::collections::BTreeSet<PathBuf>);

/// The mode of the folders bwrap makes on the way to a bound path: bwrap
/// makes them `0700`, root's, which `nobody` could not pass through.
const PATH_FOLDER_MODE: &str = "0755";

impl Args {
    fn words<S: AsRef<OsStr>>(&mut self, words: impl IntoIterator<Item = S>) {
        self.0
            .extend(words.into_iter().map(|w| w.as_ref().to_os_string()));
    }

    fn bind(&mut self, option: &str, path: &Path) {
        // The folders above it, outermost first, each made once (a
        // folder that is there already, bound or a tmpfs, is left as it is).
        let mut above: Vec<&Path> = path
            .ancestors()
            .skip(1)
            .filter(|dir| dir.parent().is_some())
            .collect();
        above.reverse();
        for dir in above {
            if self.1.insert(dir.to_path_buf()) {
                self.words([
                    OsStr::new("--perms"),
                    OsStr::new(PATH_FOLDER_MODE),
                    OsStr::new("--dir"),
                    dir.as_os_str(),
                ]);
            }
        }
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

/// `path` quoted for `sh`.
fn shell_quoted(path: &Path) -> String {
    format!("'{}'", path.to_string_lossy().replace('\'', r"'\''"))
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
