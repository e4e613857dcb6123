//! GitHub Classroom: the workflow a student edition carries, and the
//! per-task results it reports.
//!
//! `cargo xtask release DIR --classroom OWNER/REPO@REF` writes
//! `.github/workflows/classroom.yml` into the edition. On every push of a
//! student's repository it checks out the course's official edition
//! (`OWNER/REPO` at `REF`, a tag the course author pushed: the tests a
//! student edits in their own repository change nothing), grades the push
//! as a submission with `cargo xtask grade --submission`, and hands one
//! result per task to GitHub Classroom's grading reporter
//! (`classroom-resources/autograding-grading-reporter`), named and weighted
//! from each topic's `tasks.toml`: what course staff otherwise write by
//! hand for every assignment.
//!
//! The grader writes those results
//! ([`crate::grade::classroom::results`]) as `classroom/<step id>.json`
//! beside its other reports.

use std::fmt::Write as _;

pub use crate::grade::classroom::step_id;
use crate::topics::{Task, Topic};
use anyhow::{Result, ensure};

/// Where the official edition lives: a GitHub repository and, optionally,
/// the tag or branch to check out.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CourseRepo {
    /// `OWNER/NAME`.
    pub repository: String,
    /// A tag (best: it never moves under the students) or a branch; `None`
    /// checks out the default branch.
    pub reference: Option<String>,
}

impl std::str::FromStr for CourseRepo {
    type Err = anyhow::Error;

    fn from_str(text: &str) -> Result<Self> {
        let (repository, reference) = match text.split_once('@') {
            Some((repository, reference)) => (repository, Some(reference)),
            None => (text, None),
        };
        let part_ok = |part: &str| {
            !part.is_empty()
                && part
                    .chars()
                    .all(|c| c.is_ascii_alphanumeric() || "-_.".contains(c))
        };
        ensure!(
            repository
                .split_once('/')
                .is_some_and(|(owner, name)| part_ok(owner) && part_ok(name)),
            "`{text}`: the course's repository is OWNER/NAME (optionally @TAG), e.g. `my-course/rasterization@v1`"
        );
        if let Some(reference) = reference {
            ensure!(
                !reference.is_empty()
                    && reference
                        .chars()
                        .all(|c| c.is_ascii_alphanumeric() || "-_./".contains(c)),
                "`{text}`: `{reference}` is not a tag or branch name"
            );
        }
        Ok(Self {
            repository: repository.to_owned(),
            reference: reference.map(str::to_owned),
        })
    }
}

/// The file the workflow writes, relative to the edition.
pub const WORKFLOW: &str = ".github/workflows/classroom.yml";

/// Where the workflow checks out the official edition and grades into,
/// relative to the job's workspace.
const COURSE_DIR: &str = "course";
const SUBMISSION_DIR: &str = "submission";
const GRADE_DIR: &str = "grade";

/// Points as YAML and the reporter print them: `4`, `1.5`.
fn points(points: f64) -> String {
    let text = format!("{points:.2}");
    text.trim_end_matches('0').trim_end_matches('.').to_owned()
}

