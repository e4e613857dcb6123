//! What an edition is: the course without what only its authors need —
//! no `reference/`, no benchmarks (`xtask/bench`), no tests of the tooling
//! (`xtask/tests`, whose fixtures hold solutions), no staff's tools
//! (`xtask/src/staff`), no guides for tutors and authors (`docs/`), no CI
//! script or benchmark figures; of the topics only those chosen (with the
//! topics they build on), and of the course library only the crates they
//! need (found through their path dependencies). The root `Cargo.toml`,
//! xtask's manifest and `README.md` drop the lines between a `course only`
//! opening and closing marker (`# BEGIN COURSE ONLY` … `# END COURSE
//! ONLY`, and the same words in an HTML comment), the README its table
//! rows and layout lines of what is left out, and its test command is
//! cargo's own. The lock file is trimmed by cargo to the packages left, so
//! that a student's first build changes nothing in it.
//!
//! The grader stages an edition to grade a submission of one (and the
//! self-test to build one); the staff's `cargo xtask release` writes one to
//! a folder to push.

use std::collections::{BTreeSet, HashMap};
use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, ensure};
use serde::Deserialize;

use crate::cargo::{self, cargo};
use crate::topics::{self, Topic};

/// Where a staged file's contents come from.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub enum Source {
    /// A file to copy.
    File(PathBuf),
    /// Contents made by the tooling (a rewritten manifest).
    Text(Vec<u8>),
}

impl Source {
    /// The contents.
    pub fn read(&self) -> Result<Vec<u8>> {
        match self {
            Source::File(path) => {
                fs::read(path).with_context(|| format!("cannot read {}", path.display()))
            }
            Source::Text(text) => Ok(text.clone()),
        }
    }
}

/// The files of a tree: (path in it, contents), sorted by path.
pub type Files = Vec<(PathBuf, Source)>;

/// Paths (relative to the course root) that only the course's authors
/// need: never released.
const COURSE_ONLY: [&str; 8] = [
    ".ci",
    // The staff's tools (a class, review, similarity, the Classroom and
    // Gradescope writers, release, stubs, the self-test): an edition's
    // xtask is the student's tool and the grader.
    "xtask/src/staff",
    // The tutors' and authors' guides and the tutor notes.
    "docs",
    // The course's own workflows (the hosted macOS and Windows runs); an
    // edition gets its Classroom workflow from `--classroom`.
    ".github",
    "BENCHMARKS.md",
    "xtask/bench",
    "xtask/tests",
    // The viewer's own tests draw with the solutions.
    "xtask/viewer/tests",
];

/// The topics a `--topics` list selects: names as `cargo xtask grade`
/// takes them, or a range of numbers `01..=03` / `01..04`; empty: all.
#[cfg(feature = "staff")]
pub fn select_topics(root: &Path, wanted: &[String]) -> Result<Vec<Topic>> {
    let all = topics::discover(root)?;
    let mut names = Vec::new();
    for selector in wanted.iter().flat_map(|w| w.split(',')) {
        let selector = selector.trim();
        if let Some((from, to, inclusive)) = selector
            .split_once("..=")
            .map(|(a, b)| (a, b, true))
            .or_else(|| selector.split_once("..").map(|(a, b)| (a, b, false)))
        {
            let number = |text: &str| {
                text.trim()
                    .parse::<u32>()
                    .with_context(|| format!("`{selector}`: `{text}` is not a topic number"))
            };
            let (from, to) = (number(from)?, number(to)?);
            let in_range = |n: u32| n >= from && (n < to || (inclusive && n == to));
            let before = names.len();
            for topic in &all {
                if topic_number(topic).is_some_and(in_range) {
                    names.push(topic.name.clone());
                }
            }
            ensure!(names.len() > before, "`{selector}` selects no topic");
        } else {
            names.extend(
                topics::select(root, &[selector.to_owned()])?
                    .into_iter()
                    .map(|t| t.name),
            );
        }
    }
    // A topic that builds on another (06's framebuffer runs 05's depth and
    // stencil tests) needs it in the edition too.
    let mut todo = names.clone();
    while let Some(name) = todo.pop() {
        let Some(topic) = all.iter().find(|t| t.name == name) else {
            continue;
        };
        for needed in topic_dependencies(topic, &all)? {
            if !names.contains(&needed) {
                names.push(needed.clone());
                todo.push(needed);
            }
        }
    }
    Ok(all
        .into_iter()
        .filter(|topic| names.is_empty() || names.contains(&topic.name))
        .collect())
}

