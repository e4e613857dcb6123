//! The replay packages of a stage: for every topic whose passes are
//! decided by replay (`verdict = "replay"` in its sheet), a second package
//! that builds the topic's official tests against the course's own copy of
//! its crate, compiled with `--cfg transcript_replay`, where every task
//! function replays a record instead of running a body (see the
//! `transcript` crate).
//!
//! ```text
//!   stage/exercises/01-lines/      package `lines`: the graded code (the
//!     src/  tests/                 student's, the reference ...) and the tests
//!   stage/replay/01-lines/         package `lines-replay`, library `lines`:
//!     Cargo.toml build.rs          the course's own src/ (no student file),
//!     src/ tests/ (the course's)   the same tests, cfg transcript_replay
//! ```
//!
//! The package lies at another path of the stage, so cargo keeps its
//! artifacts apart from the graded package's, in the one build cache; its
//! sources are the course's whatever is graded, so they build once.

use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};

use super::{Files, Source};
use crate::files::files_under;
use crate::topics::{Topic, Verdict};

/// Where the replay packages lie in a stage.
pub const REPLAY_DIR: &str = "replay";

/// The suffix of a replay package's name (`lines` → `lines-replay`).
pub const REPLAY_SUFFIX: &str = "-replay";

/// The optimisation of the replay packages (see [`optimise`]): level 1
/// takes most of the gain for little compile time.
const REPLAY_OPT_LEVEL: u8 = 1;

/// The build script of a replay package: the `cfg` that turns every task
/// function into its replayer.
const BUILD_SCRIPT: &str = "//! Compiles the course's crate as the replayer of a recorded run.\nfn main() {\n    println!(\"cargo::rustc-cfg=transcript_replay\");\n}\n";

/// The folder of `topic`'s replay package in a stage at `stage_root`, if
/// the topic is replayed and the stage has one.
#[must_use]
pub fn package_dir(stage_root: &Path, topic: &Topic) -> Option<PathBuf> {
    let dir = stage_root.join(REPLAY_DIR).join(&topic.name);
    (topic.sheet.verdict == Verdict::Replay && dir.join("Cargo.toml").is_file()).then_some(dir)
}

/// The name of `topic`'s replay package.
#[must_use]
pub fn package_name(topic: &Topic) -> String {
    format!("{}{REPLAY_SUFFIX}", topic.package)
}

/// Adds the replay package of every replayed topic of the course at
/// `root` to `files`, and makes them members of the staged workspace.
pub fn add_packages(root: &Path, files: &mut Files) -> Result<()> {
    if !root.join("exercises").is_dir() {
        return Ok(());
    }
    let topics = crate::topics::discover(root)?;
    let replayed: Vec<&Topic> = topics
        .iter()
        .filter(|topic| topic.sheet.verdict == Verdict::Replay)
        .collect();
    if replayed.is_empty() {
        return Ok(());
    }
    for topic in &replayed {
        let home = Path::new(REPLAY_DIR).join(&topic.name);
        // The tests are copied rather than named by a path out of the
        // package (`../../exercises/..`): insta refuses to put a pending
        // snapshot under a path with `..`. The grader moves the replay's
        // pending snapshots to where the topic's own would be.
        for folder in ["src", "tests"] {
            let from = topic.dir.join(folder);
            if from.is_dir() {
                for file in files_under(&from)? {
                    files.push((home.join(folder).join(&file), Source::File(from.join(file))));
                }
            }
        }
        files.push((home.join("build.rs"), Source::Text(BUILD_SCRIPT.into())));
        files.push((
            home.join("Cargo.toml"),
            Source::Text(manifest(topic, &topics)?.into()),
        ));
    }
    add_members(files)?;
    optimise(files, &replayed)
}

