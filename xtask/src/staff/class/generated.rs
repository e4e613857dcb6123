//! `cargo xtask class DIR`: a generated class, to try and to measure
//! grading a folder of submissions (`cargo xtask grade --submission DIR`).
//!
//! Each member is the student edition of the chosen topics
//! (`cargo xtask release`) in which a student did one of the things
//! students do, in turn:
//!
//! | kind | what it holds | what grading it must say |
//! |---|---|---|
//! | `correct` | every solution | full points |
//! | `faulty` | every solution, one with a planted mistake (`xtask/tests/shortcuts/`) | that task loses points |
//! | `partial` | the solutions of every other topic, the stubs elsewhere | those topics' points |
//! | `tampered` | the stubs, and a test rewritten to pass | flagged, graded on the official test |
//! | `broken` | every solution, one with a syntax error | that topic does not compile |

use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};

use crate::files::files_under;
use crate::staff::release;
use crate::staff::test::Shortcut;
use crate::stage;

/// What a generated member did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    Correct,
    Faulty,
    Partial,
    Tampered,
    Broken,
}

impl Kind {
    /// The kinds, in the order members are made.
    pub const ALL: [Kind; 5] = [
        Kind::Correct,
        Kind::Faulty,
        Kind::Partial,
        Kind::Tampered,
        Kind::Broken,
    ];

    fn name(self) -> &'static str {
        match self {
            Kind::Correct => "correct",
            Kind::Faulty => "faulty",
            Kind::Partial => "partial",
            Kind::Tampered => "tampered",
            Kind::Broken => "broken",
        }
    }
}

/// Writes a class of `size` members of the edition of `topics` (all when
/// empty) into `dir`, a new or empty folder; the members' folder names.
pub fn write(root: &Path, dir: &Path, size: usize, topics: &[String]) -> Result<Vec<String>> {
    if size == 0 {
        bail!("a class has at least one member");
    }
    let dir = stage::outside_course(root, dir)?;
    if dir.exists()
        && fs::read_dir(&dir)
            .with_context(|| format!("cannot read {}", dir.display()))?
            .next()
            .is_some()
    {
        bail!(
            "{} is not empty; choose a new or empty folder",
            dir.display()
        );
    }
    let shortcuts = crate::staff::test::shortcuts(root)?;
    let mut names = Vec::new();
    for i in 0..size {
        let kind = Kind::ALL[i % Kind::ALL.len()];
        let name = format!("s{:02}-{}", i + 1, kind.name());
        let member = dir.join(&name);
        let edition = release::write(root, &member, topics, None)?;
        // The n-th member of a kind varies what it does.
        let nth = i / Kind::ALL.len();
        make(root, &member, &edition.topics, kind, nth, &shortcuts)
            .with_context(|| format!("cannot make {name}"))?;
        names.push(name);
    }
    Ok(names)
}

