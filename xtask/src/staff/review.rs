//! `cargo xtask review [--submission NAME] [--list]`: the snapshots the
//! last grade found different, reviewed with `cargo-insta` (installed
//! when missing), without the tutor needing to know where anything lies.
//!
//! The grade records, on each failed test, the official snapshots it
//! compared with and found different, and the body it captured (see
//! `grade::reviewed`: the record in `report.json`, never a test's reason,
//! never a pending snapshot equal to the official one). The review lays
//! each recorded body, as insta's `.snap.new`, beside a copy of the
//! official `.snap` in a review folder of its own (`<report>/review/`) and
//! runs `cargo insta review` there: stepping through the diffs, the tutor
//! accepts (the student's snapshot is right), rejects (it is wrong) or
//! skips each, and the verdicts are written to `<report>/review.json`. A
//! test whose recorded mismatches the tutor all accepted gets its points
//! back, marked as reviewed, in the member's reports and in the class's
//! gradebook; a rejection or a skip changes nothing. Accepting changes
//! only that copy: the course's official snapshots are never touched from
//! a submission. Without a terminal (or with `--list`) the snapshots and
//! their diffs are printed instead.

use std::fs;
use std::io::IsTerminal as _;
use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{Context, Result, bail, ensure};
use serde::Serialize;

use crate::grade::report::Report;
use crate::grade::{self, reviewed};
use crate::stage;

/// The verdict of a snapshot the tutor found right.
const ACCEPTED: &str = "accepted";

/// The manifest of the review folder: a package of no code, so that
/// cargo-insta finds the snapshots in it.
const REVIEW_MANIFEST: &str = "# Written by `cargo xtask review`: a copy of the snapshots under review.\n[package]\nname = \"snapshot-review\"\nversion = \"0.0.0\"\nedition = \"2021\"\npublish = false\n\n[lib]\npath = \"lib.rs\"\n\n[workspace]\n";

/// The official snapshot a pending one would replace: `x.snap.new` → `x.snap`.
fn official_of(pending: &Path) -> PathBuf {
    pending.with_extension("")
}

/// The mismatches the grade in `report` recorded, one per official
/// snapshot: (the pending snapshot's path in the course, `x.snap.new`;
/// the body captured), sorted.
fn recorded(report: &Report) -> Vec<(PathBuf, String)> {
    let mut found: Vec<(PathBuf, String)> = Vec::new();
    for test in report
        .topics
        .iter()
        .flat_map(|topic| &topic.tasks)
        .flat_map(|task| &task.tests)
    {
        for mismatch in &test.snapshot_mismatches {
            let pending = PathBuf::from(format!("{}.new", mismatch.snapshot));
            if !found.iter().any(|(p, _)| *p == pending) {
                found.push((pending, mismatch.captured.clone()));
            }
        }
    }
    found.sort();
    found
}

/// Reads the report in `graded`.
fn read_report(graded: &Path) -> Result<Report> {
    let path = graded.join("report.json");
    let text =
        fs::read_to_string(&path).with_context(|| format!("cannot read {}", path.display()))?;
    serde_json::from_str(&text).with_context(|| format!("cannot read {}", path.display()))
}

/// One snapshot's verdict.
#[derive(Debug, Serialize, PartialEq, Eq)]
struct Verdict {
    /// The official snapshot's path in the course.
    snapshot: String,
    /// `accepted` (the student's is right), `rejected` or `not reviewed`.
    verdict: &'static str,
}

/// The snapshots of one grade under review, laid out for cargo-insta.
pub struct Review {
    /// The grade's report folder.
    graded: PathBuf,
    /// The review folder inside it.
    dir: PathBuf,
    /// The pending snapshots (`x.snap.new`, at the official snapshot's
    /// path in the course), as the grade recorded them.
    pub pending: Vec<PathBuf>,
    /// The body the grade captured for each of [`Self::pending`].
    captured: Vec<String>,
    /// The cargo-insta program.
    insta: PathBuf,
}

