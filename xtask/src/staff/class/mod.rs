//! The staff's class: grading a folder of checkouts (`cargo xtask grade
//! --submission CLASS` in the course repository), its gradebook and its
//! report, resuming it, grading it in shards and merging them, and a
//! generated class to try it on ([`generated`]). No edition holds it: the
//! grader there grades one checkout (`grade::submission`), which is what
//! this builds on, and imports nothing from here.
//!
//! Each member is graded into `<out>/<name>/`; the snapshots it failed
//! are in `<out>/<name>/snapshots/`. Up to `--jobs` members (default: one
//! per two CPUs) are graded side by side, each in a stage of its own (a
//! *slot*, see `stage::class_home` and [`slots`]), all built into the one
//! build cache, so the dependencies are built once. The builds take turns
//! (cargo would make them anyway); while one member builds, the others run
//! their tests, from hard links of their executables in their slot, with
//! at most `--jobs` tests running at once in all. `<out>/gradebook.csv`
//! and `gradebook.json` list the scores (see [`gradebook`]: each member's
//! row is kept in its folder, so a member graded again updates them, and
//! shards of a class graded on several machines merge), and `class.html`
//! and `class.json` sum the class up ([`report`]). A class graded again
//! keeps the members whose grade was made from the same files (see
//! [`resume`]), so an interrupted class goes on where it stopped.
//!
//! A test sees its own stage and executables and nothing else of the
//! course's build output: not the other slots (a classmate's code), the
//! course's own stage (which may hold the solutions), the build cache or
//! the planted shortcuts of `cargo xtask test`. Without a sandbox nothing
//! hides them, and a class is graded one member at a time, so that what a
//! member's tests change is found and blamed on it.

use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};

use crate::grade::Report;
use crate::grade::report::{points, round2};
use crate::grade::submission::{self, Integrity, is_checkout, member_name};
use crate::grade::{GradeOptions, table};

pub mod generated;
mod gradebook;
mod report;
mod resume;
mod slots;

use gradebook::{Class, GradebookRow};
pub use resume::Shard;

/// A graded member in one line: its points, bonus, flag, the topics that
/// did not compile, and where its report is.
fn one_line(report: &Report, out: &Path) -> String {
    let base: f64 = report.topics.iter().map(|t| t.base_score()).sum();
    let bonus: f64 = report.topics.iter().map(|t| t.bonus().0).sum();
    let mut line = format!(
        "{} / {} points",
        points(round2(base)),
        points(report.max_score)
    );
    if bonus > 0.0 {
        line.push_str(&format!(" (+{} bonus)", points(round2(bonus))));
    }
    let broken: Vec<&str> = report
        .topics
        .iter()
        .filter(|t| t.compile_error.is_some())
        .map(|t| t.name.as_str())
        .collect();
    if !broken.is_empty() {
        line.push_str(&format!(" · does not compile: {}", broken.join(", ")));
    }
    if report.integrity.as_ref().is_some_and(Integrity::flagged) {
        line.push_str(" · FLAGGED: grading files changed");
    }
    line.push_str(&format!(" · {}", out.join("report.html").display()));
    line
}

