//! The grade as a student reads it in the terminal: a table of points per
//! task, then for every failing task its first failing test with the reason,
//! the minimal input and the raster diff.

use std::fmt::Write as _;
use std::io::IsTerminal as _;
use std::path::Path;

use super::report::{self, Report, TaskReport, TaskStatus, TestStatus, TopicReport};

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

/// A task's row in the table, as the sheet gives it.
#[derive(Debug, Clone)]
pub struct RowShape {
    /// The task's id.
    pub id: String,
    /// The task's title.
    pub title: String,
    /// Whether it is a bonus task.
    pub bonus: bool,
    /// Its points.
    pub points: f64,
}

/// The table's columns, wide enough for every row and total any grade of
/// these tasks can show: known before a test runs, so that each topic's
/// rows can be printed as soon as its tests end and still line up.
#[derive(Debug, Clone)]
pub struct Layout {
    /// topic, task, title, points.
    widths: [usize; 4],
}

/// The columns' headings.
const HEADINGS: [&str; 5] = ["topic", "task", "", "points", "status"];

impl Layout {
    /// The columns for the tasks `rows`, of the topics `topics`.
    #[must_use]
    pub fn new<'a>(topics: impl IntoIterator<Item = &'a str>, rows: &[RowShape]) -> Self {
        let width = |text: &str| text.chars().count();
        let mut widths = [0; 4];
        for (w, heading) in widths.iter_mut().zip(HEADINGS) {
            *w = width(heading);
        }
        widths[0] = widths[0].max(width("total"));
        for topic in topics {
            widths[0] = widths[0].max(width(&shown(topic)));
        }
        let (mut max, mut bonus) = (0.0, 0.0);
        for row in rows {
            widths[1] = widths[1].max(width(&shown(&row.id)));
            widths[2] = widths[2].max(width(&title_text(&row.title, row.bonus)));
            // A score has the integer digits of the points at most.
            widths[3] = widths[3].max(width(&points_text(row.points, row.points)));
            if row.bonus {
                bonus += row.points;
            } else {
                max += row.points;
            }
        }
        let (max, bonus) = (report::round2(max), report::round2(bonus));
        widths[3] = widths[3].max(width(&total_text(max, max, bonus, bonus)));
        Self { widths }
    }

    /// The columns of the tasks of `report`.
    #[must_use]
    pub fn of(report: &Report) -> Self {
        Self::new(
            report.topics.iter().map(|t| t.name.as_str()),
            &report
                .topics
                .iter()
                .flat_map(|topic| {
                    topic.tasks.iter().map(|task| RowShape {
                        id: task.id.clone(),
                        title: task.title.clone(),
                        bonus: task.bonus,
                        points: task.points,
                    })
                })
                .collect::<Vec<_>>(),
        )
    }

    /// One line of the table, its last column painted by `paint`.
    fn line(&self, cells: [&str; 4], last: &str) -> String {
        let plain = format!(
            "{}  {}  {}  {:>w$}  ",
            pad(cells[0], self.widths[0]),
            pad(cells[1], self.widths[1]),
            pad(cells[2], self.widths[2]),
            cells[3],
            w = self.widths[3]
        );
        format!("{plain}{last}").trim_end().to_owned()
    }

    /// The heading line (after a blank line).
    #[must_use]
    pub fn heading(&self, style: Style) -> String {
        let [a, b, c, d, e] = HEADINGS;
        format!("\n{}\n", style.bold(&self.line([a, b, c, d], e)))
    }

    /// The rows of one topic's tasks.
    #[must_use]
    pub fn topic_rows(&self, topic: &TopicReport, style: Style) -> String {
        let mut text = String::new();
        for (i, task) in topic.tasks.iter().enumerate() {
            let name = if i == 0 {
                shown(&topic.name)
            } else {
                String::new()
            };
            let status = status_text(task);
            let status = match task.status {
                TaskStatus::Ok => style.good(status),
                TaskStatus::Fail => style.bad(status),
                TaskStatus::CompileError | TaskStatus::Error => style.warn(status),
            };
            let points = points_text(task.score, task.points);
            let title = title_text(&task.title, task.bonus);
            let _ = writeln!(
                text,
                "{}",
                self.line([&name, &shown(&task.id), &title, &points], &status)
            );
        }
        text
    }

    /// The total line: the points of the tasks that are not bonuses
    /// against their maximum, the bonus apart (a bonus never hides a lost
    /// point).
    #[must_use]
    pub fn total(&self, report: &Report, style: Style) -> String {
        let base: f64 = report.topics.iter().map(|t| t.base_score()).sum();
        let (bonus, possible) = report.topics.iter().fold((0.0, 0.0), |(e, p), t| {
            let (earned, of) = t.bonus();
            (e + earned, p + of)
        });
        let total = total_text(
            report::round2(base),
            report.max_score,
            report::round2(bonus),
            possible,
        );
        format!(
            "{}\n",
            style.bold(&self.line(["total", "", "", &total], ""))
        )
    }
}

