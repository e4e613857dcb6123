//! Topics: the exercise crates under `exercises/` and their task sheets.
//!
//! A topic is a folder `exercises/NN-topic/` holding a cargo package (its
//! name is read from `Cargo.toml`), a task sheet `README.md` that starts
//! with its title, and beside it `tasks.toml`, the only place the tasks,
//! their points and their hints live:
//!
//! ```text
//! time_limit_s = 20          # optional: per-test wall-clock limit (default 20)
//! memory_limit_mib = 4096    # optional: per-test memory: each process's address space, and all its processes together where cgroups can be made (default 4096)
//! gpu = false                # optional: the topic needs a GPU adapter (see `setup`)
//! [[tasks]]
//! id = "dda"
//! title = "DDA with colour and depth interpolation"
//! points = 3
//! bonus = false              # optional: bonus points do not count in the maximum
//! hints = ["the goal", "the key step", "the exact rule"]   # optional: `cargo xtask hint dda`
//! ```

use std::collections::HashSet;
use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail, ensure};
use serde::{Deserialize, Serialize};

/// Per-test wall-clock limit when the task sheet gives none.
pub const DEFAULT_TIME_LIMIT_S: f64 = 20.0;
/// Per-test address-space limit when the task sheet gives none: generous
/// for rasterizers, small enough that a runaway allocation fails at once.
pub const DEFAULT_MEMORY_LIMIT_MIB: u64 = 4096;
/// The file beside a topic's sheet that lists its tasks.
pub const TASKS_FILE: &str = "tasks.toml";

/// One exercise crate.
#[derive(Debug, Clone)]
pub struct Topic {
    /// Folder name, e.g. `01-lines`.
    pub name: String,
    /// Cargo package name, e.g. `lines`.
    pub package: String,
    /// `<root>/exercises/01-lines`.
    pub dir: PathBuf,
    /// The topic's tasks and limits (`tasks.toml`).
    pub sheet: TaskSheet,
}

/// The tasks and limits of a topic: `exercises/NN-topic/tasks.toml`.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct TaskSheet {
    /// Per-test wall-clock limit in seconds.
    #[serde(default = "default_time_limit")]
    pub time_limit_s: f64,
    /// Per-test address-space limit in MiB (`0` switches it off).
    #[serde(default = "default_memory_limit")]
    pub memory_limit_mib: u64,
    /// The topic runs on the GPU: grading and testing it first make sure a
    /// Vulkan driver is installed (see `setup`), and its tests treat a
    /// missing adapter as a failure when graded.
    #[serde(default)]
    pub gpu: bool,
    /// Whether a pass is decided by replay (`verdict = "replay"`): every
    /// task function carries `#[transcript::task]`, and a staged grade runs
    /// each test twice, recording the student's code and replaying the
    /// record in a build without it (see `grade::run`). Otherwise
    /// (`"token"`, the default) the test process that ran the student's
    /// code prints the grader's token itself.
    #[serde(default)]
    pub verdict: Verdict,
    /// The tasks, in the order of the sheet.
    pub tasks: Vec<Task>,
}

fn default_time_limit() -> f64 {
    DEFAULT_TIME_LIMIT_S
}

fn default_memory_limit() -> u64 {
    DEFAULT_MEMORY_LIMIT_MIB
}

/// Where a topic's passes are decided (see [`TaskSheet::verdict`]).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Verdict {
    /// In the process that ran the student's code, authenticated by a
    /// token that process holds.
    #[default]
    Token,
    /// In a second process that replays the record of the first and never
    /// ran the student's code.
    Replay,
}

/// One task of a topic; its tests are `tests/<id>.rs`.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Task {
    /// Task id: the name of its test binary and the prefix of its `todo!`s.
    pub id: String,
    /// One-line title for tables.
    pub title: String,
    /// Full points for the task.
    pub points: f64,
    /// Bonus points count in the score but not in the maximum.
    #[serde(default)]
    pub bonus: bool,
    /// Hints, shown one more each time by `cargo xtask hint`: the first
    /// restates the goal, the last points at the exact rule.
    #[serde(default)]
    pub hints: Vec<String>,
}

