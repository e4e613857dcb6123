//! A class of the tiny fixture course, as the containment tests build
//! it: a member's checkout with its `ops.rs`, the secret in the grader's
//! environment, every file of a folder (for "nothing changed") and the
//! reasons a member's report gives.

use std::fs;
use std::path::{Path, PathBuf};

use serde_json::Value;

use super::{copy_dir, topic};

/// A secret in the grader's environment, which no student code may see.
pub const SECRET: &str = "ghp_course-grader-secret-2f9c";

/// `ops.rs` for a member: `double` and `negate` as given (bodies of the
/// functions).
pub fn ops(double: &str, negate: &str) -> String {
    format!(
        "//! Two small operations.\n\n/// `2 x`.\npub fn double(x: i32) -> i32 {{\n{double}\n}}\n\n/// `-x`.\npub fn negate(x: i32) -> i32 {{\n{negate}\n}}\n"
    )
}

/// A checkout of the tiny course with `ops.rs` as given, in `class/name`.
pub fn member(official: &Path, class: &Path, name: &str, ops: Option<&str>) -> PathBuf {
    let dir = class.join(name);
    for folder in ["exercises", "crates"] {
        copy_dir(&official.join(folder), &dir.join(folder));
    }
    fs::copy(official.join("Cargo.toml"), dir.join("Cargo.toml")).unwrap();
    if let Some(ops) = ops {
        fs::write(dir.join("exercises/01-tiny/src/ops.rs"), ops).unwrap();
    }
    dir
}

/// Every file under `dir` with its contents, for "nothing changed".
pub fn snapshot(dir: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let mut files = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in fs::read_dir(&dir).unwrap().flatten() {
            let path = entry.path();
            if entry.file_type().unwrap().is_dir() {
                if path.file_name().unwrap() != "target" {
                    stack.push(path);
                }
            } else {
                files.push((path.clone(), fs::read(&path).unwrap_or_default()));
            }
        }
    }
    files.sort();
    files
}

pub fn first_reason(report: &Value) -> String {
    let topic = topic(report, "01-tiny");
    if let Some(error) = topic["compile_error"].as_str() {
        return error.to_owned();
    }
    let mut reasons = Vec::new();
    for task in topic["tasks"].as_array().unwrap() {
        for test in task["tests"].as_array().unwrap() {
            if let Some(reason) = test["reason"].as_str() {
                reasons.push(reason.to_owned());
            }
        }
    }
    reasons.extend(
        topic["errors"]
            .as_array()
            .unwrap()
            .iter()
            .map(|e| e.as_str().unwrap().to_owned()),
    );
    reasons.join("\n")
}
