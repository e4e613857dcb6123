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

/// Text from a test or the compiler (which quotes student code) as it may
/// reach a terminal: every control character but tab and line break
/// written as its escape (`\u{1b}`), so that student code cannot move the
/// cursor, clear the screen or recolour the table.
#[must_use]
pub fn shown(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if c.is_control() && c != '\n' && c != '\t' {
            out.push_str(&c.escape_unicode().to_string());
        } else {
            out.push(c);
        }
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
                    topic.name.clone()
                } else {
                    String::new()
                },
                task.id.clone(),
                cut(&format!("{}{bonus}", task.title), TITLE_WIDTH),
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
                    topic.name
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
                style.warn(&format!("{}: {}", topic.name, shown(error)))
            );
        }
        for task in &topic.tasks {
            // (An error of every task that the topic's says once.)
            if let Some(error) = task.error.as_ref().filter(|e| !topic.errors.contains(e)) {
                let _ = writeln!(text);
                let _ = writeln!(
                    text,
                    "{}",
                    style.warn(&format!("{} / {}: {}", topic.name, task.id, shown(error)))
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
    let _ = writeln!(text);
    let _ = writeln!(
        text,
        "{}",
        style.dim(&format!(
            "report: {} (pictures side by side; also report.json, results.json, junit.xml)",
            out.join("report.html").display()
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
            "{topic} / {}: {} of {counted} tests failed",
            task.id, task.failed
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
        let _ = writeln!(text, "  images:  {}", out.join(dir).display());
    }
    if !task.hints.is_empty() {
        let _ = writeln!(
            text,
            "  hint:    cargo xtask hint {topic}/{}  ({} hints, one more each time)",
            task.id,
            task.hints.len()
        );
    }
    let others: Vec<&str> = task
        .tests
        .iter()
        .filter(|t| t.status == TestStatus::Failed && t.name != test.name)
        .map(|t| t.name.as_str())
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

    #[test]
    fn control_characters_reach_the_terminal_escaped() {
        assert_eq!(shown("a\u{1b}[2Jb\tc\nd\u{7}"), "a\\u{1b}[2Jb\tc\nd\\u{7}");
        assert_eq!(indented("x\u{1b}[H", "  "), "  x\\u{1b}[H\n");
    }
}