impl TaskSheet {
    /// Parses a topic's `tasks.toml`.
    pub fn parse(text: &str) -> Result<Self> {
        let mut sheet: TaskSheet = toml::from_str(text).context("invalid task list")?;
        for task in &mut sheet.tasks {
            for hint in &mut task.hints {
                if let Some(sealed) = hint.strip_prefix(SEALED) {
                    *hint = unseal(sealed)
                        .with_context(|| format!("task `{}` has a broken sealed hint", task.id))?;
                }
            }
        }
        sheet.validate()?;
        Ok(sheet)
    }

    fn validate(&self) -> Result<()> {
        ensure!(!self.tasks.is_empty(), "it lists no [[tasks]]");
        ensure!(
            self.time_limit_s.is_finite() && self.time_limit_s > 0.0,
            "time_limit_s must be a positive number of seconds"
        );
        let mut seen = HashSet::new();
        for task in &self.tasks {
            ensure!(
                !task.id.is_empty()
                    && task
                        .id
                        .chars()
                        .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-'),
                "task id `{}` must be a non-empty test file name (letters, digits, `_`, `-`)",
                task.id
            );
            ensure!(
                seen.insert(task.id.as_str()),
                "task id `{}` is listed twice",
                task.id
            );
            ensure!(
                task.points.is_finite() && task.points >= 0.0,
                "task `{}` has invalid points {}",
                task.id,
                task.points
            );
        }
        Ok(())
    }

    /// Task ids, comma separated, for error messages.
    #[must_use]
    pub fn task_ids(&self) -> String {
        let ids: Vec<&str> = self.tasks.iter().map(|t| t.id.as_str()).collect();
        ids.join(", ")
    }
}

impl Topic {
    /// Reads the topic in `dir` (`exercises/NN-topic`).
    pub fn load(dir: &Path) -> Result<Self> {
        let name = dir
            .file_name()
            .context("a topic folder has a name")?
            .to_string_lossy()
            .into_owned();
        let manifest_path = dir.join("Cargo.toml");
        let manifest = fs::read_to_string(&manifest_path)
            .with_context(|| format!("cannot read {}", manifest_path.display()))?;
        let package = package_name(&manifest).with_context(|| {
            format!(
                "cannot read the package name in {}",
                manifest_path.display()
            )
        })?;
        let tasks_path = dir.join(TASKS_FILE);
        let text = fs::read_to_string(&tasks_path).with_context(|| {
            format!(
                "cannot read {} (it lists the topic's tasks, points and hints)",
                tasks_path.display()
            )
        })?;
        let sheet =
            TaskSheet::parse(&text).with_context(|| format!("in {}", tasks_path.display()))?;
        Ok(Self {
            name,
            package,
            dir: dir.to_path_buf(),
            sheet,
        })
    }

    /// The folder name without its number: `lines` for `01-lines`.
    #[must_use]
    pub fn short_name(&self) -> &str {
        match self.name.split_once('-') {
            Some((number, rest)) if number.chars().all(|c| c.is_ascii_digit()) => rest,
            _ => &self.name,
        }
    }

    /// Whether the user's `TOPIC` argument names this topic: the folder
    /// name, the folder name without its number, the package name or the
    /// number alone (`01`, `1`).
    #[must_use]
    pub fn matches(&self, wanted: &str) -> bool {
        let number = self.name.split('-').next().unwrap_or_default();
        wanted == self.name
            || wanted == self.short_name()
            || wanted == self.package
            || (!wanted.is_empty()
                && wanted.chars().all(|c| c.is_ascii_digit())
                && number.trim_start_matches('0') == wanted.trim_start_matches('0'))
    }
}

fn package_name(manifest: &str) -> Result<String> {
    #[derive(Deserialize)]
    struct Manifest {
        package: Package,
    }
    #[derive(Deserialize)]
    struct Package {
        name: String,
    }
    let manifest: Manifest = toml::from_str(manifest)?;
    Ok(manifest.package.name)
}

