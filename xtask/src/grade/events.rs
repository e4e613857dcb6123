//! What a grade tells while it runs. The grade (the builds, the pool of
//! tests, the verdicts) says what happens as events to a sink its caller
//! hands in; the sink decides what a reader sees: nothing ([`Silent`],
//! where several grades share a terminal), or spinners, a progress bar and
//! each topic's rows of the table as soon as its tests have ended
//! ([`Terminal`]).

use std::io::Write as _;
use std::sync::Mutex;
use std::time::Duration;

use indicatif::{ProgressBar, ProgressStyle};

use super::report::TopicReport;
use super::table::{Layout, Style};

/// Where a grade says what it is doing. Every method does nothing unless
/// the sink wants it.
pub(crate) trait Events: Sync {
    /// A step before the tests begins (a build): `what` is done with it
    /// when the next event comes.
    fn step(&self, _what: &str) {}

    /// Whether the sink shows each topic as soon as it is graded: then the
    /// grade builds and runs topic by topic, so that the first topic's
    /// rows come after its own build; otherwise it builds every topic
    /// first, in one cargo run, which is quicker in all.
    fn topic_by_topic(&self) -> bool {
        false
    }

    /// The table of the grade will have the columns `layout`.
    fn table(&self, _layout: &Layout) {}

    /// `count` tests are about to run.
    fn tests_start(&self, _count: usize) {}

    /// A test begins (names escaped).
    fn test_start(&self, _topic: &str, _test: &str) {}

    /// A test has ended.
    fn test_end(&self) {}

    /// A topic's tests have all ended and its verdicts are in: `topic` as
    /// the grade found it (the grader's adjustments come after).
    fn topic_graded(&self, _topic: &TopicReport) {}

    /// Nothing more goes on: what a step or the tests showed goes.
    fn done(&self) {}
}

/// Tells nothing (a class's slots, graded side by side).
#[cfg(feature = "staff")]
pub(crate) struct Silent;

#[cfg(feature = "staff")]
impl Events for Silent {}

/// Tells a reader at a terminal: a spinner for each step and a progress
/// bar over the tests (on stderr, hidden where it is not a terminal), and,
/// where asked, each topic's rows of the table on stdout as soon as the
/// topic is graded.
pub(crate) struct Terminal {
    /// Whether spinners and the progress bar are shown at all.
    progress: bool,
    /// Whether each topic's rows are printed when it is graded.
    rows: bool,
    state: Mutex<State>,
}

#[derive(Default)]
struct State {
    /// The step's spinner, or the tests' progress bar.
    bar: Option<ProgressBar>,
    /// The table's columns.
    layout: Option<Layout>,
    /// The topics whose rows are printed.
    topics_shown: usize,
}

impl Terminal {
    /// Spinners and a progress bar where `progress` is set; no rows.
    #[must_use]
    pub(crate) fn new(progress: bool) -> Self {
        Self {
            progress,
            rows: false,
            state: Mutex::default(),
        }
    }

    /// As [`Terminal::new`], and each topic's rows printed as soon as it
    /// is graded: the table's heading and rows are then on screen before
    /// the grade ends, and its caller prints the rest ([`Terminal::rows_shown`]).
    #[must_use]
    pub(crate) fn with_rows(progress: bool) -> Self {
        Self {
            progress,
            rows: true,
            state: Mutex::default(),
        }
    }

    /// How many topics' rows are printed.
    pub(crate) fn rows_shown(&self) -> usize {
        self.state().topics_shown
    }

    fn state(&self) -> std::sync::MutexGuard<'_, State> {
        self.state
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
    }

    /// Replaces the shown bar with `bar` (or none).
    fn show(&self, bar: Option<ProgressBar>) {
        let mut state = self.state();
        if let Some(old) = state.bar.take() {
            old.finish_and_clear();
        }
        if let Some(bar) = &bar {
            bar.enable_steady_tick(Duration::from_millis(100));
        }
        state.bar = bar;
    }
}

impl Events for Terminal {
    fn topic_by_topic(&self) -> bool {
        self.rows
    }

    fn step(&self, what: &str) {
        let spinner = self
            .progress
            .then(|| ProgressBar::new_spinner().with_message(what.to_owned()));
        self.show(spinner);
    }

    fn table(&self, layout: &Layout) {
        self.state().layout = Some(layout.clone());
    }

    fn tests_start(&self, count: usize) {
        let bar = self.progress.then(|| {
            ProgressBar::new(count as u64).with_style(
                ProgressStyle::with_template(
                    "{spinner} [{elapsed}] {bar:30} {pos}/{len} tests  {wide_msg}",
                )
                .expect("a valid progress template"),
            )
        });
        self.show(bar);
    }

    fn test_start(&self, topic: &str, test: &str) {
        if let Some(bar) = &self.state().bar {
            bar.set_message(format!("{topic} {test}"));
        }
    }

    fn test_end(&self) {
        if let Some(bar) = &self.state().bar {
            bar.inc(1);
        }
    }

    fn topic_graded(&self, topic: &TopicReport) {
        if !self.rows {
            return;
        }
        let mut state = self.state();
        let Some(layout) = &state.layout else {
            return;
        };
        let style = Style::detect();
        let mut text = String::new();
        if state.topics_shown == 0 {
            text.push_str(&layout.heading(style));
        }
        text.push_str(&layout.topic_rows(topic, style));
        let print = || {
            let mut stdout = std::io::stdout().lock();
            let _ = stdout.write_all(text.as_bytes());
            let _ = stdout.flush();
        };
        match &state.bar {
            Some(bar) => bar.suspend(print),
            None => print(),
        }
        state.topics_shown += 1;
    }

    fn done(&self) {
        self.show(None);
    }
}

impl Drop for Terminal {
    fn drop(&mut self) {
        self.show(None);
    }
}