/// `files` with every file of a replay package's `src/` that is not Rust
/// (topic 10's WGSL) taken from the graded package at the same place.
///
/// Such a file is data the course's code reads (`include_str!`), not code
/// that runs in the process: a shader runs on the GPU, through naga's
/// validation and wgpu's bounds checks, and cannot reach the process's
/// memory. So the replay draws with the graded shaders itself, while the
/// Rust of the graded package still reaches it only as a record.
#[must_use]
pub fn with_graded_data(files: &Files) -> Files {
    let graded = |to: &Path| -> Option<&Source> {
        let mut parts = to.components();
        let replay = parts.next()?.as_os_str() == REPLAY_DIR;
        let topic = parts.next()?.as_os_str();
        let src = parts.next()?.as_os_str() == "src";
        let rust = to.extension().is_some_and(|e| e == "rs");
        if !replay || !src || rust {
            return None;
        }
        let there = Path::new("exercises")
            .join(topic)
            .join("src")
            .join(parts.as_path());
        files
            .iter()
            .find(|(path, _)| *path == there)
            .map(|(_, source)| source)
    };
    files
        .iter()
        .map(|(to, source)| (to.clone(), graded(to).unwrap_or(source).clone()))
        .collect()
}

/// Builds the replay packages with optimisation: they hold the course's
/// code and tests only, and replaying twenty million recorded fragments
/// through unoptimised test code costs more than the drawing did.
fn optimise(files: &mut Files, replayed: &[&Topic]) -> Result<()> {
    let workspace = files
        .iter_mut()
        .find(|(to, _)| to == Path::new("Cargo.toml"))
        .context("the course has no Cargo.toml")?;
    let mut text = String::from_utf8(workspace.1.read()?).context("Cargo.toml is not UTF-8")?;
    for topic in replayed {
        text.push_str(&format!(
            "\n[profile.dev.package.{}]\nopt-level = {REPLAY_OPT_LEVEL}\n",
            package_name(topic)
        ));
    }
    workspace.1 = Source::Text(text.into_bytes());
    Ok(())
}

/// Makes the replay packages members of the staged workspace.
fn add_members(files: &mut Files) -> Result<()> {
    add_member(
        files,
        "The replay builds of the graded tests (the grader's stage only).",
        &format!("{REPLAY_DIR}/*"),
    )
}

/// Adds `member` (a folder, or a pattern of folders) to the staged
/// workspace's `members`, with `comment` above it.
pub(super) fn add_member(files: &mut Files, comment: &str, member: &str) -> Result<()> {
    let workspace = files
        .iter_mut()
        .find(|(to, _)| to == Path::new("Cargo.toml"))
        .context("the course has no Cargo.toml")?;
    let text = String::from_utf8(workspace.1.read()?).context("Cargo.toml is not UTF-8")?;
    // After the opening bracket of the workspace's `members = [` list,
    // however it is laid out.
    let list = text
        .match_indices("members")
        .filter(|(at, _)| text[..*at].ends_with('\n'))
        .find_map(|(at, _)| {
            let rest = text[at + "members".len()..].trim_start();
            let rest = rest.strip_prefix('=')?.trim_start();
            rest.starts_with('[').then(|| text.len() - rest.len() + 1)
        });
    let Some(at) = list else {
        bail!("the course's Cargo.toml has no `members = [` list to add {member} to");
    };
    let text = format!(
        "{}\n    # {comment}\n    \"{member}\",{}",
        &text[..at],
        &text[at..]
    );
    workspace.1 = Source::Text(text.into_bytes());
    Ok(())
}

