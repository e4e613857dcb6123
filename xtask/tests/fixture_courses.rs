//! `cargo xtask` run end to end on two fixture courses (each its own cargo
//! workspace whose one dependency is the course's `#[testkit::test]`,
//! copied to a scratch folder first):
//!
//! - `fixtures/hostile`: student code that panics, loops, overflows its
//!   stack, exits, aborts, allocates 3 GiB, prints without end and fails a
//!   property; a topic that does not compile; a topic whose tests do not
//!   match its task sheet. The grader must report each as that task's
//!   failure with the right reason, within the time limit.
//! - `fixtures/tiny`: a correct course, on which `cargo xtask test` passes
//!   until a stub starts scoring points.

mod common;

use std::fs;
use std::path::Path;
use std::process::Command;
use std::time::Duration;

use common::{
    copy_dir, fixture, grade, grade_submission, read_json, reason, stdout, task, topic, xtask,
};
use serde_json::Value;

/// The hostile fixture's per-test time limit (its task sheet says so).
const HOSTILE_TIME_LIMIT: Duration = Duration::from_secs(3);

#[test]
fn each_misbehaviour_fails_its_task_with_its_reason() {
    let root = fixture("hostile", "student");
    let (output, report, _) = grade(&root, "grade", &[]);

    assert_eq!(report["edition"], "student");
    assert_eq!(
        report["complete"], false,
        "03-misfiled does not match its sheet"
    );

    // Full points for the task that works; ignored tests count neither way.
    let ok = task(&report, "01-hostile", "ok");
    assert_eq!(ok["status"], "ok");
    assert_eq!(ok["score"], 2.0);
    assert_eq!(
        (
            ok["passed"].as_u64(),
            ok["failed"].as_u64(),
            ok["ignored"].as_u64()
        ),
        (Some(4), Some(0), Some(1))
    );

    // Partial points: points × passed / tests.
    let panics = task(&report, "01-hostile", "panics");
    assert_eq!(panics["status"], "fail");
    assert_eq!(panics["score"], 1.0);
    let why = reason(panics);
    assert!(
        why.starts_with("panicked: assertion `left == right` failed: 7 / 2 rounds down"),
        "{why}"
    );
    assert!(why.contains("right: 3"), "{why}");

    let expected = [
        (
            "unfinished",
            "not implemented yet: unfinished: count the pixels",
        ),
        ("loops", "timed out after 3 s (infinite loop?)"),
        ("overflow", "stack overflow"),
        (
            "exits",
            "the test process exited with code 0 before the test finished (process::exit in student code?)",
        ),
        ("aborts", "aborted (signal 6)"),
        (
            "allocates",
            "out of memory (an allocation of 3221225472 bytes failed)",
        ),
        (
            "floods",
            "printed more than 64 MiB of output (endless printing?)",
        ),
        ("shrinks", "panicked: row of 3: 2 pixels instead of 3"),
    ];
    for (id, expected) in expected {
        let task = task(&report, "01-hostile", id);
        assert_eq!(reason(task), expected, "task {id}");
        if id != "shrinks" {
            assert_eq!(task["score"], 0.0, "task {id}");
        }
        for test in task["tests"].as_array().unwrap() {
            let seconds = test["duration_s"].as_f64().unwrap();
            assert!(
                seconds < HOSTILE_TIME_LIMIT.as_secs_f64() + 1.0,
                "{id}: {seconds} s"
            );
        }
    }

    // A flood's log is cut back so that it does not fill the disk.
    let flood_log = root.join("target/grade/logs/01-hostile/floods/greets_once.log");
    let flood_size = fs::metadata(&flood_log).unwrap().len();
    assert!(flood_size < 1 << 20, "{flood_size} bytes");

    // The last of many panics is the report; input and diff come apart.
    let shrinks = task(&report, "01-hostile", "shrinks");
    assert_eq!(shrinks["score"], 0.75);
    let failed = &shrinks["tests"]
        .as_array()
        .unwrap()
        .iter()
        .find(|t| t["status"] == "failed")
        .unwrap();
    assert_eq!(failed["minimal_input"], "n = 3");
    assert_eq!(failed["raster_diff"], "0 |##-");
    assert!(
        failed["output"].as_str().unwrap().contains("row of 9"),
        "the excerpt keeps the output"
    );
    let log = root
        .join("target/grade")
        .join(failed["log"].as_str().unwrap());
    assert!(
        fs::read_to_string(log)
            .unwrap()
            .contains("minimal failing input")
    );

    // A topic that does not compile fails its tasks; the others are graded.
    let broken = topic(&report, "02-broken");
    assert!(
        broken["compile_error"]
            .as_str()
            .unwrap()
            .contains("error[E0308]: mismatched types")
    );
    assert_eq!(
        task(&report, "02-broken", "works")["status"],
        "compile_error"
    );

    // Tests that do not match the task sheet are errors, not crashes.
    let misfiled = topic(&report, "03-misfiled");
    assert!(
        misfiled["errors"][0]
            .as_str()
            .unwrap()
            .contains("tests/stray.rs"),
        "{misfiled:#}"
    );
    assert_eq!(task(&report, "03-misfiled", "lonely")["status"], "error");
    assert_eq!(
        reason(task(&report, "03-misfiled", "alpha")),
        "not implemented yet: alpha: return one"
    );

    // Outside a sandbox, the task that reads the solution scores.
    let sandboxed = report["sandboxed"] == true;
    let score = if sandboxed { 3.75 } else { 4.75 };
    assert_eq!(report["score"], score);
    assert_eq!(report["max_score"], 22.5);

    // The terminal: a table, a total, the first failure of each task.
    let text = stdout(&output);
    let ok_row = text
        .lines()
        .find(|line| line.starts_with("01-hostile"))
        .unwrap();
    assert!(
        ok_row.contains(" ok ") && ok_row.contains("Works") && ok_row.ends_with("2.0 / 2  ok"),
        "{ok_row}"
    );
    assert!(text.contains("total"), "{text}");
    assert!(
        text.contains(if sandboxed {
            "3.8 / 22.5"
        } else {
            "4.8 / 22.5"
        }),
        "{text}"
    );
    assert!(text.contains("compile error"), "{text}");
    assert!(text.contains("minimal failing input:\n    n = 3"), "{text}");
    assert!(
        text.contains("raster diff (expected vs yours):\n    0 |##-"),
        "{text}"
    );
    assert!(
        !text.contains('\x1b'),
        "no colour (NO_COLOR, a pipe) and no escape from student code"
    );
    assert!(
        text.contains("reason:  panicked: \\u{1b}[2J\\u{1b}[Htotal 20.0 / 20"),
        "student text is shown escaped: {text}"
    );

    // Gradescope's shape: one entry per task.
    let results = read_json(&root.join("target/grade/results.json"));
    assert_eq!(results["score"], score);
    let tests = results["tests"].as_array().unwrap();
    assert_eq!(tests.len(), 19);
    assert_eq!(tests[0]["name"], "01-hostile / ok: Works");
    assert_eq!(tests[0]["status"], "passed");
    assert_eq!(tests[1]["status"], "failed");
    assert!(
        tests[1]["output"]
            .as_str()
            .unwrap()
            .contains("7 / 2 rounds down")
    );

    // JUnit: one suite per topic, escaped.
    let junit = fs::read_to_string(root.join("target/grade/junit.xml")).unwrap();
    assert!(junit.starts_with("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites"));
    assert_eq!(junit.matches("<testsuite ").count(), 4);
    assert!(
        junit.contains("<failure message=\"timed out after 3 s (infinite loop?)\""),
        "{junit}"
    );
    assert!(junit.contains("failed: 7 / 2 rounds down&#10;"), "{junit}");
    assert!(
        !junit.contains("thread 'halves"),
        "quotes are escaped in text too"
    );
    // 16 tests in 01, one compile error in 02, in 03 a stray binary, a test,
    // a task without tests, 8 tests in 04.
    assert_eq!(junit.matches("<testcase ").count(), 28, "{junit}");
    assert_eq!(
        junit.matches("<testcase ").count(),
        junit.matches("</testcase>").count()
            + junit.matches("\"/>\n    <testcase").count()
            + junit.matches("\"/>\n  </testsuite>").count()
    );

    // HTML: every topic and task, the first failure escaped, compile errors shown.
    let html = fs::read_to_string(root.join("target/grade/report.html")).unwrap();
    assert!(html.starts_with("<!DOCTYPE html>"), "{html}");
    assert_eq!(html.matches("<h2 id=\"topic-").count(), 4, "{html}");
    assert_eq!(
        html.matches("<td><a href=\"#topic-").count(),
        4,
        "a summary row per topic: {html}"
    );
    assert!(html.contains("href=\"#01-hostile--ok\""), "{html}");
    assert!(html.contains("7 / 2 rounds down"), "{html}");
    assert!(html.contains("does not compile"), "{html}");
    assert!(!html.contains("thread 'halves"), "quotes are escaped");
}

