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
//!     Cargo.toml lib.rs    tested; depends on what every member of the
//!                          workspace depends on (its dependencies and
//!                          dev-dependencies, each system's too), with
//!                          the features each asks for
//! ```
//!
//! Every member but the benchmarks ([`BENCHMARKS`], built only by `cargo
//! xtask bench`): the grader and the viewer too, so that the course's own
//! `cargo test` of the stage gets the same features as its grades. A
//! member's optional dependencies count where its default features turn
//! them on (the viewer's window).

use std::collections::BTreeMap;
use std::path::Path;

use anyhow::{Context, Result};

use super::{Files, Source};

/// Where the features package lies in a stage.
pub const FEATURES_DIR: &str = "features";

/// Its name, which builds name with `--package`.
pub const FEATURES_PACKAGE: &str = "course-features";

/// The benchmarks' package, whose features count for no build of a grade.
pub const BENCHMARKS: &str = "course-bench";

/// Whether the stage (or checkout) at `root` holds the features package.
#[must_use]
pub fn is_in(root: &Path) -> bool {
    root.join(FEATURES_DIR).join("Cargo.toml").is_file()
}

/// Adds the features package of the staged `files` (the manifests as the
/// stage holds them: an edition's, without the course's own lines) to
/// them, and makes it a member of the staged workspace. A workspace
/// without a `members` list (a single package) gets none.
pub fn add_package(files: &mut Files) -> Result<()> {
    let Some(members) = members(files)? else {
        return Ok(());
    };
    let manifest = manifest(files, &members)?;
    let home = Path::new(FEATURES_DIR);
    files.push((home.join("Cargo.toml"), Source::Text(manifest.into())));
    files.push((
        home.join("lib.rs"),
        Source::Text(
            "//! Names what every member of the workspace depends on, so that every build of the\n//! stage gets the same features of the dependencies (made by the grader).\n"
                .into(),
        ),
    ));
    super::replay::add_member(
        files,
        "The features every build of the stage gets (the grader's stage only).",
        FEATURES_DIR,
    )
}

/// The staged file at `path`, parsed as TOML; `None` where there is none.
fn staged_toml(files: &Files, path: &Path) -> Result<Option<toml::Table>> {
    let Some((_, source)) = files.iter().find(|(to, _)| to == path) else {
        return Ok(None);
    };
    let text = String::from_utf8(source.read()?)
        .with_context(|| format!("{} is not UTF-8", path.display()))?;
    toml::from_str(&text)
        .map(Some)
        .with_context(|| format!("cannot parse {}", path.display()))
}

/// The folders of the members of the staged workspace (its `members`, a
/// `dir/*` pattern read as the folders in `dir` with a manifest); `None`
/// where it lists none.
fn members(files: &Files) -> Result<Option<Vec<String>>> {
    let Some(workspace) = staged_toml(files, Path::new("Cargo.toml"))? else {
        return Ok(None);
    };
    let Some(listed) = workspace
        .get("workspace")
        .and_then(|w| w.get("members"))
        .and_then(toml::Value::as_array)
    else {
        return Ok(None);
    };
    let mut members = Vec::new();
    // (The replay packages are the topics again, built apart.)
    let replays = format!("{}/", super::replay::REPLAY_DIR);
    for member in listed
        .iter()
        .filter_map(toml::Value::as_str)
        .filter(|member| !member.starts_with(&replays))
    {
        match member.strip_suffix("/*") {
            Some(dir) => {
                let mut found: Vec<String> = files
                    .iter()
                    .filter_map(|(to, _)| {
                        let rest = to.strip_prefix(dir).ok()?;
                        let mut parts = rest.components();
                        let name = parts.next()?.as_os_str().to_str()?;
                        (parts.as_path() == Path::new("Cargo.toml"))
                            .then(|| format!("{dir}/{name}"))
                    })
                    .collect();
                found.sort();
                members.extend(found);
            }
            None => members.push(member.to_owned()),
        }
    }
    Ok(Some(members))
}

