//! Record and replay: the grader decides whether a test passed in a
//! process that never ran the student's code.
//!
//! A test runs the student's functions in its own process, so anything
//! decided in that process can be forged by them: safe Rust has known
//! soundness holes (rust-lang/rust#25860, made famous by the `cve-rs`
//! crate) that read and write the process's own memory without `unsafe`,
//! so a secret kept there can be read, and a "failed" can be overwritten
//! with "passed". The verdict therefore comes from a second process:
//!
//! ```text
//!  record (untrusted)                         replay (trusted)
//!  ┌──────────────────────────┐  transcript   ┌───────────────────────────┐
//!  │ the test                 │   Enter  dda  │ the same test             │
//!  │   └─ dda_line (student's)│──>Callback 0──>│   └─ dda_line (replayer): │
//!  │        └─ plot(fragment) │   Callback 0  │        plot(recorded)     │
//!  │                          │   Return  ()  │        return recorded    │
//!  └──────────────────────────┘               │ asserts, prints the token │
//!                                              └───────────────────────────┘
//! ```
//!
//! - Every function a task asks for carries [`task`]. In the student's
//!   crate it records each outermost call ([`RECORD_VAR`] names the file):
//!   the values the function hands back to its caller, in order — every
//!   call of a callback parameter with its arguments, then the return
//!   value with the final value of every `&mut` parameter, or the panic
//!   message. Calls the student's code makes of other task functions are
//!   part of the outer call and are not recorded on their own.
//! - The grader builds the same tests a second time against the course's
//!   own copy of the crate, compiled with `--cfg transcript_replay` (see
//!   [`REPLAY_CFG`]): there the student's body is not even compiled; each
//!   task function reads its call from the transcript ([`REPLAY_VAR`]),
//!   calls the test's callbacks with the recorded arguments, and returns
//!   the recorded value. That process runs the test's assertions on the
//!   values the student's code produced and alone holds the grader's
//!   token.
//!
//! A forged transcript passes only by holding the right values for the
//! test's own inputs, which is solving the task; a transcript out of step
//! with the test (a call missing, a callback too many, a value of the wrong
//! type) fails the test with a message that says where. The replay needs
//! the test to be deterministic: the same calls with the same inputs in
//! both processes (property tests get a fixed seed from the grader).
//!
//! Outside the grader (`cargo test`, the viewer, the benchmarks) nothing is
//! recorded: a task function costs one check of a thread-local counter
//! and, per callback, one branch.
#![warn(missing_docs)]

mod event;
mod evidence;
mod record;
mod replay;

pub use evidence::{Changed, Changes, Record, Replay};
pub use transcript_macros::{evidence, task};

/// The environment variable naming the file a recording process writes
/// its transcript to (unset, nothing is recorded), the one naming the
/// transcript a replaying process reads, and the `cfg` under which [`task`]
/// functions replay instead of running their bodies (a build script of the
/// grader's replay package sets it).
pub use wire::{RECORD_VAR, REPLAY_CFG, REPLAY_VAR};

/// What [`task`]'s expansion uses; not for hand-written code.
#[doc(hidden)]
pub mod __private {
    pub use crate::record::{Call, Recording};
    pub use crate::replay::{Bytes, Replaying, Step, leak};
}
