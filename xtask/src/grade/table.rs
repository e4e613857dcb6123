//! The grade as a student reads it in the terminal: a table of points per
//! task, then for every failing task its first failing test with the reason,
//! the minimal input and the raster diff.

use std::fmt::Write as _;
use std::io::IsTerminal as _;
use std::path::Path;

use super::report::{self, Report, TaskReport, TaskStatus, TestStatus};

/// Titles longer than this are cut in the table.
const TITLE_WIDTH: usize = 44;
/// Compiler errors longer than this many lines are cut in the terminal
/// (`report.json` has them all).
const COMPILE_ERROR_LINES: usize = 40;

/// Plain ANSI colours, or none.
#[derive(Debug, Clone, Copy)]
pub struct Style {
    colour: bool,
}

impl Style {
    /// Colour when stdout is a terminal and `NO_COLOR` is unset or empty.
    #[must_use]
    pub fn detect() -> Self {
        let no_colour = std::env::var_os("NO_COLOR").is_some_and(|v| !v.is_empty());
        Self {
            colour: !no_colour && std::io::stdout().is_terminal(),
        }
    }

    fn paint(self, code: &str, text: &str) -> String {
        if self.colour {
            format!("\x1b[{code}m{text}\x1b[0m")
        } else {
            text.to_owned()
        }
    }

    /// Green.
    #[must_use]
    pub fn good(self, text: &str) -> String {
        self.paint("32", text)
    }

    /// Red, bold.
    #[must_use]
    pub fn bad(self, text: &str) -> String {
        self.paint("1;31", text)
    }

    /// Yellow.
    #[must_use]
    pub fn warn(self, text: &str) -> String {
        self.paint("33", text)
    }

    /// Bold.
    #[must_use]
    pub fn bold(self, text: &str) -> String {
        self.paint("1", text)
    }

    /// Dim.
    #[must_use]
    pub fn dim(self, text: &str) -> String {
        self.paint("2", text)
    }
}

/// Cuts `text` to `width` characters, marking the cut with `…`.
fn cut(text: &str, width: usize) -> String {
    if text.chars().count() <= width {
        text.to_owned()
    } else {
        let mut cut: String = text.chars().take(width - 1).collect();
        cut.push('…');
        cut
    }
}

fn pad(text: &str, width: usize) -> String {
    let len = text.chars().count();
    format!("{text}{}", " ".repeat(width.saturating_sub(len)))
}

fn status_text(task: &TaskReport) -> &'static str {
    match task.status {
        TaskStatus::Ok => "ok",
        TaskStatus::Fail => "FAIL",
        TaskStatus::CompileError => "compile error",
        TaskStatus::Error => "error",
    }
}

fn points_text(score: f64, max: f64) -> String {
    format!("{score:.1} / {}", report::points(max))
}

/// Indents every non-blank line of `text` by `indent`.
fn indented(text: &str, indent: &str) -> String {
    let line = |line: &str| {
        if line.trim().is_empty() {
            "\n".to_owned()
        } else {
            format!("{indent}{}\n", shown(line))
        }
    };
    text.lines().map(line).collect()
}

/// Text from a submission as it may reach a terminal, on one line: every
/// control character, line breaks and tabs too, and every mark that
/// reorders or breaks the text after it (bidirectional overrides, Unicode's
/// line and paragraph separators) written as a visible escape (`\n`,
/// `\r`, `\t`, `\u{1b}`, `\u{202e}`).
///
/// The grader's one escaping function for the terminal. A file name, a
/// test's name, a panic message or a line of compiler output (which quotes
/// student code) is the submission's text: written raw, a line break in it
/// prints a line the grader never wrote (`total 20.0 / 20 ok` under the
/// real total), and an escape sequence moves the cursor, clears the screen
/// or recolours the table. Text of many lines is split at its line breaks
/// first and each line passed through here ([`indented`], [`continued`]).
#[must_use]
pub fn shown(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if c.is_control() || reorders(c) => {
                out.extend(c.escape_unicode());
            }
            c => out.push(c),
        }
    }
    out
}

