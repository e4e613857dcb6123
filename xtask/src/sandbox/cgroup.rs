//! The cgroups that limit all of a job's processes together — their
//! memory and their count — where the machine lets the grader make them,
//! on either of Linux's two cgroup hierarchies.
//!
//! **Two hierarchies.** cgroup v1 (older distributions, the machines this
//! course was first graded on) mounts each controller on a tree of its
//! own, `/sys/fs/cgroup/memory/...` and `/sys/fs/cgroup/pids/...`: a job
//! is a folder in each. cgroup v2, the *unified* hierarchy (current
//! Ubuntu, Debian and Fedora, GitHub's hosted runners, most container
//! hosts), has one tree with every controller: a job is one folder with
//! `memory.max`, `memory.swap.max` and `pids.max`, killed at once with
//! `cgroup.kill` (Linux 5.14) or else process by process. Which one a
//! machine has is read from `/proc/self/mountinfo` ([`Hierarchy::detect`]):
//! a hybrid machine, with the controllers on v1 and an empty v2 tree
//! beside them, counts as v1.
//!
//! **Where a v2 job's folder goes.** cgroup v2 has two rules that v1 has
//! not: a cgroup with processes in it cannot give its controllers to
//! children ("no internal processes", the root excepted), and a process
//! may be moved only by one who may write the `cgroup.procs` of the
//! common ancestor of where it is and where it goes. So the grader looks,
//! from its own cgroup upward, for the first cgroup whose
//! `cgroup.procs` it may write and whose children have (or can be given)
//! the memory and pids controllers: as root that is the parent of its own
//! cgroup (or the root); as a user it is a delegated subtree — e.g. the
//! parent of a transient scope, `systemd-run --user --scope -p
//! Delegate=yes cargo xtask grade ...`. Every path here is relative to a
//! root given as a parameter, so the file handling is tested on a fake
//! tree in a temporary folder.

use std::fs;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Duration;

use anyhow::{Context, Result};

use super::Limits;
use super::platform::kill_pid;

/// A shell script for a hosted CI runner (GitHub's: cgroup v2, the job run
/// as a user with `sudo`) that lets the grader it then starts make its
/// cgroups: a cgroup of the user's own, `/sys/fs/cgroup/course-grader`,
/// whose children have the memory and pids controllers, with the script's
/// shell moved into a leaf of it, `shell` (a cgroup with processes cannot
/// give its children controllers). The grader finds `course-grader` as
/// the first cgroup above its own that it may divide (see the module
/// documentation). It does nothing on a machine without cgroup v2, where
/// the grader says what is missing. Each line is prefixed with `indent`,
/// for a workflow's `run: |` block; it goes in the same step as the grade,
/// since each step starts in the runner's own cgroup.
#[must_use]
#[cfg(feature = "staff")]
pub fn delegate_script(indent: &str) -> String {
    const SCRIPT: &str = r#"# A cgroup of this user's own, so that the grader limits the memory and
# the processes of each test together (cgroup v2; see xtask/src/sandbox/cgroup.rs).
# Where it cannot be made, the grader says what is missing and refuses.
if [ -f /sys/fs/cgroup/cgroup.controllers ] && sudo -n true 2> /dev/null; then
  if ! { sudo mkdir -p /sys/fs/cgroup/course-grader/shell \
    && echo "+memory +pids" | sudo tee /sys/fs/cgroup/course-grader/cgroup.subtree_control > /dev/null \
    && sudo chown -R "$(id -u):$(id -g)" /sys/fs/cgroup/course-grader \
    && echo "$$" | sudo tee /sys/fs/cgroup/course-grader/shell/cgroup.procs > /dev/null; }; then
    echo "no cgroup of this user's own could be made"
  fi
fi
"#;
    SCRIPT
        .lines()
        .map(|line| format!("{indent}{line}\n"))
        .collect()
}

/// Which cgroup hierarchy the memory and pids controllers are on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum CgroupVersion {
    /// A tree per controller (`/sys/fs/cgroup/memory`, `/sys/fs/cgroup/pids`).
    V1,
    /// The unified hierarchy: one tree, every controller.
    V2,
}