impl Review {
    /// Lays the snapshots the grade in `graded` recorded as different
    /// (its `report.json`, see `grade::reviewed`) beside a copy of the
    /// course's (at `root`) in `graded/review/`, and finds cargo-insta
    /// (installing it when missing). `None` when no test failed on a
    /// snapshot. Nothing a test wrote is read: the bodies are the grade's
    /// record.
    pub fn prepare(root: &Path, graded: &Path) -> Result<Option<Self>> {
        ensure!(
            graded.join("report.json").is_file(),
            "no grade in {} to review: run `cargo xtask grade` first",
            graded.display()
        );
        let report = read_report(graded)?;
        let dir = graded.join("review");
        if dir.exists() {
            fs::remove_dir_all(&dir).with_context(|| format!("cannot clear {}", dir.display()))?;
        }
        let (mut pending, mut captured) = (Vec::new(), Vec::new());
        for (file, body) in recorded(&report) {
            let official_path = root.join(official_of(&file));
            let Ok(official) = fs::read_to_string(&official_path) else {
                continue; // not a snapshot of this course
            };
            // insta's header (the official one's, naming the test's
            // source) above the body the grade captured.
            let header = &official[..official.len() - reviewed::snapshot_body(&official).len()];
            let to = dir.join(&file);
            crate::files::write_file(&to, format!("{header}{body}"))?;
            crate::files::write_file(&dir.join(official_of(&file)), &official)?;
            pending.push(file);
            captured.push(body);
        }
        if pending.is_empty() {
            return Ok(None);
        }
        // cargo-insta works in a cargo package: an empty one around them.
        fs::write(dir.join("Cargo.toml"), REVIEW_MANIFEST)
            .with_context(|| format!("cannot write in {}", dir.display()))?;
        fs::write(dir.join("lib.rs"), "")
            .with_context(|| format!("cannot write in {}", dir.display()))?;
        let insta = crate::staff::setup::cargo_insta(&stage::home(root).join("tools"))?;
        Ok(Some(Self {
            graded: graded.to_path_buf(),
            dir,
            pending,
            captured,
            insta,
        }))
    }

    fn cargo_insta(&self, args: &[&str]) -> Command {
        let mut command = Command::new(&self.insta);
        command.args(args).current_dir(&self.dir);
        command
    }

    /// Each snapshot's diff as cargo-insta shows it (without a terminal,
    /// `review --snapshot` shows it and decides nothing).
    pub fn diffs(&self) -> Result<Vec<(PathBuf, String)>> {
        self.pending
            .iter()
            .map(|file| {
                let official = official_of(file);
                let output = self
                    .cargo_insta(&["review", "--snapshot", &official.to_string_lossy()])
                    .stdin(std::process::Stdio::null())
                    .output()
                    .with_context(|| format!("cannot run {}", self.insta.display()))?;
                let text = String::from_utf8_lossy(&output.stdout).into_owned();
                ensure!(
                    text.contains("Snapshot file:"),
                    "`cargo insta review --snapshot` shows no diff for {}: {}",
                    official.display(),
                    String::from_utf8_lossy(&output.stderr).trim()
                );
                Ok((official, plain_diff(&text)))
            })
            .collect()
    }

    /// Steps through the snapshots in cargo-insta's review, then writes
    /// the verdicts to `review.json` beside the report.
    fn step_through(&self) -> Result<()> {
        println!(
            "a: the student's snapshot is right · r: it is wrong · s: skip (the course's snapshots stay as they are)"
        );
        let status = self
            .cargo_insta(&["review"])
            .status()
            .with_context(|| format!("cannot run {}", self.insta.display()))?;
        if !status.success() {
            bail!("`cargo insta review` stopped ({status})");
        }
        let verdicts = verdicts(&self.dir, &self.pending, &self.captured)?;
        let path = self.graded.join("review.json");
        fs::write(
            &path,
            serde_json::to_string_pretty(&verdicts).context("cannot serialise the verdicts")?,
        )
        .with_context(|| format!("cannot write {}", path.display()))?;
        for v in &verdicts {
            println!("  {:<12} {}", v.verdict, v.snapshot);
        }
        println!("verdicts: {}", path.display());
        println!("{}", apply_verdicts(&self.graded, &verdicts)?);
        Ok(())
    }
}

/// Gives the tests whose snapshots were accepted their points back in the
/// grade in `graded` (see `grade::reviewed`): its reports written again,
/// and its row in its class's gradebook. What changed, in a line.
fn apply_verdicts(graded: &Path, verdicts: &[Verdict]) -> Result<String> {
    let mut report = read_report(graded)?;
    let accepted: Vec<String> = verdicts
        .iter()
        .filter(|v| v.verdict == ACCEPTED)
        .map(|v| v.snapshot.clone())
        .collect();
    let before = report.score;
    let passing = grade::reviewed::apply(&mut report, &accepted);
    grade::export::write_all(&report, graded)?;
    let class = crate::staff::class::update_class_row(graded, &report)?;
    Ok(format!(
        "{passing} test(s) pass by review: {} → {} of {} points in {}{}",
        grade::report::points(before),
        grade::report::points(report.score),
        grade::report::points(report.max_score),
        graded.join("report.html").display(),
        if class {
            ", and in the class's gradebook"
        } else {
            ""
        }
    ))
}

