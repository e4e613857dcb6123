//! Reading a finished test process: did it pass, and if not, why.
//!
//! The grader runs one test per process (`<exe> --exact <name> --nocapture
//! --test-threads=1`) with stdout and stderr in one file, so the output is
//! what libtest and the panic hook print, in order:
//!
//! ```text
//! running 1 test
//! test dda::steep ...
//! thread 'dda::steep' (4568) panicked at tests/dda.rs:2:23:
//! assertion `left == right` failed          <- the panic message: the lines
//!   left: 1                                    after the header, up to `note:`
//!  right: 2                                    or libtest's `FAILED`
//! note: run with `RUST_BACKTRACE=1` environment variable to display a backtrace
//! FAILED
//! ...
//! test result: FAILED. 0 passed; 1 failed; ...
//! ```
//!
//! A proptest failure prints one panic per case it tried while shrinking;
//! the last panic is proptest's final report (`Test failed: <why>.` then
//! `minimal failing input: ...`). testkit puts an ASCII raster diff into
//! panic messages between [`RASTER_DIFF_BEGIN`] and [`RASTER_DIFF_END`].

mod parse;

use parse::{
    allocation_size, failure_note, insta_summary, last_panic, property_assertion_site,
    returned_error, split_message,
};

/// The lines that open and close a raster diff in a panic message, and
/// what a `#[testkit::test]` prints, before its token, once every
/// assertion has held.
pub use wire::{RASTER_DIFF_BEGIN, RASTER_DIFF_END, VERDICT_PREFIX};
/// What libtest prints when the one selected test passed: not proof of a
/// pass (the code under test can print it), only a hint of a forgery.
const PASSED_SUMMARY: &str = "test result: ok. 1 passed";
/// The message of `todo!()` (and of `unimplemented!` with "not implemented").
const TODO_PREFIX: &str = "not yet implemented";

/// How the test process ended: the sandbox's record of it, worded here.
pub use crate::sandbox::Exit;

impl Exit {
    /// Why a limit of the grader's stopped it (or did not run it), in
    /// words; `None` when none did. `time_limit_s`: the time limit it ran
    /// under.
    #[must_use]
    pub fn stop_reason(&self, time_limit_s: f64) -> Option<String> {
        Some(if self.not_run {
            format!(
                "not run: an earlier test of this task timed out after {} s",
                seconds(time_limit_s)
            )
        } else if self.timed_out {
            format!(
                "timed out after {} s (a loop without end, or far more steps than the test needs)",
                seconds(time_limit_s)
            )
        } else if let Some(limit) = self.output_limit {
            format!(
                "printed more than {} MiB of output (endless printing?)",
                limit >> 20
            )
        } else if let Some(limit) = self.written_limit {
            format!("wrote more than {limit} MiB of files (or too many files), and was stopped")
        } else if let Some(limit) = self.memory_limit {
            format!(
                "out of memory: its processes together used more than {limit} MiB, and the system stopped them"
            )
        } else {
            return None;
        })
    }
}

/// The verdict on one test run.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Verdict {
    /// Status 0 and the run's token after [`VERDICT_PREFIX`].
    pub passed: bool,
    /// Why it failed, in one short paragraph for a student.
    pub reason: Option<String>,
    /// `file:line:col` of the final panic.
    pub panic_location: Option<String>,
    /// proptest's shrunk input.
    pub minimal_input: Option<String>,
    /// The ASCII raster diff (between the marker lines, markers excluded).
    pub raster_diff: Option<String>,
    /// insta's diff of a mismatching snapshot (`-old snapshot`, `+new results`).
    pub snapshot_diff: Option<String>,
}

/// insta's panic message for a snapshot that does not match.
const INSTA_FAILED: &str = "snapshot assertion for '";

