//! The recording side: what a [`crate::task`] function does in the
//! student's crate.

use std::any::Any;
use std::backtrace::Backtrace;
use std::cell::{Cell, RefCell};
use std::fs::File;
use std::io::{BufWriter, Write as _};
use std::panic::{AssertUnwindSafe, catch_unwind, resume_unwind};
use std::sync::{Mutex, OnceLock, PoisonError};

use crate::event;

thread_local! {
    /// How many task calls are running on this thread: only a call that
    /// starts at depth 0 is recorded (its nested task calls are the
    /// student's own business). A callback of a recorded call runs at
    /// depth 0 again: it is the test's code.
    static DEPTH: Cell<usize> = const { Cell::new(0) };
    /// What the thread's last panic inside the standard library adds to
    /// its message (see [`note_panics`]).
    static INSIDE_STD: RefCell<Option<String>> = const { RefCell::new(None) };
}

/// Chains a panic hook that notes a panic placed inside the standard
/// library: `i32::MIN.abs()` panics in `core/src/num`, not on the line that
/// called it, so the recorded message says so and names the line of the
/// code under test that called it where the backtrace can tell (a sandbox
/// that keeps the process from reading its own program leaves the frames
/// unnamed; the message then says what to look for). Other panics (an
/// `unwrap`, an index, an assertion) already name the line that made them
/// and cost nothing more.
fn note_panics() {
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        if let Some(at) = info
            .location()
            .filter(|at| std::path::Path::new(at.file()).is_absolute())
        {
            let file = at.file();
            let library = file.find("library/").map_or(file, |i| &file[i + 8..]);
            let note = match called_from(&Backtrace::force_capture().to_string()) {
                Some(line) => {
                    format!(" (raised in the standard library, {library}, called at {line})")
                }
                None => format!(
                    " (raised in the standard library, {library}, by a method this function \
                     called: `abs`, `pow`, `div_euclid` and the like panic there when they \
                     overflow or are given a value they refuse)"
                ),
            };
            INSIDE_STD.with(|inside| *inside.borrow_mut() = Some(note));
        }
        previous(info);
    }));
}

/// The first location in a backtrace's text that lies in the code under
/// test — the course's `exercises/` folder, wherever the build put it —
/// as `exercises/…/file.rs:line:column`.
fn called_from(backtrace: &str) -> Option<String> {
    backtrace
        .lines()
        .filter_map(|line| line.trim_start().strip_prefix("at "))
        .find_map(|at| {
            let at = at.strip_prefix("./").unwrap_or(at);
            if at.starts_with("exercises/") {
                Some(at)
            } else {
                at.find("/exercises/").map(|i| &at[i + 1..])
            }
        })
        .map(str::to_owned)
}

/// The transcript being written, when the grader asked for one.
struct Recorder {
    state: Mutex<State>,
}

/// The file and the batch of calls not yet written to it.
struct State {
    out: BufWriter<File>,
    /// The callback calls not yet written.
    batch: Vec<u8>,
    /// Room to encode one call's arguments in, and to compress a batch in.
    scratch: Vec<u8>,
    compressed: Vec<u8>,
}

impl State {
    // A write that fails leaves the transcript short, which the replay
    // reports as a call that never ended.
    fn write_batch(&mut self) {
        if !self.batch.is_empty() {
            let _ = event::write_calls(&mut self.out, &self.batch, &mut self.compressed);
            self.batch.clear();
        }
    }

    fn write(
        &mut self,
        write: impl FnOnce(&mut BufWriter<File>) -> std::io::Result<()>,
        flush: bool,
    ) {
        self.write_batch();
        let _ = write(&mut self.out);
        if flush {
            let _ = self.out.flush();
        }
    }
}

impl Recorder {
    /// The process's recorder: `None` outside the grader.
    fn get() -> Option<&'static Recorder> {
        static RECORDER: OnceLock<Option<Recorder>> = OnceLock::new();
        RECORDER
            .get_or_init(|| {
                let path = std::env::var_os(crate::RECORD_VAR)?;
                note_panics();
                let file = File::create(&path).unwrap_or_else(|error| {
                    panic!(
                        "cannot create the transcript {}: {error}",
                        std::path::Path::new(&path).display()
                    )
                });
                Some(Recorder {
                    state: Mutex::new(State {
                        out: BufWriter::with_capacity(1 << 20, file),
                        batch: Vec::with_capacity(event::BATCH_BYTES + 4096),
                        scratch: Vec::new(),
                        compressed: Vec::new(),
                    }),
                })
            })
            .as_ref()
    }

    fn state(&self) -> std::sync::MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(PoisonError::into_inner)
    }

    fn write(&self, write: impl FnOnce(&mut BufWriter<File>) -> std::io::Result<()>, flush: bool) {
        self.state().write(write, flush);
    }

    /// A recorded call's callback: its call recorded, and the thread
    /// marked as running the caller's code until the guard drops.
    fn callback(&self, parameter: u32, encode: &mut dyn FnMut(&mut Vec<u8>)) -> Outside {
        self.call(parameter, encode);
        Outside(Some(DEPTH.with(|depth| depth.replace(0))))
    }

    /// One call of callback parameter `parameter`, its arguments written
    /// by `encode`, added to the batch.
    fn call(&self, parameter: u32, encode: &mut dyn FnMut(&mut Vec<u8>)) {
        let mut state = self.state();
        let state = &mut *state;
        state.scratch.clear();
        encode(&mut state.scratch);
        event::push_call(&mut state.batch, parameter, &state.scratch);
        if state.batch.len() >= event::BATCH_BYTES {
            state.write_batch();
        }
    }
}

