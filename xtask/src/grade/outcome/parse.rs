//! Taking a test's output apart: the last panic and its message
//! (proptest's report, the raster diff), insta's snapshot summary, an
//! allocation that failed, a returned error, libtest's failure note.

use super::{RASTER_DIFF_BEGIN, RASTER_DIFF_END};
/// proptest's prefix of a failed property.
const PROPTEST_FAILED: &str = "Test failed: ";
/// proptest's line that starts the shrunk input.
const PROPTEST_MINIMAL: &str = "minimal failing input: ";
/// proptest's statistics after the minimal input.
const PROPTEST_STATS: &str = "\tsuccesses: ";

/// What insta's "Snapshot Summary" box says about a mismatch.
#[derive(Debug, PartialEq)]
pub(super) struct InstaSummary {
    /// `Snapshot file: ...`: the stored `.snap`.
    pub(super) file: String,
    /// `Source: file:line` of the assertion.
    pub(super) source: Option<String>,
    /// The lines between `+new results` and the box's bottom rule.
    pub(super) diff: Option<String>,
}

/// The last snapshot summary insta printed:
///
/// ```text
/// ━━━━━━━━━━━━━━ Snapshot Summary ━━━━━━━━━━━━━━
/// Snapshot file: tests/snapshots/midpoint__octants.snap
/// Source: tests/midpoint.rs:73
/// ...
/// -old snapshot
/// +new results
/// ────────────┬─────────────────────────────────
///     2       │- 11 |..............##.
///           2 │+ 11 |..............#..
/// ────────────┴─────────────────────────────────
/// ```
pub(super) fn insta_summary(output: &str) -> Option<InstaSummary> {
    let start = output.rfind("Snapshot Summary")?;
    let summary = &output[start..];
    let field = |name: &str| {
        summary
            .lines()
            .find_map(|line| line.strip_prefix(name))
            .map(|value| value.trim().to_owned())
    };
    let file = field("Snapshot file: ")?;
    let mut diff = Vec::new();
    let mut in_diff = false;
    for line in summary.lines() {
        if line.starts_with("+new results") {
            in_diff = true;
        } else if in_diff && line.contains('┴') {
            break;
        } else if in_diff && !line.contains('┬') {
            diff.push(line);
        }
    }
    Some(InstaSummary {
        file,
        source: field("Source: "),
        diff: (!diff.is_empty()).then(|| diff.join("\n")),
    })
}

/// A panic as the default hook prints it.
#[derive(Debug, PartialEq)]
pub(super) struct Panic {
    pub(super) location: String,
    pub(super) message: String,
}

/// The size in `memory allocation of N bytes failed`.
pub(super) fn allocation_size(output: &str) -> Option<u64> {
    let rest = output.split("memory allocation of ").nth(1)?;
    rest.split_whitespace().next()?.parse().ok()
}

/// The header `thread 'name' (id) panicked at file:line:col:`, found
/// anywhere in a line (libtest's `test name ... ` may precede it).
fn panic_header(line: &str) -> Option<(usize, String)> {
    let start = line.find("thread '")?;
    let rest = &line[start..];
    let at = rest.find("' panicked at ").or_else(|| {
        // Newer std prints the thread id: `thread 'name' (4568) panicked at`.
        let quote = rest[8..].find('\'')? + 8;
        let after = &rest[quote + 1..];
        let offset = after.find(" panicked at ")?;
        after[..offset]
            .trim()
            .starts_with('(')
            .then_some(quote + offset)
    })?;
    let location = rest[at..].split_once("panicked at ")?.1.trim_end();
    let location = location.strip_suffix(':').unwrap_or(location);
    Some((start, location.to_owned()))
}

/// Where a failed `prop_assert!` stands: proptest's report `Test failed:
/// … at tests/file.rs:12` (the last such place before the minimal input).
pub(super) fn property_assertion_site(message: &str) -> Option<String> {
    let report = message.strip_prefix("Test failed: ")?;
    let report = report
        .split("\nminimal failing input")
        .next()
        .unwrap_or(report);
    report.rmatch_indices(" at ").find_map(|(at, _)| {
        let place = report[at + 4..].split_whitespace().next()?;
        let place = place.trim_end_matches(['.', ',', ';']);
        let (file, line) = place.rsplit_once(':')?;
        (file.ends_with(".rs") && !line.is_empty() && line.bytes().all(|b| b.is_ascii_digit()))
            .then(|| place.to_owned())
    })
}

