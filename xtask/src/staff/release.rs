//! `cargo xtask release DIR [--topics 01..=03]`: writes the edition
//! students get ([`crate::edition`]), ready to push as a repository of its
//! own.
//!
//! Releasing again into the same folder updates it in place (its `.git`
//! stays): the next commit there is the new edition. With `--classroom
//! OWNER/REPO@TAG` the edition also carries the GitHub Classroom workflow
//! that grades each push with the official tests of that repository (see
//! [`super::classroom`]).

use std::path::{Path, PathBuf};

use anyhow::{Result, bail, ensure};

use super::class_workflow;
use super::classroom::{self, CourseRepo};
use crate::edition::Source;
use crate::edition::{edition_files, select_topics, trim_lock_file};
use crate::stage;

/// What a release holds.
#[derive(Debug)]
pub struct Release {
    /// The folder it was written to.
    pub dir: PathBuf,
    /// The released topics (folder names), in course order.
    pub topics: Vec<String>,
    /// The course-library crates they need (folder names under `crates/`).
    pub crates: Vec<String>,
    /// Files of an earlier release in the folder that this one does not
    /// hold, and which were removed (`.git` and `target/` are never
    /// touched).
    pub removed: Vec<PathBuf>,
}

/// Writes the edition of `topics` (empty: all) into `dir`.
pub fn write(
    root: &Path,
    dir: &Path,
    wanted: &[String],
    classroom: Option<&CourseRepo>,
) -> Result<Release> {
    if !root.join("reference").is_dir() {
        bail!(
            "{} is a student edition already: it has no reference/",
            root.display()
        );
    }
    let topics = select_topics(root, wanted)?;
    ensure!(!topics.is_empty(), "no topics to release");
    let (mut files, crates) = edition_files(root, &topics)?;
    // The course's lock file (if it has one), trimmed by cargo below.
    files.retain(|(to, _)| to != Path::new("Cargo.lock"));
    if root.join("Cargo.lock").is_file() {
        files.push((
            PathBuf::from("Cargo.lock"),
            Source::File(root.join("Cargo.lock")),
        ));
    }
    if let Some(course) = classroom {
        files.retain(|(to, _)| {
            to != Path::new(classroom::WORKFLOW) && to != Path::new(class_workflow::WORKFLOW)
        });
        files.push((
            PathBuf::from(classroom::WORKFLOW),
            Source::Text(classroom::workflow(course, &topics).into_bytes()),
        ));
        files.push((
            PathBuf::from(class_workflow::WORKFLOW),
            Source::Text(class_workflow::workflow(course).into_bytes()),
        ));
    }
    files.sort();
    stage::claim(dir)?;
    let (_, removed) = stage::sync(&files, dir)?;
    trim_lock_file(dir)?;
    Ok(Release {
        dir: dir.to_path_buf(),
        topics: topics.into_iter().map(|t| t.name).collect(),
        crates,
        removed,
    })
}

/// `cargo xtask release DIR [--topics ...]`.
pub fn run(
    root: &Path,
    dir: &Path,
    topics: &[String],
    classroom: Option<&CourseRepo>,
) -> Result<()> {
    let dir = stage::outside_course(root, dir)?;
    let release = write(root, &dir, topics, classroom)?;
    println!(
        "wrote the student edition to {}\n  topics: {}\n  course library: {}",
        release.dir.display(),
        release.topics.join(", "),
        release.crates.join(", ")
    );
    if !release.removed.is_empty() {
        let shown: Vec<String> = release
            .removed
            .iter()
            .map(|f| f.display().to_string())
            .collect();
        println!("  removed (not part of this edition): {}", shown.join(", "));
    }
    println!(
        "to publish it: cd {} && git init && git add -A && git commit -m \"Course edition\"",
        release.dir.display()
    );
    if let Some(course) = classroom {
        println!(
            "  GitHub Classroom: {} grades every push with the official tests of {}{}; push this edition there{} and use it as the assignment's template",
            classroom::WORKFLOW,
            course.repository,
            course
                .reference
                .as_deref()
                .map(|r| format!(" at {r}"))
                .unwrap_or_default(),
            course
                .reference
                .as_deref()
                .map(|r| format!(", tagged {r},"))
                .unwrap_or_default(),
        );
    }
    Ok(())
}