/// All topics of the checkout at `root`, in course order (folder names).
pub fn discover(root: &Path) -> Result<Vec<Topic>> {
    let exercises = root.join("exercises");
    let entries = fs::read_dir(&exercises)
        .with_context(|| format!("cannot list the topics in {}", exercises.display()))?;
    let mut dirs = Vec::new();
    for entry in entries {
        let path = entry
            .with_context(|| format!("cannot list {}", exercises.display()))?
            .path();
        if path.join("Cargo.toml").is_file() {
            dirs.push(path);
        }
    }
    dirs.sort();
    dirs.iter().map(|dir| Topic::load(dir)).collect()
}

/// The topics the user asked for (all when `wanted` is empty), in course
/// order; an unknown name is an error that lists the topics there are.
pub fn select(root: &Path, wanted: &[String]) -> Result<Vec<Topic>> {
    let all = discover(root)?;
    if wanted.is_empty() {
        return Ok(all);
    }
    for name in wanted {
        if !all.iter().any(|topic| topic.matches(name)) {
            let known: Vec<String> = all
                .iter()
                .map(|t| format!("{} ({})", t.name, t.package))
                .collect();
            bail!(
                "unknown topic `{name}`; the topics in {} are: {}",
                root.join("exercises").display(),
                if known.is_empty() {
                    "none".to_owned()
                } else {
                    known.join(", ")
                }
            );
        }
    }
    Ok(all
        .into_iter()
        .filter(|topic| wanted.iter().any(|name| topic.matches(name)))
        .collect())
}

/// The prefix of a hint as an edition's `tasks.toml` holds it: the hint's
/// UTF-8 bytes in hexadecimal, so that opening the file shows no hint and
/// reading ahead is a deliberate act (`cargo xtask hint --all`); the
/// course's own `tasks.toml` keeps them plain for its authors.
pub const SEALED: &str = "sealed:";

/// A hint sealed ([`SEALED`] and its bytes in hexadecimal).
#[must_use]
pub fn seal(hint: &str) -> String {
    use std::fmt::Write as _;
    let mut sealed = String::from(SEALED);
    for byte in hint.bytes() {
        let _ = write!(sealed, "{byte:02x}");
    }
    sealed
}

/// The hint whose bytes `hex` spells.
fn unseal(hex: &str) -> Result<String> {
    ensure!(
        hex.len().is_multiple_of(2),
        "an odd number of hexadecimal digits"
    );
    let bytes = (0..hex.len())
        .step_by(2)
        .map(|i| u8::from_str_radix(&hex[i..i + 2], 16))
        .collect::<Result<Vec<u8>, _>>()
        .context("not hexadecimal")?;
    String::from_utf8(bytes).context("not UTF-8")
}

