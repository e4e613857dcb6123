//! What containment each platform has: the seccomp filters (Linux on
//! x86-64 and AArch64), the job object (Windows), killing process groups
//! and reading the signal that ended a process (Unix).

use std::path::PathBuf;
use std::process::{Child, ExitStatus};

use anyhow::{Context, Result};

/// The seccomp filters every sandboxed process runs under, compiled once
/// per run into files bwrap reads (`--add-seccomp-fd`, one per filter).
/// Made on Linux alone (x86-64 and AArch64), where bwrap runs.
#[derive(Debug)]
#[cfg_attr(
    not(all(
        target_os = "linux",
        any(target_arch = "x86_64", target_arch = "aarch64")
    )),
    allow(dead_code)
)]
pub(super) struct Filters {
    files: Vec<PathBuf>,
}

impl Filters {
    /// The compiled filters, in the order bwrap is to load them.
    pub(super) fn files(&self) -> &[PathBuf] {
        &self.files
    }
}

/// The system calls no test needs, denied with `EPERM`, each with why —
/// as Flatpak's filter for bwrap does. A test computes, allocates, starts
/// threads and processes, reads and writes files, maps memory and talks
/// to a GPU driver (`ioctl`, `mmap`, `memfd_create`: lavapipe); none of
/// that is here. Every call is by its number for the architecture the
/// grader was built for.
#[cfg(all(
    target_os = "linux",
    any(target_arch = "x86_64", target_arch = "aarch64")
))]
fn denied_calls() -> Vec<(i64, &'static str)> {
    let mut denied = vec![
        // Another process's memory: the verdict token lives in the test.
        (libc::SYS_ptrace, "traces and writes another process"),
        (libc::SYS_process_vm_readv, "reads another process's memory"),
        (
            libc::SYS_process_vm_writev,
            "writes another process's memory",
        ),
        (libc::SYS_pidfd_getfd, "takes another process's open files"),
        (libc::SYS_kcmp, "compares another process's kernel objects"),
        // The kernel's own surface, the way out of any sandbox.
        (
            libc::SYS_perf_event_open,
            "profiling sees other processes and the kernel",
        ),
        (
            libc::SYS_userfaultfd,
            "stalls the kernel's page faults, an exploit's tool",
        ),
        (libc::SYS_bpf, "loads programs into the kernel"),
        (
            libc::SYS_io_uring_setup,
            "io_uring's operations pass by seccomp, a frequent exploit path",
        ),
        (libc::SYS_io_uring_enter, "io_uring (see io_uring_setup)"),
        (libc::SYS_io_uring_register, "io_uring (see io_uring_setup)"),
        (libc::SYS_init_module, "loads kernel code"),
        (libc::SYS_finit_module, "loads kernel code"),
        (libc::SYS_delete_module, "unloads kernel code"),
        (libc::SYS_kexec_load, "replaces the running kernel"),
        (libc::SYS_kexec_file_load, "replaces the running kernel"),
        // The keyrings are not namespaced: they are the host user's.
        (
            libc::SYS_keyctl,
            "reads and changes the kernel's keyrings, shared with the host",
        ),
        (libc::SYS_add_key, "plants keys in the kernel's keyrings"),
        (libc::SYS_request_key, "asks the kernel's keyrings for keys"),
        // The file system bwrap built is the test's whole world.
        (
            libc::SYS_mount,
            "changes the file system the sandbox set up",
        ),
        (libc::SYS_umount2, "uncovers what the sandbox's mounts hide"),
        (libc::SYS_pivot_root, "changes the sandbox's root"),
        (
            libc::SYS_chroot,
            "changes the root, a classic way out of another one",
        ),
        (libc::SYS_open_tree, "mounts (the new mount interface)"),
        (libc::SYS_move_mount, "mounts (the new mount interface)"),
        (libc::SYS_fsopen, "mounts (the new mount interface)"),
        (libc::SYS_fsconfig, "mounts (the new mount interface)"),
        (libc::SYS_fsmount, "mounts (the new mount interface)"),
        (libc::SYS_fspick, "mounts (the new mount interface)"),
        (libc::SYS_mount_setattr, "makes a read-only mount writable"),
        (
            libc::SYS_open_by_handle_at,
            "opens files by handle, past the mounts (the 'shocker' escape)",
        ),
        (
            libc::SYS_name_to_handle_at,
            "names files by handle (see open_by_handle_at)",
        ),
        (libc::SYS_setns, "joins another process's namespaces"),
        // Administration of the machine.
        (libc::SYS_reboot, "reboots the machine"),
        (libc::SYS_swapon, "changes the machine's swap"),
        (libc::SYS_swapoff, "changes the machine's swap"),
        (libc::SYS_acct, "switches process accounting"),
        (libc::SYS_quotactl, "changes disk quotas"),
        (
            libc::SYS_syslog,
            "reads the kernel's log, which holds its addresses",
        ),
        (libc::SYS_vhangup, "hangs up a terminal"),
    ];
    #[cfg(target_arch = "x86_64")]
    denied.extend([
        (libc::SYS_iopl, "reaches the machine's I/O ports"),
        (libc::SYS_ioperm, "reaches the machine's I/O ports"),
        (libc::SYS_uselib, "an obsolete loader of shared libraries"),
    ]);
    denied
}

