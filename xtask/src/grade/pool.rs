//! The pool tests run in: `--jobs` workers, and across the submissions of
//! a class graded side by side (the staff's class), one count of tests
//! running at once (`Permits`). The pool says what it does to the grade's
//! [`Events`]; when a topic's last test has ended, its caller is handed
//! the topic's outcomes at once, while the workers go on with the next.

use std::collections::{HashMap, HashSet};
use std::path::PathBuf;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;

use anyhow::Result;

use super::events::Events;
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
    /// Shared with the grades of a class's other slots: a test runs only
    /// while one of them is free.
    #[cfg(feature = "staff")]
    pub(super) permits: Option<std::sync::Arc<Permits>>,
}

/// The outcomes of a topic's tests, by the test's index in its plan.
pub(super) type TopicOutcomes = HashMap<usize, Finished>;

/// Runs the tests `jobs` ((plan, test) pairs) as `workers` says; after
/// each, `kept` sweeps what it wrote into the report folder. As soon as
/// every test of a plan has ended, and every plan before it is done,
/// `topic_done` gets the plan's index and its outcomes (a plan without
/// tests is done at once): in the plans' order, on the calling thread,
/// while the workers run the next tests.
///
/// # Errors
/// The first test that could not be run at all (not one that failed):
/// the tests still run, and the plans after it are not handed on.
pub(super) fn run_all(
    plans: &[Plan],
    jobs: &[(usize, usize)],
    workers: &Workers,
    kept: &Kept,
    events: &dyn Events,
    mut topic_done: impl FnMut(usize, TopicOutcomes),
) -> Result<()> {
    crate::sandbox::stop_all_on_interrupt();
    let mut remaining = vec![0_usize; plans.len()];
    for &(p, _) in jobs {
        remaining[p] += 1;
    }
    let mut outcomes: Vec<TopicOutcomes> = plans.iter().map(|_| HashMap::new()).collect();
    let mut told = 0;
    let mut tell = |remaining: &[usize], outcomes: &mut [TopicOutcomes]| {
        while told < plans.len() && remaining[told] == 0 {
            topic_done(told, std::mem::take(&mut outcomes[told]));
            told += 1;
        }
    };
    tell(&remaining, &mut outcomes);
    let next = AtomicUsize::new(0);
    // Fail fast: the tasks (plan, task) one of whose tests timed out; their
    // tests not started yet are not run.
    let timed_out: Mutex<HashSet<(usize, usize)>> = Mutex::default();
    let mut first_error = None;
    std::thread::scope(|scope| {
        let (sender, receiver) = mpsc::channel::<(usize, Result<Finished>)>();
        for _ in 0..workers.threads.min(jobs.len()) {
            let sender = sender.clone();
            let (next, timed_out) = (&next, &timed_out);
            scope.spawn(move || {
                loop {
                    let index = next.fetch_add(1, Ordering::Relaxed);
                    let Some(&(p, t)) = jobs.get(index) else {
                        break;
                    };
                    let plan = &plans[p];
                    let test = &plan.tests[t];
                    // (A test's name is what its program listed: escaped.)
                    events.test_start(&plan.topic.name, &super::table::shown(&test.name));
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
                    events.test_end();
                    if sender.send((index, result)).is_err() {
                        break;
                    }
                }
            });
        }
        drop(sender);
        for (index, result) in receiver {
            let (p, t) = jobs[index];
            match result {
                Ok(finished) => {
                    outcomes[p].insert(t, finished);
                }
                Err(error) => {
                    first_error.get_or_insert(error);
                }
            }
            remaining[p] -= 1;
            if first_error.is_none() {
                tell(&remaining, &mut outcomes);
            }
        }
    });
    first_error.map_or(Ok(()), Err)
}