/// `cargo xtask grade --submission DIR` in the course repository: one
/// checkout (as the grader grades it, see [`submission::run`]; graded into
/// its class's folder, its row there and the class's gradebook follow),
/// or a folder of checkouts, a class, `at_once` of them side by side
/// [default: one per two CPUs]; of a class only the members of `shard`,
/// where one is given.
pub fn run(
    official: &Path,
    dir: &Path,
    options: &GradeOptions,
    at_once: Option<usize>,
    shard: Option<Shard>,
) -> Result<()> {
    let dir = dir
        .canonicalize()
        .with_context(|| format!("cannot find the submission {}", dir.display()))?;
    let out_for = |submission: &Path| {
        let mut one = options.clone();
        one.out = options.out.join(member_name(submission));
        (member_name(submission), one)
    };
    if is_checkout(&dir) {
        let report = submission::run(official, &dir, options)?;
        let (name, one) = out_for(&dir);
        // A member graded again into its class's folder: its row there,
        // and the class's gradebook, follow.
        if options.out.join("gradebook.json").is_file() {
            GradebookRow::new(name, &report).save(&one.out)?;
            resume::save(
                &one.out,
                &resume::fingerprint(resume::tree_hash(official)?, &dir)?,
            )?;
            let class = write_class(&options.out)?;
            println!(
                "the gradebook of {} member(s) in {} now holds this grade",
                class.rows.len(),
                options.out.display()
            );
        }
        return Ok(());
    }
    let mut submissions: Vec<PathBuf> = fs::read_dir(&dir)
        .with_context(|| format!("cannot read {}", dir.display()))?
        .filter_map(|entry| entry.ok().map(|e| e.path()))
        .filter(|path| is_checkout(path))
        .collect();
    submissions.sort();
    if submissions.is_empty() {
        bail!(
            "{} is neither a course checkout (with exercises/ and Cargo.toml) nor a folder of them",
            dir.display()
        );
    }
    let whole = submissions.len();
    if let Some(shard) = shard {
        submissions.retain(|s| shard.holds(&member_name(s)));
        println!(
            "shard {}/{}: {} of the class's {whole} member(s)",
            shard.index,
            shard.count,
            submissions.len()
        );
    }
    // Members graded before from the same files keep their grade.
    let course = resume::tree_hash(official)?;
    let mut to_grade = Vec::new();
    let mut fingerprints = Vec::new();
    for submission in &submissions {
        let fingerprint = resume::fingerprint(course, submission)?;
        if !resume::is_current(&out_for(submission).1.out, &fingerprint) {
            to_grade.push(submission.clone());
            fingerprints.push(fingerprint);
        }
    }
    if to_grade.len() < submissions.len() {
        println!(
            "{} of {} member(s) were graded before from the same files: kept (their report folders in {})",
            submissions.len() - to_grade.len(),
            submissions.len(),
            options.out.display()
        );
    }
    fs::create_dir_all(&options.out)
        .with_context(|| format!("cannot create {}", options.out.display()))?;
    let graded = slots::grade_class(official, &to_grade, options, at_once, out_for)?;
    for ((name, out, result), fingerprint) in graded.into_iter().zip(&fingerprints) {
        match result {
            Ok(report) => {
                GradebookRow::new(name, &report).save(&out)?;
                resume::save(&out, fingerprint)?;
            }
            Err(error) => gradebook::save_not_graded(&out, &format!("{error:#}"))?,
        }
    }
    let class = write_class(&options.out)?;
    report_class(&class, &options.out)
}

/// After a member's report changed (a review's verdicts): its row in the
/// gradebook of its class, where its report folder `member_out` is in a
/// class's folder. Whether there was a class to update.
pub fn update_class_row(member_out: &Path, report: &Report) -> Result<bool> {
    let Some(class_out) = member_out.parent() else {
        return Ok(false);
    };
    if !class_out.join("gradebook.json").is_file()
        || !member_out.join(gradebook::ROW_FILE).is_file()
    {
        return Ok(false);
    }
    GradebookRow::new(member_name(member_out), report).save(member_out)?;
    write_class(class_out)?;
    Ok(true)
}

/// `cargo xtask gradebook merge PARTS... --out DIR`.
pub fn merge(parts: &[PathBuf], out: &Path) -> Result<()> {
    gradebook::merge(parts, out)?;
    let class = write_class(out)?;
    report_class(&class, out)
}

/// Writes the gradebook of the class whose members' folders are in `out`
/// and the class's report (`class.html`, `class.json`, see [`report`]),
/// each member's report read from its folder.
fn write_class(out: &Path) -> Result<Class> {
    let class = Class::read(out)?;
    class.write(out)?;
    let mut graded = Vec::new();
    for row in &class.rows {
        let folder = out.join(&row.submission);
        let path = folder.join("report.json");
        let report = fs::read_to_string(&path)
            .with_context(|| format!("cannot read {}", path.display()))
            .and_then(|text| {
                serde_json::from_str::<Report>(&text)
                    .with_context(|| format!("cannot read {}", path.display()))
            });
        graded.push((row.submission.clone(), folder, report));
    }
    for (name, why) in &class.not_graded {
        graded.push((name.clone(), out.join(name), Err(anyhow::anyhow!("{why}"))));
    }
    report::write(out, &graded, &class.rows)?;
    Ok(class)
}

/// Prints where the gradebook of `class` is, who is flagged, and fails
/// when a member could not be graded.
fn report_class(class: &Class, out: &Path) -> Result<()> {
    println!();
    println!(
        "gradebook of {} submission(s): {} (also gradebook.json)",
        class.rows.len(),
        out.join("gradebook.csv").display()
    );
    let flagged: Vec<&str> = class
        .rows
        .iter()
        .filter(|r| r.flagged)
        .map(|r| r.submission.as_str())
        .collect();
    if !flagged.is_empty() {
        println!(
            "flagged (grading files changed): {}",
            table::shown(&flagged.join(", "))
        );
    }
    if !class.not_graded.is_empty() {
        let lines: Vec<String> = class
            .not_graded
            .iter()
            .map(|(name, why)| format!("{}: {}", table::shown(name), table::continued(why, "  ")))
            .collect();
        bail!(
            "{} submission(s) could not be graded and are not in the gradebook:\n{}",
            lines.len(),
            lines.join("\n")
        );
    }
    Ok(())
}