/// Turns the edition at `member` (of `topics`) into a member of `kind`.
fn make(
    root: &Path,
    member: &Path,
    topics: &[String],
    kind: Kind,
    nth: usize,
    shortcuts: &[Shortcut],
) -> Result<()> {
    let solve = |topic: &str| -> Result<()> {
        let solutions = root.join("reference").join(topic);
        for file in files_under(&solutions)? {
            let text = fs::read_to_string(solutions.join(&file))
                .with_context(|| format!("cannot read {}", solutions.join(&file).display()))?;
            // As a student hands it in: no marker lines.
            crate::files::write_file(
                &member.join("exercises").join(topic).join(&file),
                crate::staff::stubs::without_markers(&text),
            )?;
        }
        Ok(())
    };
    let pick = |items: usize| nth % items.max(1);
    match kind {
        Kind::Correct => topics.iter().try_for_each(|t| solve(t))?,
        Kind::Partial => topics
            .iter()
            .enumerate()
            .filter(|(t, _)| (t + nth).is_multiple_of(2))
            .try_for_each(|(_, t)| solve(t))?,
        Kind::Faulty => {
            topics.iter().try_for_each(|t| solve(t))?;
            let ours: Vec<&Shortcut> = shortcuts
                .iter()
                .filter(|s| topics.contains(&s.topic))
                .collect();
            let Some(shortcut) = ours.get(pick(ours.len())) else {
                // No planted mistake for these topics: one task file is
                // left as it was handed out.
                let task_files = stage::task_files(root)?;
                let in_topics: Vec<&PathBuf> = task_files
                    .iter()
                    .filter(|f| {
                        topics
                            .iter()
                            .any(|t| f.starts_with(Path::new("exercises").join(t)))
                    })
                    .collect();
                let Some(file) = in_topics.get(pick(in_topics.len())) else {
                    bail!("the topics {topics:?} have no task files");
                };
                let stub = root.join(file);
                crate::files::write_file(
                    &member.join(file),
                    fs::read(&stub).with_context(|| format!("cannot read {}", stub.display()))?,
                )?;
                return Ok(());
            };
            let path = member
                .join("exercises")
                .join(&shortcut.topic)
                .join("src")
                .join(&shortcut.file);
            // Planted into the solution as the reference holds it (a
            // shortcut may replace a marked region), then handed in
            // without the markers.
            let reference = root
                .join("reference")
                .join(&shortcut.topic)
                .join("src")
                .join(&shortcut.file);
            let text = fs::read_to_string(&reference)
                .with_context(|| format!("cannot read {}", reference.display()))?;
            crate::files::write_file(
                &path,
                crate::staff::stubs::without_markers(&shortcut.plant(&text)?),
            )?;
        }
        Kind::Tampered => {
            let topic = &topics[pick(topics.len())];
            let tests = member.join("exercises").join(topic).join("tests");
            let mut files: Vec<PathBuf> = files_under(&tests)?
                .into_iter()
                .filter(|f| f.components().count() == 1 && f.extension().is_some_and(|e| e == "rs"))
                .collect();
            files.sort();
            let Some(file) = files.first() else {
                bail!("{topic} has no test files");
            };
            crate::files::write_file(&tests.join(file), "#[test]\nfn passes() {}\n")?;
        }
        Kind::Broken => {
            topics.iter().try_for_each(|t| solve(t))?;
            let topic = &topics[pick(topics.len())];
            let task_files = stage::task_files(root)?;
            let file = task_files
                .iter()
                .find(|f| f.starts_with(Path::new("exercises").join(topic)))
                .with_context(|| format!("{topic} has no task files"))?;
            let path = member.join(file);
            let text = fs::read_to_string(&path)
                .with_context(|| format!("cannot read {}", path.display()))?;
            crate::files::write_file(&path, format!("{text}\nfn unfinished( {{\n"))?;
        }
    }
    Ok(())
}

/// `cargo xtask class DIR`: writes the class and says how to grade it.
pub fn run(root: &Path, dir: &Path, size: usize, topics: &[String]) -> Result<()> {
    let names = write(root, dir, size, topics)?;
    println!(
        "wrote a class of {} submissions to {}: {}",
        names.len(),
        dir.display(),
        names.join(", ")
    );
    println!(
        "to grade it: cargo xtask grade --submission {}",
        dir.display()
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every planted mistake a faulty member may hand in is made: planted
    /// into the reference's file (a shortcut may need its markers) and
    /// handed in without markers.
    #[test]
    fn every_planted_mistake_can_be_handed_in() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
        if !root.join("reference").is_dir() {
            eprintln!("not run: a student edition holds no solutions to plant into");
            return;
        }
        let shortcuts = crate::staff::test::shortcuts(root).unwrap();
        let mut topics: Vec<String> = shortcuts.iter().map(|s| s.topic.clone()).collect();
        topics.sort();
        topics.dedup();
        let member = std::env::temp_dir().join(format!("xtask-faulty-{}", std::process::id()));
        for (nth, shortcut) in shortcuts.iter().enumerate() {
            let _ = fs::remove_dir_all(&member);
            make(root, &member, &topics, Kind::Faulty, nth, &shortcuts)
                .unwrap_or_else(|e| panic!("{}: {e:#}", shortcut.what));
            let file = member
                .join("exercises")
                .join(&shortcut.topic)
                .join("src")
                .join(&shortcut.file);
            let handed_in = fs::read_to_string(&file).unwrap();
            assert!(
                !handed_in.contains("// BEGIN SOLUTION"),
                "{}",
                shortcut.what
            );
        }
        let _ = fs::remove_dir_all(&member);
    }
}
