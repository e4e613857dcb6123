//! The tutor's and the student's workflows end to end on `fixtures/tiny`
//! (see `fixture_courses.rs`): `watch`, the classroom workflow, the
//! Gradescope autograder and hints.
mod common;

use std::fs;
use std::path::Path;
use std::process::Command;
use std::time::Duration;

use common::{copy_dir, fixture, grade, grade_submission, read_json, stdout, task, xtask};
use serde_json::Value;

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
    assert!(none.contains("has no hints in its tasks.toml"), "{none}");
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
