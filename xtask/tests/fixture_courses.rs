//! `cargo xtask` run end to end on fixture courses, each its own cargo
//! workspace whose one dependency is the course's `#[testkit::test]`,
//! copied to a scratch folder first. Here `fixtures/hostile`: student code
//! that panics, loops, overflows its stack, exits, aborts, allocates
//! 3 GiB, prints without end and fails a property; a topic that does not
//! compile; a topic whose tests do not match its task sheet. The grader
//! must report each as that task's failure with the right reason, within
//! the time limit. `fixture_stubs.rs`, `fixture_submissions.rs` and
//! `fixture_workflows.rs` run the other commands on the fixtures.
mod common;

use std::fs;
use std::process::Command;
use std::time::Duration;

use common::{fixture, grade, read_json, reason, stdout, task, topic, xtask};
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
        (
            "loops",
            "timed out after 3 s (a loop without end, or far more steps than the test needs)",
        ),
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
        junit.contains("<failure message=\"timed out after 3 s (a loop without end, or far more steps than the test needs)\""),
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
    // The sleep this grade's `spawns` leaves behind is told apart by its
    // argument: the test above grades the same course at the same time,
    // and its sleep is alive while its own `spawns` test runs.
    let marker = format!("sleep 299.{}", std::process::id());
    let tricks = root.join("exercises/04-tricks/src/tricks.rs");
    let code = fs::read_to_string(&tricks).unwrap();
    assert!(code.contains(".arg(\"299.123\")"), "{code}");
    fs::write(
        &tricks,
        code.replace(
            ".arg(\"299.123\")",
            &format!(".arg(\"{}\")", &marker["sleep ".len()..]),
        ),
    )
    .unwrap();
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
    let left = processes_with(&marker);
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
            "timed out after 3 s (a loop without end, or far more steps than the test needs)",
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
