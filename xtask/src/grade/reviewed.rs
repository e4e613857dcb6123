//! What a tutor's review of the snapshots changes in a grade, and what it
//! may act on.
//!
//! **What the grader records.** After a topic's tests ran, the grader
//! records on each failed test the official snapshots it compares with
//! (read off the official test's source: the names its `assert_*snapshot!`
//! calls give, see [`compared_snapshots`]) whose pending snapshot differs
//! from the official one: [`TestReport::snapshot_mismatches`], the
//! official path and the body the grader captured. That record, in
//! `report.json`, is the only thing a review acts on: never a test's
//! reason (the test process prints what it likes: "snapshot … does not
//! match" is a panic message anyone can write), never a pending snapshot
//! that equals the official one (that test did not fail on that snapshot,
//! whatever it printed).
//!
//! **What a verdict changes.** A test passes by review when it failed,
//! ran to its end (no limit stopped it), has recorded mismatches, and the
//! tutor accepted every one of those snapshots; its task gets its share of
//! the points back, marked as reviewed in every report. Accepting a
//! snapshot changes exactly the tests that compared with it and failed on
//! it; a rejection or a skip changes nothing, so no verdict adds points
//! that accepting would not. The verdicts are applied to the grade as it
//! came from the tests: a review done again first takes back what an
//! earlier one gave. A submission whose tests changed the course's files
//! scores 0 whatever the review says.
//!
//! **Its limit.** Until the verdict is replayed outside the student's
//! process, the body captured is the test process's pending snapshot,
//! copied by the grader after the run: evidence the tutor judges, of a
//! process that could have written anything there. What the tutor accepts
//! is that body, as shown.

use std::fs;
use std::path::{Path, PathBuf};

use super::PENDING_SNAPSHOTS;
#[cfg(feature = "staff")]
use super::report::{Report, TestReport};
use super::report::{SnapshotMismatch, TaskReport, TestStatus};
use super::submission::nofollow;
use crate::topics::Topic;

/// The most a pending snapshot may hold to be recorded (the course's are
/// a few KiB; a test could write a flood).
const MAX_SNAPSHOT: u64 = 1 << 20;

/// A snapshot file's body: what follows insta's metadata header (the part
/// insta rewrites on accepting).
#[must_use]
pub fn snapshot_body(text: &str) -> &str {
    match text.strip_prefix("---\n") {
        Some(rest) => rest.split_once("\n---\n").map_or(rest, |(_, body)| body),
        None => text,
    }
}

/// Whether two snapshot bodies hold the same result, as insta compares
/// them: line endings, trailing spaces and the blank lines at either end
/// do not count. Equal bodies are no mismatch, whatever a test printed.
#[must_use]
pub fn same_body(a: &str, b: &str) -> bool {
    let lines = |text: &str| -> Vec<String> {
        text.trim_matches(|c: char| c == '\n' || c == '\r')
            .lines()
            .map(|line| line.trim_end().to_owned())
            .collect()
    };
    lines(a) == lines(b)
}

