//! How a job's process ended, and which of the runner's limits stopped
//! it: the runner's record, which the grader words for students (see
//! `grade::outcome`).

use serde::{Deserialize, Serialize};

/// How a job's process ended.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Exit {
    /// The exit code, if it exited.
    pub code: Option<i32>,
    /// The signal that ended it, if one did (Unix).
    pub signal: Option<i32>,
    /// The grader killed it at the time limit.
    pub timed_out: bool,
    /// The grader killed it for printing more than this many bytes.
    pub output_limit: Option<u64>,
    /// Not run: an earlier test of the same task timed out, and a task
    /// that loops once is not given the time limit again for every test.
    pub not_run: bool,
    /// Its processes together used more than this many MiB of memory
    /// (a cgroup's limit: the kernel stopped one of them).
    #[serde(default)]
    pub memory_limit: Option<u64>,
    /// The grader killed it for writing more than this many MiB of files.
    #[serde(default)]
    pub written_limit: Option<u64>,
    /// Its processes met the limit of this many at once (a cgroup's: the
    /// kernel refused to start more). Not a stop: a test may still pass.
    #[serde(default)]
    pub process_limit: Option<u64>,
}

impl Exit {
    /// Whether a limit of the grader's stopped it.
    #[must_use]
    pub fn stopped(&self) -> bool {
        self.timed_out
            || self.output_limit.is_some()
            || self.memory_limit.is_some()
            || self.written_limit.is_some()
    }
}
