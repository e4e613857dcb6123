//! `cargo xtask hint TASK`: the hints a topic keeps for each task
//! (`hints = [...]` in its `tasks.toml`, sealed in an edition: see
//! `topics::SEALED`), one more each time it is asked:
//! the first restates the goal, the last points at the exact rule the
//! tests are strict about. Which hints a student has seen is kept in
//! `target/xtask/hints.json`; `--reset` starts a task over, `--all` shows
//! every hint at once.

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};

use crate::stage;
use crate::topics::{self, Task, Topic};

/// Where the count of hints seen per task is kept.
fn state_file(root: &Path) -> PathBuf {
    stage::home(root).join("hints.json")
}

/// The task `selector` names: `dda`, `lines/dda`, `01-lines/dda`, `01/dda`.
pub fn find(root: &Path, selector: &str) -> Result<(Topic, Task)> {
    let all = topics::discover(root)?;
    let (topics, id) = match selector.split_once('/') {
        Some((topic, id)) => (topics::select(root, &[topic.to_owned()])?, id),
        None => (all.clone(), selector),
    };
    let found: Vec<(Topic, Task)> = topics
        .iter()
        .flat_map(|topic| {
            topic
                .sheet
                .tasks
                .iter()
                .filter(|task| task.id == id)
                .map(|task| (topic.clone(), task.clone()))
        })
        .collect();
    match found.len() {
        1 => Ok(found.into_iter().next().expect("one")),
        0 => {
            let known: Vec<String> = topics
                .iter()
                .flat_map(|t| {
                    t.sheet
                        .tasks
                        .iter()
                        .map(|task| format!("{}/{}", t.name, task.id))
                })
                .collect();
            bail!("no task `{selector}`; the tasks are: {}", known.join(", "))
        }
        _ => {
            let named: Vec<String> = found
                .iter()
                .map(|(topic, task)| format!("{}/{}", topic.name, task.id))
                .collect();
            bail!(
                "`{selector}` is a task of several topics; say which: {}",
                named.join(", ")
            )
        }
    }
}

fn read_state(path: &Path) -> BTreeMap<String, usize> {
    fs::read_to_string(path)
        .ok()
        .and_then(|text| serde_json::from_str(&text).ok())
        .unwrap_or_default()
}

/// `cargo xtask hint TASK [--all] [--reset]`: prints the hints seen so
/// far and one more.
pub fn run(root: &Path, selector: &str, all: bool, reset: bool) -> Result<()> {
    let (topic, task) = find(root, selector)?;
    let key = format!("{}/{}", topic.name, task.id);
    let path = state_file(root);
    let mut state = read_state(&path);
    if reset {
        state.remove(&key);
        write_state(&path, &state)?;
        println!("{key}: the hints start over; `cargo xtask hint {key}` shows the first");
        return Ok(());
    }
    let hints = &task.hints;
    if hints.is_empty() {
        println!(
            "{key} ({}) has no hints in its tasks.toml: read exercises/{}/README.md and the doc comment of its todo!()",
            task.title, topic.name
        );
        return Ok(());
    }
    let seen = state.get(&key).copied().unwrap_or(0);
    let shown = if all {
        hints.len()
    } else {
        (seen + 1).min(hints.len())
    };
    println!("{key}: {} (hint {shown} of {})", task.title, hints.len());
    for (k, hint) in hints.iter().take(shown).enumerate() {
        let new = if k + 1 > seen { "  (new)" } else { "" };
        println!("  {}. {hint}{new}", k + 1);
    }
    if shown < hints.len() {
        println!("`cargo xtask hint {key}` again for the next one");
    } else {
        println!("that is every hint; `cargo xtask hint {key} --reset` starts over");
    }
    state.insert(key, shown.max(seen));
    write_state(&path, &state)
}

fn write_state(path: &Path, state: &BTreeMap<String, usize>) -> Result<()> {
    if let Some(dir) = path.parent() {
        fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    }
    let text = serde_json::to_string_pretty(state).context("cannot serialise the hints seen")?;
    fs::write(path, text).with_context(|| format!("cannot write {}", path.display()))
}