/// Judges a finished test from its exit and its output. A test passed
/// when it exited with status 0 and printed [`VERDICT_PREFIX`] followed by
/// `token`, the secret the grader gave this run alone (see
/// `crates/testkit-macros`): neither libtest's summary nor the exit status
/// is proof, since the code under test can print and exit as it likes.
/// `time_limit_s` is only used to word the timeout reason.
#[must_use]
pub fn judge(output: &str, exit: &Exit, token: &str, time_limit_s: f64) -> Verdict {
    let confirmed = !token.is_empty()
        && output
            .lines()
            .filter_map(|line| line.strip_prefix(VERDICT_PREFIX))
            .any(|t| t.trim_end() == token);
    if exit.code == Some(0) && confirmed {
        return Verdict {
            passed: true,
            ..Verdict::default()
        };
    }
    let panic = last_panic(output);
    let mut verdict = Verdict {
        // A failed `prop_assert!` panics inside proptest's generated code
        // (the test's first line); the assertion's own place is in the
        // message.
        panic_location: panic
            .as_ref()
            .map(|p| property_assertion_site(&p.message).unwrap_or_else(|| p.location.clone())),
        ..Verdict::default()
    };
    let mut panic_reason = None;
    if let Some(panic) = &panic {
        let parts = split_message(&panic.message);
        verdict.minimal_input = parts.minimal_input;
        verdict.raster_diff = parts.raster_diff;
        if parts.text.starts_with(TODO_PREFIX) {
            // Not started: the shrunk input proptest found says nothing.
            verdict.minimal_input = None;
        }
        panic_reason = Some(match parts.text.strip_prefix(TODO_PREFIX) {
            Some(rest) => {
                let rest = rest.trim_start_matches(':').trim();
                if rest.is_empty() {
                    "not implemented yet".to_owned()
                } else {
                    format!("not implemented yet: {rest}")
                }
            }
            None if parts.text.is_empty() => "panicked (with an empty message)".to_owned(),
            None => format!("panicked: {}", parts.text),
        });
        if let Some(name) = panic.message.strip_prefix(INSTA_FAILED)
            && let Some(snapshot) = insta_summary(output)
        {
            let name = name.split('\'').next().unwrap_or_default();
            panic_reason = Some(format!(
                "snapshot '{name}' does not match {} (yours is the .snap.new at the same path under the report's snapshots/)",
                snapshot.file
            ));
            verdict.panic_location = snapshot.source.or(verdict.panic_location);
            verdict.snapshot_diff = snapshot.diff;
        }
    }
    let reason = if let Some(reason) = exit.stop_reason(time_limit_s) {
        reason
    } else if output.contains("has overflowed its stack") {
        "stack overflow".to_owned()
    } else if output.contains("memory allocation of") {
        match allocation_size(output) {
            Some(bytes) => format!("out of memory (an allocation of {bytes} bytes failed)"),
            None => "out of memory".to_owned(),
        }
    } else if let Some(reason) = panic_reason {
        reason
    } else if let Some(signal) = exit.signal {
        match signal {
            6 => "aborted (signal 6)".to_owned(),
            9 => "killed (signal 9; out of memory?)".to_owned(),
            11 => "crashed (signal 11, segmentation fault)".to_owned(),
            _ => format!("aborted (signal {signal})"),
        }
    } else if let Some(reason) = returned_error(output).or_else(|| failure_note(output)) {
        reason
    } else if output.contains("test result: FAILED") {
        "failed".to_owned()
    } else if exit.code == Some(0) && output.contains(PASSED_SUMMARY) {
        "the test did not run to its end: its process reported success without the grader's \
         confirmation (did the code end the process, e.g. with `std::process::exit`?)"
            .to_owned()
    } else {
        match exit.code {
            Some(code) => format!(
                "the test process exited with code {code} before the test finished (process::exit in student code?)"
            ),
            None => "the test process ended before the test finished".to_owned(),
        }
    };
    let reason = match exit.process_limit {
        Some(limit) => format!(
            "{reason} (its processes met the limit of {limit} at once, and the system refused to start more: processes that start processes without end?)"
        ),
        None => reason,
    };
    verdict.reason = Some(reason);
    verdict
}