/// Whether `c` is an invisible mark that reorders the text around it or
/// breaks its line (the "Trojan Source" characters, CVE-2021-42574, and
/// U+2028/U+2029, which some terminals and editors break lines at).
fn reorders(c: char) -> bool {
    matches!(
        c,
        '\u{061c}'
            | '\u{200e}'
            | '\u{200f}'
            | '\u{2028}'
            | '\u{2029}'
            | '\u{202a}'..='\u{202e}'
            | '\u{2066}'..='\u{2069}'
    )
}

/// Text of many lines after a label: its first line as it is, each later
/// one on a line of its own indented by `indent`; every line [`shown`].
#[must_use]
pub fn continued(text: &str, indent: &str) -> String {
    let mut lines = text.lines();
    let mut out = shown(lines.next().unwrap_or_default());
    for line in lines {
        out.push('\n');
        out.push_str(indent);
        out.push_str(&shown(line));
    }
    out
}

/// Which failures the terminal output shows below the table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Details {
    /// The table alone.
    None,
    /// The first failure of every failing task.
    EveryTask,
    /// The first failure of the first failing task only: one screen.
    FirstTask,
}

/// The whole terminal output for a report: the table, then the failures
/// `details` asks for.
pub fn render(report: &Report, out: &Path, style: Style, details: Details) -> String {
    let mut text = String::new();
    // Columns: topic, task id, title, points (right-aligned), status.
    let mut rows: Vec<[String; 5]> =
        vec![["topic", "task", "", "points", "status"].map(str::to_owned)];
    let mut statuses = vec![None];
    for topic in &report.topics {
        for (i, task) in topic.tasks.iter().enumerate() {
            let bonus = if task.bonus { " (bonus)" } else { "" };
            rows.push([
                if i == 0 {
                    shown(&topic.name)
                } else {
                    String::new()
                },
                shown(&task.id),
                cut(&shown(&format!("{}{bonus}", task.title)), TITLE_WIDTH),
                points_text(task.score, task.points),
                status_text(task).to_owned(),
            ]);
            statuses.push(Some(task.status));
        }
    }
    // The points of the tasks that are not bonuses against their maximum,
    // the bonus apart: a bonus never hides a lost point.
    let base: f64 = report.topics.iter().map(|t| t.base_score()).sum();
    let (bonus, possible) = report.topics.iter().fold((0.0, 0.0), |(e, p), t| {
        let (earned, of) = t.bonus();
        (e + earned, p + of)
    });
    let mut total = points_text(report::round2(base), report.max_score);
    if possible > 0.0 {
        total = format!(
            "{total} + {} bonus",
            points_text(report::round2(bonus), possible)
        );
    }
    rows.push(["total", "", "", &total, ""].map(str::to_owned));
    statuses.push(None);
    let mut widths = [0; 5];
    for row in &rows {
        for (width, cell) in widths.iter_mut().zip(row) {
            *width = (*width).max(cell.chars().count());
        }
    }
    let last = rows.len() - 1;
    let _ = writeln!(text);
    for (index, (row, status)) in rows.iter().zip(&statuses).enumerate() {
        let plain = format!(
            "{}  {}  {}  {:>w$}  ",
            pad(&row[0], widths[0]),
            pad(&row[1], widths[1]),
            pad(&row[2], widths[2]),
            row[3],
            w = widths[3]
        );
        let line = match status {
            Some(TaskStatus::Ok) => format!("{plain}{}", style.good(&row[4])),
            Some(TaskStatus::Fail) => format!("{plain}{}", style.bad(&row[4])),
            Some(TaskStatus::CompileError | TaskStatus::Error) => {
                format!("{plain}{}", style.warn(&row[4]))
            }
            None if index == 0 || index == last => {
                style.bold(format!("{plain}{}", row[4]).trim_end())
            }
            None => plain,
        };
        let _ = writeln!(text, "{}", line.trim_end());
    }

    let mut shown_one = false;
    for topic in &report.topics {
        if let Some(errors) = &topic.compile_error {
            let _ = writeln!(text);
            let _ = writeln!(
                text,
                "{}",
                style.bad(&format!(
                    "{}: compile error, so all its tasks score 0",
                    shown(&topic.name)
                ))
            );
            let lines: Vec<&str> = errors.lines().collect();
            let shown = lines.len().min(COMPILE_ERROR_LINES);
            text.push_str(&indented(&lines[..shown].join("\n"), "  "));
            if shown < lines.len() {
                let _ = writeln!(
                    text,
                    "  {}",
                    style.dim(&format!(
                        "[{} more lines in report.json]",
                        lines.len() - shown
                    ))
                );
            }
        }
        for error in &topic.errors {
            let _ = writeln!(text);
            let _ = writeln!(
                text,
                "{}",
                style.warn(&format!(
                    "{}: {}",
                    shown(&topic.name),
                    continued(error, "  ")
                ))
            );
        }
        for task in &topic.tasks {
            // (An error of every task that the topic's says once.)
            if let Some(error) = task.error.as_ref().filter(|e| !topic.errors.contains(e)) {
                let _ = writeln!(text);
                let _ = writeln!(
                    text,
                    "{}",
                    style.warn(&format!(
                        "{} / {}: {}",
                        shown(&topic.name),
                        shown(&task.id),
                        continued(error, "  ")
                    ))
                );
            }
            let wanted = match details {
                Details::None => false,
                Details::EveryTask => true,
                Details::FirstTask => !shown_one,
            };
            if wanted && task.status == TaskStatus::Fail {
                failure(&mut text, out, &topic.name, task, style);
                shown_one = true;
            }
        }
    }
    if !report.sandboxed {
        let _ = writeln!(text);
        let _ = writeln!(
            text,
            "{}",
            style.warn(
                "unsandboxed: no bubblewrap here, so nothing kept the tests from the rest of this machine (install the `bubblewrap` package)"
            )
        );
    }
    if let Some(integrity) = report
        .integrity
        .as_ref()
        .filter(|i| !i.not_graded.is_empty())
    {
        let files: Vec<String> = integrity
            .not_graded
            .iter()
            .map(|f| shown(&f.to_string_lossy()))
            .collect();
        let _ = writeln!(text);
        let _ = writeln!(
            text,
            "{}",
            style.dim(&format!(
                "not graded (only task files are taken from a submission; the course's were used): {}",
                files.join(", ")
            ))
        );
    }
    if let Some(integrity) = report.integrity.as_ref().filter(|i| i.flagged()) {
        let _ = writeln!(text);
        let _ = writeln!(
            text,
            "{}",
            style.warn(&format!("FLAGGED: {}", shown(&integrity.summary())))
        );
    }
    if !report.left_out.is_empty() {
        let _ = writeln!(text);
        let _ = writeln!(
            text,
            "{}",
            style.warn(&format!(
                "left out of the report ({} entries the tests left that are no plain file, or past the {} it keeps; report.html names them all): {}",
                report.left_out.len(),
                crate::files::size(crate::files::KEPT_BUDGET),
                report
                    .left_out
                    .iter()
                    .take(3)
                    .map(|line| shown(line))
                    .collect::<Vec<_>>()
                    .join("; ")
            ))
        );
    }
    let _ = writeln!(text);
    let _ = writeln!(
        text,
        "{}",
        style.dim(&format!(
            "report: {} (pictures side by side; also report.json, results.json, junit.xml)",
            shown(&out.join("report.html").display().to_string())
        ))
    );
    text
}