/// Processes whose command line holds `marker`, by `ps`.
fn processes_with(marker: &str) -> Vec<String> {
    let ps = Command::new("ps")
        .args(["-eo", "pid,args"])
        .output()
        .expect("ps runs");
    String::from_utf8_lossy(&ps.stdout)
        .lines()
        .filter(|line| line.contains(marker))
        .map(str::to_owned)
        .collect()
}

#[test]
fn tricks_leave_nothing_behind_and_a_looping_task_fails_fast() {
    let root = fixture("hostile", "tricks");
    let (_, report, elapsed) = grade(&root, "grade", &["tricks", "--jobs", "1"]);

    // In the sandbox the solution cannot be read, and the report a test
    // scribbled over is the harness's own.
    if report["sandboxed"] == true {
        assert_eq!(task(&report, "04-tricks", "peeks")["score"], 0.0);
    }
    assert!(report["topics"].is_array(), "report.json is the grader's");

    // A test that rewrites what it is compared with (directly, and by
    // re-running itself with the bless variables) changes nothing in the
    // sandbox, where the course is read-only.
    if report["sandboxed"] == true {
        let blesses = task(&report, "04-tricks", "blesses");
        assert_eq!(blesses["score"], 0.0, "{blesses}");
        assert_eq!(
            fs::read_to_string(root.join("exercises/04-tricks/tests/expected/nine.txt")).unwrap(),
            "9\n"
        );
    }

    // A forged summary and `exit(0)` before the assertion is no pass, in or
    // out of the sandbox: the test took its token before the code ran.
    let forges = task(&report, "04-tricks", "forges");
    assert_eq!(forges["score"], 0.0, "{forges}");
    assert!(
        reason(forges).contains("did not run to its end"),
        "{forges}"
    );

    // The sleeps a test started and left running die with it.
    let spawns = task(&report, "04-tricks", "spawns");
    assert_eq!(spawns["score"], 0.0);
    let left = processes_with("sleep 299.123");
    assert!(left.is_empty(), "processes outlived their test: {left:?}");

    // Once a test of a task timed out, its other tests are not run.
    let stalls = task(&report, "04-tricks", "stalls");
    let reasons: Vec<&str> = stalls["tests"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| t["reason"].as_str().unwrap())
        .collect();
    assert_eq!(
        reasons,
        [
            "timed out after 3 s (infinite loop?)",
            "not run: an earlier test of this task timed out after 3 s",
            "not run: an earlier test of this task timed out after 3 s",
        ]
    );
    assert!(
        elapsed < HOSTILE_TIME_LIMIT * 2 + Duration::from_secs(20),
        "three looping tests took {elapsed:?}"
    );
}