/// `.github/workflows/classroom.yml` for an edition of `topics`.
#[must_use]
pub fn workflow(course: &CourseRepo, topics: &[Topic]) -> String {
    let tasks: Vec<(&Topic, &Task)> = topics
        .iter()
        .flat_map(|topic| topic.sheet.tasks.iter().map(move |task| (topic, task)))
        .collect();
    let mut yaml = String::new();
    let _ = write!(
        yaml,
        r#"# Written by `cargo xtask release --classroom`: grades every push with the
# course's official tests and reports one result per task to GitHub
# Classroom. Release the edition again to change it.
name: Autograding
on:
  push:
  workflow_dispatch:
permissions:
  checks: write
  actions: read
  contents: read
jobs:
  grade:
    runs-on: ubuntu-latest
    if: github.actor != 'github-classroom[bot]'
    timeout-minutes: 90
    steps:
      - name: Check out the submission
        uses: actions/checkout@v4
        with:
          path: {SUBMISSION_DIR}
      - name: Check out the course's official tests
        uses: actions/checkout@v4
        with:
          repository: {repository}
"#,
        repository = course.repository,
    );
    if let Some(reference) = &course.reference {
        let _ = writeln!(yaml, "          ref: {reference}");
    }
    let _ = write!(
        yaml,
        r#"          path: {COURSE_DIR}
          # A private course repository needs a token that can read it.
          token: ${{{{ secrets.COURSE_TOKEN || github.token }}}}
      - name: Install the sandbox and the software GPU driver
        run: |
          sudo apt-get update -q
          sudo apt-get install -y -q bubblewrap mesa-vulkan-drivers libvulkan1
          # Ubuntu 24.04 keeps unprivileged user namespaces, bubblewrap's
          # sandbox, from programs without an AppArmor profile.
          sudo sysctl -w kernel.apparmor_restrict_unprivileged_userns=0 || true
      - name: Install Rust
        run: rustup toolchain install stable --profile minimal && rustup default stable
      - name: Cache the build
        uses: actions/cache@v4
        with:
          path: |
            ~/.cargo/registry/index/
            ~/.cargo/registry/cache/
            ~/.cargo/git/db/
            {COURSE_DIR}/target/
          key: grade-${{{{ runner.os }}}}-${{{{ hashFiles('{COURSE_DIR}/Cargo.lock') }}}}
          restore-keys: grade-${{{{ runner.os }}}}-
      - name: Grade
        working-directory: {COURSE_DIR}
        run: |
{delegate}          cargo xtask grade --submission ../{SUBMISSION_DIR} --out ../{GRADE_DIR}
      - name: Keep the report
        if: always()
        uses: actions/upload-artifact@v4
        with:
          name: grade-report
          path: {GRADE_DIR}/
          if-no-files-found: ignore
"#,
        delegate = crate::sandbox::delegate_script("          "),
    );
    for (topic, task) in &tasks {
        let id = step_id(&topic.name, &task.id);
        let bonus = if task.bonus { ", bonus" } else { "" };
        let _ = write!(
            yaml,
            r#"      - name: "{topic} / {task}: {title} ({points} point{plural}{bonus})"
        id: {id}
        run: result=$(base64 -w0 < {GRADE_DIR}/{SUBMISSION_DIR}/classroom/{id}.json) && echo "result=$result" >> "$GITHUB_OUTPUT"
"#,
            topic = topic.name,
            task = task.id,
            title = task.title.replace(['"', '\\'], "'"),
            points = points(task.points),
            plural = if (task.points - 1.0).abs() < f64::EPSILON {
                ""
            } else {
                "s"
            },
        );
    }
    yaml.push_str(
        r"      - name: Report to GitHub Classroom
        uses: classroom-resources/autograding-grading-reporter@v1
        env:
",
    );
    for (topic, task) in &tasks {
        let id = step_id(&topic.name, &task.id);
        let _ = writeln!(
            yaml,
            "          {}_RESULTS: \"${{{{ steps.{id}.outputs.result }}}}\"",
            id.to_uppercase()
        );
    }
    let runners: Vec<String> = tasks
        .iter()
        .map(|(topic, task)| step_id(&topic.name, &task.id))
        .collect();
    let _ = write!(
        yaml,
        "        with:\n          runners: {}\n",
        runners.join(",")
    );
    yaml
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_course_repository_is_owner_name_and_an_optional_tag() {
        let repo: CourseRepo = "my-course/raster.rs@v1.2".parse().unwrap();
        assert_eq!(repo.repository, "my-course/raster.rs");
        assert_eq!(repo.reference.as_deref(), Some("v1.2"));
        assert_eq!("a/b".parse::<CourseRepo>().unwrap().reference, None);
        for bad in ["nobody", "a/", "/b", "a/b@", "a b/c", "a/b@v1 x", "a/b/c"] {
            let error = bad.parse::<CourseRepo>().unwrap_err().to_string();
            assert!(error.contains(bad), "{bad}: {error}");
        }
    }

    #[test]
    fn points_are_written_without_trailing_zeros() {
        assert_eq!(points(4.0), "4");
        assert_eq!(points(1.5), "1.5");
        assert_eq!(points(0.25), "0.25");
    }
}
