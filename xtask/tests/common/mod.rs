//! What the tests of `cargo xtask` share: fixture courses copied to a
//! scratch folder, the xtask binary run on them, and reading its reports.

#![allow(dead_code)]

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::{Duration, Instant};

use serde_json::Value;

#[cfg(target_os = "linux")]
pub mod class;

/// Copies `tests/fixtures/<name>` to a scratch folder of its own for
/// `case`, keeping an earlier copy's `target/` so that builds stay warm.
pub fn fixture(name: &str, case: &str) -> PathBuf {
    let source = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures")
        .join(name);
    let copy = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("{name}-{case}"));
    if copy.exists() {
        for entry in fs::read_dir(&copy).unwrap() {
            let path = entry.unwrap().path();
            if path.file_name().unwrap() != "target" {
                if path.is_dir() {
                    fs::remove_dir_all(&path).unwrap();
                } else {
                    fs::remove_file(&path).unwrap();
                }
            }
        }
    }
    copy_dir(&source, &copy);
    // The course's `#[testkit::test]`, which the fixtures' tests use, the
    // record and replay of `#[transcript::task]`, and the words both agree
    // on with the grader.
    let crates = Path::new(env!("CARGO_MANIFEST_DIR")).join("../crates");
    for name in ["testkit-macros", "transcript", "transcript-macros", "wire"] {
        copy_dir(&crates.join(name), &copy.join("crates").join(name));
    }
    copy
}

pub fn copy_dir(from: &Path, to: &Path) {
    fs::create_dir_all(to).unwrap();
    for entry in fs::read_dir(from).unwrap() {
        let entry = entry.unwrap();
        let target = to.join(entry.file_name());
        if entry.file_type().unwrap().is_dir() {
            copy_dir(&entry.path(), &target);
        } else {
            fs::copy(entry.path(), &target).unwrap();
        }
    }
}

/// Runs the xtask binary on the course at `root`.
pub fn xtask(root: &Path, args: &[&str]) -> Output {
    let output = Command::new(env!("CARGO_BIN_EXE_xtask"))
        .arg("--root")
        .arg(root)
        .args(args)
        // The fixtures build with their own target dir and flags.
        .env_remove("CARGO_TARGET_DIR")
        .env_remove("CARGO_BUILD_TARGET_DIR")
        .env_remove("RUSTFLAGS")
        .env_remove("CARGO_ENCODED_RUSTFLAGS")
        .env("NO_COLOR", "1")
        .output()
        .expect("xtask runs");
    eprintln!(
        "$ xtask --root {} {}\n{}\n{}",
        root.display(),
        args.join(" "),
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
    output
}

/// Grades `submission` (a checkout, or a folder of them) against the
/// course at `official` into `out`, with `extra` options.
pub fn grade_submission(official: &Path, submission: &Path, out: &Path, extra: &[&str]) -> Output {
    let mut args = vec![
        "grade",
        "--submission",
        submission.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ];
    args.extend(extra);
    xtask(official, &args)
}

pub fn stdout(output: &Output) -> String {
    String::from_utf8_lossy(&output.stdout).into_owned()
}

pub fn read_json(path: &Path) -> Value {
    let text = fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{} is not JSON: {e}", path.display()))
}

pub fn topic<'a>(report: &'a Value, name: &str) -> &'a Value {
    report["topics"]
        .as_array()
        .unwrap()
        .iter()
        .find(|t| t["name"] == name)
        .unwrap()
}

pub fn task<'a>(report: &'a Value, topic_name: &str, id: &str) -> &'a Value {
    let topic = topic(report, topic_name);
    topic["tasks"]
        .as_array()
        .unwrap()
        .iter()
        .find(|t| t["id"] == id)
        .unwrap()
}

/// The reason of the task's first failing test.
pub fn reason(task: &Value) -> String {
    let test = task["tests"]
        .as_array()
        .unwrap()
        .iter()
        .find(|t| t["status"] == "failed");
    let test = test.unwrap_or_else(|| panic!("no failed test in {task:#}"));
    test["reason"].as_str().unwrap().to_owned()
}

pub fn grade(root: &Path, out: &str, extra: &[&str]) -> (Output, Value, Duration) {
    let out = root.join("target").join(out);
    let mut args = vec!["grade", "--out", out.to_str().unwrap()];
    if !extra.contains(&"--jobs") {
        args.extend(["--jobs", "4"]);
    }
    args.extend(extra);
    let started = Instant::now();
    let output = xtask(root, &args);
    let elapsed = started.elapsed();
    assert!(
        output.status.success(),
        "grading itself must finish: {output:?}"
    );
    (output, read_json(&out.join("report.json")), elapsed)
}

/// `path` emptied: a grade's `--out` in a fixture course, whose `target/`
/// is kept between runs, so that a class graded again keeps no member
/// graded by an earlier run (see `staff::class::resume`).
pub fn fresh(path: PathBuf) -> PathBuf {
    if path.exists() {
        fs::remove_dir_all(&path).unwrap();
    }
    path
}