#[test]
fn reference_scores_full_points_where_tests_match_the_sheet() {
    let root = fixture("hostile", "reference");
    let (_, report, elapsed) = grade(&root, "grade", &["--reference", "hostile", "02"]);
    assert_eq!(report["edition"], "reference");
    assert_eq!(
        report["topics"].as_array().unwrap().len(),
        2,
        "only the topics asked for"
    );
    assert_eq!(report["score"], report["max_score"]);
    assert_eq!(report["score"], 14.5);
    assert_eq!(report["complete"], true);
    for task in topic(&report, "01-hostile")["tasks"].as_array().unwrap() {
        assert_eq!(task["status"], "ok", "{task:#}");
    }
    // Nothing waits for a time limit when every test passes.
    assert!(elapsed < Duration::from_secs(120), "{elapsed:?}");
}

#[test]
fn unknown_topic_is_an_error_that_lists_the_topics() {
    let root = fixture("hostile", "unknown");
    let output = xtask(&root, &["grade", "circles"]);
    assert!(!output.status.success());
    let error = String::from_utf8_lossy(&output.stderr);
    assert!(error.contains("unknown topic `circles`"), "{error}");
    assert!(
        error.contains("01-hostile (hostile), 02-broken (broken), 03-misfiled (misfiled)"),
        "{error}"
    );
}

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

