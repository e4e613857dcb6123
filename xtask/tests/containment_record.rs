//! The grade of record's promises (see `containment.rs` for the class of
//! attacks): it refuses to run student code without its sandbox unless a
//! tutor says so on purpose; student code never runs as root, nor makes a
//! user namespace of its own; and a build that student code makes endless
//! or huge ends in seconds with its reason, costing the class nothing.
//!
//! The grader here runs as root on a cgroup v1 machine: the v2 path of
//! the aggregate limits runs on GitHub's hosted Ubuntu runner (the
//! platforms workflow), and on file trees in `sandbox/cgroup.rs`'s tests.

mod common;

#[test]
fn a_grade_of_record_refuses_to_run_student_code_without_its_sandbox() {
    #[cfg(target_os = "linux")]
    linux::a_grade_of_record_refuses_to_run_student_code_without_its_sandbox();
    #[cfg(not(target_os = "linux"))]
    eprintln!("not run: off Linux there is no sandbox to insist on");
}

#[test]
fn student_code_is_neither_root_nor_endless_nor_huge_at_build_time() {
    #[cfg(target_os = "linux")]
    linux::student_code_is_neither_root_nor_endless_nor_huge_at_build_time();
    #[cfg(not(target_os = "linux"))]
    eprintln!("not run: the sandbox these plants meet is Linux's (bubblewrap)");
}

/// The plants, which need Linux (bubblewrap, `id`, `unshare`).
#[cfg(target_os = "linux")]
mod linux {
    use std::fs;
    use std::path::Path;
    use std::process::Output;
    use std::time::{Duration, Instant};

    use super::common::class::{first_reason, member, ops};
    use super::common::{fixture, read_json};

    /// A build limit no plant may reach: a member stopped by it was not
    /// bounded by anything else.
    const BUILD_LIMIT_S: u64 = 600;

    fn grade(
        official: &Path,
        submission: &Path,
        out: &Path,
        extra: &[&str],
        env: &[(&str, &str)],
    ) -> Output {
        let mut command = std::process::Command::new(env!("CARGO_BIN_EXE_xtask"));
        command
            .arg("--root")
            .arg(official)
            .args(["grade", "--submission"])
            .arg(submission)
            .arg("--out")
            .arg(out)
            .args(extra)
            .env_remove("CARGO_TARGET_DIR")
            .env_remove("RUSTFLAGS")
            .env("NO_COLOR", "1");
        for (name, value) in env {
            command.env(name, value);
        }
        let output = command.output().expect("xtask runs");
        eprintln!(
            "{}\n{}",
            String::from_utf8_lossy(&output.stdout),
            String::from_utf8_lossy(&output.stderr)
        );
        output
    }

    /// Without bubblewrap (as where it cannot run) `--submission` refuses,
    /// saying what is missing and how to get it, and runs nothing; with
    /// `--unsandboxed-on-purpose` it grades, and the report says so.
    pub fn a_grade_of_record_refuses_to_run_student_code_without_its_sandbox() {
        let official = fixture("tiny", "record-refused");
        let class = Path::new(env!("CARGO_TARGET_TMPDIR")).join("record-refused-class");
        if class.exists() {
            fs::remove_dir_all(&class).unwrap();
        }
        let member = member(&official, &class, "member", Some(&ops("x * 2", "-x")));
        let out = crate::common::fresh(official.join("target/record-refused"));
        let no_sandbox = [("XTASK_NO_SANDBOX", "1")];
        let refused = grade(&official, &member, &out, &[], &no_sandbox);
        let said = String::from_utf8_lossy(&refused.stderr);
        assert!(!refused.status.success(), "graded without the sandbox");
        assert!(
            said.contains("refusing to run student code") && said.contains("bubblewrap"),
            "{said}"
        );
        assert!(said.contains("--unsandboxed-on-purpose"), "{said}");
        assert!(
            !out.join("member/report.json").exists() && !out.join("report.json").exists(),
            "a report was written: student code ran"
        );

        let graded = grade(
            &official,
            &member,
            &out,
            &["--unsandboxed-on-purpose"],
            &no_sandbox,
        );
        assert!(graded.status.success());
        let report = read_json(&out.join("member/report.json"));
        assert_eq!(report["score"], 3.0, "{}", first_reason(&report));
        assert_eq!(report["sandboxed"], false);
        assert_eq!(report["containment"]["on_purpose"], true, "{report:#}");
        // Gradescope's results say it too.
        let results = read_json(&out.join("member/results.json"));
        let said = results["output"].as_str().unwrap_or_default();
        assert!(
            said.contains("graded on purpose (--unsandboxed-on-purpose) without bubblewrap"),
            "{results:#}"
        );
    }

