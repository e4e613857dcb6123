//! How a stage fared in a frame, and the guard every call of your code
//! goes through: a `todo!()` or a panic becomes the stage's status.

use std::panic::{AssertUnwindSafe, catch_unwind};

/// How a stage fared in one frame.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Status {
    /// Not needed by this frame (lines in a filled picture, say).
    Unused,
    /// Needed, but nothing reached it: a stage before it drew nothing.
    NotReached,
    /// Every call returned.
    Ok,
    /// Its topic is not part of the build (it does not compile).
    Missing,
    /// Drawn by the course's given stand-in: its topic is not in this
    /// edition, or not graded in this run.
    Given,
    /// It reached a `todo!()`: the message.
    NotYet(String),
    /// It panicked: the message.
    Panicked(String),
    /// It returned an error: the message.
    Failed(String),
}

impl Status {
    /// Whether the stage can still be called in this frame.
    #[must_use]
    pub fn usable(&self) -> bool {
        matches!(self, Self::Unused | Self::NotReached | Self::Ok)
    }

    /// One line for the screen.
    #[must_use]
    pub fn describe(&self) -> String {
        match self {
            Self::Unused => "not used by this picture".to_owned(),
            Self::NotReached => "not reached: nothing came through the stages before it".to_owned(),
            Self::Ok => "ok".to_owned(),
            Self::Given => {
                "drawn by the course's given stand-in: its topic is not in this edition (or not graded in this run)"
                    .to_owned()
            }
            Self::Missing => {
                "left out: its topic is not in this build (not in this edition, not graded in this run, or it does not compile)"
                    .to_owned()
            }
            Self::NotYet(message) => format!("not written yet: {message}"),
            Self::Panicked(message) => format!("panicked: {message}"),
            Self::Failed(message) => format!("returned an error: {message}"),
        }
    }
}

/// The text of a panic's payload.
fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| (*s).to_owned())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "(a panic without a message)".to_owned())
}

/// Runs `call` unless the stage has already failed in this frame; a panic
/// becomes the stage's status (a `todo!()` is [`Status::NotYet`]).
pub fn guarded<R>(status: &mut Status, call: impl FnOnce() -> R) -> Option<R> {
    if !status.usable() {
        return None;
    }
    match catch_unwind(AssertUnwindSafe(call)) {
        Ok(value) => {
            *status = Status::Ok;
            Some(value)
        }
        Err(payload) => {
            let message = panic_message(payload.as_ref());
            *status = match message.strip_prefix("not yet implemented") {
                Some(rest) => Status::NotYet(rest.strip_prefix(": ").unwrap_or(rest).to_owned()),
                None => Status::Panicked(message),
            };
            None
        }
    }
}

/// The name worker threads carry: panics there are reported on screen, so
/// [`quiet_panics`] keeps them off the terminal.
pub const WORKER_THREAD: &str = "viewer-stages";

/// Installs a panic hook that is silent on [`WORKER_THREAD`] threads (their
/// panics are caught and shown) and prints as usual elsewhere.
pub fn quiet_panics() {
    let default = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        if std::thread::current().name() != Some(WORKER_THREAD) {
            default(info);
        }
    }));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_todo_is_not_yet_written_and_a_panic_is_a_panic() {
        let mut status = Status::Unused;
        assert_eq!(guarded(&mut status, || 3), Some(3));
        assert_eq!(status, Status::Ok);
        let mut status = Status::Unused;
        let got: Option<()> = guarded(&mut status, || todo!("dda: plot one fragment per column"));
        assert_eq!(got, None);
        assert_eq!(
            status,
            Status::NotYet("dda: plot one fragment per column".to_owned())
        );
        // Once failed, the stage is not called again in this frame.
        assert_eq!(guarded(&mut status, || 4), None);
        let mut status = Status::Unused;
        let _ = guarded(&mut status, || -> u8 { panic!("index {} out of range", 7) });
        assert_eq!(status, Status::Panicked("index 7 out of range".to_owned()));
        assert!(status.describe().starts_with("panicked: index 7"));
    }
}