/// Where the memory and pids controllers are mounted.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) enum Hierarchy {
    /// cgroup v1: the mount points of the two controllers.
    V1 { memory: PathBuf, pids: PathBuf },
    /// cgroup v2: the mount point of the unified hierarchy.
    V2 { mount: PathBuf },
}

/// The controllers a job's cgroup needs.
const CONTROLLERS: [&str; 2] = ["memory", "pids"];

impl Hierarchy {
    /// This machine's, from `/proc/self/mountinfo`; `None` off Linux or
    /// where neither hierarchy has both controllers.
    pub(super) fn detect() -> Option<Self> {
        let mountinfo = fs::read_to_string("/proc/self/mountinfo").ok()?;
        Self::from_mountinfo(&mountinfo)
    }

    /// The hierarchy `mountinfo` (the text of `/proc/self/mountinfo`)
    /// describes. Each line is `id parent dev root mount-point options
    /// [optional fields] - type source super-options`; v1 names its
    /// controller among the super-options (`rw,memory`).
    pub(super) fn from_mountinfo(mountinfo: &str) -> Option<Self> {
        let mut memory = None;
        let mut pids = None;
        let mut unified = None;
        for line in mountinfo.lines() {
            let Some((left, right)) = line.split_once(" - ") else {
                continue;
            };
            let Some(mount_point) = left.split_whitespace().nth(4) else {
                continue;
            };
            let mut right = right.split_whitespace();
            let (kind, _source, options) = (right.next(), right.next(), right.next());
            match kind {
                Some("cgroup") => {
                    let options: Vec<&str> = options.unwrap_or("").split(',').collect();
                    if options.contains(&"memory") {
                        memory = Some(PathBuf::from(mount_point));
                    }
                    if options.contains(&"pids") {
                        pids = Some(PathBuf::from(mount_point));
                    }
                }
                // The main v2 mount is `/sys/fs/cgroup`; a hybrid machine's
                // `/sys/fs/cgroup/unified` counts only when nothing is on v1.
                Some("cgroup2") if unified.is_none() || mount_point == "/sys/fs/cgroup" => {
                    unified = Some(PathBuf::from(mount_point));
                }
                _ => {}
            }
        }
        match (memory, pids, unified) {
            (Some(memory), Some(pids), _) => Some(Self::V1 { memory, pids }),
            (_, _, Some(mount)) => Some(Self::V2 { mount }),
            _ => None,
        }
    }

    /// Its version.
    #[must_use]
    pub(super) fn version(&self) -> CgroupVersion {
        match self {
            Self::V1 { .. } => CgroupVersion::V1,
            Self::V2 { .. } => CgroupVersion::V2,
        }
    }

    /// The folders under which a job's cgroups go, given `own`, the text
    /// of `/proc/self/cgroup` (`id:controllers:path` per line; v2's line
    /// is `0::path`): v1's memory and pids cgroups of the grader itself, or
    /// v2's first usable cgroup from the grader's own upward (see the
    /// module documentation).
    pub(super) fn parents(&self, own: &str) -> Result<Vec<PathBuf>> {
        match self {
            Self::V1 { memory, pids } => {
                let path_of = |controller: &str| {
                    own.lines().find_map(|line| {
                        let mut parts = line.splitn(3, ':');
                        let (_, controllers, path) = (parts.next()?, parts.next()?, parts.next()?);
                        controllers
                            .split(',')
                            .any(|c| c == controller)
                            .then(|| path.trim_start_matches('/').to_owned())
                    })
                };
                let mut parents = Vec::new();
                for (controller, mount) in [("memory", memory), ("pids", pids)] {
                    let path = path_of(controller)
                        .with_context(|| format!("the grader is in no {controller} cgroup"))?;
                    let dir = mount.join(path);
                    anyhow::ensure!(
                        dir.join("cgroup.procs").is_file(),
                        "{} is not a cgroup",
                        dir.display()
                    );
                    parents.push(dir);
                }
                Ok(parents)
            }
            Self::V2 { mount } => {
                let path = own
                    .lines()
                    .find_map(|line| line.strip_prefix("0::"))
                    .context("the grader is in no cgroup of the unified hierarchy")?;
                let own_dir = mount.join(path.trim().trim_start_matches('/'));
                let usable = own_dir
                    .ancestors()
                    .take_while(|dir| dir.starts_with(mount))
                    .find(|dir| may_write(&dir.join("cgroup.procs")) && give_controllers(dir))
                    .with_context(|| {
                        format!(
                            "no cgroup from {} upward is this user's to divide with the memory and pids controllers \
                             (grade as root, or in a delegated scope: systemd-run --user --scope -p Delegate=yes ...)",
                            own_dir.display()
                        )
                    })?;
                Ok(vec![usable.to_path_buf()])
            }
        }
    }
}

