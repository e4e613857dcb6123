//! `cargo xtask watch [TOPIC]`: grade a topic, then again whenever a file
//! of its `src/` changes (saves within [`DEBOUNCE`] are one change), one
//! screen per grade: the table and the first failing case.

use std::fs;
use std::io::IsTerminal as _;
use std::path::Path;
use std::sync::mpsc;
use std::time::Duration;

use anyhow::{Context, Result};
use notify::{RecursiveMode, Watcher as _};

use crate::grade::{self, GradeOptions};
use crate::topics::{self, Topic};

/// Changes closer together than this are one change (an editor writes a
/// file in several steps).
const DEBOUNCE: Duration = Duration::from_millis(300);

/// Watches `topic` (as `grade` names topics), or the first topic whose
/// `src/` still holds a `todo!(`, or else the first topic.
pub fn run(root: &Path, topic: Option<&str>) -> Result<()> {
    let topic = match topic {
        Some(name) => topics::select(root, &[name.to_owned()])?
            .into_iter()
            .next()
            .context("no such topic")?,
        None => {
            let all = topics::discover(root)?;
            let unfinished = all.iter().find(|t| has_todo(&t.dir.join("src"))).cloned();
            unfinished
                .or_else(|| all.into_iter().next())
                .context("there are no topics")?
        }
    };
    let src = topic.dir.join("src");
    let (changed, changes) = mpsc::channel();
    let mut watcher = notify::recommended_watcher(move |event: notify::Result<notify::Event>| {
        if event.is_ok_and(|e| e.kind.is_modify() || e.kind.is_create() || e.kind.is_remove()) {
            let _ = changed.send(());
        }
    })
    .context("cannot watch files on this machine")?;
    watcher
        .watch(&src, RecursiveMode::Recursive)
        .with_context(|| format!("cannot watch {}", src.display()))?;
    loop {
        grade_once(root, &topic);
        println!(
            "watching {} — save a file to grade again, Ctrl-C to stop",
            src.display()
        );
        changes.recv().context("the file watcher stopped")?;
        while changes.recv_timeout(DEBOUNCE).is_ok() {}
    }
}

/// Grades `topic` and prints one screen; a failure to grade is printed,
/// and the watch goes on.
fn grade_once(root: &Path, topic: &Topic) {
    let mut options = GradeOptions::new(root.to_path_buf());
    options.topics = vec![topic.name.clone()];
    match grade::grade(&options) {
        Ok(report) => {
            if std::io::stdout().is_terminal() {
                print!("\x1b[2J\x1b[H"); // a fresh screen
            }
            print!("{}", grade::one_screen(&report, &options.out));
        }
        Err(error) => println!("error: {error:#}"),
    }
}

/// Whether any Rust file under `dir` still holds a `todo!(`.
fn has_todo(dir: &Path) -> bool {
    let Ok(entries) = fs::read_dir(dir) else {
        return false;
    };
    entries.flatten().any(|entry| {
        let path = entry.path();
        // A link is not followed: it could lead back up.
        if entry.file_type().is_ok_and(|kind| kind.is_dir()) {
            has_todo(&path)
        } else {
            path.extension().is_some_and(|e| e == "rs")
                && fs::read_to_string(&path).is_ok_and(|text| text.contains("todo!("))
        }
    })
}