    /// A class of four graded for the record in the sandbox: the honest
    /// member; one whose tests are right only as root or where they can
    /// make a user namespace; one with an endless `const` under
    /// `#[allow(long_running_const_eval)]`; one with a `const` array past
    /// the build's memory cap.
    pub fn student_code_is_neither_root_nor_endless_nor_huge_at_build_time() {
        let official = fixture("tiny", "record");
        let class = Path::new(env!("CARGO_TARGET_TMPDIR")).join("record-class");
        if class.exists() {
            fs::remove_dir_all(&class).unwrap();
        }
        member(&official, &class, "a-honest", Some(&ops("x * 2", "-x")));
        // Right only where it is root, or may make a user namespace (in
        // which it would hold every capability).
        let privileged = "    let uid = std::process::Command::new(\"id\").arg(\"-u\").output().expect(\"id runs\");\n\
             let uid = String::from_utf8_lossy(&uid.stdout).trim().to_owned();\n\
             let userns = std::process::Command::new(\"unshare\").args([\"--user\", \"true\"]).status().expect(\"unshare runs\");\n\
             assert!(uid == \"0\" || userns.success(), \"uid {uid}, no user namespace: {userns}\");";
        member(
            &official,
            &class,
            "privileged",
            Some(&ops(
                &format!("{privileged}\n    x * 2"),
                &format!("{privileged}\n    -x"),
            )),
        );
        member(
            &official,
            &class,
            "endless-const",
            Some(&format!(
                "{}\n#[allow(long_running_const_eval)]\n\
                 const FOREVER: i32 = {{ let mut i: i32 = 0; loop {{ i = i.wrapping_add(1); }} }};\n",
                ops("x * 2 + FOREVER * 0", "-x")
            )),
        );
        // 12 GiB, past the build's 8 GiB cap (a 2 GiB one, uncapped, took
        // rustc more than 20 GiB: do not plant a smaller one).
        member(
            &official,
            &class,
            "huge-const",
            Some(&format!(
                "{}\nconst HUGE: [u8; 12 << 30] = [7; 12 << 30];\n",
                ops("x * 2 + i32::from(HUGE[3]) * 0", "-x")
            )),
        );
        let out = crate::common::fresh(official.join("target/record"));
        let limit = BUILD_LIMIT_S.to_string();
        let started = Instant::now();
        let output = grade(
            &official,
            &class,
            &out,
            &["--jobs", "2", "--build-time-limit", &limit],
            &[],
        );
        let elapsed = started.elapsed();
        let gradebook = fs::read_to_string(out.join("gradebook.csv")).expect("a gradebook");
        let report = |name: &str| read_json(&out.join(name).join("report.json"));
        let honest = report("a-honest");
        assert_eq!(honest["score"], 3.0, "{}", first_reason(&honest));
        assert_eq!(
            honest["sandboxed"], true,
            "on Linux the plants must meet the sandbox"
        );
        assert_eq!(honest["containment"]["unprivileged"], true, "{honest:#}");
        assert_eq!(honest["containment"]["on_purpose"], false, "{honest:#}");
        // A grade of record had its cgroups (it refuses without them); the
        // platforms workflow says which hierarchy its runner has.
        assert_eq!(
            honest["containment"]["aggregate_limits"], true,
            "{honest:#}"
        );
        if let Ok(expected) = std::env::var("XTASK_EXPECT_CGROUP") {
            assert_eq!(
                honest["containment"]["cgroup"],
                expected.as_str(),
                "{honest:#}"
            );
        }
        assert!(gradebook.contains("a-honest,3,3"), "{gradebook}");
        assert!(
            output.status.code().is_some(),
            "the grader itself was killed"
        );

        let zero = |name: &str| {
            let report = report(name);
            assert_eq!(
                report["score"],
                0.0,
                "{name} scored: {}",
                first_reason(&report)
            );
            first_reason(&report)
        };
        let why = zero("privileged");
        assert!(why.contains("no user namespace"), "privileged: {why}");
        assert!(!why.contains("uid 0,"), "privileged ran as root: {why}");
        let why = zero("endless-const");
        assert!(
            why.contains("long_running_const_eval"),
            "endless-const: {why}"
        );
        let why = zero("huge-const");
        assert!(
            why.contains("tried to allocate more memory than available to compiler"),
            "huge-const: {why}"
        );
        // Neither build came near the build limit: a class pays seconds for them.
        assert!(
            elapsed < Duration::from_secs(BUILD_LIMIT_S / 2),
            "the class took {elapsed:?}"
        );
    }
}
