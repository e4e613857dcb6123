//! The features package of a stage: one package that depends on every
//! topic and on every topic's test dependencies, and is never built. Each
//! build of the stage names it beside what it builds, so that cargo
//! chooses the dependencies' features for the whole course whichever
//! topics a build holds.
//!
//! cargo enables a dependency's features by the packages a build names:
//! topic 01 alone gets `bytemuck` without the `derive` that topic 10's
//! `wgpu` asks for, and everything above `bytemuck` (`glam`, the course's
//! crates, every test program) is compiled again when the next build
//! names topic 10 too. Graded a topic at a time, a replay package at a
//! time, a round of the self-test's plants at a time, the same build
//! cache would otherwise hold the dependencies several times over, each
//! compiled in its turn. (The `cargo-hakari` "workspace hack" does the
//! same for a workspace of its own; cargo's `feature-unification` setting
//! is not yet stable.)
//!
//! ```text
//!   stage/features/        package `course-features`: lib.rs, empty, not
//!     Cargo.toml lib.rs    tested; depends on every topic (their own
//!                          dependencies come with them) and on their
//!                          dev-dependencies
//! ```

use std::collections::BTreeMap;
use std::fs;
use std::path::Path;

use anyhow::{Context, Result, bail};

use super::{Files, Source};
use crate::topics::Topic;

/// Where the features package lies in a stage.
pub const FEATURES_DIR: &str = "features";

/// Its name, which builds name with `--package`.
pub const FEATURES_PACKAGE: &str = "course-features";

/// Whether the stage (or checkout) at `root` holds the features package.
#[must_use]
pub fn is_in(root: &Path) -> bool {
    root.join(FEATURES_DIR).join("Cargo.toml").is_file()
}

/// Adds the features package of the course's `topics` to `files`, and
/// makes it a member of the staged workspace.
pub fn add_package(topics: &[Topic], files: &mut Files) -> Result<()> {
    if topics.is_empty() {
        return Ok(());
    }
    let home = Path::new(FEATURES_DIR);
    files.push((
        home.join("Cargo.toml"),
        Source::Text(manifest(topics)?.into()),
    ));
    files.push((
        home.join("lib.rs"),
        Source::Text(
            "//! Names every topic and its test dependencies, so that every build of the stage\n//! gets the same features of the dependencies (made by the grader).\n"
                .into(),
        ),
    ));
    super::replay::add_member(
        files,
        "The features every build of the stage gets (the grader's stage only).",
        FEATURES_DIR,
    )
}

/// The manifest: every topic by its path, and every topic's
/// dev-dependency with the features any topic asks for.
fn manifest(topics: &[Topic]) -> Result<String> {
    let mut dependencies: BTreeMap<String, toml::Value> = BTreeMap::new();
    for topic in topics {
        let path = topic.dir.join("Cargo.toml");
        let text =
            fs::read_to_string(&path).with_context(|| format!("cannot read {}", path.display()))?;
        let manifest: toml::Table =
            toml::from_str(&text).with_context(|| format!("cannot parse {}", path.display()))?;
        let mut topic_table = toml::Table::new();
        topic_table.insert("path".into(), format!("../exercises/{}", topic.name).into());
        merge(&mut dependencies, &topic.package, topic_table.into())
            .with_context(|| format!("in {}", path.display()))?;
        let dev = manifest
            .get("dev-dependencies")
            .and_then(toml::Value::as_table)
            .cloned()
            .unwrap_or_default();
        for (name, spec) in dev {
            let spec = rebased(spec, &topic.name);
            merge(&mut dependencies, &name, spec)
                .with_context(|| format!("in {}", path.display()))?;
        }
    }
    let mut lib = toml::Table::new();
    lib.insert("path".into(), "lib.rs".into());
    for kind in ["test", "doctest", "bench"] {
        lib.insert(kind.into(), false.into());
    }
    let mut package = toml::Table::new();
    package.insert("name".into(), FEATURES_PACKAGE.into());
    package.insert("version".into(), "0.0.0".into());
    package.insert(
        "description".into(),
        "The features every build of the stage gets (made by the grader).".into(),
    );
    package.insert("publish".into(), false.into());
    let mut edition = toml::Table::new();
    edition.insert("workspace".into(), true.into());
    package.insert("edition".into(), edition.into());
    let mut manifest = toml::Table::new();
    manifest.insert("package".into(), package.into());
    manifest.insert("lib".into(), lib.into());
    manifest.insert(
        "dependencies".into(),
        toml::Table::from_iter(dependencies).into(),
    );
    toml::to_string(&manifest).context("cannot write the features package's manifest")
}