/// The snapshot files (names in the test crate's `tests/snapshots/`)
/// that test `test` (libtest's name: `module::function`) of the test file
/// `binary` (`tests/<binary>.rs`, whose official text is `source`)
/// compares with: for each `…snapshot!("name", …)` in its function's body
/// `<binary>__<modules>__name.snap`, for an unnamed one the function's
/// name (without a `test_` prefix), numbered `-2`, `-3` … after the first,
/// as insta names them.
#[must_use]
pub fn compared_snapshots(source: &str, binary: &str, test: &str) -> Vec<String> {
    let mut parts: Vec<&str> = test.split("::").collect();
    let Some(function) = parts.pop() else {
        return Vec::new();
    };
    let prefix: String = std::iter::once(binary)
        .chain(parts.iter().copied())
        .collect::<Vec<_>>()
        .join("__");
    let masked = crate::stubs::quiet::mask(source);
    let is_ident = |c: char| c.is_alphanumeric() || c == '_';
    let declared = format!("fn {function}(");
    let Some(at) = masked
        .match_indices(&declared)
        .map(|(at, _)| at)
        .find(|&at| !masked[..at].ends_with(is_ident))
    else {
        return Vec::new();
    };
    let Some(open) = masked[at..].find('{').map(|n| at + n) else {
        return Vec::new();
    };
    // The body ends where its braces balance (the mask leaves none in
    // comments or strings).
    let mut depth = 0usize;
    let close = masked[open..]
        .char_indices()
        .find(|&(_, c)| {
            match c {
                '{' => depth += 1,
                '}' => depth -= 1,
                _ => {}
            }
            depth == 0
        })
        .map_or(masked.len(), |(i, _)| open + i);
    let body = &masked[open..close];
    let unnamed = function.strip_prefix("test_").unwrap_or(function);
    let mut unnamed_count = 0;
    let mut names = Vec::new();
    for (offset, call) in body.match_indices("snapshot!(") {
        let after = open + offset + call.len();
        let first = after + (masked[after..].len() - masked[after..].trim_start().len());
        let name = if masked[first..].starts_with('"') {
            // The mask blanks a string's contents and keeps its quotes.
            let Some(end) = masked[first + 1..].find('"').map(|n| first + 1 + n) else {
                continue;
            };
            source[first + 1..end].to_owned()
        } else {
            unnamed_count += 1;
            if unnamed_count == 1 {
                unnamed.to_owned()
            } else {
                format!("{unnamed}-{unnamed_count}")
            }
        };
        names.push(format!("{prefix}__{name}.snap"));
    }
    names
}

/// Records on each failed test of `tasks` (of `topic`, graded into `out`)
/// the official snapshots it compares with whose pending snapshot, as the
/// grader finds it in `out` after the run, differs from the official one
/// (see the module's doc). A test stopped by a limit or not run records
/// none: it did not fail only on a snapshot.
pub fn record_mismatches(out: &Path, topic: &Topic, tasks: &mut [TaskReport]) {
    let pending_dir = out.join(PENDING_SNAPSHOTS);
    for task in tasks {
        let test_file = topic.dir.join("tests").join(format!("{}.rs", task.id));
        let Ok(source) = fs::read_to_string(&test_file) else {
            continue;
        };
        for test in &mut task.tests {
            if test.status != TestStatus::Failed || test.exit.stopped() || test.exit.not_run {
                continue;
            }
            test.snapshot_mismatches = compared_snapshots(&source, &task.id, &test.name)
                .into_iter()
                .filter_map(|file| {
                    let relative: PathBuf = ["exercises", &topic.name, "tests", "snapshots", &file]
                        .iter()
                        .collect();
                    let official =
                        fs::read_to_string(topic.dir.join("tests").join("snapshots").join(&file))
                            .ok()?;
                    let pending = nofollow::read(
                        &pending_dir,
                        &relative.with_extension("snap.new"),
                        MAX_SNAPSHOT,
                    )
                    .ok()?;
                    let pending = String::from_utf8_lossy(&pending);
                    let captured = snapshot_body(&pending);
                    (!same_body(captured, snapshot_body(&official))).then(|| SnapshotMismatch {
                        snapshot: slashed(&relative),
                        captured: captured.to_owned(),
                    })
                })
                .collect();
        }
    }
}

/// A relative path with `/` separators, as `report.json` and
/// `review.json` name snapshots.
fn slashed(path: &Path) -> String {
    path.components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect::<Vec<_>>()
        .join("/")
}

