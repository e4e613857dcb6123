//! The memory and pids cgroups that limit all of a job's processes
//! together, where the machine lets the grader make them.

use std::fs;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Duration;

use anyhow::{Context, Result};

use super::Limits;
use super::platform::kill_pid;

/// A memory and a pids cgroup (cgroup v1, which needs root) for one job:
/// all its processes together are limited, and all are found to kill.
/// Removed when dropped.
pub(super) struct Cgroup {
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
    pub(super) fn available() -> bool {
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

    pub(super) fn new(limits: &Limits) -> Result<Self> {
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

    pub(super) fn procs_files(&self) -> [PathBuf; 2] {
        [
            self.memory.join("cgroup.procs"),
            self.pids.join("cgroup.procs"),
        ]
    }

    /// Whether the kernel had to stop a process of it for memory (or
    /// refused it memory).
    pub(super) fn out_of_memory(&self) -> bool {
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
    pub(super) fn kill_all(&self) {
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
