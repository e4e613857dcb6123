//! The gradebook of a class: one row per submission, as CSV and JSON.
//!
//! Each member's row is kept in its report folder (`<out>/<member>/`
//! [`ROW_FILE`], or [`NOT_GRADED_FILE`] with why it could not be graded),
//! and the gradebook is made from the folders that `<out>` holds. So a
//! member graded again updates the class's gradebook, a class graded in
//! shards on several machines is joined by copying the members' folders
//! into one (`cargo xtask gradebook merge`), and either gives the
//! gradebook a single run gives.

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use serde::{Deserialize, Serialize};

use crate::files::{MAX_SUBMITTED_FILE, files_under, read_capped, remove_tree};
use crate::grade::report::{self, Report};
use crate::grade::submission::Integrity;

/// A member's row, in its report folder.
pub const ROW_FILE: &str = "gradebook-row.json";
/// Why a member could not be graded, in its report folder.
pub const NOT_GRADED_FILE: &str = "not-graded.txt";

/// One row of the gradebook.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(super) struct GradebookRow {
    pub(super) submission: String,
    /// Points of the tasks that are not bonuses.
    pub(super) score: f64,
    pub(super) max_score: f64,
    /// Bonus points, apart.
    pub(super) bonus: f64,
    pub(super) complete: bool,
    pub(super) flagged: bool,
    pub(super) integrity: Option<String>,
    /// Per topic, its points (bonus apart).
    pub(super) topics: Vec<(String, f64)>,
    /// Per task (`topic/task`), its points.
    pub(super) tasks: Vec<(String, f64)>,
    /// The topics that could not be graded, each with why.
    pub(super) not_graded: Vec<String>,
    /// The member's report, relative to the class's folder.
    pub(super) report: String,
}

impl GradebookRow {
    pub(super) fn new(submission: String, report: &Report) -> Self {
        let integrity = report.integrity.as_ref();
        Self {
            score: report::round2(report.topics.iter().map(|t| t.base_score()).sum()),
            max_score: report.max_score,
            bonus: report::round2(report.topics.iter().map(|t| t.bonus().0).sum()),
            complete: report.complete,
            flagged: integrity.is_some_and(Integrity::flagged),
            integrity: integrity.filter(|i| i.flagged()).map(Integrity::summary),
            topics: report
                .topics
                .iter()
                .map(|t| (t.name.clone(), t.base_score()))
                .collect(),
            tasks: report
                .topics
                .iter()
                .flat_map(|t| {
                    t.tasks
                        .iter()
                        .map(move |task| (format!("{}/{}", t.name, task.id), task.score))
                })
                .collect(),
            not_graded: report
                .topics
                .iter()
                .filter_map(|t| {
                    let why = match (&t.compile_error, t.errors.first()) {
                        (Some(_), _) => "does not compile".to_owned(),
                        (None, Some(error)) => error.lines().next().unwrap_or_default().to_owned(),
                        (None, None) => return None,
                    };
                    Some(format!("{}: {why}", t.name))
                })
                .collect(),
            report: format!("{submission}/report.html"),
            submission,
        }
    }

    /// Keeps the row in the member's report folder `out`.
    pub(super) fn save(&self, out: &Path) -> Result<()> {
        let _ = fs::remove_file(out.join(NOT_GRADED_FILE));
        let path = out.join(ROW_FILE);
        let json =
            serde_json::to_string_pretty(self).context("cannot serialise a gradebook row")?;
        fs::write(&path, json).with_context(|| format!("cannot write {}", path.display()))
    }
}

/// Keeps why the member of report folder `out` could not be graded.
pub(super) fn save_not_graded(out: &Path, why: &str) -> Result<()> {
    fs::create_dir_all(out).with_context(|| format!("cannot create {}", out.display()))?;
    let _ = fs::remove_file(out.join(ROW_FILE));
    let path = out.join(NOT_GRADED_FILE);
    fs::write(&path, why).with_context(|| format!("cannot write {}", path.display()))
}

