//! `cargo xtask stubs` and `cargo xtask test` run end to end on the
//! fixture courses (see `fixture_courses.rs`): the stubs are checked,
//! generated and score 0, marker errors name their file and line, and on
//! `fixtures/tiny`, a correct course, `cargo xtask test` passes until a
//! stub starts scoring points.
mod common;

use std::fs;

use common::{fixture, grade, stdout, xtask};

#[test]
fn stubs_are_checked_generated_and_score_zero() {
    let root = fixture("hostile", "stubs");

    // The hostile student files are not what the reference generates.
    let check = xtask(&root, &["stubs", "--check"]);
    assert!(!check.status.success());
    let text = stdout(&check);
    assert!(
        text.contains("exercises/01-hostile/src/misbehave.rs:1: out of date (first difference)"),
        "{text}"
    );
    assert!(
        text.contains("exercises/02-broken/src/value.rs:1: out of date"),
        "{text}"
    );
    assert!(!text.contains("03-misfiled"), "{text}");
    let student = fs::read_to_string(root.join("exercises/01-hostile/src/misbehave.rs")).unwrap();
    assert!(student.contains("div_ceil"), "--check writes nothing");

    let write = xtask(&root, &["stubs"]);
    assert!(write.status.success());
    let stub = fs::read_to_string(root.join("exercises/01-hostile/src/misbehave.rs")).unwrap();
    assert!(
        stub.starts_with(
            "//! The solutions: every function does what its test expects.\n\n/// `a + b`.\n"
        ),
        "{stub}"
    );
    assert!(stub.contains("pub fn add(a: u32, b: u32) -> u32 {\n    // Unused until you write the body:\n    let _ = (&a, &b);\n    todo!(\"ok: add \\\"a\\\" and \\\"b\\\"\")\n}\n"), "{stub}");
    assert!(
        stub.contains("    todo!(\"panics: halve {{x}}\")\n"),
        "{stub}"
    );
    assert!(
        !stub.contains("black_box") && !stub.contains("SOLUTION"),
        "{stub}"
    );
    assert!(xtask(&root, &["stubs", "--check"]).status.success());

    // Given code exists once, in exercises/: a copy in reference/ without
    // a solution is an error, a given file in exercises/ alone is not.
    fs::write(root.join("exercises/02-broken/src/given.rs"), "").unwrap();
    assert!(xtask(&root, &["stubs", "--check"]).status.success());
    fs::write(root.join("reference/02-broken/src/given.rs"), "").unwrap();
    let copied = xtask(&root, &["stubs", "--check"]);
    assert!(!copied.status.success());
    assert!(
        stdout(&copied).contains("reference/02-broken/src/given.rs holds no `// BEGIN SOLUTION`: given code belongs in exercises/02-broken/src/given.rs alone"),
        "{}",
        stdout(&copied)
    );
    fs::remove_file(root.join("reference/02-broken/src/given.rs")).unwrap();
    fs::remove_file(root.join("exercises/02-broken/src/given.rs")).unwrap();

    // Crate roots are plain: a `#[path]` switch is an error.
    let lib = root.join("exercises/02-broken/src/lib.rs");
    let plain = fs::read_to_string(&lib).unwrap();
    fs::write(
        &lib,
        plain.replace(
            "pub mod value;",
            "#[cfg_attr(feature = \"reference\", path = \"../../../reference/02-broken/src/value.rs\")]\npub mod value;",
        ),
    )
    .unwrap();
    let switched = xtask(&root, &["stubs", "--check"]);
    assert!(!switched.status.success());
    assert!(
        stdout(&switched).contains(
            "exercises/02-broken/src/lib.rs:3: a crate root declares its modules plainly"
        ),
        "{}",
        stdout(&switched)
    );
    fs::write(&lib, plain).unwrap();

    // Untouched stubs compile, score 0, and every failure names its todo.
    let (_, report, _) = grade(&root, "grade", &["01", "broken"]);
    assert_eq!(report["score"], 0.0);
    assert_eq!(report["complete"], true);
    for topic in report["topics"].as_array().unwrap() {
        for task in topic["tasks"].as_array().unwrap() {
            let id = task["id"].as_str().unwrap();
            assert_eq!(task["status"], "fail", "{task:#}");
            for test in task["tests"]
                .as_array()
                .unwrap()
                .iter()
                .filter(|t| t["status"] == "failed")
            {
                let reason = test["reason"].as_str().unwrap();
                assert!(
                    reason.starts_with(&format!("not implemented yet: {id}: ")),
                    "{id}: {reason}"
                );
            }
        }
    }
}