/// `text`, a `tasks.toml`, with each hint sealed ([`seal`]): every line of
/// a `hints = [ … ]` array that holds one string. Everything else —
/// comments, ids, points — stays as written.
#[must_use]
pub fn seal_hints(text: &str) -> String {
    let mut out = String::with_capacity(text.len() * 2);
    let mut in_hints = false;
    for line in text.split_inclusive('\n') {
        let trimmed = line.trim();
        if trimmed.starts_with("hints = [") {
            in_hints = !trimmed.ends_with(']');
        } else if in_hints && trimmed.starts_with(']') {
            in_hints = false;
        } else if in_hints && trimmed.starts_with('"') {
            let literal = trimmed.trim_end_matches(',');
            if let Ok(value) = toml::from_str::<toml::Table>(&format!("x = {literal}"))
                && let Some(hint) = value.get("x").and_then(toml::Value::as_str)
            {
                let indent = &line[..line.len() - line.trim_start().len()];
                let comma = if trimmed.ends_with(',') { "," } else { "" };
                let newline = if line.ends_with('\n') { "\n" } else { "" };
                out.push_str(&format!("{indent}\"{}\"{comma}{newline}", seal(hint)));
                continue;
            }
        }
        out.push_str(line);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    const SHEET: &str = "time_limit_s = 3\n[[tasks]]\nid = \"dda\"\ntitle = \"DDA\"\npoints = 3\n[[tasks]]\nid = \"wu\"\ntitle = \"Wu\"\npoints = 1.5\nbonus = true\n";

    #[test]
    fn sealed_hints_read_as_the_plain_ones() {
        let plain = "# The tasks.\ntime_limit_s = 10\n\n[[tasks]]\nid = \"dda\"\ntitle = \"DDA\"\npoints = 4\nhints = [\n    \"Goal: «draw» the line, `d = 2Δy − Δx`.\",\n    \"Then \\\"quote\\\" it.\",\n]\n";
        let sealed = seal_hints(plain);
        assert!(
            !sealed.contains("Goal") && sealed.contains("# The tasks."),
            "{sealed}"
        );
        assert_eq!(
            TaskSheet::parse(&sealed).unwrap().tasks[0].hints,
            TaskSheet::parse(plain).unwrap().tasks[0].hints
        );
        assert!(TaskSheet::parse(&plain.replace("Goal", "")).is_ok());
        assert!(unseal("e4b").is_err() && unseal("zz").is_err());
    }

    #[test]
    fn the_task_list_gives_tasks_points_and_limits() {
        let sheet = TaskSheet::parse(SHEET).unwrap();
        assert_eq!(sheet.time_limit_s, 3.0);
        assert_eq!(sheet.memory_limit_mib, DEFAULT_MEMORY_LIMIT_MIB);
        assert_eq!(sheet.task_ids(), "dda, wu");
        assert_eq!(sheet.tasks[0].points, 3.0);
        assert!(!sheet.tasks[0].bonus);
        assert_eq!(sheet.tasks[1].points, 1.5);
        assert!(sheet.tasks[1].bonus);
    }

    #[test]
    fn time_limit_defaults() {
        let sheet = TaskSheet::parse("[[tasks]]\nid = \"a\"\ntitle = \"A\"\npoints = 1\n").unwrap();
        assert_eq!(sheet.time_limit_s, DEFAULT_TIME_LIMIT_S);
    }

    #[test]
    fn a_bad_task_list_is_an_error() {
        assert!(TaskSheet::parse("# Topic 01\n").is_err(), "no tasks");
        assert!(
            TaskSheet::parse("+++\n[[tasks]]\nid = \"a\"\ntitle = \"A\"\npoints = 1\n+++\n")
                .is_err()
        );
        let twice = "[[tasks]]\nid = \"a\"\ntitle = \"A\"\npoints = 1\n[[tasks]]\nid = \"a\"\ntitle = \"B\"\npoints = 1\n";
        assert!(format!("{:#}", TaskSheet::parse(twice).unwrap_err()).contains("twice"));
        let typo = "[[tasks]]\nid = \"a\"\ntitle = \"A\"\npoint = 1\n";
        assert!(TaskSheet::parse(typo).is_err());
    }

    #[test]
    fn topic_names_match_folder_suffix_package_and_number() {
        let topic = Topic {
            name: "01-lines".into(),
            package: "raster-lines".into(),
            dir: PathBuf::new(),
            sheet: TaskSheet::parse(SHEET).unwrap(),
        };
        for name in ["01-lines", "lines", "raster-lines", "01", "1"] {
            assert!(topic.matches(name), "{name}");
        }
        for name in ["02", "line", "", "01-line"] {
            assert!(!topic.matches(name), "{name}");
        }
    }

    #[test]
    fn every_task_of_the_course_has_hints_from_the_goal_to_the_rule() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
        for topic in discover(&root).unwrap() {
            for task in &topic.sheet.tasks {
                assert!(
                    (2..=4).contains(&task.hints.len()),
                    "{}/{} has {} hints in its sheet (2 to 4: the goal first, the exact rule last)",
                    topic.name,
                    task.id,
                    task.hints.len()
                );
                for hint in &task.hints {
                    assert!(
                        hint.len() > 20 && !hint.contains("```"),
                        "{}/{}: a hint is a sentence or two, not code: {hint:?}",
                        topic.name,
                        task.id
                    );
                }
            }
        }
    }
}
