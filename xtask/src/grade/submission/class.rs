//! Grading a class: its submissions side by side in class slots, all
//! built into one build cache.

use std::fs;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use anyhow::{Context, Result};
use indicatif::{ProgressBar, ProgressStyle};

use super::report::Report;
use super::{GradeOptions, Permits, Slot, grade_one, one_line, submissions_build, table};
use crate::stage;

/// A graded member of a class: its name, its report folder and its report
/// (or why it could not be graded).
type Graded = (String, PathBuf, Result<Report>);

/// Grades the `submissions` of a class, up to `options.jobs` side by side
/// in class slots (one at a time without a sandbox), printing one line for
/// each as it is done (the details are in its report); (name, report folder, report) of each, in the
/// order given.
pub(super) fn grade_class(
    official: &Path,
    submissions: &[PathBuf],
    options: &GradeOptions,
    out_for: impl Fn(&Path) -> (String, GradeOptions) + Sync,
) -> Result<Vec<Graded>> {
    if submissions.is_empty() {
        return Ok(Vec::new());
    }
    let sandboxed = crate::sandbox::Jail::get().sandboxed();
    // Side by side, a submission's tests run while another builds. A grade
    // keeps two CPUs busy on its own (cargo's build, `--jobs` tests): on a
    // machine with two, one at a time was the faster (`BENCHMARKS.md`).
    let wanted = options
        .submissions_at_once
        .unwrap_or_else(|| (crate::grade::default_jobs() / 2).max(1));
    let slots = if sandboxed {
        wanted.clamp(1, submissions.len())
    } else {
        1
    };
    // No other `cargo xtask` builds into the cache while the slots do.
    let _stage = stage::lock(official)?;
    let target_dir = options
        .target_dir
        .clone()
        .unwrap_or_else(|| submissions_build(official));
    // Every slot's folder exists before the first test runs, so that each
    // slot's sandbox hides all the others (`stage::hidden_beside` hides
    // what it finds).
    for index in 0..slots {
        let home = stage::class_home(official, index);
        fs::create_dir_all(&home).with_context(|| format!("cannot create {}", home.display()))?;
    }
    let turn = Mutex::new(());
    let permits = Arc::new(Permits::new(options.jobs));
    let bar = ProgressBar::new(submissions.len() as u64).with_style(
        ProgressStyle::with_template(
            "{spinner} [{elapsed}] {bar:30} {pos}/{len} submissions  {wide_msg}",
        )
        .expect("a valid progress template"),
    );
    bar.enable_steady_tick(Duration::from_millis(100));
    if slots > 1 {
        bar.println(format!(
            "grading {} submissions, {slots} at a time",
            submissions.len()
        ));
    }
    let busy: Mutex<Vec<String>> = Mutex::new(vec![String::new(); slots]);
    let next = AtomicUsize::new(0);
    let done = AtomicUsize::new(0);
    let results: Mutex<Vec<Option<Graded>>> =
        Mutex::new((0..submissions.len()).map(|_| None).collect());
    std::thread::scope(|scope| {
        for index in 0..slots {
            let (turn, permits, target_dir) = (&turn, &permits, &target_dir);
            let (bar, busy, next, done, results, out_for) =
                (&bar, &busy, &next, &done, &results, &out_for);
            scope.spawn(move || {
                let slot = Slot {
                    home: stage::class_home(official, index),
                    target_dir: target_dir.clone(),
                    turn,
                    permits: Arc::clone(permits),
                };
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(submission) = submissions.get(i) else {
                        break;
                    };
                    let (name, one) = out_for(submission);
                    {
                        let mut busy = busy.lock().expect("no slot panics");
                        busy[index].clone_from(&name);
                        bar.set_message(
                            busy.iter()
                                .filter(|b| !b.is_empty())
                                .cloned()
                                .collect::<Vec<_>>()
                                .join(", "),
                        );
                    }
                    let result = grade_one(official, submission, &one, Some(&slot));
                    let n = done.fetch_add(1, Ordering::Relaxed) + 1;
                    let shown = match &result {
                        Ok(report) => one_line(report, &one.out),
                        Err(error) => {
                            format!(
                                "not graded: {}",
                                format!("{error:#}").lines().next().unwrap_or_default()
                            )
                        }
                    };
                    bar.suspend(|| {
                        println!(
                            "[{n}/{}] {}: {shown}",
                            submissions.len(),
                            table::shown(&name)
                        );
                    });
                    bar.inc(1);
                    results.lock().expect("no slot panics")[i] = Some((name, one.out, result));
                }
                busy.lock().expect("no slot panics")[index].clear();
            });
        }
    });
    bar.finish_and_clear();
    Ok(results
        .into_inner()
        .expect("no slot panics")
        .into_iter()
        .map(|result| result.expect("every submission was graded"))
        .collect())
}
