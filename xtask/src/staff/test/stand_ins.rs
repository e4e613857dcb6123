//! Given code stands in for no task (step 9): every public function of the
//! given code with a task's signature, and every method of the given code
//! with a task method's name or signature, planted into that task's stub,
//! scores 0.

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};

use crate::stage;
use crate::topics;

use super::{grade_planted, rounds};

/// A given function with a task's signature, and how it gets into the
/// task's file.
pub(super) struct StandIn {
    topic: String,
    task: String,
    /// The task file, relative to the course.
    file: PathBuf,
    /// The given function: `crates/canvas/src/lib.rs: round`.
    given: String,
    /// The stub with the given function planted in.
    planted: String,
}

/// Every public function of the given code (library crates, and files of
/// exercise crates that hold no task) whose signature is a task's, planted
/// into that task's stub, scores 0 there (see `stubs::stand_ins`).
pub(super) fn given_code_stands_in_for_no_task(root: &Path) -> Result<String> {
    let (stand_ins, given, uncallable) = find_stand_ins(root)?;
    if stand_ins.is_empty() {
        return Ok(format!(
            "none of the {given} public functions and methods of the given code has a task's signature or a task method's name"
        ));
    }
    // A round holds at most one stand-in per topic, so that one that does
    // not compile where planted hides no other.
    let mut problems = Vec::new();
    let mut not_compiling = Vec::new();
    grade_planted(
        root,
        &rounds(&stand_ins, |a, b| a.topic == b.topic),
        |s| (&s.topic, &s.task),
        "stand-ins",
        |number| format!("stand-ins-{}", number + 1),
        |planted, stand_in| {
            crate::files::write_file(&planted.join(&stand_in.file), &stand_in.planted)
        },
        |round, report| {
            for stand_in in round {
                let topic = report.topics.iter().find(|t| t.name == stand_in.topic);
                let task = topic
                    .into_iter()
                    .flat_map(|t| &t.tasks)
                    .find(|t| t.id == stand_in.task);
                match (topic, task) {
                    (Some(topic), _) if topic.compile_error.is_some() => {
                        not_compiling.push(format!("{} in {}", stand_in.given, stand_in.topic));
                    }
                    (_, Some(task)) if task.score > 0.0 => problems.push(format!(
                        "{} scores {} of {} points in place of {} / {}",
                        stand_in.given, task.score, task.points, stand_in.topic, stand_in.task
                    )),
                    (_, Some(_)) => {}
                    _ => problems.push(format!(
                        "{}: no task {} / {} in the report",
                        stand_in.given, stand_in.topic, stand_in.task
                    )),
                }
            }
        },
    )?;
    if !problems.is_empty() {
        bail!(
            "{} given function(s) or method(s) solve a task (given code must not: replace them, or make the task's tests tell them apart):\n  {}",
            problems.len(),
            problems.join("\n  ")
        );
    }
    let mut summary = format!(
        "{} given function(s) with a task's signature or method(s) with a task method's name or signature planted in, each scores 0",
        stand_ins.len()
    );
    if !not_compiling.is_empty() {
        let _ = write!(
            summary,
            "; {} of them do not compile where planted as they are: {}",
            not_compiling.len(),
            not_compiling.join(", ")
        );
    }
    if uncallable > 0 {
        let _ = write!(summary, "; {uncallable} take parameters they drop");
    }
    Ok(summary)
}

