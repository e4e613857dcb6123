//! Planted shortcuts (step 8): simpler or copied algorithms, read from
//! `xtask/tests/shortcuts/`, each planted into the solutions, must lose
//! their points.

use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail, ensure};

use crate::grade::Report;
use crate::grade::report::TestStatus;
use crate::stubs;

use super::{SHORTCUTS, grade_planted, rounds};

/// The planted shortcuts (see [`SHORTCUTS`]).
#[derive(serde::Deserialize)]
pub(super) struct Shortcuts {
    #[serde(default)]
    shortcut: Vec<Shortcut>,
}

/// One shortcut: where it goes, how it is made, what it must cost.
#[derive(serde::Deserialize)]
pub(crate) struct Shortcut {
    /// What the planted mistake is, in words.
    pub what: String,
    /// Its topic (folder name).
    pub topic: String,
    /// Its solution file, in the topic's `src/`.
    pub file: String,
    task: String,
    function: Option<String>,
    body: Option<String>,
    #[serde(default)]
    replace: Vec<[String; 2]>,
    #[serde(default)]
    zero: bool,
    #[serde(default)]
    failing: Vec<String>,
}

impl Shortcut {
    /// What this shortcut keeps that it should lose, graded as `report`.
    fn problems(&self, report: &Report) -> Vec<String> {
        let task = report
            .topics
            .iter()
            .filter(|t| t.name == self.topic)
            .flat_map(|t| &t.tasks)
            .find(|t| t.id == self.task);
        let Some(task) = task else {
            return vec![format!(
                "{}: no task {} / {}",
                self.what, self.topic, self.task
            )];
        };
        let mut problems = Vec::new();
        if let Some(error) = report
            .topics
            .iter()
            .find(|t| t.name == self.topic)
            .and_then(|t| t.compile_error.as_deref())
        {
            problems.push(format!(
                "{}: {} does not compile where it is planted, so its loss proves nothing: {}",
                self.what,
                self.topic,
                error.lines().next().unwrap_or_default()
            ));
        }
        if self.zero && task.score > 0.0 {
            problems.push(format!(
                "{} scores {} of {} points on {} / {}",
                self.what, task.score, task.points, self.topic, self.task
            ));
        }
        for name in &self.failing {
            let failed = task
                .tests
                .iter()
                .any(|t| &t.name == name && t.status == TestStatus::Failed);
            if !failed {
                problems.push(format!(
                    "{}: `{name}` of {} / {} does not fail",
                    self.what, self.topic, self.task
                ));
            }
        }
        problems
    }

    /// Whether this shortcut and `other` could change each other's grade
    /// if planted in one round: the same task, the same file, or one
    /// calling into the other's module.
    fn meets(&self, other: &Shortcut) -> bool {
        self.topic == other.topic
            && (self.task == other.task
                || self.file == other.file
                || self.calls_into(other)
                || other.calls_into(self))
    }

    /// Whether this shortcut's code names the module of `other`'s file
    /// (`crate::de_casteljau::…` from the Bernstein task): planted in one
    /// round, it would call `other`'s planted code instead of the solution.
    fn calls_into(&self, other: &Shortcut) -> bool {
        let module = other.file.trim_end_matches(".rs");
        let code = self
            .body
            .iter()
            .chain(self.replace.iter().map(|[_, new]| new))
            .any(|text| text.contains(&format!("{module}::")));
        code && self.file != other.file
    }

    /// The solution file `source` with this shortcut planted.
    pub(crate) fn plant(&self, source: &str) -> Result<String> {
        let mut text = source.to_owned();
        if let (Some(function), Some(body)) = (&self.function, &self.body) {
            let at = [format!("fn {function}("), format!("fn {function}<")]
                .iter()
                .filter_map(|f| text.find(f.as_str()))
                .min()
                .with_context(|| format!("no `fn {function}` in {}", self.file))?;
            let begin = text[at..]
                .find(stubs::BEGIN_MARKER)
                .map(|n| at + n)
                .with_context(|| format!("`fn {function}` has no solution region"))?;
            let body_start = begin + text[begin..].find('\n').context("a marker line")? + 1;
            let end = text[body_start..]
                .find(stubs::END_MARKER)
                .map(|n| body_start + n)
                .context("a solution region without an end")?;
            let end_line = text[..end].rfind('\n').map_or(end, |n| n + 1);
            text.replace_range(body_start..end_line, body);
        }
        for [old, new] in &self.replace {
            let count = text.matches(old.as_str()).count();
            ensure!(
                count == 1,
                "`{old}` occurs {count} times in {}, not once",
                self.file
            );
            text = text.replacen(old.as_str(), new, 1);
        }
        Ok(text)
    }
}