/// Whether this process may write the file `path`: it is opened for
/// writing (and closed unwritten). The kernel says no for a cgroup that is
/// not this user's, and for a file system mounted read-only, as a
/// container's `/sys/fs/cgroup` is.
fn may_write(path: &Path) -> bool {
    fs::OpenOptions::new().write(true).open(path).is_ok()
}

/// Whether the children of the v2 cgroup `dir` have the memory and pids
/// controllers, giving them first where they have not (which the kernel
/// refuses where `dir` holds processes, the root excepted).
fn give_controllers(dir: &Path) -> bool {
    let has_both = || {
        fs::read_to_string(dir.join("cgroup.subtree_control")).is_ok_and(|text| {
            CONTROLLERS
                .iter()
                .all(|c| text.split_whitespace().any(|w| w == *c))
        })
    };
    if has_both() {
        return true;
    }
    let _ = fs::write(dir.join("cgroup.subtree_control"), "+memory +pids");
    has_both()
}

/// The first part of the name of every cgroup the grader makes.
const NAME_PREFIX: &str = "course-grader-";

/// How long after it was made a job's cgroup without a process in it
/// counts as left behind: longer than any job may run (a build is stopped
/// after 15 minutes).
const STALE_AFTER: Duration = Duration::from_secs(3600);

/// Removes from `parent` the grader's cgroups that were [`left_behind`]:
/// those of a grader killed with `SIGKILL` (or of a machine that lost
/// power), which had no chance to remove its own.
fn sweep(parent: &Path, stale_after: Duration) {
    let Ok(entries) = fs::read_dir(parent) else {
        return;
    };
    for entry in entries.flatten() {
        let dir = entry.path();
        let procs = fs::read_to_string(dir.join("cgroup.procs"));
        let age = entry
            .metadata()
            .and_then(|m| m.modified())
            .ok()
            .and_then(|made| made.elapsed().ok());
        if let (Some(name), Ok(procs), Some(age)) = (entry.file_name().to_str(), procs, age)
            && left_behind(name, &procs, age, stale_after)
        {
            // The kernel refuses it if a process joined since.
            let _ = fs::remove_dir(&dir);
        }
    }
}

/// Whether the cgroup `name`, listing `procs` and made `age` ago, was
/// left behind by a grader: one of the grader's, holding no process, made
/// longer than `stale_after` ago. Only empty and old ones, so that a
/// grader running beside this one — perhaps in another container, whose
/// processes this one cannot see — loses nothing: its cgroups are young
/// or busy.
fn left_behind(name: &str, procs: &str, age: Duration, stale_after: Duration) -> bool {
    name.starts_with(NAME_PREFIX) && procs.trim().is_empty() && age > stale_after
}

/// The cgroups of one job: all its processes together are limited, and
/// all are found to kill. Removed when dropped.
pub(super) struct Cgroup {
    /// Its folders: v1's memory and pids cgroups, or v2's one.
    dirs: Vec<PathBuf>,
    version: CgroupVersion,
}

impl Cgroup {
    /// Whether this machine lets the grader make cgroups on `hierarchy`:
    /// one is made and removed again.
    /// The cgroups that graders killed before they could remove theirs
    /// left behind are removed first (see [`sweep`]).
    pub(super) fn available(hierarchy: &Hierarchy) -> Result<()> {
        if let Ok(own) = fs::read_to_string("/proc/self/cgroup")
            && let Ok(parents) = hierarchy.parents(&own)
        {
            for parent in parents {
                sweep(&parent, STALE_AFTER);
            }
        }
        Cgroup::new(hierarchy, &Limits::test(Duration::from_secs(1), 64)).map(drop)
    }