/// The given code's public functions with a task's signature, planted into
/// the task's stub; also how many given functions there are, and how many
/// stand-ins could not be planted (a pattern such as `_` drops a value).
pub(super) fn find_stand_ins(root: &Path) -> Result<(Vec<StandIn>, usize, usize)> {
    use crate::staff::stubs::stand_ins::{
        Function, Method, methods, plant, plant_method, public_functions,
    };
    let read = |path: &Path| {
        fs::read_to_string(root.join(path))
            .with_context(|| format!("cannot read {}", root.join(path).display()))
    };
    let topics = topics::discover(root)?;
    let task_files = stage::task_files(root)?;
    // Given files: (crate dir, file relative to the course, package name).
    let mut given_files: Vec<(PathBuf, PathBuf, String)> = Vec::new();
    let libraries = root.join("crates");
    let mut crate_dirs: Vec<(PathBuf, String)> = topics
        .iter()
        .map(|t| (Path::new("exercises").join(&t.name), t.package.clone()))
        .collect();
    if libraries.is_dir() {
        for entry in fs::read_dir(&libraries).context("cannot read crates/")? {
            let dir = entry.context("cannot read crates/")?.path();
            let Ok(manifest) = fs::read_to_string(dir.join("Cargo.toml")) else {
                continue;
            };
            let manifest: toml::Table = toml::from_str(&manifest)
                .with_context(|| format!("cannot read {}/Cargo.toml", dir.display()))?;
            let package = manifest
                .get("package")
                .and_then(|p| p.get("name"))
                .and_then(|n| n.as_str())
                .unwrap_or_default()
                .to_owned();
            let relative = dir.strip_prefix(root).unwrap_or(&dir).to_path_buf();
            crate_dirs.push((relative, package));
        }
    }
    for (dir, package) in &crate_dirs {
        let src = root.join(dir).join("src");
        if !src.is_dir() {
            continue;
        }
        for file in crate::files::files_under(&src)? {
            let course_path = dir.join("src").join(&file);
            let is_rust = file.extension().is_some_and(|e| e == "rs");
            if is_rust && !task_files.contains(&course_path) {
                given_files.push((dir.clone(), course_path, package.clone()));
            }
        }
    }
    let mut given: Vec<(&(PathBuf, PathBuf, String), String, Function)> = Vec::new();
    let mut given_methods: Vec<(&(PathBuf, PathBuf, String), String, Method)> = Vec::new();
    for entry in &given_files {
        let text = read(&entry.1)?;
        for function in public_functions(&text) {
            given.push((entry, text.clone(), function));
        }
        for method in methods(&text) {
            given_methods.push((entry, text.clone(), method));
        }
    }
    let mut found = Vec::new();
    let mut uncallable = 0;
    for topic in &topics {
        let crate_dir = Path::new("exercises").join(&topic.name);
        let manifest: toml::Table = toml::from_str(&read(&crate_dir.join("Cargo.toml"))?)
            .with_context(|| format!("cannot read {}/Cargo.toml", crate_dir.display()))?;
        let depends_on = |package: &str| {
            manifest
                .get("dependencies")
                .and_then(|d| d.as_table())
                .is_some_and(|d| d.contains_key(package))
        };
        for file in task_files.iter().filter(|f| f.starts_with(&crate_dir)) {
            let stub = read(file)?;
            for task_fn in public_functions(&stub) {
                let Some(task) = task_fn.task.clone() else {
                    continue;
                };
                for ((dir, given_file, package), text, function) in &given {
                    if function.shape != task_fn.shape {
                        continue;
                    }
                    let module = module_path(
                        given_file
                            .strip_prefix(dir.join("src"))
                            .unwrap_or(given_file),
                    );
                    let reachable = *dir == crate_dir
                        || (depends_on(package) && public_chain(root, dir, &module));
                    let path = if *dir == crate_dir {
                        format!("crate{}::{}", prefixed(&module), function.name)
                    } else if reachable {
                        format!(
                            "{}{}::{}",
                            package.replace('-', "_"),
                            prefixed(&module),
                            function.name
                        )
                    } else {
                        format!("stand_in::{}", function.name)
                    };
                    let copy = (!reachable).then_some(text.as_str());
                    let Some(planted) = plant(&stub, &task_fn, &path, copy) else {
                        uncallable += 1;
                        continue;
                    };
                    found.push(StandIn {
                        topic: topic.name.clone(),
                        task: task.clone(),
                        file: file.clone(),
                        given: format!("{}: {}", given_file.display(), function.name),
                        planted,
                    });
                }
            }
            // Methods and trait methods: a given body in place of the
            // task's, its parameters bound to the task's arguments and the
            // names of its module in scope.
            for task_method in methods(&stub) {
                let Some(task) = task_method.function.task.clone() else {
                    continue;
                };
                for ((dir, given_file, package), text, method) in &given_methods {
                    if !task_method.could_be(method) {
                        continue;
                    }
                    let module = module_path(
                        given_file
                            .strip_prefix(dir.join("src"))
                            .unwrap_or(given_file),
                    );
                    let path = if *dir == crate_dir {
                        Some(format!("crate{}", prefixed(&module)))
                    } else if depends_on(package) && public_chain(root, dir, &module) {
                        Some(format!(
                            "{}{}",
                            package.replace('-', "_"),
                            prefixed(&module)
                        ))
                    } else {
                        None
                    };
                    let Some(planted) =
                        plant_method(&stub, &task_method, method, text, path.as_deref())
                    else {
                        uncallable += 1;
                        continue;
                    };
                    found.push(StandIn {
                        topic: topic.name.clone(),
                        task: task.clone(),
                        file: file.clone(),
                        given: format!("{}: {}", given_file.display(), method.display()),
                        planted,
                    });
                }
            }
        }
    }
    Ok((found, given.len() + given_methods.len(), uncallable))
}

/// The module a source file is, relative to its crate's `src`
/// (`raster/dda.rs` → `["raster", "dda"]`, `lib.rs` → `[]`).
pub(super) fn module_path(file: &Path) -> Vec<String> {
    let mut parts: Vec<String> = file
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    if let Some(last) = parts.pop() {
        let stem = last.strip_suffix(".rs").unwrap_or(&last);
        if !matches!(stem, "lib" | "mod" | "main") {
            parts.push(stem.to_owned());
        }
    }
    parts
}

/// `::a::b` for `["a", "b"]`.
pub(super) fn prefixed(module: &[String]) -> String {
    module.iter().map(|m| format!("::{m}")).collect()
}

/// Whether every module of `module` is declared `pub mod` by its parent,
/// so that another crate can name it.
pub(super) fn public_chain(root: &Path, crate_dir: &Path, module: &[String]) -> bool {
    let src = root.join(crate_dir).join("src");
    let mut parent = src.join("lib.rs");
    let mut folder = src.clone();
    for name in module {
        let text = fs::read_to_string(&parent).unwrap_or_default();
        if !declares_public_module(&text, name) {
            return false;
        }
        folder = folder.join(name);
        parent = if folder.join("mod.rs").is_file() {
            folder.join("mod.rs")
        } else {
            folder.with_extension("rs")
        };
    }
    true
}

/// Whether the Rust file `text` declares `pub mod name;` among its items
/// (read from its syntax tree: not in a comment, not in a nested module).
fn declares_public_module(text: &str, name: &str) -> bool {
    syn::parse_str::<syn::File>(text).is_ok_and(|file| {
        file.items.iter().any(|item| {
            matches!(item, syn::Item::Mod(module)
                if module.ident == name
                    && module.content.is_none()
                    && matches!(module.vis, syn::Visibility::Public(_)))
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_public_module_is_declared_by_an_item_not_a_comment() {
        let text = "// pub mod commented;\n/* pub mod hidden; */\nmod private;\nmod outer {\n    pub mod inner;\n}\npub mod dda;\n";
        assert!(declares_public_module(text, "dda"));
        for name in ["commented", "hidden", "private", "inner"] {
            assert!(!declares_public_module(text, name), "{name}");
        }
    }
}
