//! Drawing off the UI thread: your stages may be slow or never return, and
//! the window must stay responsive either way.
//!
//! A worker thread draws one picture at a time (a frame of the pipeline
//! scene, a drawing of the pixel playground). The window asks for the
//! newest request only (requests made while a picture is drawn replace
//! each other), and shows for how long the current one has been running:
//! one that takes longer than [`SLOW`] is named as such. Rust cannot stop
//! a thread, so a stage in an endless loop keeps that worker busy until
//! the viewer is closed; the window says so.

use std::sync::mpsc::{self, Receiver, Sender, TryRecvError};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use crate::stages::WORKER_THREAD;

/// A picture that takes longer than this is reported as slow.
pub const SLOW: Duration = Duration::from_secs(2);

/// The worker thread and its mailbox: requests `J`, pictures `R`.
pub struct Worker<J, R> {
    jobs: Sender<J>,
    results: Receiver<(R, Duration)>,
    /// When the picture being drawn was asked for, if one is.
    busy_since: Option<Instant>,
    /// A request that waits for the current picture to finish.
    pending: Option<J>,
    /// How long the last picture took.
    last: Option<Duration>,
    /// The worker's own clock for the picture it draws (shared with it).
    started: Arc<Mutex<Option<Instant>>>,
    /// A picture running longer than this is reported as slow.
    slow: Duration,
}

impl<J: Send + 'static, R: Send + 'static> Worker<J, R> {
    /// Starts the worker thread, which answers each request with `draw`.
    ///
    /// # Panics
    /// If the operating system cannot start a thread.
    #[must_use]
    pub fn start(mut draw: impl FnMut(J) -> R + Send + 'static) -> Self {
        let (jobs, inbox) = mpsc::channel::<J>();
        let (outbox, results) = mpsc::channel();
        let started = Arc::new(Mutex::new(None));
        let clock = Arc::clone(&started);
        std::thread::Builder::new()
            .name(WORKER_THREAD.to_owned())
            .spawn(move || {
                while let Ok(mut job) = inbox.recv() {
                    // Only the newest request counts.
                    while let Ok(newer) = inbox.try_recv() {
                        job = newer;
                    }
                    let begun = Instant::now();
                    *clock
                        .lock()
                        .unwrap_or_else(std::sync::PoisonError::into_inner) = Some(begun);
                    let result = draw(job);
                    if outbox.send((result, begun.elapsed())).is_err() {
                        break;
                    }
                }
            })
            .expect("a thread for the stages");
        Self {
            jobs,
            results,
            busy_since: None,
            pending: None,
            last: None,
            started,
            slow: SLOW,
        }
    }

    /// Asks for a picture; if one is being drawn, this one follows it.
    pub fn request(&mut self, job: J) {
        if self.busy_since.is_some() {
            self.pending = Some(job);
        } else {
            self.send(job);
        }
    }

    fn send(&mut self, job: J) {
        if self.jobs.send(job).is_ok() {
            self.busy_since = Some(Instant::now());
        }
    }

    /// The newest finished picture, if one arrived since the last call.
    pub fn poll(&mut self) -> Option<R> {
        match self.results.try_recv() {
            Ok(done) => Some(self.arrived(done)),
            Err(TryRecvError::Empty | TryRecvError::Disconnected) => None,
        }
    }

    /// Waits for the picture being drawn, at most `limit`; `None` if it has
    /// not arrived by then (or none is being drawn).
    pub fn wait(&mut self, limit: Duration) -> Option<R> {
        self.busy_since?;
        self.results
            .recv_timeout(limit)
            .ok()
            .map(|done| self.arrived(done))
    }

    /// A picture the worker finished: the worker is free for the request
    /// that waited, if one did.
    fn arrived(&mut self, (result, took): (R, Duration)) -> R {
        self.busy_since = None;
        self.last = Some(took);
        if let Some(job) = self.pending.take() {
            self.send(job);
        }
        result
    }
}

impl<J, R> Worker<J, R> {
    /// How long the picture being drawn has been running, if one is.
    #[must_use]
    pub fn busy_for(&self) -> Option<Duration> {
        let started = *self
            .started
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        self.busy_since
            .map(|asked| started.filter(|s| *s >= asked).unwrap_or(asked).elapsed())
    }

    /// Reports pictures as slow after `limit` instead of [`SLOW`].
    pub fn set_slow_after(&mut self, limit: Duration) {
        self.slow = limit;
    }

    /// How long the picture being drawn has been running, if longer than
    /// the slow limit.
    #[must_use]
    pub fn slow_for(&self) -> Option<Duration> {
        self.busy_for().filter(|b| *b > self.slow)
    }

    /// How long the last finished picture took.
    #[must_use]
    pub fn last_frame_time(&self) -> Option<Duration> {
        self.last
    }
}