/// The other topics `topic`'s crate depends on (path dependencies into
/// `exercises/`), by folder name.
#[cfg(feature = "staff")]
fn topic_dependencies(topic: &Topic, all: &[Topic]) -> Result<Vec<String>> {
    let path = topic.dir.join("Cargo.toml");
    let text =
        fs::read_to_string(&path).with_context(|| format!("cannot read {}", path.display()))?;
    let manifest: toml::Table =
        toml::from_str(&text).with_context(|| format!("cannot read {}", path.display()))?;
    let mut found = Vec::new();
    for (_, dependency) in manifest
        .get("dependencies")
        .and_then(toml::Value::as_table)
        .into_iter()
        .flatten()
    {
        let Some(to) = dependency.get("path").and_then(toml::Value::as_str) else {
            continue;
        };
        let folder = Path::new(to).file_name().map(|f| f.to_string_lossy());
        if let Some(other) = all
            .iter()
            .find(|t| folder.as_deref() == Some(t.name.as_str()) && t.name != topic.name)
        {
            found.push(other.name.clone());
        }
    }
    Ok(found)
}

/// `01` of `01-lines`.
#[cfg(feature = "staff")]
fn topic_number(topic: &Topic) -> Option<u32> {
    topic.name.split('-').next()?.parse().ok()
}

#[derive(Deserialize)]
struct Metadata {
    packages: Vec<Package>,
}

#[derive(Deserialize)]
struct Package {
    manifest_path: PathBuf,
    dependencies: Vec<Dependency>,
}

#[derive(Deserialize)]
struct Dependency {
    #[serde(default)]
    path: Option<PathBuf>,
}

/// The folders under `crates/` that `topics` and the tooling need, directly
/// or through each other.
fn needed_crates(root: &Path, topics: &[Topic]) -> Result<Vec<String>> {
    let mut command = cargo();
    command.current_dir(root).args([
        "metadata",
        "--format-version",
        "1",
        "--no-deps",
        "--offline",
    ]);
    let output = command
        .output()
        .with_context(|| format!("cannot run `{}`", cargo::display(&command)))?;
    ensure!(
        output.status.success(),
        "`{}` failed: {}",
        cargo::display(&command),
        String::from_utf8_lossy(&output.stderr).trim()
    );
    let metadata: Metadata =
        serde_json::from_slice(&output.stdout).context("cannot read cargo's metadata")?;
    let deps: HashMap<PathBuf, Vec<PathBuf>> = metadata
        .packages
        .into_iter()
        .filter_map(|p| {
            let dir = p.manifest_path.parent()?.to_path_buf();
            Some((
                dir,
                p.dependencies.into_iter().filter_map(|d| d.path).collect(),
            ))
        })
        .collect();
    let library = root.join("crates");
    let mut todo: Vec<PathBuf> = topics.iter().map(|t| t.dir.clone()).collect();
    todo.push(root.join("xtask"));
    todo.push(root.join(VIEWER_MANIFEST).with_file_name(""));
    let mut seen = BTreeSet::new();
    let mut crates = BTreeSet::new();
    while let Some(dir) = todo.pop() {
        if !seen.insert(dir.clone()) {
            continue;
        }
        if let Ok(relative) = dir.strip_prefix(&library) {
            crates.insert(relative.to_string_lossy().into_owned());
        }
        todo.extend(deps.get(&dir).into_iter().flatten().cloned());
    }
    Ok(crates.into_iter().collect())
}

/// `text` without the lines from one containing `begin` to the next one
/// containing `end` (both included).
fn drop_marked(text: &str, begin: &str, end: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut dropping = false;
    for line in text.split_inclusive('\n') {
        if !dropping && line.contains(begin) {
            dropping = true;
        } else if dropping && line.contains(end) {
            dropping = false;
        } else if !dropping {
            out.push_str(line);
        }
    }
    out
}