#[test]
fn submissions_are_graded_with_the_official_tests_and_changes_are_flagged() {
    let official = fixture("tiny", "official");
    // A class of four: anna solved `double`, made `negate`'s test pass
    // without solving it and edited lib.rs; ben handed in the stubs
    // untouched; cy compiles the official solution in by `#[path]`, dee
    // reads it with `include_str!`; eve's code rewrites a test of the
    // stage and the course's own task sheet while it runs.
    let class = Path::new(env!("CARGO_TARGET_TMPDIR")).join("tiny-class");
    if class.exists() {
        fs::remove_dir_all(&class).unwrap();
    }
    for name in ["anna", "ben", "cy", "dee", "eve"] {
        for dir in ["exercises", "crates"] {
            copy_dir(&official.join(dir), &class.join(name).join(dir));
        }
        fs::copy(
            official.join("Cargo.toml"),
            class.join(name).join("Cargo.toml"),
        )
        .unwrap();
    }
    let anna = class.join("anna/exercises/01-tiny");
    let ops = fs::read_to_string(anna.join("src/ops.rs")).unwrap();
    fs::write(
        anna.join("src/ops.rs"),
        ops.replace("todo!(\"double: return twice x\")", "x * 2"),
    )
    .unwrap();
    fs::write(anna.join("tests/negate.rs"), "#[test]\nfn negates() {}\n").unwrap();
    fs::write(anna.join("tests/extra.rs"), "#[test]\nfn free() {}\n").unwrap();
    fs::write(anna.join("src/lib.rs"), "pub mod ops;\npub mod extra;\n").unwrap();
    let solution = official.join("reference/01-tiny/src/ops.rs");
    fs::write(
        class.join("cy/exercises/01-tiny/src/ops.rs"),
        format!(
            "#[path = {:?}]\nmod solution;\npub fn double(x: i32) -> i32 {{ solution::double(x) }}\npub fn negate(x: i32) -> i32 {{ solution::negate(x) }}\n",
            solution.display().to_string()
        ),
    )
    .unwrap();
    fs::write(
        class.join("dee/exercises/01-tiny/src/ops.rs"),
        format!(
            "const LEAK: () = panic!(\"{{}}\", include_str!({:?}));\npub fn double(x: i32) -> i32 {{ let () = LEAK; x * 2 }}\npub fn negate(x: i32) -> i32 {{ -x }}\n",
            solution.display().to_string()
        ),
    )
    .unwrap();

    let sheet = official.join("exercises/01-tiny/tasks.toml");
    let official_sheet = fs::read_to_string(&sheet).unwrap();
    // Eve's negate also writes into the class's gradebook and the course's
    // tooling, and answers right only if it can read a classmate's code:
    // in the class folder, in another slot's stage (the class is graded
    // two at a time), or compiled, in the build cache.
    let gradebook = official.join("target/class/gradebook.csv");
    let tooling = official.join("xtask/src/main.rs");
    let classmate = class.join("anna/exercises/01-tiny/src/ops.rs");
    let slots = official.join("target/xtask/class");
    let build = official.join("target/xtask/build");
    fs::write(
        class.join("eve/exercises/01-tiny/src/ops.rs"),
        format!(
            "pub fn double(x: i32) -> i32 {{\n    let _ = std::fs::write(\"tests/negate.rs\", \"#[test] fn negates() {{}}\");\n    let _ = std::fs::write({:?}, \"points = 1000\");\n    x * 2\n}}\n\
             pub fn negate(x: i32) -> i32 {{\n    let _ = std::fs::write({:?}, \"eve,3,3,true,false,3\");\n    let _ = std::fs::create_dir_all(std::path::Path::new({:?}).parent().unwrap());\n    let _ = std::fs::write({:?}, \"fn main() {{}}\");\n\
             let mut seen = std::fs::read_to_string({:?}).is_ok();\n\
             for slot in 0..4 {{\n        let staged = format!(\"{{}}/{{slot}}/stage/exercises/01-tiny/src/ops.rs\", {:?});\n        seen |= std::fs::read_to_string(staged).is_ok_and(|code| !code.contains(\"read_to_string\"));\n    }}\n\
             seen |= std::fs::read_dir({:?}).is_ok_and(|mut entries| entries.next().is_some());\n\
             if seen {{ -x }} else {{ x }}\n}}\n",
            sheet.display().to_string(),
            gradebook.display().to_string(),
            tooling.display().to_string(),
            tooling.display().to_string(),
            classmate.display().to_string(),
            slots.display().to_string(),
            build.display().to_string()
        ),
    )
    .unwrap();
    let out = official.join("target/class");
    let output = grade_submission(&official, &class, &out, &["--jobs", "2"]);
    assert!(output.status.success(), "{output:?}");
    assert!(stdout(&output).contains("flagged (grading files changed): anna"));

    let anna_report = read_json(&out.join("anna/report.json"));
    assert_eq!(anna_report["score"], 2.0, "the official negate test fails");
    assert_eq!(task(&anna_report, "01-tiny", "negate")["score"], 0.0);
    let integrity = &anna_report["integrity"];
    assert_eq!(integrity["changed"][0], "exercises/01-tiny/tests/negate.rs");
    assert_eq!(integrity["added"][0], "exercises/01-tiny/tests/extra.rs");
    assert!(
        anna_report["root"].as_str().unwrap().ends_with("anna"),
        "the report names the submission, not the stage"
    );
    assert_eq!(
        integrity["not_graded"][0], "exercises/01-tiny/src/lib.rs",
        "the course's lib.rs was used"
    );
    for cheat in ["cy", "dee"] {
        let report = read_json(&out.join(cheat).join("report.json"));
        assert_eq!(
            report["score"], 0.0,
            "{cheat}: the solution was not compiled in"
        );
        let why = topic(&report, "01-tiny")["compile_error"]
            .as_str()
            .unwrap()
            .to_owned();
        assert!(
            why.starts_with("not compiled: task code may not reach other files at compile time\nexercises/01-tiny/src/ops.rs:1: "),
            "{cheat}: {why}"
        );
        assert!(
            !why.contains("BEGIN SOLUTION"),
            "{cheat}: the solution leaked: {why}"
        );
    }
    // Eve's tests write official files and read a classmate's: in the
    // sandbox they can do neither (and she scores what her code earns);
    // without one the writes are found afterwards, and she is flagged,
    // scores 0, and is named. The gradebook is the grader's either way.
    let eve = read_json(&out.join("eve/report.json"));
    if eve["sandboxed"] == true {
        assert_eq!(eve["score"], 2.0, "double is right, negate wrong");
        assert_eq!(eve["integrity"]["tampered"], serde_json::json!([]));
        assert_eq!(fs::read_to_string(&sheet).unwrap(), official_sheet);
        assert!(!tooling.exists(), "eve wrote into the course's tooling");
    } else {
        assert_eq!(eve["score"], 0.0, "double passed, but eve scores nothing");
        assert_eq!(
            eve["integrity"]["tampered"],
            serde_json::json!([
                "exercises/01-tiny/tasks.toml",
                "stage/exercises/01-tiny/tests/negate.rs"
            ])
        );
        assert!(
            String::from_utf8_lossy(&output.stderr).contains("changed files of the course itself"),
            "{output:?}"
        );
        assert_ne!(fs::read_to_string(&sheet).unwrap(), official_sheet);
    }
    let ben_report = read_json(&out.join("ben/report.json"));
    assert_eq!(ben_report["score"], 0.0);
    assert_eq!(ben_report["integrity"]["changed"], serde_json::json!([]));
    assert_eq!(ben_report["integrity"]["added"], serde_json::json!([]));

    let csv = fs::read_to_string(out.join("gradebook.csv")).unwrap();
    let (members, eve_row) = csv.split_at(csv.find("\neve,").expect("eve's row") + 1);
    assert_eq!(
        members,
        "submission,score,max_score,bonus,complete,flagged,01-tiny,01-tiny/double,01-tiny/negate,not_graded\n\
         anna,2,3,0,true,true,2,2,0,\n\
         ben,0,3,0,true,false,0,0,0,\n\
         cy,0,3,0,false,false,0,0,0,01-tiny: does not compile\n\
         dee,0,3,0,false,false,0,0,0,01-tiny: does not compile\n"
    );
    if eve["sandboxed"] == true {
        assert_eq!(eve_row, "eve,2,3,0,true,false,2,2,0,\n");
    } else {
        assert!(eve_row.starts_with("eve,0,3,0,false,true,0,"), "{eve_row}");
    }
    let html = fs::read_to_string(out.join("anna/report.html")).unwrap();
    assert!(html.contains("Flagged"), "{html}");
    assert!(html.contains("<h1>anna: 2 of 3 points</h1>"), "{html}");
    // Gradescope shows the flag as a failed entry of its own.
    let gradescope = read_json(&out.join("anna/results.json"));
    assert_eq!(gradescope["extra_data"]["submission"], "anna");
    assert_eq!(gradescope["extra_data"]["flagged"], true);
    assert_eq!(gradescope["tests"][0]["status"], "failed");
    assert!(
        gradescope["tests"][0]["name"]
            .as_str()
            .unwrap()
            .starts_with("Integrity:")
    );
    assert_eq!(
        read_json(&out.join("ben/results.json"))["extra_data"]["flagged"],
        false
    );
    // Nothing was written into the submissions.
    assert!(!class.join("anna/target").exists());
    assert!(!class.join("ben/target").exists());
    assert!(!class.join("cy/target").exists());
}