/// `cargo xtask review`.
pub fn run(root: &Path, out: Option<&Path>, submission: Option<&str>, list: bool) -> Result<()> {
    let grade = out.map_or_else(|| root.join("target").join("grade"), Path::to_path_buf);
    let graded = match submission {
        Some(name) => grade.join(name),
        None => grade,
    };
    let Some(review) = Review::prepare(root, &graded)? else {
        println!(
            "every snapshot of the grade in {} matches: nothing to review",
            graded.display()
        );
        return Ok(());
    };
    println!(
        "{} snapshot(s) of {} differ from the course's:",
        review.pending.len(),
        graded.display()
    );
    for file in &review.pending {
        println!("  {}", official_of(file).display());
    }
    if !list && std::io::stdin().is_terminal() && std::io::stdout().is_terminal() {
        return review.step_through();
    }
    for (official, diff) in review.diffs()? {
        println!("\n==> {}", official.display());
        print!("{diff}");
    }
    println!(
        "\nin a terminal, `cargo xtask review{}{}` steps through them: a accepts (the student's is right, its tests get their points back), r rejects, s skips",
        submission.map_or(String::new(), |n| format!(" --submission {n}")),
        out.map_or(String::new(), |o| format!(" --out {}", o.display()))
    );
    Ok(())
}

/// cargo-insta's page for one snapshot, as a diff to read in a log: no
/// terminal control sequences (its closing screen clears the terminal),
/// none of its own hints (which name its commands and the review folder,
/// not this one's), only the snapshot, its expression and the diff.
fn plain_diff(page: &str) -> String {
    let page = page.split("\x1b[2J").next().unwrap_or(page);
    let mut plain = String::with_capacity(page.len());
    let mut chars = page.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\x1b' => {
                // A CSI sequence: ESC [ parameters final-letter.
                if chars.peek() == Some(&'[') {
                    chars.next();
                    for c in chars.by_ref() {
                        if c.is_ascii_alphabetic() {
                            break;
                        }
                    }
                }
            }
            '\r' => {}
            c => plain.push(c),
        }
    }
    let hint = |line: &str| {
        let line = line.trim_start();
        [
            "insta not found",
            "Package:",
            "Source:",
            "To accept:",
            "To reject:",
            "To skip:",
        ]
        .iter()
        .any(|prefix| line.starts_with(prefix))
    };
    let lines: Vec<&str> = plain.lines().filter(|line| !hint(line)).collect();
    let mut text = lines.join("\n");
    text.truncate(text.trim_end().len());
    text.push('\n');
    text
}

