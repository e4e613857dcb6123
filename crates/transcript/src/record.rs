//! The recording side: what a [`crate::task`] function does in the
//! student's crate.

use std::any::Any;
use std::cell::Cell;
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
                    let message = message(payload.as_ref());
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

    /// The call invokes its callback parameter number `parameter`, whose
    /// arguments `encode` writes; keep the returned guard alive while the
    /// callback runs.
    ///
    /// Inlined: outside the grader (a benchmark, the viewer) a callback
    /// costs the test of one pointer.
    #[must_use]
    #[inline]
    pub fn callback(self, parameter: u32, encode: &mut dyn FnMut(&mut Vec<u8>)) -> Outside {
        match self.0 {
            Some(recorder) => recorder.callback(parameter, encode),
            None => Outside(None),
        }
    }
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