#[test]
fn watch_grades_again_when_a_file_is_saved() {
    use std::io::{BufRead as _, BufReader};
    use std::sync::mpsc;

    /// Stops the watch however the test ends (it would run on forever).
    struct Stop(std::process::Child);
    impl Drop for Stop {
        fn drop(&mut self) {
            let _ = self.0.kill();
            let _ = self.0.wait();
        }
    }

    let root = fixture("tiny", "watch");
    let child = Command::new(env!("CARGO_BIN_EXE_xtask"))
        .arg("--root")
        .arg(&root)
        .args(["watch", "tiny"])
        .env_remove("CARGO_TARGET_DIR")
        .env("NO_COLOR", "1")
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("xtask watch starts");
    let mut watch = Stop(child);
    let (lines, output) = mpsc::channel();
    let stdout = watch.0.stdout.take().unwrap();
    std::thread::spawn(move || {
        for line in BufReader::new(stdout).lines().map_while(Result::ok) {
            if lines.send(line).is_err() {
                break;
            }
        }
    });
    // Reads lines until one holds `wanted`, and returns what it read.
    let until = |wanted: &str| -> String {
        let mut seen = String::new();
        loop {
            match output.recv_timeout(Duration::from_secs(300)) {
                Ok(line) => {
                    seen.push_str(&line);
                    seen.push('\n');
                    if line.contains(wanted) {
                        return seen;
                    }
                }
                Err(_) => panic!("no line with {wanted:?} after:\n{seen}"),
            }
        }
    };
    let first = until("watching");
    assert!(first.contains("0.0 / 3"), "{first}");
    assert!(
        first.contains("not implemented yet"),
        "the first failing case is shown: {first}"
    );
    // Solve `double`: saving the file grades again.
    let ops = root.join("exercises/01-tiny/src/ops.rs");
    let text = fs::read_to_string(&ops).unwrap();
    fs::write(
        &ops,
        text.replace("todo!(\"double: return twice x\")", "x * 2"),
    )
    .unwrap();
    let second = until("watching");
    drop(watch);
    assert!(second.contains("2.0 / 3"), "{second}");
    assert_eq!(
        second.matches(" / ").count(),
        first.matches(" / ").count(),
        "one screen per grade: {second}"
    );
}