/// The members a class folder holds: their rows, and (name, why) of those
/// that could not be graded, both by name.
pub(super) struct Class {
    pub(super) rows: Vec<GradebookRow>,
    pub(super) not_graded: Vec<(String, String)>,
}

impl Class {
    /// Reads the members' folders of the class folder `out`.
    pub(super) fn read(out: &Path) -> Result<Self> {
        let mut class = Self {
            rows: Vec::new(),
            not_graded: Vec::new(),
        };
        for member in member_folders(out)? {
            let name = member
                .file_name()
                .map(|n| n.to_string_lossy().into_owned())
                .unwrap_or_default();
            let row_path = member.join(ROW_FILE);
            if row_path.is_file() {
                // A row that cannot be read is that member's problem, named
                // with why; the gradebook holds the others.
                let row = read_capped(&row_path, MAX_SUBMITTED_FILE).and_then(|bytes| {
                    serde_json::from_slice::<GradebookRow>(&bytes)
                        .with_context(|| format!("cannot read {}", row_path.display()))
                });
                match row {
                    Ok(row) => class.rows.push(row),
                    Err(error) => class
                        .not_graded
                        .push((name, format!("its gradebook row is unreadable: {error:#}"))),
                }
            } else if let Ok(why) = read_capped(&member.join(NOT_GRADED_FILE), MAX_SUBMITTED_FILE) {
                class
                    .not_graded
                    .push((name, String::from_utf8_lossy(&why).into_owned()));
            }
        }
        Ok(class)
    }

    /// Writes `gradebook.csv` and `gradebook.json` into `out`.
    pub(super) fn write(&self, out: &Path) -> Result<()> {
        let csv = gradebook_csv(&self.rows);
        let json =
            serde_json::to_string_pretty(&self.rows).context("cannot serialise the gradebook")?;
        for (file, contents) in [("gradebook.csv", csv), ("gradebook.json", json)] {
            let path = out.join(file);
            fs::write(&path, contents)
                .with_context(|| format!("cannot write {}", path.display()))?;
        }
        Ok(())
    }
}

/// The folders of `out` that hold a member (a row or why it has none),
/// sorted by name. A link is no member's folder: it could name any folder
/// of the machine, which a merge would then copy.
fn member_folders(out: &Path) -> Result<Vec<PathBuf>> {
    let mut found = Vec::new();
    for entry in fs::read_dir(out).with_context(|| format!("cannot read {}", out.display()))? {
        let entry = entry.with_context(|| format!("cannot read {}", out.display()))?;
        let path = entry.path();
        let folder = entry.file_type().is_ok_and(|kind| kind.is_dir());
        let holds =
            |file: &str| fs::symlink_metadata(path.join(file)).is_ok_and(|meta| meta.is_file());
        if folder && (holds(ROW_FILE) || holds(NOT_GRADED_FILE)) {
            found.push(path);
        }
    }
    found.sort();
    Ok(found)
}

/// `cargo xtask gradebook merge PARTS... --out DIR`: the members' folders
/// of the parts (the `--out` folders of a class graded in shards) copied
/// into `out`, and the class's gradebook made from them.
pub(super) fn merge(parts: &[PathBuf], out: &Path) -> Result<Class> {
    fs::create_dir_all(out).with_context(|| format!("cannot create {}", out.display()))?;
    let mut seen: Vec<(String, PathBuf)> = Vec::new();
    for part in parts {
        let members = member_folders(part)?;
        if members.is_empty() {
            bail!(
                "{} holds no graded member (a folder with {ROW_FILE} or {NOT_GRADED_FILE}): is it the --out of a class's grade?",
                part.display()
            );
        }
        for member in members {
            let name = member
                .file_name()
                .map(|n| n.to_string_lossy().into_owned())
                .unwrap_or_default();
            if let Some((_, other)) = seen.iter().find(|(n, _)| *n == name) {
                bail!(
                    "{name} is in two parts, {} and {}: each member belongs to one shard",
                    other.display(),
                    part.display()
                );
            }
            let to = out.join(&name);
            if to != member {
                remove_tree(&to).with_context(|| format!("cannot replace {}", to.display()))?;
                // A member whose folder cannot be copied is that member's
                // problem: named in the gradebook as not graded, with why,
                // and the merge goes on.
                if let Err(error) = copy_tree(&member, &to) {
                    let _ = remove_tree(&to);
                    save_not_graded(
                        &to,
                        &format!(
                            "its report folder in {} could not be copied: {error:#}",
                            part.display()
                        ),
                    )?;
                }
            }
            seen.push((name, part.clone()));
        }
    }
    Class::read(out)
}