/// Whether `test` passes by the review that accepted `accepted` (official
/// snapshots' paths): it failed, ran to its end, and the grader recorded
/// mismatches, every one of them accepted.
#[cfg(feature = "staff")]
fn passes_by_review(test: &TestReport, accepted: &[String]) -> bool {
    test.status == TestStatus::Failed
        && !test.exit.stopped()
        && !test.exit.not_run
        && !test.snapshot_mismatches.is_empty()
        && test
            .snapshot_mismatches
            .iter()
            .all(|m| accepted.contains(&m.snapshot))
}

/// Applies the review's verdicts to `report`: `accepted` are the official
/// snapshots' paths (as `review.json` names them) the tutor found the
/// student's right. Returns how many tests pass by review.
#[cfg(feature = "staff")]
pub fn apply(report: &mut Report, accepted: &[String]) -> usize {
    let tampered = report
        .integrity
        .as_ref()
        .is_some_and(|i| !i.tampered.is_empty());
    let mut passing = 0;
    for topic in &mut report.topics {
        for task in &mut topic.tasks {
            for test in &mut task.tests {
                if test.reviewed.take().is_some() {
                    test.status = TestStatus::Failed;
                }
                if !tampered && passes_by_review(test, accepted) {
                    test.status = TestStatus::Passed;
                    test.reviewed = Some(
                        test.snapshot_mismatches
                            .iter()
                            .map(|m| m.snapshot.as_str())
                            .collect::<Vec<_>>()
                            .join(", "),
                    );
                    passing += 1;
                }
            }
            // A tampered submission keeps its zero: its counts say what
            // the review saw.
            let (status, score) = (task.status, task.score);
            super::score::recount(task);
            if tampered {
                (task.status, task.score) = (status, score);
            }
        }
    }
    super::score::totals(report);
    passing
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(feature = "staff")]
    use crate::grade::report::tests::{report_of, test};

    #[cfg(feature = "staff")]
    const SNAP: &str = "exercises/01-lines/tests/snapshots/midpoint__octants.snap";

    #[cfg(feature = "staff")]
    /// The reason the grader's outcome gives a snapshot's mismatch, which
    /// any test process can print.
    fn insta_words() -> String {
        format!(
            "snapshot 'octants' does not match {SNAP} (yours is the .snap.new at the same path under the report's snapshots/)"
        )
    }

    #[cfg(feature = "staff")]
    fn mismatch(name: &str) -> crate::grade::report::TestReport {
        let mut failed = test(name, TestStatus::Failed);
        failed.reason = Some(insta_words());
        failed.snapshot_mismatches = vec![SnapshotMismatch {
            snapshot: SNAP.to_owned(),
            captured: "#.\n.#\n".to_owned(),
        }];
        failed
    }

    #[cfg(feature = "staff")]
    #[test]
    fn a_reason_in_insta_words_without_a_recorded_mismatch_gets_nothing() {
        let mut words = test("octants", TestStatus::Failed);
        words.reason = Some(insta_words());
        let mut report = report_of(4.0, vec![words, test("a", TestStatus::Failed)]);
        assert_eq!(apply(&mut report, &[SNAP.to_owned()]), 0);
        assert_eq!(report.score, 0.0);
    }

    #[cfg(feature = "staff")]
    #[test]
    fn a_test_stopped_by_a_limit_gets_nothing_back() {
        let mut stopped = mismatch("octants");
        stopped.exit.timed_out = true;
        let mut report = report_of(4.0, vec![stopped]);
        assert_eq!(apply(&mut report, &[SNAP.to_owned()]), 0);
        assert_eq!(report.score, 0.0);
    }

    #[test]
    fn the_snapshots_a_test_compares_with_are_read_off_its_source() {
        let source = "\
#[test]
fn lines_in_all_octants() {
    // assert_snapshot!(\"in_a_comment\", x)
    testkit::insta::assert_snapshot!(\"octants\", sheet);
    testkit::assert_raster_snapshot!( \"second\", canvas);
}
#[test]
fn test_unnamed() { insta::assert_snapshot!(grid); insta::assert_snapshot!(grid); }
mod nested {
    #[test]
    fn inner() { testkit::assert_raster_snapshot!(\"deep\", canvas); }
}
#[test]
fn plain() { assert_eq!(1, 1); }
";
        assert_eq!(
            compared_snapshots(source, "dda", "lines_in_all_octants"),
            ["dda__octants.snap", "dda__second.snap"]
        );
        assert_eq!(
            compared_snapshots(source, "dda", "test_unnamed"),
            ["dda__unnamed.snap", "dda__unnamed-2.snap"]
        );
        assert_eq!(
            compared_snapshots(source, "dda", "nested::inner"),
            ["dda__nested__deep.snap"]
        );
        assert!(compared_snapshots(source, "dda", "plain").is_empty());
        assert!(compared_snapshots(source, "dda", "absent").is_empty());
    }

    #[cfg(feature = "staff")]
    #[test]
    fn only_pending_snapshots_that_differ_are_recorded_and_links_never() {
        let dir = std::env::temp_dir().join(format!("xtask-reviewed-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        let (course, out) = (dir.join("course"), dir.join("out"));
        let topic_dir = course.join("exercises/01-x");
        let write = |path: PathBuf, text: &str| {
            fs::create_dir_all(path.parent().unwrap()).unwrap();
            fs::write(path, text).unwrap();
        };
        write(
            topic_dir.join("tests/t.rs"),
            "#[test]\nfn same() { insta::assert_snapshot!(\"same\", x); }\n#[test]\nfn differs() { insta::assert_snapshot!(\"differs\", x); }\n#[test]\nfn linked() { insta::assert_snapshot!(\"linked\", x); }\n",
        );
        for name in ["same", "differs", "linked"] {
            write(
                topic_dir.join(format!("tests/snapshots/t__{name}.snap")),
                "---\nsource: tests/t.rs\n---\n#.\n",
            );
        }
        let pending = out
            .join(PENDING_SNAPSHOTS)
            .join("exercises/01-x/tests/snapshots");
        // The official body again (the planted attack), a real difference,
        // and a link to a file the grader must not read.
        write(
            pending.join("t__same.snap.new"),
            "---\nsource: forged\n---\n#.\n",
        );
        write(
            pending.join("t__differs.snap.new"),
            "---\nsource: tests/t.rs\n---\n.#\n",
        );
        write(dir.join("secret"), "---\n---\nthe solution\n");
        #[cfg(unix)]
        std::os::unix::fs::symlink(dir.join("secret"), pending.join("t__linked.snap.new")).unwrap();
        let topic = Topic {
            name: "01-x".to_owned(),
            package: "x".to_owned(),
            dir: topic_dir,
            sheet: crate::topics::TaskSheet::parse(
                "[[tasks]]\nid = \"t\"\ntitle = \"T\"\npoints = 3\n",
            )
            .unwrap(),
        };
        let tests = ["same", "differs", "linked"]
            .map(|name| test(name, TestStatus::Failed))
            .to_vec();
        let mut report = report_of(3.0, tests);
        let tasks = &mut report.topics[0].tasks;
        tasks[0].id = "t".to_owned();
        record_mismatches(&out, &topic, tasks);
        let recorded: Vec<&Vec<SnapshotMismatch>> = tasks[0]
            .tests
            .iter()
            .map(|t| &t.snapshot_mismatches)
            .collect();
        assert!(
            recorded[0].is_empty(),
            "equal bodies recorded: {recorded:?}"
        );
        assert_eq!(
            recorded[1],
            &vec![SnapshotMismatch {
                snapshot: "exercises/01-x/tests/snapshots/t__differs.snap".to_owned(),
                captured: ".#\n".to_owned(),
            }]
        );
        assert!(recorded[2].is_empty(), "a link was read: {recorded:?}");
        // Accepting every snapshot passes exactly the test that differed.
        let all: Vec<String> = ["same", "differs", "linked"]
            .map(|n| format!("exercises/01-x/tests/snapshots/t__{n}.snap"))
            .to_vec();
        assert_eq!(apply(&mut report, &all), 1);
        assert_eq!(
            report.topics[0].tasks[0].tests[1].status,
            TestStatus::Passed
        );
        assert_eq!(report.score, 1.0);
        let _ = fs::remove_dir_all(&dir);
    }

    #[test]
    fn every_snapshot_of_the_course_is_named_by_a_test_that_compares_with_it() {
        // Otherwise a failed comparison with it could never be recorded,
        // and a tutor could never accept it.
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
        for topic in crate::topics::discover(&root).unwrap() {
            let snapshots = topic.dir.join("tests").join("snapshots");
            for file in crate::files::files_under(&snapshots).unwrap() {
                let name = file.to_string_lossy().into_owned();
                let Some(stem) = name.strip_suffix(".snap") else {
                    continue;
                };
                let mut parts: Vec<&str> = stem.split("__").collect();
                parts.pop();
                let binary = parts.remove(0);
                let source =
                    fs::read_to_string(topic.dir.join("tests").join(format!("{binary}.rs")))
                        .unwrap();
                let named = source
                    .match_indices("fn ")
                    .filter_map(|(at, _)| {
                        let rest = &source[at + 3..];
                        let end = rest.find('(')?;
                        let function = &rest[..end];
                        let test = parts
                            .iter()
                            .copied()
                            .chain([function])
                            .collect::<Vec<_>>()
                            .join("::");
                        Some(compared_snapshots(&source, binary, &test))
                    })
                    .any(|compared| compared.contains(&name));
                assert!(named, "{}/tests/snapshots/{name}", topic.name);
            }
        }
    }

    #[test]
    fn bodies_compare_as_insta_compares_them() {
        assert_eq!(snapshot_body("---\nsource: a.rs\n---\n#.\n"), "#.\n");
        assert!(same_body("#.\r\n.#  \n\n", "\n#.\n.#"));
        assert!(!same_body("#.\n.#\n", "#.\n##\n"));
    }

    #[cfg(feature = "staff")]
    #[test]
    fn an_accepted_snapshot_gives_its_test_back_and_a_rejected_one_takes_it_again() {
        let tests = vec![
            test("a", TestStatus::Passed),
            mismatch("octants"),
            test("b", TestStatus::Failed),
            test("c", TestStatus::Passed),
        ];
        let mut report = report_of(4.0, tests);
        assert_eq!(report.score, 2.0);
        assert_eq!(apply(&mut report, &[SNAP.to_owned()]), 1);
        let task = &report.topics[0].tasks[0];
        assert_eq!((task.passed, task.failed, task.score), (3, 1, 3.0));
        assert_eq!(task.tests[1].reviewed.as_deref(), Some(SNAP));
        assert_eq!((report.topics[0].score, report.score), (3.0, 3.0));
        // Another snapshot accepted: this one is failed again.
        assert_eq!(apply(&mut report, &["other.snap".to_owned()]), 0);
        let task = &report.topics[0].tasks[0];
        assert_eq!((task.passed, task.failed, task.score), (2, 2, 2.0));
        assert_eq!(task.tests[1].status, TestStatus::Failed);
        assert_eq!(report.score, 2.0);
    }

    #[cfg(feature = "staff")]
    #[test]
    fn a_submission_that_tampered_gets_nothing_back() {
        let mut report = report_of(
            4.0,
            vec![mismatch("octants"), test("a", TestStatus::Failed)],
        );
        report.topics[0].tasks[0].score = 0.0;
        report.integrity = Some(crate::grade::submission::Integrity {
            tampered: vec!["exercises/01-lines/tests/dda.rs".into()],
            ..Default::default()
        });
        assert_eq!(apply(&mut report, &[SNAP.to_owned()]), 0);
        assert_eq!(report.topics[0].tasks[0].score, 0.0);
    }
}