#[test]
fn the_classroom_workflow_reports_each_task_with_its_partial_score() {
    let official = fixture("tiny", "classroom");
    // The edition the students' repositories are made from, carrying the
    // workflow; the course's official copy is the same edition.
    let job = Path::new(env!("CARGO_TARGET_TMPDIR")).join("tiny-classroom-job");
    if job.exists() {
        fs::remove_dir_all(&job).unwrap();
    }
    let released = xtask(
        &official,
        &[
            "release",
            job.join("course").to_str().unwrap(),
            "--classroom",
            "course-author/tiny@v1",
        ],
    );
    assert!(released.status.success());
    assert!(stdout(&released).contains("course-author/tiny at v1"));
    let workflow = fs::read_to_string(job.join("course/.github/workflows/classroom.yml")).unwrap();
    assert!(workflow.contains("repository: course-author/tiny\n          ref: v1\n"));
    assert!(workflow.contains("runners: task-01-tiny-double,task-01-tiny-negate\n"));
    // A student solved `double`, got `negate` wrong, and rewrote its test.
    copy_dir(&job.join("course"), &job.join("submission"));
    let tiny = job.join("submission/exercises/01-tiny");
    let ops = fs::read_to_string(tiny.join("src/ops.rs")).unwrap();
    let ops = ops
        .replace("todo!(\"double: return twice x\")", "x * 2")
        .replace("todo!(\"negate: return minus x\")", "x");
    fs::write(tiny.join("src/ops.rs"), ops).unwrap();
    fs::write(tiny.join("tests/negate.rs"), "#[test]\nfn negates() {}\n").unwrap();
    // The workflow's grading step (here with this xtask), then its task
    // steps as written, each appending to the step's output file.
    let graded = grade_submission(
        &job.join("course"),
        &job.join("submission"),
        &job.join("grade"),
        &[],
    );
    assert!(graded.status.success());
    let mut results = Vec::new();
    for step in workflow.split("\n      - name: ").skip(1) {
        let Some(id) = step.lines().find_map(|l| l.trim().strip_prefix("id: ")) else {
            continue;
        };
        let run = step
            .lines()
            .find_map(|l| l.trim().strip_prefix("run: "))
            .unwrap();
        let output = job.join(format!("{id}.out"));
        let status = Command::new("bash")
            .args(["-e", "-c", run])
            .current_dir(&job)
            .env("GITHUB_OUTPUT", &output)
            .status()
            .unwrap();
        assert!(status.success(), "{id}: {run}");
        let line = fs::read_to_string(&output).unwrap();
        let encoded = line.trim().strip_prefix("result=").unwrap();
        let decoded = Command::new("base64")
            .arg("-d")
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::piped())
            .spawn()
            .and_then(|mut child| {
                use std::io::Write as _;
                child.stdin.take().unwrap().write_all(encoded.as_bytes())?;
                child.wait_with_output()
            })
            .unwrap();
        let result: Value = serde_json::from_slice(&decoded.stdout).unwrap();
        results.push((id.to_owned(), result));
    }
    let ids: Vec<&str> = results.iter().map(|(id, _)| id.as_str()).collect();
    assert_eq!(ids, ["task-01-tiny-double", "task-01-tiny-negate"]);
    // What the reporter adds up: the tests' scores, and max_score per task.
    let score = |r: &Value| r["tests"][0]["score"].as_f64().unwrap();
    let (double, negate) = (&results[0].1, &results[1].1);
    assert_eq!(
        (
            double["status"].as_str(),
            double["max_score"].as_f64(),
            score(double)
        ),
        (Some("pass"), Some(2.0), 2.0)
    );
    assert_eq!(
        (
            negate["status"].as_str(),
            negate["max_score"].as_f64(),
            score(negate)
        ),
        (Some("fail"), Some(1.0), 0.0)
    );
    let message = negate["tests"][0]["message"].as_str().unwrap();
    assert!(message.contains("first failing test: negates"), "{message}");
}