/// The flag of `clone` and `unshare` that makes a user namespace, in which
/// an unprivileged process holds every capability over its own mounts,
/// network and more: the kernel's widest surface for a user. bwrap made
/// the namespaces a test needs; it makes none of its own.
#[cfg(all(
    target_os = "linux",
    any(target_arch = "x86_64", target_arch = "aarch64")
))]
const CLONE_NEWUSER: u64 = libc::CLONE_NEWUSER as u64;

/// The x32 ABI's numbers (bit 30 set) pass seccompiler's architecture
/// check on x86-64: each denied call is denied by that number too, and by
/// the x32 numbers of the calls x32 numbers apart.
#[cfg(all(target_os = "linux", target_arch = "x86_64"))]
fn with_x32(calls: Vec<i64>) -> Vec<i64> {
    const X32: i64 = 0x4000_0000;
    /// x32's own numbers of `ptrace`, `kexec_load`, `process_vm_readv` and
    /// `process_vm_writev`.
    const X32_OWN: [i64; 4] = [521, 528, 539, 540];
    let mut all = calls.clone();
    all.extend(calls.iter().map(|call| X32 + call));
    all.extend(X32_OWN.map(|call| X32 + call));
    all
}

#[cfg(all(target_os = "linux", target_arch = "aarch64"))]
fn with_x32(calls: Vec<i64>) -> Vec<i64> {
    calls
}