/// The shortcuts of [`SHORTCUTS`], file by file in the order of their
/// names (none where the course has no such folder).
pub(crate) fn shortcuts(root: &Path) -> Result<Vec<Shortcut>> {
    let dir = root.join(SHORTCUTS);
    let Ok(entries) = fs::read_dir(&dir) else {
        return Ok(Vec::new());
    };
    let mut files: Vec<PathBuf> = entries
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    let mut all = Vec::new();
    for path in files {
        let text =
            fs::read_to_string(&path).with_context(|| format!("cannot read {}", path.display()))?;
        let shortcuts: Shortcuts =
            toml::from_str(&text).with_context(|| format!("cannot read {}", path.display()))?;
        all.extend(shortcuts.shortcut);
    }
    Ok(all)
}

/// Each shortcut of [`SHORTCUTS`] planted into its topic's solutions loses
/// what it must: all points of its task, or the tests named.
pub(super) fn shortcuts_lose_their_points(root: &Path) -> Result<String> {
    if !root.join(SHORTCUTS).is_dir() {
        return Ok(format!(
            "no shortcuts to plant ({SHORTCUTS} does not exist)"
        ));
    }
    let shortcuts = Shortcuts {
        shortcut: shortcuts(root)?,
    };
    // A round is one submission-like folder: the solutions of its topics
    // with shortcuts planted, no two of one task or one file, so that every
    // shortcut is graded against the solutions of its task's other files;
    // a task is graded on its own, so the shortcuts of a topic's other
    // tasks in the same round change nothing of it. A round whose topic
    // does not compile proves nothing and is reported.
    let mut problems = Vec::new();
    let mut topics = std::collections::BTreeSet::new();
    let mut duration_s = 0.0;
    let rounds = grade_planted(
        root,
        &rounds(&shortcuts.shortcut, Shortcut::meets),
        |s| (&s.topic, &s.task),
        "shortcuts",
        |number| match number {
            0 => "shortcuts".to_owned(),
            n => format!("shortcuts-{}", n + 1),
        },
        |planted, shortcut| {
            // The topic's solutions, once a round: the shortcuts planted
            // before this one in the round stay.
            let solutions = root.join("reference").join(&shortcut.topic);
            let copied = planted.join("exercises").join(&shortcut.topic).exists();
            for file in crate::files::files_under(&solutions)? {
                if copied {
                    break;
                }
                let to = Path::new("exercises").join(&shortcut.topic).join(&file);
                let text = fs::read(solutions.join(&file))
                    .with_context(|| format!("cannot read {}", solutions.join(&file).display()))?;
                crate::files::write_file(&planted.join(to), text)?;
            }
            let file = Path::new("exercises")
                .join(&shortcut.topic)
                .join("src")
                .join(&shortcut.file);
            let solution = root
                .join("reference")
                .join(&shortcut.topic)
                .join("src")
                .join(&shortcut.file);
            let source = fs::read_to_string(&solution)
                .with_context(|| format!("cannot read {}", solution.display()))?;
            let text = shortcut
                .plant(&source)
                .with_context(|| format!("cannot plant {}", shortcut.what))?;
            crate::files::write_file(&planted.join(file), text)
        },
        |round, report| {
            topics.extend(round.iter().map(|s| s.topic.clone()));
            duration_s += report.duration_s;
            for shortcut in round {
                problems.extend(shortcut.problems(report));
            }
        },
    )?;
    if !problems.is_empty() {
        bail!(
            "{} planted shortcut(s) keep points they should lose:\n  {}",
            problems.len(),
            problems.join("\n  ")
        );
    }
    Ok(format!(
        "{} shortcuts planted in {} topics ({} rounds), each loses what it must ({duration_s:.1} s)",
        shortcuts.shortcut.len(),
        topics.len(),
        rounds
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shortcut(function: Option<&str>, body: Option<&str>, replace: &[[&str; 2]]) -> Shortcut {
        Shortcut {
            what: "a shortcut".to_owned(),
            topic: "01-x".to_owned(),
            file: "x.rs".to_owned(),
            task: "x".to_owned(),
            function: function.map(str::to_owned),
            body: body.map(str::to_owned),
            replace: replace.iter().map(|p| p.map(str::to_owned)).collect(),
            zero: true,
            failing: Vec::new(),
        }
    }

    #[test]
    fn shortcuts_share_a_round_only_where_they_cannot_meet() {
        let at = |file: &str, task: &str, body: &str| Shortcut {
            file: file.to_owned(),
            task: task.to_owned(),
            ..shortcut(Some("f"), Some(body), &[])
        };
        let items = [
            at("a.rs", "a", "0"),
            at("a.rs", "a", "1"),
            at("b.rs", "b", "2"),
            at("c.rs", "c", "crate::b::f()"),
            at("d.rs", "a", "3"),
        ];
        let bodies: Vec<Vec<&str>> = super::super::rounds(&items, Shortcut::meets)
            .iter()
            .map(|round| round.iter().map(|s| s.body.as_deref().unwrap()).collect())
            .collect();
        // One task or one file apart; the one calling into b.rs apart from b's.
        assert_eq!(
            bodies,
            [vec!["0", "2"], vec!["1", "crate::b::f()"], vec!["3"]]
        );
    }

    #[test]
    fn a_shortcut_replaces_its_functions_region_or_substitutes_once() {
        let source = "\
pub fn a() -> u32 {
    // BEGIN SOLUTION x: one
    1
    // END SOLUTION
}

pub fn b<T>() -> u32 {
    // BEGIN SOLUTION x: two
    let two = 2;
    two
    // END SOLUTION
}
";
        let planted = shortcut(Some("b"), Some("    3\n"), &[])
            .plant(source)
            .unwrap();
        assert!(
            planted.contains("// BEGIN SOLUTION x: two\n    3\n    // END SOLUTION"),
            "{planted}"
        );
        assert!(
            planted.contains("    1\n"),
            "only b's region changes: {planted}"
        );
        let planted = shortcut(None, None, &[["let two = 2;", "let two = 4;"]])
            .plant(source)
            .unwrap();
        assert!(planted.contains("let two = 4;"), "{planted}");
        // What is not there, or there twice, is an error, not a silent no-op.
        assert!(
            shortcut(None, None, &[["three", "3"]])
                .plant(source)
                .is_err()
        );
        assert!(
            shortcut(None, None, &[["SOLUTION", "x"]])
                .plant(source)
                .is_err()
        );
        assert!(shortcut(Some("c"), Some("0"), &[]).plant(source).is_err());
    }

    #[test]
    fn the_courses_shortcuts_are_read_and_each_file_holds_its_topics() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
        if !root.join(SHORTCUTS).is_dir() {
            // A student edition holds no shortcuts (they are the course's).
            eprintln!("not run: no {SHORTCUTS} in this checkout");
            return;
        }
        let shortcuts = shortcuts(&root).unwrap();
        assert!(shortcuts.len() >= 29, "{} shortcuts", shortcuts.len());
        for entry in fs::read_dir(root.join(SHORTCUTS)).unwrap().flatten() {
            let path = entry.path();
            let Some(topic) = path
                .file_stem()
                .filter(|_| path.extension().is_some_and(|e| e == "toml"))
            else {
                continue;
            };
            let text = fs::read_to_string(&path).unwrap();
            let file: Shortcuts = toml::from_str(&text).unwrap();
            assert!(!file.shortcut.is_empty(), "{}", path.display());
            assert!(
                file.shortcut.iter().all(|s| *s.topic == *topic),
                "{} holds another topic's shortcut",
                path.display()
            );
        }
    }
}
