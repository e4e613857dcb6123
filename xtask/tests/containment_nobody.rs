//! Student code graded without the sandbox (see `containment.rs`): the
//! environment is still scrubbed, and a grader that is root runs it as
//! nobody. On Linux only, where `/proc/self/status` tells the user.

mod common;

#[test]
fn unsandboxed_student_code_runs_as_nobody_and_sees_no_secret() {
    #[cfg(target_os = "linux")]
    linux::unsandboxed_student_code_runs_as_nobody_and_sees_no_secret();
    #[cfg(not(target_os = "linux"))]
    eprintln!("not run: the user test reads Linux's /proc/self/status");
}

/// The attacks, which need Linux (symbolic links, `/proc`, bubblewrap).
#[cfg(target_os = "linux")]
mod linux {
    use std::fs;
    use std::path::Path;

    use super::common::class::{SECRET, first_reason, member, ops};
    use super::common::{fixture, read_json};

    /// Without the sandbox (as where bubblewrap cannot run) the promises that
    /// remain still hold: the environment is scrubbed, and student code never
    /// runs as root — a grader that is root (Gradescope's container) runs it
    /// as nobody.
    pub fn unsandboxed_student_code_runs_as_nobody_and_sees_no_secret() {
        let official = fixture("tiny", "unsandboxed");
        let class = Path::new(env!("CARGO_TARGET_TMPDIR")).join("unsandboxed-class");
        if class.exists() {
            fs::remove_dir_all(&class).unwrap();
        }
        let checks = "    let status = std::fs::read_to_string(\"/proc/self/status\").unwrap();\n\
             let uid = status.lines().find(|l| l.starts_with(\"Uid:\")).unwrap().to_owned();\n\
             assert!(!uid.split_whitespace().skip(1).any(|id| id == \"0\"), \"ran as root: {uid}\");\n\
             assert!(std::env::vars().all(|(_, v)| !v.contains(\"course-grader-secret\")), \"saw the secret\");";
        let member = member(
            &official,
            &class,
            "member",
            Some(&ops(
                &format!("{checks}\n    x * 2"),
                &format!("{checks}\n    -x"),
            )),
        );
        let out = crate::common::fresh(official.join("target/unsandboxed"));
        let output = std::process::Command::new(env!("CARGO_BIN_EXE_xtask"))
            .arg("--root")
            .arg(&official)
            .args(["grade", "--submission"])
            .arg(&member)
            .arg("--out")
            .arg(&out)
            // Without the sandbox a grade of record refuses unless told.
            .arg("--unsandboxed-on-purpose")
            .env_remove("CARGO_TARGET_DIR")
            .env_remove("RUSTFLAGS")
            .env("XTASK_NO_SANDBOX", "1")
            .env("COURSE_GRADER_SECRET", SECRET)
            .env("NO_COLOR", "1")
            .output()
            .expect("xtask runs");
        eprintln!(
            "{}\n{}",
            String::from_utf8_lossy(&output.stdout),
            String::from_utf8_lossy(&output.stderr)
        );
        assert!(output.status.success());
        let report = read_json(&out.join("member/report.json"));
        assert_eq!(report["sandboxed"], false);
        assert_eq!(report["containment"]["on_purpose"], true, "{report:#}");
        assert_eq!(report["score"], 3.0, "{}", first_reason(&report));
    }
}
