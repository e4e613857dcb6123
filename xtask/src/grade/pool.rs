//! The pool tests run in: `--jobs` workers, and across the submissions of
//! a class graded side by side (the staff's class), one count of tests
//! running at once (`Permits`).

use std::collections::HashSet;
use std::path::PathBuf;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Duration;

use anyhow::Result;
use indicatif::{ProgressBar, ProgressStyle};

use super::plan::{Plan, PlannedTest};
use super::run::Finished;
use crate::files::Keeper;

/// A counting semaphore: the tests that may run at once, shared by the
/// submissions of a class graded side by side.
#[cfg(feature = "staff")]
#[derive(Debug)]
pub struct Permits {
    free: Mutex<usize>,
    freed: std::sync::Condvar,
}

#[cfg(feature = "staff")]
impl Permits {
    /// `count` permits (at least one).
    #[must_use]
    pub fn new(count: usize) -> Self {
        Self {
            free: Mutex::new(count.max(1)),
            freed: std::sync::Condvar::new(),
        }
    }

    /// Waits for a permit, which is given back when the guard drops.
    pub fn take(&self) -> PermitGuard<'_> {
        let mut free = self.free.lock().expect("no permit holder panics");
        while *free == 0 {
            free = self.freed.wait(free).expect("no permit holder panics");
        }
        *free -= 1;
        PermitGuard(self)
    }
}

/// A permit of [`Permits`], held while a test runs.
#[cfg(feature = "staff")]
pub struct PermitGuard<'a>(&'a Permits);

#[cfg(feature = "staff")]
impl Drop for PermitGuard<'_> {
    fn drop(&mut self) {
        *self.0.free.lock().expect("no permit holder panics") += 1;
        self.0.freed.notify_one();
    }
}

/// What a grade keeps of what its tests write into the report folder:
/// each test's pictures and log, and the pending snapshots all tests
/// share, swept after every test (see [`Keeper`]).
pub(super) struct Kept {
    /// The grade's one keeper, shared by the workers.
    pub(super) keeper: Mutex<Keeper>,
    /// The folder of pending snapshots, which every test may write.
    pub(super) pending: PathBuf,
}

impl Kept {
    /// Sweeps what the test `test` (just ended) could write.
    fn sweep_after(&self, test: &PlannedTest) {
        let mut keeper = self
            .keeper
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        keeper.sweep(&test.images_dir);
        keeper.sweep(&self.pending);
        if let Some(command) = &test.command {
            keeper.keep_log(&command.log);
        }
    }
}

/// How the tests of a grade run.
pub(super) struct Workers {
    /// Tests run at the same time.
    pub(super) threads: usize,
    /// A progress bar on stderr (hidden when stderr is not a terminal).
    pub(super) progress: bool,
    /// Shared with the grades of a class's other slots: a test runs only
    /// while one of them is free.
    #[cfg(feature = "staff")]
    pub(super) permits: Option<std::sync::Arc<Permits>>,
}

/// Runs the given tests as `workers` says; after each, `kept` sweeps what
/// it wrote into the report folder.
pub(super) fn run_all(
    plans: &[Plan],
    jobs: &[(usize, usize)],
    workers: &Workers,
    kept: &Kept,
) -> Result<Vec<Finished>> {
    crate::sandbox::stop_all_on_interrupt();
    let bar = if workers.progress {
        let bar = ProgressBar::new(jobs.len() as u64).with_style(
            ProgressStyle::with_template(
                "{spinner} [{elapsed}] {bar:30} {pos}/{len} tests  {wide_msg}",
            )
            .expect("a valid progress template"),
        );
        bar.enable_steady_tick(Duration::from_millis(100));
        bar
    } else {
        ProgressBar::hidden()
    };
    let next = AtomicUsize::new(0);
    let results: Mutex<Vec<Option<Result<Finished>>>> =
        Mutex::new((0..jobs.len()).map(|_| None).collect());
    // Fail fast: the tasks (plan, task) one of whose tests timed out; their
    // tests not started yet are not run.
    let timed_out: Mutex<HashSet<(usize, usize)>> = Mutex::default();
    std::thread::scope(|scope| {
        for _ in 0..workers.threads.min(jobs.len()) {
            scope.spawn(|| {
                loop {
                    let index = next.fetch_add(1, Ordering::Relaxed);
                    let Some(&(p, t)) = jobs.get(index) else {
                        break;
                    };
                    let plan = &plans[p];
                    let test = &plan.tests[t];
                    // (A test's name is what its program listed: escaped.)
                    bar.set_message(format!(
                        "{} {}",
                        plan.topic.name,
                        super::table::shown(&test.name)
                    ));
                    let command = test.command.as_ref().expect("only runnable tests are jobs");
                    let key = (p, test.task);
                    let skip = timed_out.lock().expect("no worker panics").contains(&key);
                    let result = if skip {
                        Ok(Finished::not_run())
                    } else {
                        #[cfg(feature = "staff")]
                        let _permit = workers.permits.as_deref().map(Permits::take);
                        command.run()
                    };
                    kept.sweep_after(test);
                    if result.as_ref().is_ok_and(|f| f.exit.timed_out) {
                        timed_out.lock().expect("no worker panics").insert(key);
                    }
                    results.lock().expect("no worker panics")[index] = Some(result);
                    bar.inc(1);
                }
            });
        }
    });
    bar.finish_and_clear();
    results
        .into_inner()
        .expect("no worker panics")
        .into_iter()
        .map(|result| result.expect("every job ran"))
        .collect()
}
