//! The replaying side: what a [`crate::task`] function does in the
//! grader's replay build, where the student's body is not compiled.
//!
//! Every way the transcript and the test can fall out of step ends in a
//! panic that names the task function, so the test fails with a reason
//! a student can read.

use std::fs::File;
use std::io::BufReader;
use std::path::PathBuf;
use std::sync::{Arc, Mutex, OnceLock, PoisonError};

use crate::evidence::Replay;

use crate::event::{self, Event};

/// The transcript being read.
enum Player {
    /// Its frames, read one at a time.
    Reading(Mutex<Reader>),
    /// The recording process made no call of a task function at all.
    Empty,
}

/// The file and the batch of calls being replayed.
struct Reader {
    input: BufReader<File>,
    /// The batch of calls and where its next call starts.
    batch: Option<(Arc<[u8]>, usize)>,
}

/// A step of the record, a batch taken apart into its calls.
enum Next {
    Event(Event),
    Call(u32, Bytes),
}

/// One call's arguments: a piece of its batch, shared rather than copied
/// (a long line's batch holds tens of thousands of calls).
pub struct Bytes {
    batch: Arc<[u8]>,
    range: std::ops::Range<usize>,
}

impl std::ops::Deref for Bytes {
    type Target = [u8];

    fn deref(&self) -> &[u8] {
        &self.batch[self.range.clone()]
    }
}

impl Player {
    fn get() -> &'static Player {
        static PLAYER: OnceLock<Player> = OnceLock::new();
        PLAYER.get_or_init(|| {
            let Some(path) = std::env::var_os(crate::REPLAY_VAR).map(PathBuf::from) else {
                panic!(
                    "this build replays a recorded run of the student's code and was started without one (`{}` is unset): run the tests with `cargo test`, or grade with `cargo xtask grade`",
                    crate::REPLAY_VAR
                )
            };
            match File::open(&path) {
                Ok(file) => Player::Reading(Mutex::new(Reader {
                    input: BufReader::new(file),
                    batch: None,
                })),
                Err(error) if error.kind() == std::io::ErrorKind::NotFound => Player::Empty,
                Err(error) => panic!("cannot read the transcript {}: {error}", path.display()),
            }
        })
    }

    /// The next step; `None` at the end.
    fn next(&self, name: &str) -> Option<Next> {
        let broken = |error: std::io::Error| -> ! {
            panic!("the record of your code's run is broken during a call of `{name}`: {error}")
        };
        let Player::Reading(reader) = self else {
            return None;
        };
        let mut reader = reader.lock().unwrap_or_else(PoisonError::into_inner);
        loop {
            if let Some((batch, at)) = &mut reader.batch {
                match event::next_call(batch, at) {
                    Ok(Some((parameter, range))) => {
                        let bytes = Bytes {
                            batch: Arc::clone(batch),
                            range,
                        };
                        return Some(Next::Call(parameter, bytes));
                    }
                    Ok(None) => reader.batch = None,
                    Err(error) => broken(error),
                }
            }
            match event::read(&mut reader.input) {
                Ok(Some(Event::Calls(calls))) => reader.batch = Some((calls.into(), 0)),
                Ok(event) => return event.map(Next::Event),
                Err(error) => broken(error),
            }
        }
    }
}

/// What a replayed call does next.
pub enum Step {
    /// Call callback parameter number `.0` with the encoded arguments `.1`.
    Callback(u32, Bytes),
    /// Return the encoded values (the value, then the `&mut` parameters').
    Return(Vec<u8>),
    /// Panic with this message, as the student's code did.
    Panic(String),
}

/// One replayed call of a task function.
pub struct Replaying {
    name: &'static str,
}

impl Replaying {
    /// The test calls the task function `name`: the transcript must say
    /// that the student's code was called here too.
    #[must_use]
    pub fn enter(name: &'static str) -> Replaying {
        match Player::get().next(name) {
            Some(Next::Event(Event::Enter(recorded))) if recorded == name => Replaying { name },
            Some(Next::Event(Event::Enter(recorded))) => panic!(
                "the test calls `{name}` where your code's run called `{recorded}`: the runs differ (does your code depend on the time, on randomness or on the order of a HashMap?)"
            ),
            Some(other) => panic!(
                "the test calls `{name}` where your code's run was still inside another call ({}): the runs differ",
                describe(&other)
            ),
            None => panic!(
                "the test calls `{name}`, but your code's run ended before this call (it crashed, exited or was stopped: see its own output)"
            ),
        }
    }

    /// The next step of this call.
    #[must_use]
    pub fn next(&self) -> Step {
        let name = self.name;
        match Player::get().next(name) {
            Some(Next::Call(parameter, arguments)) => Step::Callback(parameter, arguments),
            Some(Next::Event(Event::Return(values))) => Step::Return(values),
            Some(Next::Event(Event::Panic(message))) => Step::Panic(message),
            Some(Next::Event(Event::Enter(other))) => panic!(
                "during the call of `{name}` your code's run called `{other}` from the test's code, where the test does not: the runs differ"
            ),
            Some(Next::Event(Event::Calls(_))) => unreachable!("batches are taken apart"),
            None => panic!(
                "your code's run ended during the call of `{name}` (it crashed, exited or was stopped: see its own output)"
            ),
        }
    }

    /// Reads a recorded value the test expects to be of type `T` from the
    /// front of `input`.
    #[must_use]
    pub fn decode<T: Replay>(&self, input: &mut &[u8]) -> T {
        T::replay(input).unwrap_or_else(|error| {
            panic!(
                "the record of `{}` does not hold values of the types the test expects ({error})",
                self.name
            )
        })
    }

    /// Brings `value`, a `&mut` parameter of the call, to what the
    /// student's call left of it, from the front of `input`.
    pub fn changes<T: Replay>(&self, value: &mut T, input: &mut &[u8]) {
        value.replay_changes(input).unwrap_or_else(|error| {
            panic!(
                "the record of `{}` does not hold the changes of a value the test passed in ({error})",
                self.name
            )
        });
    }

    /// Every recorded value was read.
    pub fn done(&self, input: &[u8]) {
        assert!(
            input.is_empty(),
            "the record of `{}` holds more values than the test expects",
            self.name
        );
    }

    /// The transcript names a callback parameter that does not exist.
    pub fn no_such_callback(&self, parameter: u32) -> ! {
        panic!(
            "the record of `{}` calls parameter {parameter}, which is not a callback",
            self.name
        )
    }
}

/// A recorded `&'static` value: kept for the rest of the process (a replay
/// is one short test).
#[must_use]
pub fn leak<T>(value: T) -> &'static T {
    Box::leak(Box::new(value))
}

/// A step of the record, for a message.
fn describe(next: &Next) -> String {
    match next {
        Next::Event(Event::Enter(name)) => format!("a call of `{name}`"),
        Next::Call(parameter, _) => format!("a callback of parameter {parameter}"),
        Next::Event(Event::Calls(_)) => "its callbacks".to_owned(),
        Next::Event(Event::Return(_)) => "its return".to_owned(),
        Next::Event(Event::Panic(_)) => "its panic".to_owned(),
    }
}