/// The opening marker of a part of the README about some topics only:
/// `<!-- topics 07-bezier 08-nurbs -->`, closed by [`TOPICS_END`].
const TOPICS_BEGIN: &str = "<!-- topics ";

/// The closing marker of a [`TOPICS_BEGIN`] part.
const TOPICS_END: &str = "<!-- /topics -->";

/// `text` with its marked parts about some topics (see [`TOPICS_BEGIN`])
/// kept where one of their topics is released and dropped where none is;
/// the markers go either way.
fn keep_parts_of(text: &str, topics: &[String]) -> String {
    let mut out = String::with_capacity(text.len());
    let mut keeping = true;
    for line in text.split_inclusive('\n') {
        if let Some(names) = line
            .trim_start()
            .strip_prefix(TOPICS_BEGIN)
            .and_then(|rest| rest.trim_end().strip_suffix("-->"))
        {
            keeping = names
                .split_whitespace()
                .any(|n| topics.iter().any(|t| t == n));
        } else if line.trim() == TOPICS_END {
            keeping = true;
        } else if keeping {
            out.push_str(line);
        }
    }
    out
}

/// The root manifest of the edition.
fn manifest(text: &str, crates: &[String], all_crates: &[String]) -> String {
    let text = drop_marked(text, "# BEGIN COURSE ONLY", "# END COURSE ONLY");
    text.lines()
        .filter(|line| {
            // `gpu = { path = "crates/gpu" }` of a crate not released.
            !all_crates
                .iter()
                .any(|c| !crates.contains(c) && line.contains(&format!("path = \"crates/{c}\"")))
        })
        .map(|line| format!("{line}\n"))
        .collect()
}

/// Lines of the course's README that say something else in an edition,
/// where the test command is cargo's own.
const README_REPLACEMENTS: [(&str, &str); 2] = [
    (
        "# the project's test suite (course authors, CI)",
        "# the tests alone, as cargo shows them",
    ),
    ("cargo xtask test", "cargo test"),
];

/// The README of the edition: without the course-only parts, the parts
/// and table rows of topics not released and the layout lines of what it
/// lacks.
fn readme(text: &str, topics: &[String], all_topics: &[String], crates: &[String]) -> String {
    let text = drop_marked(text, "<!-- course only -->", "<!-- /course only -->");
    let text = keep_parts_of(&text, topics);
    let absent_topic = |line: &str| {
        line.starts_with('|')
            && all_topics
                .iter()
                .any(|t| !topics.contains(t) && line.contains(&format!("exercises/{t}/")))
    };
    let absent_layout = |line: &str| {
        line.starts_with("reference/")
            || line.starts_with("docs/")
            || line.starts_with("xtask/src/staff")
            || line.starts_with("xtask/bench")
            || line
                .strip_prefix("crates/")
                .and_then(|rest| rest.split_whitespace().next())
                .is_some_and(|name| !crates.iter().any(|c| c == name))
    };
    text.lines()
        .filter(|line| !absent_topic(line) && !absent_layout(line))
        .map(|line| {
            let line = README_REPLACEMENTS
                .iter()
                .find(|(from, _)| line == *from)
                .map_or(line, |(_, to)| *to);
            format!("{line}\n")
        })
        .collect()
}

/// Whether `path` (relative to the course) is a topic's `tasks.toml`.
fn is_task_sheet(path: &str) -> bool {
    let parts: Vec<&str> = path.split(['/', '\\']).collect();
    matches!(parts.as_slice(), ["exercises", _, "tasks.toml"])
}

/// xtask's manifest: the staff's feature is on by default in the course
/// repository only.
const XTASK_MANIFEST: &str = "xtask/Cargo.toml";

/// The viewer's manifest: its features and dependencies name the topics
/// whose stages it draws.
const VIEWER_MANIFEST: &str = "xtask/viewer/Cargo.toml";