/// The seccomp filters every sandboxed process runs under (see
/// [`denied_calls`]): the denied calls, and `clone` or `unshare` asking
/// for a user namespace, fail with `EPERM`; `clone3`, whose flags lie in
/// memory a filter cannot read, fails with `ENOSYS`, on which the C
/// library falls back to `clone`, whose flags it can (so threads and
/// processes still start). Every other call is allowed. An architecture
/// other than the one they were compiled for is killed (seccompiler's own
/// check), so the 32-bit calls of an x86-64 machine cannot go round them.
#[cfg(all(
    target_os = "linux",
    any(target_arch = "x86_64", target_arch = "aarch64")
))]
pub(super) fn seccomp_filter() -> Result<Filters> {
    use std::collections::BTreeMap;
    use std::fs;

    use seccompiler::{
        BpfProgram, SeccompAction, SeccompCmpArgLen, SeccompCmpOp, SeccompCondition, SeccompFilter,
        SeccompRule, TargetArch,
    };
    let arch =
        TargetArch::try_from(std::env::consts::ARCH).map_err(|e| anyhow::anyhow!("{e:?}"))?;
    let error = |e: seccompiler::BackendError| anyhow::anyhow!("{e}");
    let mut rules: BTreeMap<i64, Vec<SeccompRule>> = BTreeMap::new();
    let plain: Vec<i64> = denied_calls().into_iter().map(|(call, _)| call).collect();
    for call in with_x32(plain) {
        rules.insert(call, Vec::new());
    }
    let new_user = || -> Result<SeccompRule> {
        let flags = SeccompCondition::new(
            0,
            SeccompCmpArgLen::Qword,
            SeccompCmpOp::MaskedEq(CLONE_NEWUSER),
            CLONE_NEWUSER,
        )
        .map_err(error)?;
        SeccompRule::new(vec![flags]).map_err(error)
    };
    for call in with_x32(vec![libc::SYS_clone, libc::SYS_unshare]) {
        rules.insert(call, vec![new_user()?]);
    }
    let no_clone3: BTreeMap<i64, Vec<SeccompRule>> = with_x32(vec![libc::SYS_clone3])
        .into_iter()
        .map(|call| (call, Vec::new()))
        .collect();
    let dir = std::env::temp_dir().join(format!("course-grader-{}", std::process::id()));
    fs::create_dir_all(&dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let mut files = Vec::new();
    for (name, rules, errno) in [
        ("seccomp.bpf", rules, libc::EPERM),
        ("seccomp-clone3.bpf", no_clone3, libc::ENOSYS),
    ] {
        let filter = SeccompFilter::new(
            rules,
            SeccompAction::Allow,
            SeccompAction::Errno(errno as u32),
            arch,
        )
        .map_err(error)?;
        let program: BpfProgram = filter.try_into().map_err(error)?;
        let mut bytes = Vec::with_capacity(program.len() * 8);
        for instruction in &program {
            bytes.extend_from_slice(&instruction.code.to_ne_bytes());
            bytes.push(instruction.jt);
            bytes.push(instruction.jf);
            bytes.extend_from_slice(&instruction.k.to_ne_bytes());
        }
        let path = dir.join(name);
        fs::write(&path, bytes).with_context(|| format!("cannot write {}", path.display()))?;
        files.push(path);
    }
    Ok(Filters { files })
}

#[cfg(not(all(
    target_os = "linux",
    any(target_arch = "x86_64", target_arch = "aarch64")
)))]
pub(super) fn seccomp_filter() -> Result<Filters> {
    anyhow::bail!("seccomp filters are built for Linux on x86-64 and AArch64 only")
}

/// Puts `child` into a job object that kills every process in it when it
/// is dropped (Windows, where there are no process groups to kill).
#[cfg(windows)]
pub(super) fn contain(child: &Child) -> Option<win32job::Job> {
    use std::os::windows::io::AsRawHandle as _;
    let mut limits = win32job::ExtendedLimitInfo::new();
    limits.limit_kill_on_job_close();
    let job = win32job::Job::create_with_limit_info(&limits).ok()?;
    job.assign_process(child.as_raw_handle() as isize).ok()?;
    Some(job)
}

#[cfg(not(windows))]
pub(super) fn contain(_: &Child) -> Option<()> {
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
pub(super) fn kill_pid(pid: i32) {
    use rustix::process::{Pid, Signal, kill_process};
    // Never 0 or below: those would name a whole group, or every process.
    if let Some(pid) = Pid::from_raw(pid).filter(|p| p.as_raw_nonzero().get() > 0) {
        let _ = kill_process(pid, Signal::KILL);
    }
}

#[cfg(not(unix))]
pub(super) fn kill_pid(_: i32) {}

#[cfg(not(unix))]
pub fn kill_group(_: u32) {}

pub(super) fn kill(child: &mut Child) -> Result<ExitStatus> {
    // It may have ended between `try_wait` and now; `wait` tells either way.
    let _ = child.kill();
    child.wait().context("cannot wait for a killed job")
}

#[cfg(unix)]
pub(super) fn signal(status: &ExitStatus) -> Option<i32> {
    use std::os::unix::process::ExitStatusExt as _;
    status.signal()
}

#[cfg(not(unix))]
pub(super) fn signal(_: &ExitStatus) -> Option<i32> {
    None
}