/// A dependency of topic `topic` as the features package names it: a
/// `path` is the topic folder's, made the features folder's.
fn rebased(spec: toml::Value, topic: &str) -> toml::Value {
    match spec {
        toml::Value::Table(mut table) => {
            if let Some(path) = table.get("path").and_then(toml::Value::as_str) {
                let path = format!("../exercises/{topic}/{path}");
                table.insert("path".into(), path.into());
            }
            toml::Value::Table(table)
        }
        other => other,
    }
}

/// Adds `spec` for `name` to `dependencies`: where another topic named it
/// already, the features of both, default features where either has
/// them; the rest of the two must agree.
fn merge(
    dependencies: &mut BTreeMap<String, toml::Value>,
    name: &str,
    spec: toml::Value,
) -> Result<()> {
    let as_table = |spec: toml::Value| -> toml::Table {
        match spec {
            toml::Value::Table(table) => table,
            version => toml::Table::from_iter([("version".to_owned(), version)]),
        }
    };
    let Some(known) = dependencies.remove(name) else {
        dependencies.insert(name.to_owned(), toml::Value::Table(as_table(spec)));
        return Ok(());
    };
    let (mut known, new) = (as_table(known), as_table(spec));
    let features = |table: &toml::Table| -> Vec<String> {
        table
            .get("features")
            .and_then(toml::Value::as_array)
            .map(|list| {
                list.iter()
                    .filter_map(|f| f.as_str().map(str::to_owned))
                    .collect()
            })
            .unwrap_or_default()
    };
    let defaults = |table: &toml::Table| {
        table
            .get("default-features")
            .and_then(toml::Value::as_bool)
            .unwrap_or(true)
    };
    let mut all = features(&known);
    all.extend(features(&new));
    all.sort();
    all.dedup();
    let default_features = defaults(&known) || defaults(&new);
    let rest = |table: &toml::Table| -> toml::Table {
        table
            .iter()
            .filter(|(key, _)| {
                !["features", "default-features", "optional"].contains(&key.as_str())
            })
            .map(|(key, value)| (key.clone(), value.clone()))
            .collect()
    };
    if rest(&known) != rest(&new) {
        bail!("the topics name the dependency `{name}` in different ways");
    }
    if !all.is_empty() {
        known.insert("features".into(), all.into());
    }
    if !default_features {
        known.insert("default-features".into(), false.into());
    } else {
        known.remove("default-features");
    }
    dependencies.insert(name.to_owned(), toml::Value::Table(known));
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(text: &str) -> toml::Value {
        toml::Value::Table(toml::from_str(text).unwrap())
    }

    #[test]
    fn a_dependency_named_twice_gets_the_features_of_both() {
        let mut dependencies = BTreeMap::new();
        merge(&mut dependencies, "glam", table("workspace = true")).unwrap();
        merge(
            &mut dependencies,
            "glam",
            table("workspace = true\nfeatures = [\"bytemuck\"]"),
        )
        .unwrap();
        merge(
            &mut dependencies,
            "glam",
            table("workspace = true\nfeatures = [\"serde\", \"bytemuck\"]"),
        )
        .unwrap();
        assert_eq!(
            dependencies["glam"],
            table("workspace = true\nfeatures = [\"bytemuck\", \"serde\"]")
        );
        // Default features where either has them.
        merge(
            &mut dependencies,
            "image",
            table("version = \"0.25\"\ndefault-features = false"),
        )
        .unwrap();
        merge(&mut dependencies, "image", toml::Value::from("0.25")).unwrap();
        assert_eq!(dependencies["image"], table("version = \"0.25\""));
        // Two ways of naming one dependency are the course's mistake.
        let clash = merge(&mut dependencies, "glam", table("path = \"../glam\""));
        assert!(clash.unwrap_err().to_string().contains("`glam`"));
    }

    #[test]
    fn a_path_of_a_topic_is_made_the_features_folders() {
        assert_eq!(
            rebased(table("path = \"../../crates/x\""), "01-lines"),
            table("path = \"../exercises/01-lines/../../crates/x\"")
        );
        assert_eq!(
            rebased(table("workspace = true"), "01-lines"),
            table("workspace = true")
        );
    }
}