/// The viewer's manifest for an edition of `topics`. A line marked
/// `# course only` goes; a line marked `# topic NN-name` goes when that
/// topic is not released, except that a feature keeps its name and its
/// marker with nothing in it (`lines = [] # topic 01-lines`), so that the
/// viewer still builds and draws the stage with the given code.
fn viewer_manifest(text: &str, topics: &[String]) -> String {
    let mut out = String::new();
    for line in text.lines() {
        if line.contains("# course only") {
            continue;
        }
        if let Some((code, topic)) = line.split_once("# topic ")
            && !topics.iter().any(|t| t == topic.trim())
        {
            if let Some((name, value)) = code.split_once('=')
                && value.trim().starts_with('[')
            {
                // Kept with its marker: the feature still names its topic
                // (`cargo xtask view` draws it with the given code).
                out.push_str(&format!("{} = [] # topic {}\n", name.trim(), topic.trim()));
            }
            continue;
        }
        out.push_str(line);
        out.push('\n');
    }
    out
}

/// The files of the edition of `topics` and the course-library crates it
/// holds, without its lock file (which cargo trims when writing it).
pub fn edition_files(root: &Path, topics: &[Topic]) -> Result<(Files, Vec<String>)> {
    let all_topics: Vec<String> = topics::discover(root)?
        .into_iter()
        .map(|t| t.name)
        .collect();
    let crates = needed_crates(root, topics)?;
    let library = root.join("crates");
    let all_crates: Vec<String> = if library.is_dir() {
        fs::read_dir(&library)
            .with_context(|| format!("cannot read {}", library.display()))?
            .filter_map(|e| e.ok().map(|e| e.file_name().to_string_lossy().into_owned()))
            .collect()
    } else {
        Vec::new()
    };
    let names: Vec<String> = topics.iter().map(|t| t.name.clone()).collect();
    let released = |file: &Path| {
        let mut parts = file.components().map(|c| c.as_os_str().to_string_lossy());
        let first = parts.next().unwrap_or_default();
        let second = parts.next().unwrap_or_default();
        if COURSE_ONLY.iter().any(|only| file.starts_with(only)) {
            return false;
        }
        match first.as_ref() {
            "exercises" => names.iter().any(|n| *n == second),
            "crates" => crates.iter().any(|c| *c == second),
            _ => true,
        }
    };
    let mut files = Files::new();
    for file in crate::files::files_under(root)? {
        if !released(&file) {
            continue;
        }
        let source = root.join(&file);
        let source = match file.to_str() {
            Some("Cargo.toml") => {
                Source::Text(manifest(&read(&source)?, &crates, &all_crates).into_bytes())
            }
            Some("README.md") => {
                Source::Text(readme(&read(&source)?, &names, &all_topics, &crates).into_bytes())
            }
            Some(VIEWER_MANIFEST) => {
                Source::Text(viewer_manifest(&read(&source)?, &names).into_bytes())
            }
            // A topic's hints, sealed: the edition's `cargo xtask hint` shows
            // them one at a time, and the file does not show them at all.
            Some(path) if is_task_sheet(path) => {
                Source::Text(topics::seal_hints(&read(&source)?).into_bytes())
            }
            // Without its course-only lines xtask builds without the staff's
            // feature, whose code the edition does not hold.
            Some(XTASK_MANIFEST) => Source::Text(
                drop_marked(&read(&source)?, "# BEGIN COURSE ONLY", "# END COURSE ONLY")
                    .into_bytes(),
            ),
            _ => Source::File(source),
        };
        files.push((file, source));
    }
    Ok((files, crates))
}

/// Lets cargo drop the packages the edition no longer uses from its lock
/// file, without touching the versions of the others.
pub(crate) fn trim_lock_file(dir: &Path) -> Result<()> {
    // Offline first; cargo needs the manifests of every platform's
    // packages, which a machine that never built for Windows may lack.
    let mut output = None;
    for offline in [true, false] {
        let mut command = cargo();
        command
            .current_dir(dir)
            .args(["metadata", "--format-version", "1"])
            .stdout(std::process::Stdio::null());
        if offline {
            command.arg("--offline");
        }
        let result = command
            .output()
            .with_context(|| format!("cannot run `{}`", cargo::display(&command)))?;
        let success = result.status.success();
        output = Some((command, result));
        if success {
            break;
        }
    }
    let (command, output) = output.expect("ran at least once");
    ensure!(
        output.status.success(),
        "the edition in {} does not load: `{}` failed: {}",
        dir.display(),
        cargo::display(&command),
        String::from_utf8_lossy(&output.stderr).trim()
    );
    Ok(())
}