#[test]
fn the_gradescope_autograder_grades_correct_faulty_and_tampered_submissions() {
    let official = fixture("tiny", "gradescope");
    let bundle = Path::new(env!("CARGO_TARGET_TMPDIR")).join("tiny-gradescope-bundle");
    let written = xtask(&official, &["gradescope", bundle.to_str().unwrap()]);
    assert!(written.status.success());
    for script in ["setup.sh", "run_autograder"] {
        let checked = Command::new("bash")
            .arg("-n")
            .arg(bundle.join(script))
            .status()
            .unwrap();
        assert!(checked.success(), "{script} is not valid bash");
    }
    assert!(
        !bundle.join("course/reference").exists(),
        "the bundle holds the solutions"
    );
    let solution = fs::read_to_string(official.join("reference/01-tiny/src/ops.rs")).unwrap();
    // Gradescope's tree, under a prefix: the zip unpacked into source/.
    let autograder = |case: &str, submission: &dyn Fn(&Path)| -> Value {
        let root = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("tiny-gradescope-{case}"));
        if root.exists() {
            fs::remove_dir_all(&root).unwrap();
        }
        fs::create_dir_all(root.join("source")).unwrap();
        let unzipped = Command::new("unzip")
            .args(["-q", bundle.join("autograder.zip").to_str().unwrap()])
            .current_dir(root.join("source"))
            .status()
            .unwrap();
        assert!(unzipped.success());
        fs::create_dir_all(root.join("submission")).unwrap();
        submission(&root.join("submission"));
        let output = Command::new("bash")
            .arg(root.join("source/run_autograder"))
            .env("AUTOGRADER_ROOT", &root)
            .env("XTASK", env!("CARGO_BIN_EXE_xtask"))
            .env_remove("CARGO_TARGET_DIR")
            .env("NO_COLOR", "1")
            .output()
            .unwrap();
        eprintln!("{case}:\n{}", String::from_utf8_lossy(&output.stdout));
        assert!(output.status.success(), "{case}: run_autograder fails");
        read_json(&root.join("results/results.json"))
    };
    let edition = bundle.join("course");
    let solved = |dir: &Path, ops: &str| {
        copy_dir(&edition, dir);
        fs::write(dir.join("exercises/01-tiny/src/ops.rs"), ops).unwrap();
    };
    let tests = |result: &Value| -> Vec<(String, f64)> {
        result["tests"]
            .as_array()
            .unwrap()
            .iter()
            .map(|t| {
                (
                    t["name"].as_str().unwrap().to_owned(),
                    t["score"].as_f64().unwrap(),
                )
            })
            .collect()
    };

    // Correct, uploaded as a zip of the repository's folder.
    let correct = autograder("correct", &|dir| solved(&dir.join("tiny-main"), &solution));
    assert_eq!(correct["score"], 3.0, "{correct:#}");
    assert_eq!(correct["visibility"], "visible");
    assert_eq!(correct["extra_data"]["flagged"], false);
    // Faulty: negate returns x.
    let faulty = autograder("faulty", &|dir| {
        solved(dir, &solution.replace("    -x\n", "    x\n"))
    });
    assert_eq!(faulty["score"], 2.0, "{faulty:#}");
    assert!(tests(&faulty).contains(&("01-tiny / negate: Negation".to_owned(), 0.0)));
    let negate = &faulty["tests"].as_array().unwrap()[1];
    assert!(
        negate["output"]
            .as_str()
            .unwrap()
            .contains("first failing test: negates"),
        "{negate:#}"
    );
    // Tampered: negate's test made to pass anything; flagged, graded on
    // the official test.
    let tampered = autograder("tampered", &|dir| {
        solved(dir, &solution.replace("    -x\n", "    x\n"));
        fs::write(
            dir.join("exercises/01-tiny/tests/negate.rs"),
            "#[test]\nfn negates() {}\n",
        )
        .unwrap();
    });
    assert_eq!(tampered["extra_data"]["flagged"], true, "{tampered:#}");
    assert_eq!(tampered["score"], 2.0, "{tampered:#}");
    assert!(
        tests(&tampered)[0].0.starts_with("Integrity"),
        "{tampered:#}"
    );
    // Not a checkout at all: a result that says so, not a missing file.
    let stray = autograder("stray", &|dir| {
        fs::write(dir.join("ops.rs"), &solution).unwrap()
    });
    assert_eq!(stray["score"], 0, "{stray:#}");
    assert!(
        stray["output"].as_str().unwrap().contains("Not graded"),
        "{stray:#}"
    );
}

#[test]
fn hints_come_one_more_each_time_and_failing_tasks_point_at_them() {
    let root = fixture("tiny", "hints");
    let hint = |args: &[&str]| {
        let mut all = vec!["hint"];
        all.extend(args);
        let output = xtask(&root, &all);
        (
            output.status.success(),
            stdout(&output),
            String::from_utf8_lossy(&output.stderr).into_owned(),
        )
    };
    // What an earlier run of this test saw is kept in the fixture's target/.
    assert!(hint(&["negate", "--reset"]).0);
    let (ok, first, _) = hint(&["negate"]);
    assert!(ok);
    assert!(
        first.contains("01-tiny/negate: Negation (hint 1 of 2)"),
        "{first}"
    );
    assert!(
        first.contains("1. Return the number with its sign flipped.  (new)"),
        "{first}"
    );
    assert!(!first.contains("Zero stays zero"), "{first}");
    let (_, second, _) = hint(&["tiny/negate"]);
    assert!(second.contains("(hint 2 of 2)"), "{second}");
    assert!(
        second.contains("1. Return the number with its sign flipped.\n"),
        "{second}"
    );
    assert!(second.contains("2. Zero stays zero"), "{second}");
    assert!(second.contains("that is every hint"), "{second}");
    let (_, again, _) = hint(&["negate"]);
    assert!(
        again.contains("(hint 2 of 2)") && !again.contains("(new)"),
        "{again}"
    );
    let (ok, _, _) = hint(&["negate", "--reset"]);
    assert!(ok);
    let (_, restarted, _) = hint(&["negate"]);
    assert!(restarted.contains("(hint 1 of 2)"), "{restarted}");
    let (_, none, _) = hint(&["double"]);
    assert!(none.contains("has no hints in its sheet"), "{none}");
    let (ok, _, error) = hint(&["triple"]);
    assert!(
        !ok && error.contains("no task `triple`; the tasks are: 01-tiny/double, 01-tiny/negate"),
        "{error}"
    );
    // The untouched stub fails: the grade names the hint command.
    let (output, report, _) = grade(&root, "grade", &[]);
    assert!(
        stdout(&output)
            .contains("hint:    cargo xtask hint 01-tiny/negate  (2 hints, one more each time)"),
        "{}",
        stdout(&output)
    );
    assert_eq!(
        task(&report, "01-tiny", "negate")["hints"]
            .as_array()
            .unwrap()
            .len(),
        2
    );
    let html = fs::read_to_string(root.join("target/grade/report.html")).unwrap();
    assert!(
        html.contains("<details class=\"hints\"><summary>Hints (2)"),
        "{html}"
    );
}

