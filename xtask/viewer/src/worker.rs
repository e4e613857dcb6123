//! Drawing off the UI thread: your stages may be slow or never return, and
//! the window must stay responsive either way.
//!
//! One worker thread draws one frame at a time. The window asks for the
//! newest settings only (requests made while a frame is drawn replace each
//! other), and shows for how long the current frame has been running: a
//! frame that takes longer than [`SLOW`] is named as such, with the stage
//! it is stuck in. Rust cannot stop a thread, so a stage in an endless loop
//! keeps that worker busy until the viewer is closed; the window says so.

use std::sync::mpsc::{self, Receiver, Sender, TryRecvError};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use scene::Mesh;

use crate::render::{Frame, Settings, render};
use crate::stages::{Stages, WORKER_THREAD};

/// A frame that takes longer than this is reported as slow.
pub const SLOW: Duration = Duration::from_secs(2);

/// A request: what to draw.
struct Job {
    mesh: Arc<Mesh>,
    settings: Settings,
}

/// The worker thread and its mailbox.
pub struct Worker {
    jobs: Sender<Job>,
    frames: Receiver<(Frame, Duration)>,
    /// When the frame being drawn was asked for, if one is.
    busy_since: Option<Instant>,
    /// A request that waits for the current frame to finish.
    pending: Option<Job>,
    /// How long the last frame took.
    last: Option<Duration>,
    /// The worker's own clock for the frame it draws (shared with it).
    started: Arc<Mutex<Option<Instant>>>,
    /// A frame running longer than this is reported as slow.
    slow: Duration,
}

impl Worker {
    /// Starts the worker thread, which draws with `stages`.
    ///
    /// # Panics
    /// If the operating system cannot start a thread.
    #[must_use]
    pub fn start(stages: Stages) -> Self {
        let (jobs, inbox) = mpsc::channel::<Job>();
        let (outbox, frames) = mpsc::channel();
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
                    let frame = render(&job.mesh, &job.settings, &stages);
                    if outbox.send((frame, begun.elapsed())).is_err() {
                        break;
                    }
                }
            })
            .expect("a thread for the stages");
        Self {
            jobs,
            frames,
            busy_since: None,
            pending: None,
            last: None,
            started,
            slow: SLOW,
        }
    }

    /// Asks for a frame; if one is being drawn, this one follows it.
    pub fn request(&mut self, mesh: Arc<Mesh>, settings: Settings) {
        let job = Job { mesh, settings };
        if self.busy_since.is_some() {
            self.pending = Some(job);
        } else {
            self.send(job);
        }
    }

    fn send(&mut self, job: Job) {
        if self.jobs.send(job).is_ok() {
            self.busy_since = Some(Instant::now());
        }
    }

    /// The newest finished frame, if one arrived since the last call.
    pub fn poll(&mut self) -> Option<Frame> {
        match self.frames.try_recv() {
            Ok(done) => Some(self.arrived(done)),
            Err(TryRecvError::Empty | TryRecvError::Disconnected) => None,
        }
    }

    /// Waits for the frame being drawn, at most `limit`; `None` if it has
    /// not arrived by then (or none is being drawn).
    pub fn wait(&mut self, limit: Duration) -> Option<Frame> {
        self.busy_since?;
        self.frames
            .recv_timeout(limit)
            .ok()
            .map(|done| self.arrived(done))
    }

    /// A frame the worker finished: the worker is free for the request
    /// that waited, if one did.
    fn arrived(&mut self, (frame, took): (Frame, Duration)) -> Frame {
        self.busy_since = None;
        self.last = Some(took);
        if let Some(job) = self.pending.take() {
            self.send(job);
        }
        frame
    }

    /// How long the frame being drawn has been running, if one is.
    #[must_use]
    pub fn busy_for(&self) -> Option<Duration> {
        let started = *self
            .started
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        self.busy_since
            .map(|asked| started.filter(|s| *s >= asked).unwrap_or(asked).elapsed())
    }

    /// Reports frames as slow after `limit` instead of [`SLOW`].
    pub fn set_slow_after(&mut self, limit: Duration) {
        self.slow = limit;
    }

    /// How long the frame being drawn has been running, if longer than the
    /// slow limit.
    #[must_use]
    pub fn slow_for(&self) -> Option<Duration> {
        self.busy_for().filter(|b| *b > self.slow)
    }

    /// How long the last finished frame took.
    #[must_use]
    pub fn last_frame_time(&self) -> Option<Duration> {
        self.last
    }
}