fn read(path: &Path) -> Result<String> {
    fs::read_to_string(path).with_context(|| format!("cannot read {}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[cfg(feature = "staff")]
    #[test]
    fn a_topic_brings_the_topics_it_builds_on() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
        if !root.join("exercises/06-csg").is_dir() || !root.join("exercises/05-buffers").is_dir() {
            eprintln!("not run: this edition does not hold topics 05 and 06");
            return;
        }
        let names = |wanted: &str| -> Vec<String> {
            select_topics(root, &[wanted.to_owned()])
                .unwrap()
                .into_iter()
                .map(|t| t.name)
                .collect()
        };
        assert_eq!(names("csg"), ["05-buffers", "06-csg"]);
        assert_eq!(names("buffers"), ["05-buffers"]);
        assert_eq!(names("01..=02"), ["01-lines", "02-circles"]);
    }

    #[test]
    fn marked_lines_are_dropped_with_their_markers() {
        let text = "a\n# BEGIN COURSE ONLY\nb\n# END COURSE ONLY\nc\n";
        assert_eq!(
            drop_marked(text, "# BEGIN COURSE ONLY", "# END COURSE ONLY"),
            "a\nc\n"
        );
    }

    #[test]
    fn a_part_about_topics_stays_only_with_one_of_them() {
        let text = "a\n<!-- topics 07-bezier 08-nurbs -->\ncurves\n<!-- /topics -->\nb\n<!-- topics 10-gpu -->\ngpu\n<!-- /topics -->\n";
        assert_eq!(
            keep_parts_of(text, &["08-nurbs".to_owned()]),
            "a\ncurves\nb\n"
        );
        assert_eq!(keep_parts_of(text, &["01-lines".to_owned()]), "a\nb\n");
    }

    #[test]
    fn the_manifest_loses_crates_not_released() {
        let text = "canvas = { path = \"crates/canvas\" }\ngpu = { path = \"crates/gpu\" }\nglam = \"0.34\"\n";
        let all = ["canvas".to_owned(), "gpu".to_owned()];
        assert_eq!(
            manifest(text, &all[..1], &all),
            "canvas = { path = \"crates/canvas\" }\nglam = \"0.34\"\n"
        );
    }

    #[test]
    fn the_viewer_keeps_only_the_stages_of_released_topics() {
        let text = "[features]\ndefault = [\"lines\", \"clipping\"]\nlines = [\"dep:lines\"] # topic 01-lines\nclipping = [\"dep:clipping\"] # topic 04-clipping\n\n[dependencies]\nlines = { path = \"../../exercises/01-lines\", optional = true } # topic 01-lines\nclipping = { path = \"../../exercises/04-clipping\", optional = true } # topic 04-clipping\n\n[dev-dependencies]\negui_kittest.workspace = true # course only\n";
        let out = viewer_manifest(text, &["01-lines".to_owned()]);
        assert_eq!(
            out,
            "[features]\ndefault = [\"lines\", \"clipping\"]\nlines = [\"dep:lines\"] # topic 01-lines\nclipping = [] # topic 04-clipping\n\n[dependencies]\nlines = { path = \"../../exercises/01-lines\", optional = true } # topic 01-lines\n\n[dev-dependencies]\n"
        );
    }

    #[test]
    fn the_readme_loses_rows_of_topics_not_released() {
        let text = "| 01 | [`exercises/01-lines/README.md`](exercises/01-lines/README.md) |\n| 02 | [x](exercises/02-circles/README.md) |\ntext about exercises/02-circles/\n";
        let all = ["01-lines".to_owned(), "02-circles".to_owned()];
        assert_eq!(
            readme(text, &all[..1], &all, &[]),
            "| 01 | [`exercises/01-lines/README.md`](exercises/01-lines/README.md) |\ntext about exercises/02-circles/\n"
        );
    }
}
