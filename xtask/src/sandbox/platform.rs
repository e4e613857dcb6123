//! What containment each platform has: the seccomp filter (Linux on
//! x86-64 and AArch64), the job object (Windows), killing process groups
//! and reading the signal that ended a process (Unix).

use std::path::PathBuf;
use std::process::{Child, ExitStatus};

use anyhow::{Context, Result};

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
pub(super) fn seccomp_filter() -> Result<PathBuf> {
    use seccompiler::{BpfProgram, SeccompAction, SeccompFilter, TargetArch};
    use std::fs;
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
pub(super) fn seccomp_filter() -> Result<PathBuf> {
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