/// `20` for 20.0, `2.5` for 2.5.
fn seconds(s: f64) -> String {
    if s.fract() == 0.0 {
        format!("{s:.0}")
    } else {
        format!("{s}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn exit(code: i32) -> Exit {
        Exit {
            code: Some(code),
            ..Exit::default()
        }
    }

    fn signal(signal: i32) -> Exit {
        Exit {
            signal: Some(signal),
            ..Exit::default()
        }
    }

    fn reason(output: &str, exit: &Exit) -> String {
        judge(output, exit, TOKEN, 20.0)
            .reason
            .expect("a failure has a reason")
    }

    const TOKEN: &str = "3f0c9a61d2b84e07a5c1e9d6b0f27c48";
    const SUMMARY: &str = "\ntest result: ok. 1 passed; 0 failed; 0 ignored; 0 measured; 3 filtered out; finished in 0.00s\n\n";

    fn passed_output(token: &str) -> String {
        format!("\nrunning 1 test\ntest a ... \n{VERDICT_PREFIX}{token}\nok\n{SUMMARY}")
    }

    #[test]
    fn passes_only_with_status_zero_and_this_runs_token() {
        assert!(judge(&passed_output(TOKEN), &exit(0), TOKEN, 20.0).passed);
        assert!(!judge(&passed_output(TOKEN), &exit(1), TOKEN, 20.0).passed);
        assert!(!judge("\nrunning 1 test\ntest a ... ", &exit(0), TOKEN, 20.0).passed);
        // Another run's token, a prefix of this one's, or none at all.
        let other = "0123456789abcdef0123456789abcdef";
        assert!(!judge(&passed_output(other), &exit(0), TOKEN, 20.0).passed);
        assert!(!judge(&passed_output(&TOKEN[..8]), &exit(0), TOKEN, 20.0).passed);
        assert!(!judge(&passed_output(""), &exit(0), "", 20.0).passed);
    }

    #[test]
    fn a_forged_summary_and_exit_zero_fail_and_say_so() {
        let forged = format!("\nrunning 1 test\ntest a ... ok\n{SUMMARY}");
        let verdict = judge(&forged, &exit(0), TOKEN, 20.0);
        assert!(!verdict.passed);
        assert!(
            verdict
                .reason
                .as_deref()
                .unwrap()
                .contains("did not run to its end"),
            "{verdict:?}"
        );
        // An `#[ignore]`d test is never run, so its summary is a forgery too.
        let ignored = "running 1 test\ntest a ... ignored\n\ntest result: ok. 0 passed; 0 failed; 1 ignored; 0 measured; 3 filtered out\n";
        assert!(!judge(ignored, &exit(0), TOKEN, 20.0).passed);
    }

    #[test]
    fn assertion_message_is_the_lines_up_to_the_note() {
        let output = "\nrunning 1 test\ntest panics ... \nthread 'panics' (4568) panicked at tests/t.rs:2:23:\nassertion `left == right` failed: values differ\n  left: 1\n right: 2\nnote: run with `RUST_BACKTRACE=1` environment variable to display a backtrace\nFAILED\n\nfailures:\n\nfailures:\n    panics\n\ntest result: FAILED. 0 passed; 1 failed; 0 ignored\n";
        let verdict = judge(output, &exit(101), TOKEN, 20.0);
        assert_eq!(
            verdict.reason.as_deref(),
            Some("panicked: assertion `left == right` failed: values differ\n  left: 1\n right: 2")
        );
        assert_eq!(verdict.panic_location.as_deref(), Some("tests/t.rs:2:23"));
    }

    #[test]
    fn todo_is_not_implemented_yet() {
        let output = "test todo ... \nthread 'todo' panicked at src/dda.rs:3:22:\nnot yet implemented: dda: draw {x}\nnote: run with `RUST_BACKTRACE=1` environment variable to display a backtrace\nFAILED\n";
        assert_eq!(
            reason(output, &exit(101)),
            "not implemented yet: dda: draw {x}"
        );
        let bare = "thread 'todo' panicked at src/dda.rs:3:22:\nnot yet implemented\nFAILED\n";
        assert_eq!(reason(bare, &exit(101)), "not implemented yet");
    }

    #[test]
    fn last_panic_wins_and_header_may_follow_libtest_text() {
        let output = "test multi ... thread 'multi' (1) panicked at a.rs:1:1:\ncase 0\nnote: run with `RUST_BACKTRACE=1` environment variable\n\nthread 'multi' (1) panicked at a.rs:1:2:\ncase 1\n\nthread 'multi' panicked at a.rs:1:3:\nfinal\nline2\nFAILED\n\nfailures:\n";
        let verdict = judge(output, &exit(101), TOKEN, 20.0);
        assert_eq!(verdict.reason.as_deref(), Some("panicked: final\nline2"));
        assert_eq!(verdict.panic_location.as_deref(), Some("a.rs:1:3"));
        let old_style = "thread 'x' panicked at 'boom', src/lib.rs:1:1\nnote: run\n";
        assert_eq!(reason(old_style, &exit(101)), "panicked: boom");
    }

    #[test]
    fn raster_diff_is_taken_out_of_the_message() {
        let output = format!(
            "thread 't' panicked at tests/dda.rs:9:5:\nsteep line: the pixels differ\n{RASTER_DIFF_BEGIN}\nlegend\n2 |.+\n1 |#-\n{RASTER_DIFF_END}\nnote: run with\nFAILED\n"
        );
        let verdict = judge(&output, &exit(101), TOKEN, 20.0);
        assert_eq!(
            verdict.reason.as_deref(),
            Some("panicked: steep line: the pixels differ")
        );
        assert_eq!(verdict.raster_diff.as_deref(), Some("legend\n2 |.+\n1 |#-"));
        assert_eq!(verdict.minimal_input, None);
    }

    #[test]
    fn a_failed_prop_assert_is_placed_at_its_assertion() {
        // proptest panics in the code its macro generated (the test's first
        // line); `prop_assert!` names its own place in the message.
        let output = "thread 'p' panicked at tests/liang_barsky.rs:7:1:\nTest failed: x = -0.6 runs parallel to the left border: rejected at tests/common/lines.rs:293.\nminimal failing input: y = 0.5\n\tsuccesses: 0\n\tlocal rejects: 0\n\tglobal rejects: 0\n\nFAILED\n";
        let verdict = judge(output, &exit(101), TOKEN, 20.0);
        assert_eq!(
            verdict.panic_location.as_deref(),
            Some("tests/common/lines.rs:293")
        );
        // A message that names no place keeps the panic's.
        let output = "thread 'p' panicked at tests/dda.rs:20:1:\nTest failed: the ends differ at x = 3\nminimal failing input: a = 1\n\nFAILED\n";
        let verdict = judge(output, &exit(101), TOKEN, 20.0);
        assert_eq!(verdict.panic_location.as_deref(), Some("tests/dda.rs:20:1"));
    }

    #[test]
    fn proptest_report_gives_reason_minimal_input_and_diff() {
        // proptest prints every shrinking step's panic; the last one is its report.
        let output = format!(
            "test p ... \nthread 'p' panicked at tests/dda.rs:9:5:\nfirst {RASTER_DIFF_BEGIN}\n\nthread 'p' panicked at tests/dda.rs:9:5:\nstep\n\nthread 'p' panicked at tests/dda.rs:20:1:\nTest failed: covers both ends\n{RASTER_DIFF_BEGIN}\n1 |#-\n{RASTER_DIFF_END}.\nminimal failing input: line = Line {{\n    a: 1.0,\n}}\n\tsuccesses: 3\n\tlocal rejects: 0\n\tglobal rejects: 0\n\nFAILED\n"
        );
        let verdict = judge(&output, &exit(101), TOKEN, 20.0);
        assert_eq!(
            verdict.reason.as_deref(),
            Some("panicked: covers both ends")
        );
        assert_eq!(
            verdict.minimal_input.as_deref(),
            Some("line = Line {\n    a: 1.0,\n}")
        );
        assert_eq!(verdict.raster_diff.as_deref(), Some("1 |#-"));
        assert_eq!(verdict.panic_location.as_deref(), Some("tests/dda.rs:20:1"));

        let todo = "thread 'p' panicked at tests/dda.rs:20:1:\nTest failed: not yet implemented: dda: draw it.\nminimal failing input: a = 0.0, b = 1.0\n\tsuccesses: 0\n\tlocal rejects: 0\n\tglobal rejects: 0\n\nFAILED\n";
        let verdict = judge(todo, &exit(101), TOKEN, 20.0);
        assert_eq!(
            verdict.reason.as_deref(),
            Some("not implemented yet: dda: draw it")
        );
        // A task not started fails for every input: the shrunk one says nothing.
        assert_eq!(verdict.minimal_input, None);
    }

    #[test]
    fn snapshot_mismatch_gives_insta_diff_and_assertion_line() {
        let output = "running 1 test
test octants ... ━━━━━━━━━━━━━━━━ Snapshot Summary ━━━━━━━━━━━━━━━━
Snapshot file: exercises/01-lines/tests/snapshots/midpoint__octants.snap
Snapshot: octants
Source: exercises/01-lines/tests/midpoint.rs:73
────────────────────────────────────────
Expression: sheet
────────────────────────────────────────
-old snapshot
+new results
────────────┬───────────────────────────
    2       │- 11 |..##.
          2 │+ 11 |..#..
    3     3 │ 10 |.##..
────────────┴───────────────────────────
stored new snapshot /w/exercises/01-lines/tests/snapshots/midpoint__octants.snap.new

thread 'octants' (32248) panicked at /home/u/.cargo/registry/src/x/insta-1.49.0/src/runtime.rs:734:13:
snapshot assertion for 'octants' failed in line 73
note: run with `RUST_BACKTRACE=1` environment variable to display a backtrace
FAILED
";
        let verdict = judge(output, &exit(101), TOKEN, 20.0);
        assert_eq!(
            verdict.reason.as_deref(),
            Some(
                "snapshot 'octants' does not match exercises/01-lines/tests/snapshots/midpoint__octants.snap (yours is the .snap.new at the same path under the report's snapshots/)"
            )
        );
        assert_eq!(
            verdict.panic_location.as_deref(),
            Some("exercises/01-lines/tests/midpoint.rs:73")
        );
        assert_eq!(
            verdict.snapshot_diff.as_deref(),
            Some("    2       │- 11 |..##.\n          2 │+ 11 |..#..\n    3     3 │ 10 |.##..")
        );
    }

    #[test]
    fn crashes_have_their_own_reasons() {
        let timed_out = Exit {
            timed_out: true,
            signal: Some(9),
            ..Exit::default()
        };
        assert_eq!(
            reason("test l ... ", &timed_out),
            "timed out after 20 s (a loop without end, or far more steps than the test needs)"
        );
        assert_eq!(
            judge("", &timed_out, TOKEN, 2.5).reason.as_deref(),
            Some(
                "timed out after 2.5 s (a loop without end, or far more steps than the test needs)"
            )
        );
        let flood = Exit {
            output_limit: Some(64 << 20),
            signal: Some(9),
            ..Exit::default()
        };
        assert!(reason("aaaa", &flood).starts_with("printed more than 64 MiB"));
        assert_eq!(
            reason(
                "test o ... \nthread 'o' (1) has overflowed its stack\nfatal runtime error: stack overflow, aborting\n",
                &signal(6)
            ),
            "stack overflow"
        );
        assert_eq!(
            reason(
                "test a ... memory allocation of 1099511627776 bytes failed\nnote: run with\n",
                &signal(6)
            ),
            "out of memory (an allocation of 1099511627776 bytes failed)"
        );
        assert_eq!(reason("test a ... ", &signal(6)), "aborted (signal 6)");
        let forked = Exit {
            process_limit: Some(256),
            ..exit(101)
        };
        assert_eq!(
            reason(
                "test f ... \nthread 'f' (1) panicked at src/f.rs:3:5:\nfork: Resource temporarily unavailable\n",
                &forked
            ),
            "panicked: fork: Resource temporarily unavailable (its processes met the limit of 256 at once, and the system refused to start more: processes that start processes without end?)"
        );
        assert_eq!(
            reason("test a ... ", &signal(11)),
            "crashed (signal 11, segmentation fault)"
        );
        assert_eq!(
            reason("\nrunning 1 test\ntest exits ... ", &exit(3)),
            "the test process exited with code 3 before the test finished (process::exit in student code?)"
        );
        assert!(
            reason("\nrunning 1 test\ntest exits ... ", &exit(0)).contains("exited with code 0")
        );
    }

    #[test]
    fn libtest_failures_without_a_panic() {
        let returned = "test err ... Error: \"bad\"\nFAILED\n\nfailures:\n\ntest result: FAILED. 0 passed; 1 failed\n";
        assert_eq!(reason(returned, &exit(101)), "returned an error: \"bad\"");
        let should_panic = "test sp - should panic ... FAILED\n\nfailures:\n\n---- sp stdout ----\nnote: test did not panic as expected at tests/t.rs:5:28\n\nfailures:\n    sp\n\ntest result: FAILED. 0 passed; 1 failed\n";
        assert_eq!(
            reason(should_panic, &exit(101)),
            "failed: test did not panic as expected at tests/t.rs:5:28"
        );
    }
}