/// The dependencies a manifest's default features turn on (`dep:x`, or an
/// optional `x` named as a feature), each with the features they ask of it
/// (`x/feature`).
fn enabled_by_default(manifest: &toml::Table) -> BTreeMap<String, Vec<String>> {
    let features = manifest
        .get("features")
        .and_then(toml::Value::as_table)
        .cloned()
        .unwrap_or_default();
    let mut enabled: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut seen = std::collections::BTreeSet::new();
    let mut to_visit = vec!["default".to_owned()];
    while let Some(feature) = to_visit.pop() {
        if !seen.insert(feature.clone()) {
            continue;
        }
        let Some(entries) = features.get(&feature).and_then(toml::Value::as_array) else {
            // Not a feature: an optional dependency's implicit one.
            enabled.entry(feature).or_default();
            continue;
        };
        for entry in entries.iter().filter_map(toml::Value::as_str) {
            if let Some(dep) = entry.strip_prefix("dep:") {
                enabled.entry(dep.to_owned()).or_default();
            } else if let Some((dep, feature)) = entry.split_once('/') {
                if let Some(dep) = dep.strip_suffix('?') {
                    // Only where the dependency is on for another reason.
                    if enabled.contains_key(dep) {
                        enabled
                            .entry(dep.to_owned())
                            .or_default()
                            .push(feature.to_owned());
                    }
                } else {
                    enabled
                        .entry(dep.to_owned())
                        .or_default()
                        .push(feature.to_owned());
                }
            } else {
                to_visit.push(entry.to_owned());
            }
        }
    }
    enabled
}

