//! `cargo xtask review [--submission NAME] [--list]`: the snapshots the
//! last grade found different, reviewed with `cargo-insta` (installed
//! when missing), without the tutor needing to know where anything lies.
//!
//! The grade leaves each failed snapshot as insta's `.snap.new` under its
//! report folder, at the official snapshot's path. The review lays each
//! beside a copy of the official `.snap` in a review folder of its own
//! (`<report>/review/`) and runs `cargo insta review` there: stepping
//! through the diffs, the tutor accepts (the student's snapshot is right),
//! rejects (it is wrong) or skips each, and the verdicts are written to
//! `<report>/review.json`. A test that failed only on a snapshot the tutor
//! accepted gets its points back, marked as reviewed, in the member's
//! reports and in the class's gradebook (see `grade::reviewed`). Accepting changes only that copy: the course's
//! official snapshots are never touched from a submission. Without a
//! terminal (or with `--list`) the snapshots and their diffs are printed
//! instead.

use std::fs;
use std::io::IsTerminal as _;
use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{Context, Result, bail, ensure};
use serde::Serialize;

use crate::grade::report::Report;
use crate::grade::{self, PENDING_SNAPSHOTS};
use crate::{setup, stage};

/// The verdict of a snapshot the tutor found right.
const ACCEPTED: &str = "accepted";

/// The manifest of the review folder: a package of no code, so that
/// cargo-insta finds the snapshots in it.
const REVIEW_MANIFEST: &str = "# Written by `cargo xtask review`: a copy of the snapshots under review.\n[package]\nname = \"snapshot-review\"\nversion = \"0.0.0\"\nedition = \"2021\"\npublish = false\n\n[lib]\npath = \"lib.rs\"\n\n[workspace]\n";

/// The pending snapshots under `dir`, relative to it, sorted. The folder
/// is written by tests: its walk follows no link and is bounded.
fn pending_under(dir: &Path) -> Result<Vec<PathBuf>> {
    let mut found = Vec::new();
    if dir.is_dir() {
        for file in crate::files::listing(dir) {
            if file.to_string_lossy().ends_with(".snap.new") {
                found.push(file);
            }
        }
    }
    found.sort();
    Ok(found)
}

/// The official snapshot a pending one would replace: `x.snap.new` → `x.snap`.
fn official_of(pending: &Path) -> PathBuf {
    pending.with_extension("")
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
    /// The pending snapshots, relative to the grade's snapshots folder.
    pub pending: Vec<PathBuf>,
    /// The cargo-insta program.
    insta: PathBuf,
}

impl Review {
    /// Lays the snapshots the grade in `graded` found different beside a
    /// copy of the course's (at `root`) in `graded/review/`, and finds
    /// cargo-insta (installing it when missing). `None` when every
    /// snapshot matched.
    pub fn prepare(root: &Path, graded: &Path) -> Result<Option<Self>> {
        ensure!(
            graded.join("report.json").is_file(),
            "no grade in {} to review: run `cargo xtask grade` first",
            graded.display()
        );
        let pending = pending_under(&graded.join(PENDING_SNAPSHOTS))?;
        if pending.is_empty() {
            return Ok(None);
        }
        let dir = graded.join("review");
        if dir.exists() {
            fs::remove_dir_all(&dir).with_context(|| format!("cannot clear {}", dir.display()))?;
        }
        for file in &pending {
            let official = root.join(official_of(file));
            let to = dir.join(file);
            fs::create_dir_all(to.parent().expect("a snapshot lies in a folder"))
                .with_context(|| format!("cannot create the folder of {}", to.display()))?;
            fs::copy(graded.join(PENDING_SNAPSHOTS).join(file), &to)
                .with_context(|| format!("cannot copy {}", file.display()))?;
            if official.is_file() {
                fs::copy(&official, dir.join(official_of(file)))
                    .with_context(|| format!("cannot copy {}", official.display()))?;
            }
        }
        // cargo-insta works in a cargo package: an empty one around them.
        fs::write(dir.join("Cargo.toml"), REVIEW_MANIFEST)
            .with_context(|| format!("cannot write in {}", dir.display()))?;
        fs::write(dir.join("lib.rs"), "")
            .with_context(|| format!("cannot write in {}", dir.display()))?;
        let insta = setup::cargo_insta(&stage::home(root).join("tools"))?;
        Ok(Some(Self {
            graded: graded.to_path_buf(),
            dir,
            pending,
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
        let verdicts = verdicts(
            &self.dir,
            &self.graded.join(PENDING_SNAPSHOTS),
            &self.pending,
        )?;
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
    let path = graded.join("report.json");
    let text =
        fs::read_to_string(&path).with_context(|| format!("cannot read {}", path.display()))?;
    let mut report: Report =
        serde_json::from_str(&text).with_context(|| format!("cannot read {}", path.display()))?;
    let accepted: Vec<String> = verdicts
        .iter()
        .filter(|v| v.verdict == ACCEPTED)
        .map(|v| v.snapshot.clone())
        .collect();
    let before = report.score;
    let passing = grade::reviewed::apply(&mut report, &accepted);
    grade::export::write_all(&report, graded)?;
    let class = grade::submission::update_class_row(graded, &report)?;
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
/// accepted when the graded snapshot took the official one's place,
/// rejected when it was thrown away, not reviewed while it waits.
fn verdicts(review: &Path, graded: &Path, pending: &[PathBuf]) -> Result<Vec<Verdict>> {
    pending
        .iter()
        .map(|file| {
            let official = official_of(file);
            let verdict = if review.join(file).exists() {
                "not reviewed"
            } else if snapshot_body(&review.join(&official)) == snapshot_body(&graded.join(file)) {
                ACCEPTED
            } else {
                "rejected"
            };
            Ok(Verdict {
                snapshot: official.display().to_string(),
                verdict,
            })
        })
        .collect()
}

/// A snapshot file's contents after its metadata header (the part insta
/// rewrites on accepting).
fn snapshot_body(path: &Path) -> Option<String> {
    let text = fs::read_to_string(path).ok()?;
    Some(match text.strip_prefix("---\n") {
        Some(rest) => rest
            .split_once("\n---\n")
            .map_or(rest, |(_, body)| body)
            .to_owned(),
        None => text,
    })
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
        let (review, graded) = (dir.join("review"), dir.join("graded"));
        let snap = |name: &str| PathBuf::from(format!("t/snapshots/{name}.snap.new"));
        let write = |path: PathBuf, body: &str| {
            fs::create_dir_all(path.parent().unwrap()).unwrap();
            fs::write(path, format!("---\nsource: t.rs\n---\n{body}")).unwrap();
        };
        for name in ["a", "b", "c"] {
            write(graded.join(snap(name)), "yours\n");
        }
        // a accepted (the .snap now holds the graded body), b rejected (the
        // official body stays), c not reviewed yet.
        write(review.join(official_of(&snap("a"))), "yours\n");
        write(review.join(official_of(&snap("b"))), "official\n");
        write(review.join(official_of(&snap("c"))), "official\n");
        write(review.join(snap("c")), "yours\n");
        let got = verdicts(&review, &graded, &[snap("a"), snap("b"), snap("c")]).unwrap();
        let words: Vec<&str> = got.iter().map(|v| v.verdict).collect();
        assert_eq!(words, ["accepted", "rejected", "not reviewed"]);
        assert_eq!(got[0].snapshot, "t/snapshots/a.snap");
        let _ = fs::remove_dir_all(&dir);
    }
}