/// Where a recorded call's callbacks report to: `None` when the call is
/// not recorded (nothing asked for, or a nested call).
#[derive(Clone, Copy)]
pub struct Recording(Option<&'static Recorder>);

/// One call of a task function, from its start to its end.
pub struct Call {
    recording: Recording,
}

impl Call {
    /// A call of the task function `name` begins.
    #[must_use]
    pub fn enter(name: &str) -> Call {
        let depth = DEPTH.with(|depth| depth.replace(depth.get() + 1));
        let recorder = if depth == 0 { Recorder::get() } else { None };
        if let Some(recorder) = recorder {
            recorder.write(|out| event::write_enter(out, name), false);
        }
        Call {
            recording: Recording(recorder),
        }
    }

    /// Where this call's callbacks report to.
    #[must_use]
    pub fn recording(&self) -> Recording {
        self.recording
    }

    /// Runs the function's body; a panic is recorded with its message and
    /// goes on unwinding.
    pub fn run<R>(&self, body: impl FnOnce() -> R) -> R {
        match catch_unwind(AssertUnwindSafe(body)) {
            Ok(value) => value,
            Err(payload) => {
                if let Some(recorder) = self.recording.0 {
                    let mut message = message(payload.as_ref());
                    if let Some(note) = INSIDE_STD.with(|inside| inside.borrow_mut().take()) {
                        message.push_str(&note);
                    }
                    recorder.write(|out| event::write_panic(out, &message), true);
                }
                resume_unwind(payload)
            }
        }
    }

    /// The call returns: `encode` writes its value, then the final value
    /// of each `&mut` parameter.
    pub fn finish(&self, encode: &mut dyn FnMut(&mut Vec<u8>)) {
        if let Some(recorder) = self.recording.0 {
            let mut values = Vec::new();
            encode(&mut values);
            recorder.write(|out| event::write_return(out, &values), true);
        }
    }
}

impl Drop for Call {
    fn drop(&mut self) {
        DEPTH.with(|depth| depth.set(depth.get().saturating_sub(1)));
    }
}

/// While alive, the thread runs the caller's code (a callback of a
/// recorded call): task calls it makes are recorded as calls of their own.
pub struct Outside(Option<usize>);

impl Drop for Outside {
    #[inline]
    fn drop(&mut self) {
        if let Some(depth) = self.0 {
            DEPTH.with(|d| d.set(depth));
        }
    }
}

impl Recording {
    /// Whether the call is recorded.
    #[must_use]
    #[inline]
    pub fn is_on(self) -> bool {
        self.0.is_some()
    }

    /// The call invokes its callback parameter number `parameter`:
    /// `call(arguments)` runs it, and `encode` writes the arguments to
    /// the record first when the call is recorded (the thread then runs
    /// the caller's code until `call` returns).
    ///
    /// Always inlined, with the recording kept out of line: outside the
    /// grader (a benchmark, the viewer) a callback costs the test of one
    /// pointer, and the caller's closure is inlined into the task's loop
    /// (a midpoint line plots its pixels 1.6 times as fast as through a
    /// wrapper that is called, see BENCHMARKS.md).
    #[inline(always)]
    pub fn callback<A, R>(
        self,
        parameter: u32,
        arguments: A,
        encode: impl Fn(&A, &mut Vec<u8>),
        call: impl FnOnce(A) -> R,
    ) -> R {
        match self.0 {
            None => call(arguments),
            Some(recorder) => recorded_callback(recorder, parameter, arguments, encode, call),
        }
    }
}

/// [`Recording::callback`] of a recorded call.
#[cold]
#[inline(never)]
fn recorded_callback<A, R>(
    recorder: &'static Recorder,
    parameter: u32,
    arguments: A,
    encode: impl Fn(&A, &mut Vec<u8>),
    call: impl FnOnce(A) -> R,
) -> R {
    let outside = recorder.callback(parameter, &mut |out| encode(&arguments, out));
    let value = call(arguments);
    drop(outside);
    value
}

/// A panic's message, as the panic hook prints it.
fn message(payload: &(dyn Any + Send)) -> String {
    if let Some(text) = payload.downcast_ref::<&str>() {
        (*text).to_owned()
    } else if let Some(text) = payload.downcast_ref::<String>() {
        text.clone()
    } else {
        "Box<dyn Any>".to_owned()
    }
}

#[cfg(test)]
mod tests {
    use super::called_from;

    #[test]
    fn the_first_frame_in_the_code_under_test_is_named() {
        let relative = "   0: std::backtrace::Backtrace::force_capture
             at /rustc/abc/library/std/src/backtrace.rs:310:9
   1: transcript::record::note_panics::{{closure}}
             at ./crates/transcript/src/record.rs:40:25
   2: core::num::<impl i32>::abs
             at /rustc/abc/library/core/src/num/mod.rs:394:5
   3: lines::midpoint::midpoint_line
             at ./exercises/01-lines/src/midpoint.rs:36:39
   4: midpoint::first_octant
             at ./exercises/01-lines/tests/midpoint.rs:12:5
";
        let absolute = "   0: core::num::<impl i32>::abs
             at /rustc/abc/library/core/src/num/mod.rs:394:5
   1: lines::midpoint::midpoint_line
             at /course/exercises/01-lines/src/midpoint.rs:36:39
   2: start_thread
             at ./nptl/pthread_create.c:442:8
";
        for backtrace in [relative, absolute] {
            assert_eq!(
                called_from(backtrace).as_deref(),
                Some("exercises/01-lines/src/midpoint.rs:36:39")
            );
        }
        assert_eq!(
            called_from("   0: start_thread\n             at ./nptl/pthread_create.c:442:8\n"),
            None
        );
    }
}