/// What the review did with each snapshot, read off the review folder:
/// accepted when the body the grade captured took the official one's
/// place, rejected when it was thrown away, not reviewed while it waits.
/// `pending` and `captured` are the grade's record ([`Review::prepare`]).
fn verdicts(review: &Path, pending: &[PathBuf], captured: &[String]) -> Result<Vec<Verdict>> {
    pending
        .iter()
        .zip(captured)
        .map(|(file, body)| {
            let official = official_of(file);
            let now = fs::read_to_string(review.join(&official)).unwrap_or_default();
            let verdict = if review.join(file).exists() {
                "not reviewed"
            } else if reviewed::same_body(reviewed::snapshot_body(&now), body) {
                ACCEPTED
            } else {
                "rejected"
            };
            Ok(Verdict {
                snapshot: official
                    .components()
                    .map(|c| c.as_os_str().to_string_lossy().into_owned())
                    .collect::<Vec<_>>()
                    .join("/"),
                verdict,
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_listed_diff_holds_no_control_sequences_and_no_hints_of_insta() {
        let page = "insta not found in cargo metadata; defaulting to 1.0.0\nSnapshot: tests/a.rs (x.snap):\n  Package: snapshot-review@0.0.0\n\nSnapshot file: tests/snapshots/a__x.snap\nSnapshot: x.snap\nSource: /tmp/rv\n────\nExpression: x\n────\n-old snapshot\n+new results\n────┬────\n    1     1 │ ##..\n    2       │-.##.\n          2 │+..##\n────┴────\n\nTo accept: cargo insta accept --snapshot 'tests/snapshots/a__x.snap'\nTo reject: cargo insta reject --snapshot 'tests/snapshots/a__x.snap'\n\n\r\x1b[2J\r\x1b[Hinsta review finished\nskipped:\n  tests/a.rs (x.snap)\n";
        let plain = plain_diff(page);
        for gone in [
            "insta not found",
            "Package:",
            "/tmp/rv",
            "To accept",
            "finished",
            "\x1b",
            "\r",
        ] {
            assert!(!plain.contains(gone), "{gone:?} in {plain}");
        }
        assert!(
            plain.contains("Snapshot file: tests/snapshots/a__x.snap\n"),
            "{plain}"
        );
        assert!(
            plain.contains("    2       │-.##.\n          2 │+..##\n"),
            "{plain}"
        );
        assert!(plain.ends_with("────┴────\n"), "{plain}");
        assert_eq!(plain_diff("a\x1b[31mred\x1b[0m\n"), "ared\n");
    }

    #[test]
    fn verdicts_are_read_off_the_review_folder() {
        let dir = std::env::temp_dir().join(format!("xtask-review-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        let review = dir.join("review");
        let snap = |name: &str| PathBuf::from(format!("t/snapshots/{name}.snap.new"));
        let write = |path: PathBuf, body: &str| {
            fs::create_dir_all(path.parent().unwrap()).unwrap();
            fs::write(path, format!("---\nsource: t.rs\n---\n{body}")).unwrap();
        };
        // a accepted (the .snap now holds the captured body), b rejected
        // (the official body stays), c not reviewed yet.
        write(review.join(official_of(&snap("a"))), "yours\n");
        write(review.join(official_of(&snap("b"))), "official\n");
        write(review.join(official_of(&snap("c"))), "official\n");
        write(review.join(snap("c")), "yours\n");
        let captured = vec!["yours\n".to_owned(); 3];
        let got = verdicts(&review, &[snap("a"), snap("b"), snap("c")], &captured).unwrap();
        let words: Vec<&str> = got.iter().map(|v| v.verdict).collect();
        assert_eq!(words, ["accepted", "rejected", "not reviewed"]);
        assert_eq!(got[0].snapshot, "t/snapshots/a.snap");
        let _ = fs::remove_dir_all(&dir);
    }
}

/// The review's attack, planted: a test that writes the official body as
/// its pending snapshot and panics with insta's words, then a tutor who
/// rejects what is shown. Before the review acted on the grader's record,
/// the equal bodies read as "accepted" and the reason's words named the
/// snapshot: 0 points became full marks.
#[cfg(test)]
mod planted {
    use super::*;
    use crate::grade::report::TestStatus;
    use crate::grade::report::tests::{report_of, test};
    use crate::topics::{TaskSheet, Topic};

    #[test]
    fn a_pending_snapshot_equal_to_the_official_one_and_a_reject_score_nothing() {
        let dir = std::env::temp_dir().join(format!("xtask-review-plant-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        let (course, graded) = (dir.join("course"), dir.join("graded"));
        let snapshot = "exercises/01-x/tests/snapshots/t__octants.snap";
        let official = "---\nsource: tests/t.rs\nexpression: sheet\n---\n#..\n.#.\n";
        crate::files::write_file(
            &course.join("exercises/01-x/tests/t.rs"),
            "#[test]\nfn octants() { testkit::insta::assert_snapshot!(\"octants\", sheet); }\n",
        )
        .unwrap();
        crate::files::write_file(&course.join(snapshot), official).unwrap();
        // What the student's test left: the official body as its pending
        // snapshot, and insta's words as its reason.
        crate::files::write_file(
            &graded
                .join(grade::PENDING_SNAPSHOTS)
                .join(format!("{snapshot}.new")),
            official,
        )
        .unwrap();
        let mut failed = test("octants", TestStatus::Failed);
        failed.reason = Some(format!(
            "snapshot 'octants' does not match {snapshot} (yours is the .snap.new at the same path under the report's snapshots/)"
        ));
        let mut report = report_of(4.0, vec![failed]);
        let topic = Topic {
            name: "01-x".to_owned(),
            package: "x".to_owned(),
            dir: course.join("exercises/01-x"),
            sheet: TaskSheet::parse("[[tasks]]\nid = \"t\"\ntitle = \"T\"\npoints = 4\n").unwrap(),
        };
        grade::reviewed::record_mismatches(&graded, &topic, &mut report.topics[0].tasks);
        assert!(
            report.topics[0].tasks[0].tests[0]
                .snapshot_mismatches
                .is_empty(),
            "an equal body was recorded as a mismatch"
        );
        fs::write(
            graded.join("report.json"),
            serde_json::to_string(&report).unwrap(),
        )
        .unwrap();
        // Nothing to review: cargo-insta is not even needed.
        assert!(Review::prepare(&course, &graded).unwrap().is_none());
        // And whatever verdicts a review file names, the test stays failed.
        assert_eq!(
            grade::reviewed::apply(&mut report, &[snapshot.to_owned()]),
            0
        );
        assert_eq!(report.score, 0.0, "a reject gave points");
        let _ = fs::remove_dir_all(&dir);
    }
}