#[test]
fn marker_errors_are_reported_with_file_and_line() {
    let root = fixture("hostile", "markers");
    let solution = root.join("reference/03-misfiled/src/alpha.rs");
    let text = fs::read_to_string(&solution).unwrap();
    fs::write(
        &solution,
        text.replace("alpha: return one", "beta: return one"),
    )
    .unwrap();
    let output = xtask(&root, &["stubs"]);
    assert!(!output.status.success());
    let text = stdout(&output);
    assert!(
        text.contains("reference/03-misfiled/src/alpha.rs:5: task `beta` is not a task of this topic (the task sheet lists: alpha, lonely)"),
        "{text}"
    );
}

#[test]
fn test_command_passes_on_a_correct_course_and_fails_when_a_stub_scores() {
    let root = fixture("tiny", "test");
    // The steps every course has; those after them are about the course's
    // own tooling on other systems (the Windows build of `xtask`, the
    // hosted-runner workflow), which the fixture has none of.
    let course_steps: Vec<String> = (1..=10).map(|n| n.to_string()).collect();
    let mut test_args = vec!["test"];
    for step in &course_steps {
        test_args.extend(["--step", step.as_str()]);
    }
    let output = xtask(&root, &test_args);
    let text = stdout(&output);
    assert!(output.status.success(), "{text}");
    for heading in [
        "==> [1/",
        "==> [2/",
        "] reference solutions are clippy-clean",
        "==> [4/",
        "==> [5/",
        "] the stubs are clippy-clean",
        "] a do-nothing edition scores 0 on every task",
        "] planted shortcuts lose their points",
        "] given code stands in for no task",
        "==> [10/",
        "] the student edition",
        "==> summary",
        "all 10 steps passed",
    ] {
        assert!(text.contains(heading), "{heading} in {text}");
    }
    assert!(root.join("target/grade/reference/report.json").is_file());
    assert!(root.join("target/grade/stubs/junit.xml").is_file());
    let edition = root.join("target/xtask/release");
    assert!(edition.join("exercises/01-tiny/src/ops.rs").is_file());
    assert!(
        !edition.join("reference").exists(),
        "no solutions in the edition"
    );

    // A "stub" that already solves its task breaks steps 1, 5, 7 and 9
    // (the edition students get would pay for it too, and so would a
    // student who does nothing).
    let stub = root.join("exercises/01-tiny/src/ops.rs");
    let text = fs::read_to_string(&stub).unwrap();
    let text_before = text.clone();
    fs::write(
        &stub,
        text.replace("todo!(\"negate: return minus x\")", "-x"),
    )
    .unwrap();
    let output = xtask(&root, &test_args);
    let text = stdout(&output);
    assert!(!output.status.success(), "{text}");
    assert!(
        text.contains("FAIL") && text.contains("stubs are in sync with reference/"),
        "{text}"
    );
    assert!(text.contains("`negates` passes against the stub"), "{text}");
    assert!(
        text.contains("`cargo xtask grade 01-tiny` in the edition scores 1.0 instead of 0"),
        "{text}"
    );
    assert!(
        text.contains(
            "01-tiny / negate: 1 of 1 points for doing nothing (1 of 1 tests pass: negates)"
        ),
        "{text}"
    );
    assert!(
        text.contains("4 of 10 steps failed")
            || String::from_utf8_lossy(&output.stderr).contains("4 of 10 steps failed"),
        "{text}"
    );

    // Given code that solves a task: a library function with the task's
    // signature fails the step that plants it into the stub.
    fs::write(&stub, &text_before).unwrap();
    fs::write(
        root.join("exercises/01-tiny/src/helpers.rs"),
        "//! Given helpers.\n\n/// Minus `x`.\npub fn minus(x: i32) -> i32 {\n    -x\n}\n",
    )
    .unwrap();
    let lib = root.join("exercises/01-tiny/src/lib.rs");
    let mut crate_root = fs::read_to_string(&lib).unwrap();
    crate_root.push_str("pub mod helpers;\n");
    fs::write(&lib, crate_root).unwrap();
    let output = xtask(&root, &["test", "--step", "9"]);
    let text = stdout(&output);
    assert!(!output.status.success(), "{text}");
    assert!(
        text.contains(
            "exercises/01-tiny/src/helpers.rs: minus scores 1 of 1 points in place of 01-tiny / negate"
        ),
        "{text}"
    );
}
