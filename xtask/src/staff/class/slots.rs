//! Grading a class: its submissions side by side in class slots, all
//! built into one build cache, each graded by the grader
//! (`grade::submission::grade_in_slot`) in its slot.

use std::fs;
use std::panic::AssertUnwindSafe;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use anyhow::{Context, Result, anyhow};
use indicatif::{ProgressBar, ProgressStyle};

use super::one_line;
use crate::grade::submission::{Slot, grade_in_slot, submissions_build};
use crate::grade::{GradeOptions, Permits, Report, table};
use crate::stage;

/// A graded member of a class: its name, its report folder and its report
/// (or why it could not be graded).
type Graded = (String, PathBuf, Result<Report>);

/// Grades the `submissions` of a class, up to `at_once` side by side
/// (default: one per two CPUs) in class slots (one at a time without a
/// sandbox), printing one line for each as it is done (the details are in
/// its report); (name, report folder, report) of each, in the order given.
pub(super) fn grade_class(
    official: &Path,
    submissions: &[PathBuf],
    options: &GradeOptions,
    at_once: Option<usize>,
    out_for: impl Fn(&Path) -> (String, GradeOptions) + Sync,
) -> Result<Vec<Graded>> {
    if submissions.is_empty() {
        return Ok(Vec::new());
    }
    let sandboxed = crate::sandbox::Jail::get().sandboxed();
    // Side by side, a submission's tests run while another builds. A grade
    // keeps two CPUs busy on its own (cargo's build, `--jobs` tests): on a
    // machine with two, one at a time was the faster (`BENCHMARKS.md`).
    let wanted = at_once.unwrap_or_else(|| (crate::grade::default_jobs() / 2).max(1));
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
    // Every slot's folder exists before the first test runs.
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
    // Printed, not shown on the bar: also without a terminal, where the
    // bar is hidden, the log says what the first minutes are spent on.
    bar.suspend(|| {
        println!(
            "grading {} submission(s), {slots} at a time; the first build compiles the course's dependencies too (a few minutes), each later one its member's topics",
            submissions.len()
        );
    });
    let started = Instant::now();
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
                                .map(|name| table::shown(name))
                                .collect::<Vec<_>>()
                                .join(", "),
                        );
                    }
                    // A member is the unit of failure: whatever grading it
                    // meets, a panic of the grader's own included, is its
                    // result, and the slot goes on with the next member.
                    let result = std::panic::catch_unwind(AssertUnwindSafe(|| {
                        grade_in_slot(official, submission, &one, &slot)
                    }))
                    .unwrap_or_else(|panic| {
                        Err(anyhow!(
                            "the grader failed on this member: {}",
                            panic_message(panic.as_ref())
                        ))
                    });
                    let n = done.fetch_add(1, Ordering::Relaxed) + 1;
                    let shown = match &result {
                        Ok(report) if !report.left_out.is_empty() => format!(
                            "{} · {} left out of its report (links, pipes, deep folders, past the budget: see it)",
                            one_line(report, &one.out),
                            report.left_out.len()
                        ),
                        Ok(report) => one_line(report, &one.out),
                        Err(error) => {
                            format!(
                                "not graded: {}",
                                format!("{error:#}").lines().next().unwrap_or_default()
                            )
                        }
                    };
                    let left = submissions.len() - n;
                    let estimate = if left == 0 {
                        String::new()
                    } else {
                        // The first members paid for the dependencies: the
                        // estimate is on the safe side.
                        // Members done so far per second of the class,
                        // all slots together.
                        let each = started.elapsed().as_secs_f64() / n as f64;
                        format!(" (about {} left)", minutes(each * left as f64))
                    };
                    // Every part escaped: a member's folder name, and so
                    // the path of its report, is the submission's text.
                    bar.suspend(|| {
                        println!(
                            "[{n}/{}] {}: {}{estimate}",
                            submissions.len(),
                            table::shown(&name),
                            table::shown(&shown)
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

/// What a panic said (its message, when it has one that is text).
fn panic_message(panic: &(dyn std::any::Any + Send)) -> String {
    panic
        .downcast_ref::<&str>()
        .map(|s| (*s).to_owned())
        .or_else(|| panic.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "a panic without a message".to_owned())
}

/// `seconds` for people: `40 s`, `3 min`, `1 h 5 min`.
fn minutes(seconds: f64) -> String {
    let seconds = seconds.max(0.0).round() as u64;
    match seconds {
        0..60 => format!("{seconds} s"),
        60..3600 => format!("{} min", seconds.div_ceil(60)),
        _ => format!("{} h {} min", seconds / 3600, (seconds % 3600) / 60),
    }
}

#[cfg(test)]
mod tests {
    use super::minutes;

    #[test]
    fn a_panic_says_what_it_said() {
        let panic = std::panic::catch_unwind(|| panic!("slot {}", 3)).unwrap_err();
        assert_eq!(super::panic_message(panic.as_ref()), "slot 3");
    }

    #[test]
    fn times_are_said_in_the_largest_unit_that_fits() {
        assert_eq!(minutes(40.2), "40 s");
        assert_eq!(minutes(61.0), "2 min");
        assert_eq!(minutes(3900.0), "1 h 5 min");
        assert_eq!(minutes(-3.0), "0 s");
    }
}