/// A task's title in the table, cut to [`TITLE_WIDTH`].
fn title_text(title: &str, bonus: bool) -> String {
    let bonus = if bonus { " (bonus)" } else { "" };
    cut(&shown(&format!("{title}{bonus}")), TITLE_WIDTH)
}

/// The total's points, with the bonus where a bonus is possible.
fn total_text(base: f64, max: f64, bonus: f64, possible: f64) -> String {
    let total = points_text(base, max);
    if possible > 0.0 {
        format!("{total} + {} bonus", points_text(bonus, possible))
    } else {
        total
    }
}

/// The whole terminal output for a report: the table, then the failures
/// `details` asks for.
pub fn render(report: &Report, out: &Path, style: Style, details: Details) -> String {
    let layout = Layout::of(report);
    let mut text = layout.heading(style);
    for topic in &report.topics {
        text.push_str(&layout.topic_rows(topic, style));
    }
    text.push_str(&layout.total(report, style));
    text.push_str(&below_table(report, out, style, details));
    text
}

/// What the terminal shows below the table: the compile errors, the
/// errors, the failures `details` asks for, and the report's notes.
pub fn below_table(report: &Report, out: &Path, style: Style, details: Details) -> String {
    let mut text = String::new();
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
        assert_eq!(totals, ["total            0.0 / 20"], "{text}");
        assert!(!text.contains(['\r', '\u{1b}', '\u{202e}']), "{text}");
        assert!(
            text.contains("x\\ntotal 20.0 / 20 ok\\r\\u{1b}[2J"),
            "{text}"
        );
    }

    /// The table's lines are as long whatever the scores: a topic's rows
    /// printed as soon as it is graded line up with the rows and the
    /// total printed later.
    #[test]
    fn the_columns_do_not_depend_on_the_scores() {
        let failed = report_of(12.5, vec![test("t::a", TestStatus::Failed)]);
        let passed = report_of(12.5, vec![test("t::a", TestStatus::Passed)]);
        let lines = |report: &Report| -> Vec<usize> {
            let layout = Layout::of(report);
            let style = Style { colour: false };
            let text = format!(
                "{}{}{}",
                layout.heading(style),
                layout.topic_rows(&report.topics[0], style),
                layout.total(report, style)
            );
            // (The status column is last and not padded.)
            text.lines()
                .map(|line| {
                    line.trim_end_matches(['o', 'k', 'F', 'A', 'I', 'L', ' '])
                        .len()
                })
                .collect()
        };
        assert_eq!(passed.topics[0].tasks[0].score, 12.5);
        assert_eq!(failed.topics[0].tasks[0].score, 0.0);
        assert_eq!(lines(&failed), lines(&passed));
        let text = render(
            &failed,
            Path::new("out"),
            Style { colour: false },
            Details::None,
        );
        assert!(text.contains("t   0.0 / 12.5  FAIL"), "{text}");
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