#[test]
fn a_generated_class_is_graded_two_at_a_time_as_each_member_earns() {
    let official = fixture("tiny", "generated-class");
    let class = Path::new(env!("CARGO_TARGET_TMPDIR")).join("generated-tiny-class");
    if class.exists() {
        fs::remove_dir_all(&class).unwrap();
    }
    let output = xtask(
        &official,
        &["class", class.to_str().unwrap(), "--size", "5"],
    );
    assert!(output.status.success(), "{output:?}");
    assert!(
        stdout(&output).contains("s01-correct, s02-faulty, s03-partial, s04-tampered, s05-broken"),
        "{output:?}"
    );
    let out = official.join("target/generated-class");
    let output = grade_submission(&official, &class, &out, &["--jobs", "2"]);
    assert!(output.status.success(), "{output:?}");
    // The tiny course's one task file holds both tasks and it has no
    // planted mistakes: the faulty member hands in that file unsolved, the
    // partial one solves its one topic. The two slots build into one cache
    // by turns: without the touch of `stage::claim_build`, a member whose
    // file equals its slot's last occupant's is graded with the other
    // slot's build (the faulty or the tampered one scores 3, or the
    // partial one 0).
    assert_eq!(
        fs::read_to_string(out.join("gradebook.csv")).unwrap(),
        "submission,score,max_score,bonus,complete,flagged,01-tiny,01-tiny/double,01-tiny/negate,not_graded\n\
         s01-correct,3,3,0,true,false,3,2,1,\n\
         s02-faulty,0,3,0,true,false,0,0,0,\n\
         s03-partial,3,3,0,true,false,3,2,1,\n\
         s04-tampered,0,3,0,true,true,0,0,0,\n\
         s05-broken,0,3,0,false,false,0,0,0,01-tiny: does not compile\n"
    );
    let tampered = read_json(&out.join("s04-tampered/report.json"));
    assert_eq!(
        tampered["integrity"]["changed"],
        serde_json::json!(["exercises/01-tiny/tests/double.rs"])
    );
    let broken = read_json(&out.join("s05-broken/report.json"));
    assert!(
        topic(&broken, "01-tiny")["compile_error"]
            .as_str()
            .unwrap()
            .contains("exercises/01-tiny/src/ops.rs"),
        "{broken:#}"
    );
    // The slots' executables are gone once their tests ran.
    for slot in ["0", "1"] {
        assert!(
            !official
                .join("target/xtask/class")
                .join(slot)
                .join("bin")
                .exists(),
            "slot {slot} keeps its executables"
        );
    }
}

/// A checkout whose every text file ends its lines in `\r\n` (Windows'
/// git with `core.autocrlf`, where the course's `.gitattributes` was not
/// honoured) grades exactly like the same checkout with `\n`: the same
/// score, no grading file flagged.
#[test]
fn a_crlf_checkout_grades_like_an_lf_one() {
    let official = fixture("tiny", "crlf");
    let class = Path::new(env!("CARGO_TARGET_TMPDIR")).join("crlf-class");
    if class.exists() {
        fs::remove_dir_all(&class).unwrap();
    }
    let solved = fs::read_to_string(official.join("exercises/01-tiny/src/ops.rs"))
        .unwrap()
        .replace("todo!(\"double: return twice x\")", "x * 2");
    for name in ["crlf", "lf"] {
        let member = class.join(name);
        for dir in ["exercises", "crates"] {
            copy_dir(&official.join(dir), &member.join(dir));
        }
        fs::copy(official.join("Cargo.toml"), member.join("Cargo.toml")).unwrap();
        fs::write(member.join("exercises/01-tiny/src/ops.rs"), &solved).unwrap();
    }
    let mut stack = vec![class.join("crlf")];
    let mut converted = 0;
    while let Some(dir) = stack.pop() {
        for entry in fs::read_dir(&dir).unwrap().flatten() {
            let path = entry.path();
            if entry.file_type().unwrap().is_dir() {
                stack.push(path);
            } else if let Ok(text) = fs::read_to_string(&path) {
                fs::write(&path, text.replace('\n', "\r\n")).unwrap();
                converted += 1;
            }
        }
    }
    assert!(converted >= 6, "only {converted} files converted");
    let out = official.join("target/crlf-class");
    let output = grade_submission(&official, &class, &out, &[]);
    assert!(output.status.success(), "{output:?}");
    assert_eq!(
        fs::read_to_string(out.join("gradebook.csv")).unwrap(),
        "submission,score,max_score,bonus,complete,flagged,01-tiny,01-tiny/double,01-tiny/negate,not_graded\n\
         crlf,2,3,0,true,false,2,2,0,\n\
         lf,2,3,0,true,false,2,2,0,\n"
    );
}