/// Copies the report folder `from` to `to`: its plain files, by the
/// bounded walk of `files_under` (no link followed or copied, no deeper
/// than `files::MAX_DEPTH`: a grade keeps its report within that, see
/// `files::Keeper`), the member's row last, so that a copy cut short
/// holds no row.
fn copy_tree(from: &Path, to: &Path) -> Result<()> {
    fs::create_dir_all(to).with_context(|| format!("cannot create {}", to.display()))?;
    let mut files = files_under(from)?;
    files.sort_by_key(|file| file == Path::new(ROW_FILE));
    for file in files {
        let target = to.join(&file);
        if let Some(parent) = target.parent() {
            fs::create_dir_all(parent)
                .with_context(|| format!("cannot create {}", parent.display()))?;
        }
        fs::copy(from.join(&file), &target)
            .with_context(|| format!("cannot copy {}", from.join(&file).display()))?;
    }
    Ok(())
}

/// The gradebook as CSV: one row per submission; columns by name (a
/// member without a topic leaves its cell empty, never shifts the others):
/// the points (bonus apart), then one per topic, one per task, and why a
/// topic was not graded.
pub(super) fn gradebook_csv(rows: &[GradebookRow]) -> String {
    // Every topic and task any member has, in the order first met.
    let mut topics: Vec<&str> = Vec::new();
    let mut tasks: Vec<&str> = Vec::new();
    for row in rows {
        for (name, _) in &row.topics {
            if !topics.contains(&name.as_str()) {
                topics.push(name);
            }
        }
        for (name, _) in &row.tasks {
            if !tasks.contains(&name.as_str()) {
                tasks.push(name);
            }
        }
    }
    let mut csv = String::from("submission,score,max_score,bonus,complete,flagged");
    for column in topics.iter().chain(&tasks) {
        csv.push(',');
        csv.push_str(&csv_field(column));
    }
    csv.push_str(",not_graded\n");
    let cell = |values: &[(String, f64)], column: &str| {
        values
            .iter()
            .find(|(name, _)| name == column)
            .map_or_else(String::new, |(_, score)| report::points(*score))
    };
    for row in rows {
        let _ = write!(
            csv,
            "{},{},{},{},{},{}",
            csv_field(&row.submission),
            report::points(row.score),
            report::points(row.max_score),
            report::points(row.bonus),
            row.complete,
            row.flagged
        );
        for topic in &topics {
            let _ = write!(csv, ",{}", cell(&row.topics, topic));
        }
        for task in &tasks {
            let _ = write!(csv, ",{}", cell(&row.tasks, task));
        }
        let _ = writeln!(csv, ",{}", csv_field(&row.not_graded.join("; ")));
    }
    csv
}