/// The manifest of `topic`'s replay package: the topic's own, renamed,
/// with its library named as before (its tests are copies of the topic's),
/// and another topic it builds on (06's framebuffer runs 05's depth and
/// stencil tests) taken from that topic's replay package: the replay
/// links no student code, and the calls of that topic's task functions
/// are replayed from the same record.
fn manifest(topic: &Topic, topics: &[Topic]) -> Result<String> {
    let path = topic.dir.join("Cargo.toml");
    let text =
        fs::read_to_string(&path).with_context(|| format!("cannot read {}", path.display()))?;
    let mut manifest: toml::Table =
        toml::from_str(&text).with_context(|| format!("cannot parse {}", path.display()))?;
    let package = manifest
        .get_mut("package")
        .and_then(toml::Value::as_table_mut)
        .with_context(|| format!("{} has no [package]", path.display()))?;
    package.insert("name".into(), package_name(topic).into());
    package.insert(
        "description".into(),
        format!(
            "The replay build of {}'s tests (made by the grader).",
            topic.name
        )
        .into(),
    );
    package.insert("build".into(), "build.rs".into());
    for auto in ["autobenches", "autoexamples", "autobins"] {
        package.insert(auto.into(), false.into());
    }
    for kind in ["dependencies", "dev-dependencies", "build-dependencies"] {
        let Some(dependencies) = manifest.get_mut(kind).and_then(toml::Value::as_table_mut) else {
            continue;
        };
        for (name, dependency) in dependencies.iter_mut() {
            let Some(dependency) = dependency.as_table_mut() else {
                continue;
            };
            let Some(sibling) = dependency
                .get("path")
                .and_then(toml::Value::as_str)
                .and_then(|path| path.strip_prefix("../"))
            else {
                continue;
            };
            let Some(other) = topics.iter().find(|other| other.name == sibling) else {
                bail!(
                    "{}'s dependency `{name}` lies at ../{sibling}, which is not a topic: a replay build links no code but the course's",
                    topic.name
                );
            };
            if other.sheet.verdict != Verdict::Replay {
                bail!(
                    "{} is decided by replay and builds on {}, which is not (its sheet has no `verdict = \"replay\"`): its replay would run the student's code of {}",
                    topic.name,
                    other.name,
                    other.name
                );
            }
            dependency.insert("package".into(), package_name(other).into());
        }
    }
    let mut lib = toml::Table::new();
    lib.insert("name".into(), topic.package.replace('-', "_").into());
    lib.insert("path".into(), "src/lib.rs".into());
    manifest.insert("lib".into(), lib.into());
    manifest.remove("bench");
    toml::to_string(&manifest).context("cannot write a replay manifest")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_replay_reads_the_graded_shaders_and_only_its_own_rust() {
        let text = |t: &str| Source::Text(t.as_bytes().to_vec());
        let files: Files = vec![
            (
                "exercises/10-gpu/src/control.wgsl".into(),
                text("student's wgsl"),
            ),
            (
                "exercises/10-gpu/src/domain.rs".into(),
                text("student's rust"),
            ),
            (
                "exercises/10-gpu/tests/data.txt".into(),
                text("student's test data"),
            ),
            (
                "replay/10-gpu/src/control.wgsl".into(),
                text("course's wgsl"),
            ),
            ("replay/10-gpu/src/domain.rs".into(), text("course's rust")),
            (
                "replay/10-gpu/tests/data.txt".into(),
                text("course's test data"),
            ),
        ];
        let staged = with_graded_data(&files);
        let at = |path: &str| {
            let (_, source) = staged.iter().find(|(to, _)| to == Path::new(path)).unwrap();
            String::from_utf8(source.read().unwrap()).unwrap()
        };
        assert_eq!(at("replay/10-gpu/src/control.wgsl"), "student's wgsl");
        assert_eq!(at("replay/10-gpu/src/domain.rs"), "course's rust");
        assert_eq!(at("replay/10-gpu/tests/data.txt"), "course's test data");
        assert_eq!(staged.len(), files.len());
    }

    #[test]
    fn the_replay_packages_join_the_members_however_the_list_is_laid_out() {
        for manifest in [
            "[workspace]\nmembers = [\"exercises/*\"]\n",
            "[workspace]\nresolver = \"3\"\nmembers = [\n    \"crates/*\",\n]\ndefault-members = [\"crates/*\"]\n",
        ] {
            let mut files: Files = vec![(
                PathBuf::from("Cargo.toml"),
                Source::Text(manifest.as_bytes().to_vec()),
            )];
            add_members(&mut files).unwrap();
            let text = String::from_utf8(files[0].1.read().unwrap()).unwrap();
            let parsed: toml::Table = toml::from_str(&text).unwrap();
            let members = parsed["workspace"]["members"].as_array().unwrap();
            assert_eq!(members[0].as_str(), Some("replay/*"), "{text}");
            assert_eq!(members.len(), 2, "{text}");
            let default = parsed["workspace"].get("default-members");
            assert!(
                default.is_none_or(|d| d.as_array().unwrap().len() == 1),
                "the default members stay as they were: {text}"
            );
        }
    }
}
