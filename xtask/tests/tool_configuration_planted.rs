//! Test tools configured by the course alone, planted end to end: a real
//! insta snapshot test of `fixtures/tiny`, and an `insta.yaml` that would
//! make every snapshot pass (`force_pass`) planted in a submission (at its
//! root and in `.config/`) and in the folder above the course. A wrong
//! drawing fails its snapshot all the same, and both members score alike.
mod common;

use std::fs;
use std::path::Path;

use common::{copy_dir, fixture, grade_submission, read_json, task};

/// A configuration that, if insta read it, would pass every snapshot and
/// write the student's over the official one.
const LOOSE: &str = "behavior:\n  force_pass: true\n  update: always\n  output: none\n";

#[test]
fn an_insta_yaml_in_the_submission_or_above_the_course_changes_nothing() {
    // The course one folder below a folder of its own, which gets a
    // configuration file too.
    let fixture_copy = fixture("tiny", "insta-config");
    let above = Path::new(env!("CARGO_TARGET_TMPDIR")).join("insta-config-above");
    let official = above.join("course");
    for dir in ["exercises", "crates"] {
        if official.join(dir).exists() {
            fs::remove_dir_all(official.join(dir)).unwrap();
        }
        copy_dir(&fixture_copy.join(dir), &official.join(dir));
    }
    // The fixture's workspace with insta, resolved offline from the
    // course's own lock file (the workspace depends on insta 1.49).
    let workspace = fs::read_to_string(fixture_copy.join("Cargo.toml")).unwrap();
    fs::write(
        official.join("Cargo.toml"),
        workspace.replace(
            "[workspace.dependencies]\n",
            "[workspace.dependencies]\ninsta = \"1.49\"\n",
        ),
    )
    .unwrap();
    let lock = Path::new(env!("CARGO_MANIFEST_DIR")).join("../Cargo.lock");
    fs::copy(lock, official.join("Cargo.lock")).unwrap();
    let topic = official.join("exercises/01-tiny");
    let manifest = fs::read_to_string(topic.join("Cargo.toml")).unwrap();
    fs::write(
        topic.join("Cargo.toml"),
        manifest.replace(
            "[dev-dependencies]\n",
            "[dev-dependencies]\ninsta.workspace = true\n",
        ),
    )
    .unwrap();
    let tests = fs::read_to_string(topic.join("tests/double.rs")).unwrap();
    fs::write(
        topic.join("tests/double.rs"),
        tests
            + "\n#[testkit::test]\nfn the_answer() {\n    insta::assert_snapshot!(\"answer\", double(21).to_string());\n}\n",
    )
    .unwrap();
    fs::create_dir_all(topic.join("tests/snapshots")).unwrap();
    fs::write(
        topic.join("tests/snapshots/double__answer.snap"),
        "---\nsource: exercises/01-tiny/tests/double.rs\nexpression: double(21).to_string()\n---\n42\n",
    )
    .unwrap();
    // The sandboxed build is offline: insta's sources fetched first
    // (nothing to do where the course was built).
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let fetched = std::process::Command::new(cargo)
        .arg("fetch")
        .current_dir(&official)
        .env_remove("CARGO_TARGET_DIR")
        .status()
        .unwrap();
    assert!(fetched.success(), "cargo fetch in {}", official.display());
    fs::write(above.join("insta.yaml"), LOOSE).unwrap();
    fs::create_dir_all(above.join(".config")).unwrap();
    fs::write(above.join(".config/insta.yaml"), LOOSE).unwrap();

    // Two members with the same wrong `double`; one planted the files.
    let class = above.join("class");
    if class.exists() {
        fs::remove_dir_all(&class).unwrap();
    }
    for name in ["plain", "planted"] {
        let member = class.join(name);
        for dir in ["exercises", "crates"] {
            copy_dir(&official.join(dir), &member.join(dir));
        }
        fs::copy(official.join("Cargo.toml"), member.join("Cargo.toml")).unwrap();
        fs::write(
            member.join("exercises/01-tiny/src/ops.rs"),
            "pub fn double(x: i32) -> i32 {\n    x * 3\n}\npub fn negate(x: i32) -> i32 {\n    -x\n}\n",
        )
        .unwrap();
    }
    let planted = class.join("planted");
    fs::write(planted.join("insta.yaml"), LOOSE).unwrap();
    fs::write(planted.join(".insta.yaml"), LOOSE).unwrap();
    fs::create_dir_all(planted.join(".config")).unwrap();
    fs::write(planted.join(".config/insta.yaml"), LOOSE).unwrap();
    fs::write(planted.join("exercises/01-tiny/insta.yaml"), LOOSE).unwrap();

    let out = common::fresh(official.join("target/insta-config-class"));
    let output = grade_submission(&official, &class, &out, &["--jobs", "2"]);
    assert!(output.status.success(), "{output:?}");
    let scores: Vec<serde_json::Value> = ["plain", "planted"]
        .iter()
        .map(|name| {
            let report = read_json(&out.join(name).join("report.json"));
            let double = task(&report, "01-tiny", "double");
            let answer = double["tests"]
                .as_array()
                .unwrap()
                .iter()
                .find(|t| t["name"] == "the_answer")
                .cloned()
                .expect("the snapshot test was graded");
            assert_eq!(answer["status"], "failed", "{name}: {answer:#}");
            assert!(
                answer["reason"]
                    .as_str()
                    .unwrap()
                    .contains("does not match"),
                "{name}: not a snapshot failure: {answer:#}"
            );
            report["score"].clone()
        })
        .collect();
    assert_eq!(scores[0], scores[1], "the planted files changed the score");

    // Even a configuration file at the stage's root (where insta does
    // look) sets nothing the grader sets: each setting comes from the
    // job's environment first.
    fs::write(official.join("insta.yaml"), LOOSE).unwrap();
    let again = common::fresh(official.join("target/insta-config-again"));
    let output = grade_submission(&official, &class.join("plain"), &again, &[]);
    assert!(output.status.success(), "{output:?}");
    let report = read_json(&again.join("plain/report.json"));
    assert_eq!(
        report["score"], scores[0],
        "insta.yaml in the stage loosened the grade"
    );
    fs::remove_file(official.join("insta.yaml")).unwrap();
    // The official snapshot was never written over.
    assert!(
        fs::read_to_string(topic.join("tests/snapshots/double__answer.snap"))
            .unwrap()
            .ends_with("\n42\n")
    );
}