/// A CSV text field, quoted when it holds a comma, a quote or a line
/// break. A field that a spreadsheet would take for a formula (a member's
/// folder named `=HYPERLINK(…)`: it starts with `=`, `+`, `-`, `@`, a tab
/// or a carriage return) gets a `'` in front, which spreadsheets read as
/// "text follows" (OWASP's advice on CSV injection).
fn csv_field(text: &str) -> String {
    let text = if text.starts_with(['=', '+', '-', '@', '\t', '\r']) {
        format!("'{text}")
    } else {
        text.to_owned()
    };
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gradebook_columns_go_by_name_not_by_position() {
        let row = |name: &str, topics: &[(&str, f64)], tasks: &[(&str, f64)]| GradebookRow {
            submission: name.to_owned(),
            score: topics.iter().map(|t| t.1).sum(),
            max_score: 5.0,
            bonus: 0.0,
            complete: true,
            flagged: false,
            integrity: None,
            topics: topics.iter().map(|(n, s)| ((*n).to_owned(), *s)).collect(),
            tasks: tasks.iter().map(|(n, s)| ((*n).to_owned(), *s)).collect(),
            not_graded: Vec::new(),
            report: format!("{name}/report.html"),
        };
        let mut lacking = row("ben", &[("02-b", 1.0)], &[("02-b/y", 1.0)]);
        lacking.not_graded = vec!["01-a: the submission has no exercises/01-a".to_owned()];
        let csv = gradebook_csv(&[
            row(
                "anna",
                &[("01-a", 2.0), ("02-b", 3.0)],
                &[("01-a/x", 2.0), ("02-b/y", 3.0)],
            ),
            lacking,
        ]);
        assert_eq!(
            csv,
            "submission,score,max_score,bonus,complete,flagged,01-a,02-b,01-a/x,02-b/y,not_graded\n\
             anna,5,5,0,true,false,2,3,2,3,\n\
             ben,1,5,0,true,false,,1,,1,01-a: the submission has no exercises/01-a\n"
        );
    }

    /// A part whose member's picture folder holds a chain of 2,100
    /// folders (its path far past `PATH_MAX`; an older grade kept it), a
    /// member whose row is torn, and a link posing as a member: the merge
    /// copies the honest member, names the other two as not graded with
    /// why, copies nothing through the link, and is written.
    #[test]
    fn a_merge_goes_on_past_a_member_it_cannot_copy() {
        use crate::files::tests::{chain, scratch};
        let dir = scratch("merge-hostile");
        let part = dir.join("part");
        let row = |name: &str| GradebookRow {
            submission: name.to_owned(),
            score: 1.0,
            max_score: 1.0,
            bonus: 0.0,
            complete: true,
            flagged: false,
            integrity: None,
            topics: Vec::new(),
            tasks: Vec::new(),
            not_graded: Vec::new(),
            report: format!("{name}/report.html"),
        };
        for name in ["anna", "deep"] {
            fs::create_dir_all(part.join(name).join("images")).unwrap();
            row(name).save(&part.join(name)).unwrap();
        }
        chain(&part.join("deep/images"), "t", 2_100, "d");
        fs::create_dir_all(part.join("torn")).unwrap();
        fs::write(part.join("torn").join(ROW_FILE), "{ not json").unwrap();
        #[cfg(unix)]
        std::os::unix::fs::symlink(part.join("anna"), part.join("linked")).unwrap();
        let out = dir.join("merged");
        let class = merge(&[part], &out).expect("the merge is written");
        let names: Vec<&str> = class.rows.iter().map(|r| r.submission.as_str()).collect();
        assert_eq!(names, ["anna"]);
        assert_eq!(class.not_graded.len(), 2, "{:?}", class.not_graded);
        assert_eq!(class.not_graded[0].0, "deep");
        assert!(
            class.not_graded[0].1.contains("could not be copied"),
            "{:?}",
            class.not_graded
        );
        assert_eq!(class.not_graded[1].0, "torn");
        assert!(
            class.not_graded[1].1.contains("row is unreadable"),
            "{:?}",
            class.not_graded
        );
        assert!(!out.join("linked").exists(), "a link is no member");
        crate::files::remove_tree(&dir).unwrap();
    }

    #[test]
    fn csv_fields_are_quoted_only_when_needed_and_never_formulas() {
        assert_eq!(csv_field("anna"), "anna");
        assert_eq!(csv_field("a,b"), "\"a,b\"");
        assert_eq!(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
        assert_eq!(csv_field("=1+1"), "'=1+1");
        assert_eq!(csv_field("@SUM(A1)"), "'@SUM(A1)");
        assert_eq!(csv_field("-2,3"), "\"'-2,3\"");
        assert_eq!(csv_field("anna-2"), "anna-2");
    }
}