/// The last panic in the output: its location and its message lines.
pub(super) fn last_panic(output: &str) -> Option<Panic> {
    let lines: Vec<&str> = output.lines().collect();
    let (index, location) = lines
        .iter()
        .enumerate()
        .rev()
        .find_map(|(index, line)| panic_header(line).map(|(_, location)| (index, location)))?;
    // Old std printed `panicked at 'message', file:line:col` on one line.
    if let Some(rest) = location.strip_prefix('\'')
        && let Some((message, location)) = rest.rsplit_once("', ")
    {
        return Some(Panic {
            location: location.to_owned(),
            message: message.to_owned(),
        });
    }
    let mut message = Vec::new();
    for line in &lines[index + 1..] {
        if line.starts_with("note: ")
            || *line == "FAILED"
            || line.starts_with("failures:")
            || line.starts_with("test result: ")
            || line.starts_with("stack backtrace:")
            || line.starts_with("fatal runtime error:")
        {
            break;
        }
        message.push(*line);
    }
    while message.last().is_some_and(|line| line.trim().is_empty()) {
        message.pop();
    }
    Some(Panic {
        location,
        message: message.join("\n"),
    })
}

/// A panic message taken apart.
#[derive(Debug, Default, PartialEq)]
pub(super) struct MessageParts {
    /// The message without the diff, the minimal input and proptest's
    /// statistics.
    pub(super) text: String,
    pub(super) minimal_input: Option<String>,
    pub(super) raster_diff: Option<String>,
}

pub(super) fn split_message(message: &str) -> MessageParts {
    let mut parts = MessageParts::default();
    let mut why = message;
    if let Some(rest) = message.strip_prefix(PROPTEST_FAILED) {
        // `Test failed: <why>.\nminimal failing input: <input>\n\tsuccesses: ...`
        let (before, input) = match rest.find(&format!("\n{PROPTEST_MINIMAL}")) {
            Some(at) => (&rest[..at], Some(&rest[at + 1 + PROPTEST_MINIMAL.len()..])),
            None => (rest, None),
        };
        why = before.strip_suffix('.').unwrap_or(before);
        parts.minimal_input = input.map(|input| {
            let input = input
                .find(&format!("\n{PROPTEST_STATS}"))
                .map_or(input, |at| &input[..at]);
            input.trim().to_owned()
        });
    }
    let mut text = Vec::new();
    let mut diffs: Vec<Vec<&str>> = Vec::new();
    let mut in_diff = false;
    for line in why.lines() {
        if in_diff {
            if line.trim_start().starts_with(RASTER_DIFF_END) {
                in_diff = false;
            } else if let Some(diff) = diffs.last_mut() {
                diff.push(line);
            }
        } else if line.trim() == RASTER_DIFF_BEGIN {
            in_diff = true;
            diffs.push(Vec::new());
        } else {
            text.push(line);
        }
    }
    // Keep the first diff of a message: later ones repeat the story.
    let diff = diffs.into_iter().next();
    while text.last().is_some_and(|line| line.trim().is_empty()) {
        text.pop();
    }
    parts.text = text.join("\n").trim().to_owned();
    if parts.text.is_empty() && diff.is_some() {
        "the rasters differ".clone_into(&mut parts.text); // a message that is only a diff
    }
    parts.raster_diff = diff.map(|lines| lines.join("\n"));
    parts
}

/// A test returning `Err(e)` prints `Error: <e:?>` then fails.
pub(super) fn returned_error(output: &str) -> Option<String> {
    let at = output.find("Error: ")?;
    let rest = &output[at + "Error: ".len()..];
    let end = rest.find("\nFAILED").unwrap_or(rest.len());
    let error = rest[..end].trim();
    (!error.is_empty()).then(|| format!("returned an error: {error}"))
}

/// libtest's own failure note, e.g. `note: test did not panic as expected`.
pub(super) fn failure_note(output: &str) -> Option<String> {
    let block = output.split("\n---- ").nth(1)?;
    let note = block.lines().nth(1)?.trim();
    let note = note.strip_prefix("note: ").unwrap_or(note);
    (!note.is_empty()).then(|| format!("failed: {note}"))
}