/// The manifest: what every member (but the benchmarks) depends on, each
/// system's dependencies under that system's `target` table.
fn manifest(files: &Files, members: &[String]) -> Result<String> {
    let mut dependencies: BTreeMap<String, toml::Value> = BTreeMap::new();
    let mut targets: BTreeMap<String, BTreeMap<String, toml::Value>> = BTreeMap::new();
    for member in members {
        let Some(manifest) = staged_toml(files, &Path::new(member).join("Cargo.toml"))? else {
            continue;
        };
        let name = manifest
            .get("package")
            .and_then(|p| p.get("name"))
            .and_then(toml::Value::as_str);
        if name == Some(BENCHMARKS) || name.is_none() {
            continue;
        }
        let by_default = enabled_by_default(&manifest);
        let tables = |table: &toml::Table| -> Vec<(String, toml::Value)> {
            ["dependencies", "dev-dependencies"]
                .iter()
                .filter_map(|kind| table.get(*kind).and_then(toml::Value::as_table))
                .flat_map(|deps| deps.iter().map(|(k, v)| (k.clone(), v.clone())))
                .filter_map(|(name, spec)| {
                    let optional =
                        spec.get("optional").and_then(toml::Value::as_bool) == Some(true);
                    let features = by_default.get(&name);
                    if optional && features.is_none() {
                        return None;
                    }
                    let mut spec = spec;
                    if let (Some(features), toml::Value::Table(table)) = (features, &mut spec)
                        && !features.is_empty()
                    {
                        let mut all: Vec<toml::Value> = table
                            .get("features")
                            .and_then(toml::Value::as_array)
                            .cloned()
                            .unwrap_or_default();
                        all.extend(features.iter().map(|f| toml::Value::from(f.as_str())));
                        table.insert("features".into(), all.into());
                    }
                    Some((name, spec))
                })
                .collect()
        };
        for (name, spec) in tables(&manifest) {
            merge(&mut dependencies, &name, rebased(spec, member));
        }
        let system_tables = manifest
            .get("target")
            .and_then(toml::Value::as_table)
            .cloned()
            .unwrap_or_default();
        for (system, table) in system_tables {
            let Some(table) = table.as_table() else {
                continue;
            };
            for (name, spec) in tables(table) {
                merge(
                    targets.entry(system.clone()).or_default(),
                    &name,
                    rebased(spec, member),
                );
            }
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
    let mut target = toml::Table::new();
    for (system, deps) in targets {
        let mut table = toml::Table::new();
        table.insert("dependencies".into(), toml::Table::from_iter(deps).into());
        target.insert(system, table.into());
    }
    if !target.is_empty() {
        manifest.insert("target".into(), target.into());
    }
    toml::to_string(&manifest).context("cannot write the features package's manifest")
}

/// A dependency of the member in folder `member` as the features package
/// names it: a `path` is the member's, made the features folder's.
fn rebased(spec: toml::Value, member: &str) -> toml::Value {
    match spec {
        toml::Value::Table(mut table) => {
            if let Some(path) = table.get("path").and_then(toml::Value::as_str) {
                let path = format!("../{member}/{path}");
                table.insert("path".into(), path.into());
            }
            toml::Value::Table(table)
        }
        other => other,
    }
}

/// Adds `spec` for `name` to `dependencies`: where another member named
/// it already, the first's way of naming it (a version, the workspace's,
/// a path: the one package either way) with the features of both, and
/// default features where either has them.
fn merge(dependencies: &mut BTreeMap<String, toml::Value>, name: &str, spec: toml::Value) {
    let as_table = |spec: toml::Value| -> toml::Table {
        match spec {
            toml::Value::Table(mut table) => {
                table.remove("optional");
                table
            }
            version => toml::Table::from_iter([("version".to_owned(), version)]),
        }
    };
    let Some(known) = dependencies.remove(name) else {
        dependencies.insert(name.to_owned(), toml::Value::Table(as_table(spec)));
        return;
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
    if !all.is_empty() {
        known.insert("features".into(), all.into());
    }
    if defaults(&known) || defaults(&new) {
        known.remove("default-features");
    }
    dependencies.insert(name.to_owned(), toml::Value::Table(known));
}

#[cfg(test)]
mod tests {
    use std::path::PathBuf;

    use super::*;

    fn table(text: &str) -> toml::Value {
        toml::Value::Table(toml::from_str(text).unwrap())
    }

    #[test]
    fn a_dependency_named_twice_gets_the_features_of_both() {
        let mut dependencies = BTreeMap::new();
        merge(&mut dependencies, "glam", table("workspace = true"));
        merge(
            &mut dependencies,
            "glam",
            table("workspace = true\nfeatures = [\"bytemuck\"]"),
        );
        merge(
            &mut dependencies,
            "glam",
            table("workspace = true\nfeatures = [\"serde\", \"bytemuck\"]"),
        );
        assert_eq!(
            dependencies["glam"],
            table("workspace = true\nfeatures = [\"bytemuck\", \"serde\"]")
        );
        // Default features where either has them.
        merge(
            &mut dependencies,
            "image",
            table("version = \"0.25\"\ndefault-features = false"),
        );
        merge(&mut dependencies, "image", toml::Value::from("0.25"));
        assert_eq!(dependencies["image"], table("version = \"0.25\""));
        // Named another way: the first way, the features of both.
        merge(
            &mut dependencies,
            "syn",
            table("version = \"2\"\ndefault-features = false\nfeatures = [\"full\"]"),
        );
        merge(
            &mut dependencies,
            "syn",
            table("workspace = true\ndefault-features = false\nfeatures = [\"parsing\"]"),
        );
        assert_eq!(
            dependencies["syn"],
            table("version = \"2\"\ndefault-features = false\nfeatures = [\"full\", \"parsing\"]")
        );
    }

    #[test]
    fn a_path_of_a_member_is_made_the_features_folders() {
        assert_eq!(
            rebased(table("path = \"../../crates/x\""), "exercises/01-lines"),
            table("path = \"../exercises/01-lines/../../crates/x\"")
        );
        assert_eq!(
            rebased(table("workspace = true"), "exercises/01-lines"),
            table("workspace = true")
        );
    }

    #[test]
    fn the_course_s_members_but_the_benchmarks_are_named() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
        let files = crate::stage::edition_plan(root, crate::stage::Overlay::Own).unwrap();
        let members = members(&files).unwrap().unwrap();
        assert!(
            members.contains(&"exercises/01-lines".to_owned()),
            "{members:?}"
        );
        assert!(members.contains(&"xtask/viewer".to_owned()), "{members:?}");
        let manifest: toml::Table = toml::from_str(&manifest(&files, &members).unwrap()).unwrap();
        let dependencies = manifest["dependencies"].as_table().unwrap();
        // A topic's, the grader's, the viewer's, a test's; not the benchmarks'.
        for name in ["glam", "proptest", "clap", "eframe", "approx"] {
            assert!(dependencies.contains_key(name), "{name}: {dependencies:?}");
        }
        assert!(!dependencies.contains_key("criterion"), "{dependencies:?}");
        // An optional dependency no default feature turns on is left out.
        let by_default = enabled_by_default(
            &toml::from_str("[features]\ndefault = [\"window\"]\nwindow = [\"dep:eframe\", \"wgpu/dx12\"]\nextra = [\"dep:lz4\"]\n").unwrap(),
        );
        assert_eq!(by_default["wgpu"], ["dx12"]);
        assert!(by_default.contains_key("eframe") && !by_default.contains_key("lz4"));
    }

    #[test]
    fn the_features_of_a_staged_edition_are_its_own() {
        // An edition's workspace names no course-only dependency: neither
        // may the features package built from it.
        let files: Files = vec![
            (
                PathBuf::from("Cargo.toml"),
                Source::Text(b"[workspace]\nmembers = [\"exercises/*\"]\n".to_vec()),
            ),
            (
                PathBuf::from("exercises/01-x/Cargo.toml"),
                Source::Text(
                    b"[package]\nname = \"x\"\n[dev-dependencies]\nglam.workspace = true\n"
                        .to_vec(),
                ),
            ),
            (
                PathBuf::from("exercises/01-x/src/lib.rs"),
                Source::Text(Vec::new()),
            ),
        ];
        let members = members(&files).unwrap().unwrap();
        assert_eq!(members, ["exercises/01-x"]);
        let manifest: toml::Table = toml::from_str(&manifest(&files, &members).unwrap()).unwrap();
        let dependencies = manifest["dependencies"].as_table().unwrap();
        assert_eq!(dependencies.keys().collect::<Vec<_>>(), ["glam"]);
    }
}
