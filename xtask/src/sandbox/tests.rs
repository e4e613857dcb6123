//! The runner's limits over all of a job's processes together, tried on
//! this machine's kernel rather than on a fake cgroup tree: too many
//! processes, too much memory between them, and who they run as. They
//! hold on cgroup v1 and v2 alike (the name of the hierarchy is printed).
//! Where the grader is root on Linux the cgroups must be had, so a run
//! without them fails; elsewhere (a user without a delegated cgroup,
//! macOS, Windows) the tests say they were not run.

use std::path::Path;
use std::time::Duration;

use super::{Jail, Job, Limits, Purpose};

/// A scratch folder of its own for each test, made empty.
fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("xtask-limits-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("course")).unwrap();
    dir
}

/// A job that runs `script` with `sh` in `dir`, with `limits`.
fn shell_job(dir: &Path, script: &str, limits: Limits) -> Job {
    Job {
        purpose: Purpose::Run,
        program: "/bin/sh".into(),
        args: vec!["-c".into(), script.into()],
        cwd: dir.join("work"),
        course: dir.join("course"),
        read_only: Vec::new(),
        writable: vec![dir.join("work")],
        emptied: Vec::new(),
        env: Vec::new(),
        gpu: false,
        limits,
        stdout: dir.join("out.log"),
        stderr: None,
    }
}

/// The jail, where it can limit a job's processes together; `None` (and
/// a line saying why) where it cannot and need not.
fn jail_with_cgroups() -> Option<&'static Jail> {
    let jail = Jail::get();
    let cgroup = jail.containment().cgroup;
    let as_root = cfg!(target_os = "linux") && rustix::process::geteuid().is_root();
    match cgroup {
        Some(version) => {
            eprintln!("cgroup {version:?}, sandboxed: {}", jail.sandboxed());
            Some(jail)
        }
        None if as_root => panic!(
            "as root on Linux the cgroups must be had: {}",
            jail.missing().join("; ")
        ),
        None => {
            eprintln!(
                "not run: no cgroup can be made here ({})",
                jail.missing().join("; ")
            );
            None
        }
    }
}

#[test]
fn processes_past_the_limit_are_refused_and_the_report_names_it() {
    let Some(jail) = jail_with_cgroups() else {
        return;
    };
    let dir = scratch("processes");
    let limits = Limits {
        processes: 32,
        ..Limits::test(Duration::from_secs(30), 256)
    };
    // A hundred processes at once, which the kernel refuses past 32.
    let script = "i=0; while [ $i -lt 100 ]; do sleep 1 & i=$((i+1)); done; wait; echo done";
    let ended = jail.run(&shell_job(&dir, script, limits)).unwrap();
    let output = std::fs::read_to_string(dir.join("out.log")).unwrap_or_default();
    assert_eq!(
        ended.exit.process_limit,
        Some(32),
        "{:?}\n{output}",
        ended.exit
    );
    assert!(!ended.exit.timed_out, "{:?}", ended.exit);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn processes_that_use_more_memory_together_than_the_limit_are_stopped() {
    let Some(jail) = jail_with_cgroups() else {
        return;
    };
    let dir = scratch("memory");
    // Four processes that each keep what they read (`tail` holds the
    // last line, and /dev/zero has no line break): each stays below the
    // address-space limit of one process (96 MiB) until their sum meets
    // the cgroup's, which stops them.
    let limits = Limits::test(Duration::from_secs(60), 96);
    let script = "for i in 1 2 3 4; do tail /dev/zero & done; wait";
    let ended = jail.run(&shell_job(&dir, script, limits)).unwrap();
    let output = std::fs::read_to_string(dir.join("out.log")).unwrap_or_default();
    assert_eq!(
        ended.exit.memory_limit,
        Some(96),
        "{:?}\n{output}",
        ended.exit
    );
    assert!(
        ended
            .exit
            .stop_reason(60.0)
            .unwrap()
            .contains("out of memory"),
        "{:?}",
        ended.exit
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_test_never_runs_as_root() {
    let Some(jail) = jail_with_cgroups() else {
        return;
    };
    let dir = scratch("user");
    let ended = jail
        .run(&shell_job(
            &dir,
            "id -u",
            Limits::test(Duration::from_secs(30), 256),
        ))
        .unwrap();
    let uid = std::fs::read_to_string(dir.join("out.log")).unwrap();
    assert!(ended.success(), "{:?}: {uid}", ended.exit);
    assert_ne!(uid.trim(), "0", "a test ran as root");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_cgroup_that_a_killed_grader_left_is_removed_at_the_next_start() {
    use super::cgroup::{Cgroup, Hierarchy};
    use std::time::SystemTime;
    if jail_with_cgroups().is_none() {
        return;
    }
    let hierarchy = Hierarchy::detect().unwrap();
    let own = std::fs::read_to_string("/proc/self/cgroup").unwrap();
    let parent = hierarchy.parents(&own).unwrap().remove(0);
    // As a grader killed with SIGKILL leaves its cgroup: empty, and made
    // long ago (no process has the id 0, so it is no running grader's).
    let left = parent.join("course-grader-0-0");
    let young = parent.join("course-grader-0-1");
    for dir in [&left, &young] {
        let _ = std::fs::create_dir(dir);
    }
    let two_hours_ago = SystemTime::now() - Duration::from_secs(7200);
    std::fs::File::open(&left)
        .unwrap()
        .set_modified(two_hours_ago)
        .unwrap();
    Cgroup::available(&hierarchy).unwrap();
    let (left_gone, young_kept) = (!left.exists(), young.exists());
    let _ = std::fs::remove_dir(&young);
    let _ = std::fs::remove_dir(&left);
    assert!(left_gone, "{} was left", left.display());
    assert!(young_kept, "a cgroup made just now was removed");
}
