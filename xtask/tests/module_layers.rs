//! The tooling's modules in layers: no two top-level modules of
//! `xtask/src` use each other (directly or round a circle), the sandbox
//! uses nothing of the grader above it, and nothing the student's edition
//! holds uses the staff's tools (`staff`, which no edition holds).
//!
//! A module's uses are the `crate::name` paths in its code (comments are
//! not read), which is how the tooling names its modules.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::Path;

/// Each top-level module of `src` and the top-level modules its code
/// names as `crate::name`.
fn uses(src: &Path) -> BTreeMap<String, BTreeSet<String>> {
    let mut graph: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    let mut folders = vec![src.to_path_buf()];
    while let Some(folder) = folders.pop() {
        for entry in fs::read_dir(&folder).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                folders.push(path);
                continue;
            }
            if path.extension().is_none_or(|e| e != "rs") {
                continue;
            }
            let relative = path.strip_prefix(src).unwrap();
            let first = relative.components().next().unwrap();
            let module = Path::new(first.as_os_str())
                .file_stem()
                .unwrap()
                .to_string_lossy()
                .into_owned();
            if module == "main" {
                continue;
            }
            let text = fs::read_to_string(&path).unwrap();
            let named = graph.entry(module.clone()).or_default();
            for line in text.lines().filter(|l| !l.trim_start().starts_with("//")) {
                for (at, _) in line.match_indices("crate::") {
                    let rest = &line[at + "crate::".len()..];
                    let name: String = rest
                        .chars()
                        .take_while(|c| c.is_ascii_lowercase() || *c == '_')
                        .collect();
                    // `crate::name` inside a longer path (`my_crate::x`) is
                    // another crate's.
                    let before = line[..at].chars().next_back();
                    let own = before.is_none_or(|c| !(c.is_alphanumeric() || c == '_'));
                    if own && !name.is_empty() && name != module {
                        named.insert(name);
                    }
                }
            }
        }
    }
    graph
}

/// A circle of modules each using the next, if there is one.
fn circle(graph: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        module: &str,
        graph: &BTreeMap<String, BTreeSet<String>>,
        path: &mut Vec<String>,
        done: &mut BTreeSet<String>,
    ) -> Option<Vec<String>> {
        if let Some(at) = path.iter().position(|m| m == module) {
            let mut found = path[at..].to_vec();
            found.push(module.to_owned());
            return Some(found);
        }
        if done.contains(module) {
            return None;
        }
        path.push(module.to_owned());
        for next in graph.get(module).into_iter().flatten() {
            if let Some(found) = visit(next, graph, path, done) {
                return Some(found);
            }
        }
        path.pop();
        done.insert(module.to_owned());
        None
    }
    let mut done = BTreeSet::new();
    graph
        .keys()
        .find_map(|module| visit(module, graph, &mut Vec::new(), &mut done))
}

fn tooling() -> BTreeMap<String, BTreeSet<String>> {
    uses(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"))
}

#[test]
fn no_two_modules_use_each_other() {
    let graph = tooling();
    assert!(graph.contains_key("grade") && graph.contains_key("sandbox"));
    assert_eq!(circle(&graph), None, "modules that use each other");
}

#[test]
fn the_sandbox_uses_nothing_of_the_grader() {
    let graph = tooling();
    let allowed: BTreeSet<String> = ["files", "setup"].map(String::from).into();
    let extra: Vec<&String> = graph["sandbox"].difference(&allowed).collect();
    assert!(extra.is_empty(), "the sandbox uses {extra:?}");
}

#[test]
fn what_an_edition_holds_uses_nothing_of_the_staffs() {
    let graph = tooling();
    let users: Vec<&String> = graph
        .iter()
        .filter(|(module, named)| *module != "staff" && named.contains("staff"))
        .map(|(module, _)| module)
        .collect();
    assert!(users.is_empty(), "{users:?} use the staff's tools");
}

#[test]
fn a_circle_is_found_where_there_is_one() {
    let graph: BTreeMap<String, BTreeSet<String>> = [
        ("a", vec!["b"]),
        ("b", vec!["c"]),
        ("c", vec!["a"]),
        ("d", vec![]),
    ]
    .into_iter()
    .map(|(m, n)| (m.to_owned(), n.into_iter().map(String::from).collect()))
    .collect();
    assert_eq!(
        circle(&graph),
        Some(["a", "b", "c", "a"].map(String::from).to_vec())
    );
    let mut layered = graph;
    layered.get_mut("c").unwrap().clear();
    assert_eq!(circle(&layered), None);
}
