//! The review's attack, planted end to end on `fixtures/tiny`: a test of
//! the course compares with an official snapshot; one student's code
//! writes the official body as its pending snapshot and panics with
//! insta's words, another's honestly draws something else. The grade
//! records a mismatch for the honest one alone, so the review has nothing
//! of the forger's to accept or reject, and the forger keeps 0 points.
mod common;

use std::fs;
use std::path::Path;

use common::{copy_dir, fixture, grade_submission, read_json, stdout, task, xtask};
use serde_json::Value;

/// insta's `assert_snapshot!` in miniature (the fixture builds offline,
/// without insta): it compares with the official snapshot and, on a
/// mismatch, leaves a pending one in `INSTA_PENDING_DIR` at the official
/// one's path, and panics with insta's words.
const SNAPSHOT_TEST: &str = r#"
macro_rules! assert_snapshot {
    ($name:literal, $value:expr) => {{
        let value: String = $value;
        let file = concat!("tests/snapshots/double__", $name, ".snap");
        let official = std::fs::read_to_string(file).unwrap();
        let body = official.splitn(3, "---\n").nth(2).unwrap_or(&official).to_owned();
        if body.trim_end() != value.trim_end() {
            let pending = std::path::Path::new(&std::env::var("INSTA_PENDING_DIR").unwrap())
                .join("exercises/01-tiny")
                .join(file)
                .with_extension("snap.new");
            std::fs::create_dir_all(pending.parent().unwrap()).unwrap();
            std::fs::write(&pending, format!("---\nsource: tests/double.rs\n---\n{value}\n")).unwrap();
            panic!("snapshot assertion for '{}' failed in line {}", $name, line!());
        }
    }};
}

#[testkit::test]
fn the_answer() {
    assert_snapshot!("answer", double(21).to_string());
}
"#;

const OFFICIAL_SNAPSHOT: &str = "---\nsource: tests/double.rs\nexpression: double(21)\n---\n42\n";

/// The forger's `double`: the official body as its pending snapshot, and
/// insta's words, whatever it was asked.
const FORGED: &str = r#"pub fn double(_x: i32) -> i32 {
    let dir = std::env::var("INSTA_PENDING_DIR").unwrap_or_default();
    let pending = std::path::Path::new(&dir)
        .join("exercises/01-tiny/tests/snapshots/double__answer.snap.new");
    let _ = std::fs::create_dir_all(pending.parent().unwrap());
    let _ = std::fs::write(&pending, "---\nsource: tests/double.rs\n---\n42\n");
    panic!("snapshot assertion for 'answer' failed in line 3")
}
pub fn negate(x: i32) -> i32 {
    -x
}
"#;

/// The tests of task `id` in `report`'s only topic.
fn tests_of<'a>(report: &'a Value, id: &str) -> &'a Vec<Value> {
    task(report, "01-tiny", id)["tests"].as_array().unwrap()
}

#[test]
fn a_forged_snapshot_mismatch_is_never_recorded_and_an_honest_one_is() {
    let official = fixture("tiny", "review");
    let topic = official.join("exercises/01-tiny");
    let tests = fs::read_to_string(topic.join("tests/double.rs")).unwrap();
    fs::write(topic.join("tests/double.rs"), tests + SNAPSHOT_TEST).unwrap();
    let snapshots = topic.join("tests/snapshots");
    fs::create_dir_all(&snapshots).unwrap();
    fs::write(snapshots.join("double__answer.snap"), OFFICIAL_SNAPSHOT).unwrap();

    let class = Path::new(env!("CARGO_TARGET_TMPDIR")).join("review-class");
    if class.exists() {
        fs::remove_dir_all(&class).unwrap();
    }
    for name in ["mallory", "olga"] {
        for dir in ["exercises", "crates"] {
            copy_dir(&official.join(dir), &class.join(name).join(dir));
        }
        fs::copy(
            official.join("Cargo.toml"),
            class.join(name).join("Cargo.toml"),
        )
        .unwrap();
    }
    let ops = |name: &str| class.join(name).join("exercises/01-tiny/src/ops.rs");
    fs::write(ops("mallory"), FORGED).unwrap();
    // Olga's is honest and wrong: the test's own comparison leaves her
    // drawing as the pending snapshot.
    fs::write(
        ops("olga"),
        "pub fn double(x: i32) -> i32 {\n    x * 3\n}\npub fn negate(x: i32) -> i32 {\n    -x\n}\n",
    )
    .unwrap();

    let out = common::fresh(official.join("target/review-class"));
    let output = grade_submission(&official, &class, &out, &["--jobs", "2"]);
    assert!(output.status.success(), "{output:?}");

    let mallory = read_json(&out.join("mallory/report.json"));
    assert_eq!(task(&mallory, "01-tiny", "double")["score"], 0.0);
    let answer = |report: &Value| -> Value {
        tests_of(report, "double")
            .iter()
            .find(|t| t["name"] == "the_answer")
            .cloned()
            .expect("the snapshot test was graded")
    };
    assert_eq!(answer(&mallory)["status"], "failed");
    assert!(
        answer(&mallory)["reason"]
            .as_str()
            .unwrap()
            .contains("snapshot assertion for 'answer'"),
        "the forged words reached the reason: {:#}",
        answer(&mallory)
    );
    for test in tests_of(&mallory, "double") {
        assert!(
            test.get("snapshot_mismatches").is_none(),
            "a forged mismatch was recorded: {test:#}"
        );
    }
    // Nothing to review: no verdict of a tutor can reach her tests.
    let review = xtask(
        &official,
        &[
            "review",
            "--submission",
            "mallory",
            "--out",
            out.to_str().unwrap(),
            "--list",
        ],
    );
    assert!(review.status.success(), "{review:?}");
    assert!(
        stdout(&review).contains("nothing to review"),
        "{}",
        stdout(&review)
    );
    assert_eq!(read_json(&out.join("mallory/report.json"))["score"], 1.0);

    let olga = read_json(&out.join("olga/report.json"));
    assert_eq!(
        answer(&olga)["snapshot_mismatches"],
        serde_json::json!([{
            "snapshot": "exercises/01-tiny/tests/snapshots/double__answer.snap",
            "captured": "63\n",
        }])
    );
    for test in tests_of(&olga, "double") {
        if test["name"] != "the_answer" {
            assert!(test.get("snapshot_mismatches").is_none(), "{test:#}");
        }
    }
}