    /// A job's cgroups on this machine's `hierarchy`, with `limits`.
    pub(super) fn new(hierarchy: &Hierarchy, limits: &Limits) -> Result<Self> {
        let own =
            fs::read_to_string("/proc/self/cgroup").context("cannot read /proc/self/cgroup")?;
        Self::new_in(hierarchy, &own, limits)
    }

    /// [`Cgroup::new`] for a grader whose `/proc/self/cgroup` reads `own`.
    fn new_in(hierarchy: &Hierarchy, own: &str, limits: &Limits) -> Result<Self> {
        static NEXT: AtomicU64 = AtomicU64::new(0);
        let name = format!(
            "{NAME_PREFIX}{}-{}",
            std::process::id(),
            NEXT.fetch_add(1, Ordering::Relaxed)
        );
        let mut cgroup = Self {
            dirs: Vec::new(),
            version: hierarchy.version(),
        };
        for parent in hierarchy.parents(own)? {
            let dir = parent.join(&name);
            fs::create_dir(&dir)
                .with_context(|| format!("cannot make the cgroup {}", dir.display()))?;
            // Pushed at once: dropped on an error below, it is removed.
            cgroup.dirs.push(dir);
        }
        let bytes = (limits.memory_mib << 20).to_string();
        let processes = limits.processes.to_string();
        let write = |file: &str, value: &str| {
            let dir = cgroup.dir_with(file);
            fs::write(dir.join(file), value)
                .with_context(|| format!("cannot write {} of {}", file, dir.display()))
        };
        match cgroup.version {
            CgroupVersion::V1 => {
                write("memory.limit_in_bytes", &bytes)?;
                // With swap accounting, the same limit for memory and
                // swap together; without, swap is not the job's to use.
                let _ = write("memory.memsw.limit_in_bytes", &bytes);
            }
            CgroupVersion::V2 => {
                write("memory.max", &bytes)?;
                // v2 counts swap apart: none, so that memory.max is all.
                // A kernel without swap accounting has no such file.
                let _ = write("memory.swap.max", "0");
            }
        }
        write("pids.max", &processes)?;
        Ok(cgroup)
    }

    /// The folder of the controller whose `file` it is (v1's memory or
    /// pids cgroup; v2's only one).
    fn dir_with(&self, file: &str) -> &Path {
        match (self.version, file.starts_with("pids.")) {
            (CgroupVersion::V1, true) => &self.dirs[1],
            _ => &self.dirs[0],
        }
    }

    /// The `cgroup.procs` files a process writes its id into to join it.
    pub(super) fn procs_files(&self) -> Vec<PathBuf> {
        self.dirs.iter().map(|d| d.join("cgroup.procs")).collect()
    }

    /// Whether the kernel refused it a process for its `pids.max`
    /// (`pids.events`' `max` counter, v1 and v2 alike).
    pub(super) fn out_of_processes(&self) -> bool {
        fs::read_to_string(self.dir_with("pids.events").join("pids.events"))
            .ok()
            .and_then(|text| {
                text.lines()
                    .find_map(|line| line.strip_prefix("max "))
                    .and_then(|n| n.trim().parse::<u64>().ok())
            })
            .is_some_and(|refused| refused > 0)
    }

    /// Whether the kernel had to stop a process of it for memory (or, on
    /// v1, refused it memory).
    pub(super) fn out_of_memory(&self) -> bool {
        let counter = |file: &str, name: &str| {
            fs::read_to_string(self.dirs[0].join(file))
                .ok()
                .and_then(|text| {
                    text.lines()
                        .find_map(|line| line.strip_prefix(name))
                        .and_then(|n| n.trim().parse::<u64>().ok())
                })
                .unwrap_or(0)
        };
        match self.version {
            CgroupVersion::V1 => {
                let failures = fs::read_to_string(self.dirs[0].join("memory.failcnt"))
                    .ok()
                    .and_then(|n| n.trim().parse::<u64>().ok())
                    .unwrap_or(0);
                counter("memory.oom_control", "oom_kill ") > 0 || failures > 0
            }
            // `oom`: the limit was met and reclaim could not help;
            // `oom_kill`: a process was killed for it.
            CgroupVersion::V2 => {
                counter("memory.events", "oom ") > 0 || counter("memory.events", "oom_kill ") > 0
            }
        }
    }

