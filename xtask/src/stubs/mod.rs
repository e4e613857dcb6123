//! The student files' stubs, as the grader reads them: the markers of a
//! solution region, which file holds a task's stub, and the masking of
//! comments and strings the grader's checks share. Writing the stubs, and
//! the do-nothing edition of the self-test, is the staff's (`cargo xtask
//! stubs`, in the course repository only, which reads Rust as syn's
//! syntax trees).
//!
//! Every `reference/NN-topic/src/X.rs` is copied to `exercises/NN-topic/src/X.rs`
//! with each marked solution replaced by a `todo!`:
//!
//! ```text
//!     // BEGIN SOLUTION dda: draw the line with the DDA        todo!("dda: draw the line with the DDA")
//!     let steps = ...;                                    =>
//!     // END SOLUTION
//! ```
//!
//! The `todo!` sits at the indentation of the `BEGIN` line. A bare
//! `// BEGIN SOLUTION` (no `<task>: <instruction>`) removes its region
//! entirely: helpers and `use` lines only the solution needs. Everything
//! else, doc comments and signatures included, is copied verbatim, and
//! the stub is then kept free of the warnings its `todo!`s alone provoke
//! (see [`quiet`]).
//!
//! `reference/` holds solutions only: a file there without a marker is an
//! error. Given code (and `src/lib.rs`, hand-written) exists once, in
//! `exercises/`; a stage lays `reference/*/src` over it (see `stage`).

use std::path::Path;

use crate::files::is_wgsl;

pub mod quiet;

/// Opens a solution region; may be followed by `<task>: <instruction>`.
#[cfg(feature = "staff")]
pub const BEGIN_MARKER: &str = "// BEGIN SOLUTION";
/// Closes a solution region.
#[cfg(feature = "staff")]
pub const END_MARKER: &str = "// END SOLUTION";

/// Whether `text`, the official copy of `file` in a topic whose tasks are
/// `task_ids`, holds the stub of one of them as `cargo xtask stubs` writes it:
/// `todo!("<task id>: …")` in Rust code (not in a comment, not inside a
/// string), a line `// TODO <task id>: …` in WGSL. This is what makes a
/// file a task file in an edition (which has no `reference/` to say so):
/// a given file whose doc comment mentions `todo!()` holds no such call,
/// and stays the course's.
#[must_use]
pub fn holds_task_stub(file: &Path, text: &str, task_ids: &[&str]) -> bool {
    let names_a_task = |rest: &str| {
        task_ids
            .iter()
            .any(|id| rest.strip_prefix(id).is_some_and(|r| r.starts_with(':')))
    };
    if is_wgsl(file) {
        return text.lines().any(|line| {
            line.trim_start()
                .strip_prefix("// TODO ")
                .is_some_and(names_a_task)
        });
    }
    let masked = quiet::mask(text);
    masked.match_indices("todo!(").any(|(at, call)| {
        let word_start = !masked[..at].ends_with(|c: char| c.is_alphanumeric() || c == '_');
        let after = at + call.len();
        let open = after + (masked[after..].len() - masked[after..].trim_start().len());
        // The mask keeps a string's quotes and blanks what is between
        // them: the task id is read from the text itself.
        word_start && masked[open..].starts_with('"') && names_a_task(&text[open + 1..])
    })
}