fn failure(text: &mut String, out: &Path, topic: &str, task: &TaskReport, style: Style) {
    let Some(test) = task.first_failure() else {
        return;
    };
    let counted = task.passed + task.failed;
    let _ = writeln!(text);
    let _ = writeln!(
        text,
        "{}",
        style.bad(&format!(
            "{} / {}: {} of {counted} tests failed",
            shown(topic),
            shown(&task.id),
            task.failed
        ))
    );
    let _ = writeln!(text, "  test:    {}", style.bold(&shown(&test.name)));
    if let Some(location) = &test.panic_location {
        let _ = writeln!(text, "  at:      {}", shown(location));
    }
    if let Some(reason) = &test.reason {
        let mut lines = reason.lines();
        let _ = writeln!(
            text,
            "  reason:  {}",
            shown(lines.next().unwrap_or_default())
        );
        for line in lines {
            let _ = writeln!(text, "           {}", shown(line));
        }
    }
    if let Some(input) = &test.minimal_input {
        let _ = writeln!(text, "  minimal failing input:");
        text.push_str(&indented(input, "    "));
    }
    if let Some(diff) = &test.raster_diff {
        let _ = writeln!(text, "  raster diff (expected vs yours):");
        text.push_str(&indented(diff, "    "));
    }
    if let Some(diff) = &test.snapshot_diff {
        let _ = writeln!(text, "  snapshot diff (- expected, + yours):");
        text.push_str(&indented(diff, "    "));
    }
    if let Some(dir) = &test.images_dir {
        let _ = writeln!(
            text,
            "  images:  {}",
            shown(&out.join(dir).display().to_string())
        );
    }
    if !task.hints.is_empty() {
        let _ = writeln!(
            text,
            "  hint:    cargo xtask hint {}/{}  ({} hints, one more each time)",
            shown(topic),
            shown(&task.id),
            task.hints.len()
        );
    }
    let others: Vec<String> = task
        .tests
        .iter()
        .filter(|t| t.status == TestStatus::Failed && t.name != test.name)
        .map(|t| shown(&t.name))
        .collect();
    if !others.is_empty() {
        let names = if others.len() <= 3 {
            others.join(", ")
        } else {
            format!("{}, ...", others[..3].join(", "))
        };
        let _ = writeln!(
            text,
            "  {}",
            style.dim(&format!(
                "and {} other failing test(s) in this task: {names}",
                others.len()
            ))
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grade::report::tests::{report_of, test};

    /// What a hostile submission names can hold: a line break, a fake
    /// table line after it, and a terminal's "clear the screen".
    const PLANTED: &str = "x\ntotal 20.0 / 20 ok\r\u{1b}[2J\u{202e}";

    /// The table of a report whose every text from the submission (a
    /// grading file's name, a test's name, its reason, its panic place, a
    /// topic's error, a compiler message, what was left out, the report's
    /// folder) holds [`PLANTED`]: no line of its own appears, and no
    /// control character reaches the terminal.
    #[test]
    fn text_from_a_submission_prints_no_line_of_its_own() {
        let mut failed = test(&format!("t::{PLANTED}"), TestStatus::Failed);
        failed.reason = Some(format!("assertion failed: {PLANTED}"));
        failed.panic_location = Some(PLANTED.to_owned());
        failed.images_dir = Some(std::path::PathBuf::from(PLANTED));
        let mut report = report_of(20.0, vec![failed, test(PLANTED, TestStatus::Failed)]);
        report.integrity = Some(crate::grade::submission::Integrity {
            changed: vec![PLANTED.into()],
            not_graded: vec![PLANTED.into()],
            ..Default::default()
        });
        report.topics[0]
            .errors
            .push(format!("cannot list {PLANTED}"));
        report.topics[0].compile_error = Some(format!("error: {PLANTED}\n  --> {PLANTED}"));
        report
            .left_out
            .push(format!("images/{PLANTED}: a symbolic link"));
        let text = render(
            &report,
            std::path::Path::new(PLANTED),
            Style { colour: false },
            Details::EveryTask,
        );
        // (Text of many lines, a compiler's message or a reason, keeps its
        // lines, each indented under its label: none starts a line.)
        let totals: Vec<&str> = text.lines().filter(|l| l.starts_with("total")).collect();
        assert_eq!(totals, ["total           0.0 / 20"], "{text}");
        assert!(!text.contains(['\r', '\u{1b}', '\u{202e}']), "{text}");
        assert!(
            text.contains("x\\ntotal 20.0 / 20 ok\\r\\u{1b}[2J"),
            "{text}"
        );
    }

    #[test]
    fn control_characters_reach_the_terminal_escaped() {
        assert_eq!(
            shown("a\u{1b}[2Jb\tc\nd\u{7}"),
            "a\\u{1b}[2Jb\\tc\\nd\\u{7}"
        );
        assert_eq!(indented("x\u{1b}[H", "  "), "  x\\u{1b}[H\n");
    }
}