    /// Kills every process left in it, until none is: at once through v2's
    /// `cgroup.kill` where the kernel has it (no process can fork past
    /// it), else process by process, again until the list is empty.
    pub(super) fn kill_all(&self) {
        let kill_file = self.dirs.first().map(|dir| dir.join("cgroup.kill"));
        if let Some(kill_file) =
            kill_file.filter(|f| self.version == CgroupVersion::V2 && f.is_file())
        {
            let _ = fs::write(&kill_file, "1");
        }
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
        for dir in &self.dirs {
            // A cgroup's files are the kernel's: `rmdir` is all it takes.
            let _ = fs::remove_dir(dir);
        }
    }
}

#[cfg(test)]
mod tests {
    //! The file handling, on fake trees in temporary folders: a real v2
    //! cgroup cannot be made on this course's machines, which are v1 (the
    //! platforms workflow grades the containment plants on a v2 runner).
    use super::*;

    /// A mountinfo of a cgroup v2 machine (Ubuntu 24.04), abridged.
    const UNIFIED: &str = "\
24 30 0:22 / /sys rw,nosuid,nodev,noexec,relatime shared:7 - sysfs sysfs rw
35 24 0:30 / /sys/fs/cgroup rw,nosuid,nodev,noexec,relatime shared:9 - cgroup2 cgroup2 rw,nsdelegate,memory_recursiveprot
";
    /// A mountinfo of a hybrid machine: the controllers on v1, an empty
    /// unified tree beside them.
    const HYBRID: &str = "\
25 24 0:24 / /sys/fs/cgroup ro,nosuid,nodev,noexec shared:9 - tmpfs tmpfs ro,mode=755
26 25 0:25 / /sys/fs/cgroup/unified rw,nosuid,nodev,noexec,relatime shared:10 - cgroup2 cgroup2 rw,nsdelegate
30 25 0:29 / /sys/fs/cgroup/memory rw,nosuid,nodev,noexec,relatime shared:14 - cgroup cgroup rw,memory
31 25 0:30 / /sys/fs/cgroup/pids rw,nosuid,nodev,noexec,relatime shared:15 - cgroup cgroup rw,pids
";

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("xtask-cgroup-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    /// A fake v2 tree: the grader in `user.slice/grader.scope`, whose
    /// parent gives its children the memory and pids controllers.
    fn fake_unified(name: &str) -> (PathBuf, Hierarchy) {
        let mount = scratch(name);
        let slice = mount.join("user.slice");
        fs::create_dir_all(slice.join("grader.scope")).unwrap();
        fs::write(slice.join("cgroup.procs"), "").unwrap();
        fs::write(slice.join("cgroup.subtree_control"), "cpu memory pids\n").unwrap();
        let hierarchy = Hierarchy::V2 {
            mount: mount.clone(),
        };
        (mount, hierarchy)
    }

    const OWN_V2: &str = "0::/user.slice/grader.scope\n";

    #[test]
    fn the_hierarchy_is_read_from_the_mount_table() {
        assert_eq!(
            Hierarchy::from_mountinfo(UNIFIED),
            Some(Hierarchy::V2 {
                mount: "/sys/fs/cgroup".into()
            })
        );
        assert_eq!(
            Hierarchy::from_mountinfo(HYBRID),
            Some(Hierarchy::V1 {
                memory: "/sys/fs/cgroup/memory".into(),
                pids: "/sys/fs/cgroup/pids".into()
            }),
            "a hybrid machine's controllers are on v1"
        );
        let none = "24 30 0:22 / /sys rw,nosuid - sysfs sysfs rw\n";
        assert_eq!(Hierarchy::from_mountinfo(none), None);
    }

    #[test]
    fn a_v2_job_gets_memory_swap_and_pids_limits_in_the_first_cgroup_it_may_divide() {
        let (mount, hierarchy) = fake_unified("limits");
        let limits = Limits::test(Duration::from_secs(1), 64);
        let cgroup = Cgroup::new_in(&hierarchy, OWN_V2, &limits).unwrap();
        let dir = cgroup.dirs[0].clone();
        // Beside the grader's own scope, which holds processes and so
        // cannot have children with controllers.
        assert_eq!(dir.parent(), Some(mount.join("user.slice").as_path()));
        let read = |file: &str| fs::read_to_string(dir.join(file)).unwrap();
        assert_eq!(read("memory.max"), (64_u64 << 20).to_string());
        assert_eq!(read("memory.swap.max"), "0");
        assert_eq!(read("pids.max"), limits.processes.to_string());
        assert_eq!(cgroup.procs_files(), [dir.join("cgroup.procs")]);
        assert_eq!(cgroup.version, CgroupVersion::V2);
        drop(cgroup);
        fs::remove_dir_all(&mount).unwrap();
    }

    #[test]
    fn a_v2_cgroup_that_met_its_memory_limit_says_so() {
        let (mount, hierarchy) = fake_unified("oom");
        let cgroup = Cgroup::new_in(
            &hierarchy,
            OWN_V2,
            &Limits::test(Duration::from_secs(1), 64),
        )
        .unwrap();
        let events = cgroup.dirs[0].join("memory.events");
        fs::write(&events, "low 0\nhigh 0\nmax 12\noom 0\noom_kill 0\n").unwrap();
        assert!(
            !cgroup.out_of_memory(),
            "reclaim at the limit is no failure"
        );
        fs::write(&events, "low 0\nhigh 0\nmax 12\noom 1\noom_kill 1\n").unwrap();
        assert!(cgroup.out_of_memory());
        drop(cgroup);
        fs::remove_dir_all(&mount).unwrap();
    }

    #[test]
    fn a_cgroup_that_met_its_process_limit_says_so() {
        let (mount, hierarchy) = fake_unified("pids");
        let cgroup = Cgroup::new_in(
            &hierarchy,
            OWN_V2,
            &Limits::test(Duration::from_secs(1), 64),
        )
        .unwrap();
        let events = cgroup.dirs[0].join("pids.events");
        assert!(
            !cgroup.out_of_processes(),
            "no events file: nothing refused"
        );
        fs::write(&events, "max 0\n").unwrap();
        assert!(!cgroup.out_of_processes());
        fs::write(&events, "max 3\n").unwrap();
        assert!(cgroup.out_of_processes());
        drop(cgroup);
        fs::remove_dir_all(&mount).unwrap();
    }

    #[test]
    fn a_v2_cgroup_is_killed_with_cgroup_kill_where_the_kernel_has_it() {
        let (mount, hierarchy) = fake_unified("kill");
        let cgroup = Cgroup::new_in(
            &hierarchy,
            OWN_V2,
            &Limits::test(Duration::from_secs(1), 64),
        )
        .unwrap();
        let kill = cgroup.dirs[0].join("cgroup.kill");
        fs::write(&kill, "").unwrap();
        cgroup.kill_all();
        assert_eq!(fs::read_to_string(&kill).unwrap(), "1");
        drop(cgroup);
        fs::remove_dir_all(&mount).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn without_cgroup_kill_every_listed_process_is_killed() {
        use std::os::unix::process::ExitStatusExt as _;
        let (mount, hierarchy) = fake_unified("procs");
        let cgroup = Cgroup::new_in(
            &hierarchy,
            OWN_V2,
            &Limits::test(Duration::from_secs(1), 64),
        )
        .unwrap();
        let mut child = std::process::Command::new("sleep")
            .arg("60")
            .spawn()
            .unwrap();
        fs::write(&cgroup.procs_files()[0], format!("{}\n", child.id())).unwrap();
        cgroup.kill_all();
        let status = child.wait().unwrap();
        assert_eq!(status.signal(), Some(9), "{status:?}");
        // The fake file still lists it: empty it before the drop kills again.
        fs::write(&cgroup.procs_files()[0], "").unwrap();
        drop(cgroup);
        fs::remove_dir_all(&mount).unwrap();
    }

    #[test]
    fn a_v2_cgroup_whose_children_cannot_have_the_controllers_is_passed_over() {
        let (mount, hierarchy) = fake_unified("passed-over");
        // The slice gives only `cpu`; "+memory +pids" written to a fake
        // tree's plain file reads back as those words, not as the
        // controllers a kernel would list, so it stays without them.
        fs::write(mount.join("user.slice/cgroup.subtree_control"), "cpu\n").unwrap();
        // The grader's own scope and the mount above are no cgroups to
        // divide either (no `cgroup.procs` to write).
        let error = Cgroup::new_in(
            &hierarchy,
            OWN_V2,
            &Limits::test(Duration::from_secs(1), 64),
        )
        .map(drop)
        .unwrap_err();
        assert!(error.to_string().contains("Delegate=yes"), "{error:#}");
        assert!(
            !mount.join("user.slice").read_dir().unwrap().any(|e| e
                .unwrap()
                .file_name()
                .to_string_lossy()
                .starts_with("course-grader")),
            "a cgroup was made where its limits cannot hold"
        );
        fs::remove_dir_all(&mount).unwrap();
    }

    #[test]
    fn a_grader_in_the_root_cgroup_makes_its_jobs_under_the_root() {
        // As in a host without systemd, or a container at the root of its
        // cgroup namespace: the root alone may hold processes and still
        // give its children controllers.
        let mount = scratch("root");
        fs::write(mount.join("cgroup.procs"), "").unwrap();
        fs::write(mount.join("cgroup.subtree_control"), "memory pids\n").unwrap();
        let hierarchy = Hierarchy::V2 {
            mount: mount.clone(),
        };
        let cgroup = Cgroup::new_in(
            &hierarchy,
            "0::/\n",
            &Limits::test(Duration::from_secs(1), 64),
        )
        .unwrap();
        assert_eq!(cgroup.dirs[0].parent(), Some(mount.as_path()));
        drop(cgroup);
        fs::remove_dir_all(&mount).unwrap();
    }

    #[test]
    fn only_old_empty_cgroups_of_the_grader_count_as_left_behind() {
        let hour = Duration::from_secs(3600);
        let old = 2 * hour;
        assert!(left_behind("course-grader-17-3", "", old, hour));
        assert!(left_behind("course-grader-17-3", "\n", old, hour));
        assert!(
            !left_behind("course-grader-17-3", "", hour / 2, hour),
            "young: its grader may be about to use it"
        );
        assert!(
            !left_behind("course-grader-17-3", "4242\n", old, hour),
            "busy: its processes may be another container's grader's"
        );
        assert!(
            !left_behind("system.slice", "", old, hour),
            "not the grader's"
        );
    }

    #[test]
    fn a_v1_job_gets_a_memory_and_a_pids_cgroup() {
        let root = scratch("v1");
        let hierarchy = Hierarchy::V1 {
            memory: root.join("memory"),
            pids: root.join("pids"),
        };
        for controller in ["memory", "pids"] {
            fs::create_dir_all(root.join(controller).join("grader")).unwrap();
            fs::write(root.join(controller).join("grader/cgroup.procs"), "").unwrap();
        }
        let own = "9:pids:/grader\n4:memory:/grader\n0::/\n";
        let limits = Limits::test(Duration::from_secs(1), 64);
        let cgroup = Cgroup::new_in(&hierarchy, own, &limits).unwrap();
        assert_eq!(cgroup.version, CgroupVersion::V1);
        let memory = fs::read_to_string(cgroup.dirs[0].join("memory.limit_in_bytes")).unwrap();
        assert_eq!(memory, (64_u64 << 20).to_string());
        let pids = fs::read_to_string(cgroup.dirs[1].join("pids.max")).unwrap();
        assert_eq!(pids, limits.processes.to_string());
        assert!(cgroup.dirs[1].starts_with(root.join("pids/grader")));
        drop(cgroup);
        fs::remove_dir_all(&root).unwrap();
    }
}
