//! Generating one student file from its reference file: each marked
//! solution region becomes a `todo!` (or a comment, in WGSL) formatted as
//! rustfmt would, or is removed.

use std::fs;
use std::path::Path;

use anyhow::{Context, Result};

use super::quiet;
use crate::files::is_wgsl;
use crate::stubs::{BEGIN_MARKER, END_MARKER};
/// What a marker line says, if it is one.
#[derive(Debug, PartialEq)]
pub(super) enum Marker<'a> {
    /// `// BEGIN SOLUTION <rest>`; `rest` is trimmed, possibly empty.
    Begin { rest: &'a str },
    /// `// END SOLUTION`.
    End,
}

pub(super) fn marker(line: &str) -> Option<Marker<'_>> {
    let code = line.trim();
    let after = |prefix: &str| {
        let rest = code.strip_prefix(prefix)?;
        // `// BEGIN SOLUTIONS` is not a marker.
        (rest.is_empty() || rest.starts_with(char::is_whitespace)).then(|| rest.trim())
    };
    if let Some(rest) = after(BEGIN_MARKER) {
        Some(Marker::Begin { rest })
    } else {
        after(END_MARKER).map(|_| Marker::End)
    }
}

/// A reference file as a student would hand it in: the solutions without
/// their marker lines.
#[must_use]
pub fn without_markers(reference: &str) -> String {
    reference
        .split_inclusive('\n')
        .filter(|line| marker(line).is_none())
        .collect()
}

/// rustfmt's default line width.
pub const RUSTFMT_MAX_WIDTH: usize = 100;

/// The `todo!` for a region, formatted as rustfmt would: the string literal
/// escapes `\` and `"`, and doubles `{`/`}` because `todo!("...")` is a
/// format string; a call wider than `max_width` is split over three lines
/// (rustfmt never breaks the literal itself).
fn todo_call(
    indent: &str,
    task: &str,
    instruction: &str,
    newline: &str,
    max_width: usize,
) -> String {
    let mut literal = String::new();
    for c in format!("{task}: {instruction}").chars() {
        match c {
            '\\' => literal.push_str("\\\\"),
            '"' => literal.push_str("\\\""),
            '{' => literal.push_str("{{"),
            '}' => literal.push_str("}}"),
            c => literal.push(c),
        }
    }
    let one_line = format!("{indent}todo!(\"{literal}\")");
    if display_width(&one_line) <= max_width {
        return format!("{one_line}{newline}");
    }
    let newline = if newline.is_empty() { "\n" } else { newline };
    format!("{indent}todo!({newline}{indent}    \"{literal}\"{newline}{indent}){newline}")
}

/// Columns a line takes in rustfmt's eyes: East Asian wide characters and
/// emoji count two (a close approximation of the `unicode-width` crate).
fn display_width(line: &str) -> usize {
    line.chars()
        .map(|c| match u32::from(c) {
            0x1100..=0x115F
            | 0x2E80..=0xA4CF
            | 0xAC00..=0xD7A3
            | 0xF900..=0xFAFF
            | 0xFE30..=0xFE4F
            | 0xFF00..=0xFF60
            | 0xFFE0..=0xFFE6
            | 0x1F300..=0x1F64F
            | 0x1F900..=0x1F9FF
            | 0x20000..=0x3FFFD => 2,
            _ => 1,
        })
        .sum()
}

/// `max_width` from the checkout's `rustfmt.toml` or `.rustfmt.toml`, or
/// rustfmt's default.
pub fn rustfmt_max_width(root: &Path) -> Result<usize> {
    #[derive(serde::Deserialize)]
    struct Config {
        max_width: Option<usize>,
    }
    for name in ["rustfmt.toml", ".rustfmt.toml"] {
        let path = root.join(name);
        if let Ok(text) = fs::read_to_string(&path) {
            let config: Config =
                toml::from_str(&text).with_context(|| format!("cannot read {}", path.display()))?;
            return Ok(config.max_width.unwrap_or(RUSTFMT_MAX_WIDTH));
        }
    }
    Ok(RUSTFMT_MAX_WIDTH)
}

/// Generates the student file from a reference file. `file` names the
/// reference file in errors (`file:line: ...`); `task_ids` are the topic's
/// tasks; `max_width` is rustfmt's. Every problem in the file is reported,
/// not just the first.
pub fn generate(
    source: &str,
    file: &str,
    task_ids: &[&str],
    max_width: usize,
) -> Result<String, Vec<String>> {
    let mut out = String::with_capacity(source.len());
    let mut errors = Vec::new();
    // The line number of the open region's BEGIN and whether it is a bare
    // (helper) region, if inside one.
    let mut open: Option<(usize, bool)> = None;
    // A helper region was just removed: blank lines that would now double
    // an earlier one are dropped too, so that the stub stays rustfmt-clean.
    let mut after_removal = false;
    // The `todo!` calls written: (first line, line after), 0-based in `out`.
    let mut todos: Vec<(usize, usize)> = Vec::new();
    for (index, line) in source.split_inclusive('\n').enumerate() {
        let number = index + 1;
        match marker(line) {
            Some(Marker::Begin { rest }) => {
                if let Some((outer, _)) = open {
                    errors.push(format!(
                        "{file}:{number}: nested `{BEGIN_MARKER}` (the region opened at line {outer} is not closed)"
                    ));
                    continue;
                }
                open = Some((number, rest.is_empty()));
                if rest.is_empty() {
                    continue; // a helper region: removed without a trace
                }
                let Some((task, instruction)) = rest.split_once(':') else {
                    errors.push(format!(
                        "{file}:{number}: expected `{BEGIN_MARKER} <task>: <instruction>`, found `{}`",
                        line.trim()
                    ));
                    continue;
                };
                let (task, instruction) = (task.trim(), instruction.trim());
                if !task_ids.contains(&task) {
                    errors.push(format!(
                        "{file}:{number}: task `{task}` is not a task of this topic (the task sheet lists: {})",
                        task_ids.join(", ")
                    ));
                } else if instruction.is_empty() {
                    errors.push(format!(
                        "{file}:{number}: the instruction for task `{task}` is empty"
                    ));
                }
                let indent = &line[..line.len() - line.trim_start().len()];
                let newline = if line.ends_with("\r\n") {
                    "\r\n"
                } else if line.ends_with('\n') {
                    "\n"
                } else {
                    ""
                };
                let call = if is_wgsl(file) {
                    // WGSL has no `todo!()`: the stub says what to write,
                    // and a file of comments only is a task not started
                    // (see topic 10's `src/wgsl.rs`).
                    format!("{indent}// TODO {task}: {instruction}{newline}")
                } else {
                    todo_call(indent, task, instruction, newline, max_width)
                };
                let first = out.matches('\n').count();
                todos.push((first, first + call.matches('\n').count().max(1)));
                out.push_str(&call);
            }
            Some(Marker::End) => {
                if let Some((_, bare)) = open.take() {
                    after_removal |= bare;
                } else {
                    errors.push(format!(
                        "{file}:{number}: `{END_MARKER}` without a `{BEGIN_MARKER}`"
                    ));
                }
            }
            None if open.is_some() => {} // solution code
            None if after_removal && line.trim().is_empty() && ends_with_blank_line(&out) => {}
            None => {
                after_removal &= line.trim().is_empty();
                out.push_str(line);
            }
        }
    }
    if after_removal {
        // The file ended with a helper region: no blank lines at the end.
        while out.ends_with("\n\n") || out.ends_with("\n\r\n") {
            out.truncate(out.trim_end().len());
            out.push_str(if source.ends_with("\r\n") {
                "\r\n"
            } else {
                "\n"
            });
        }
    }
    if let Some((begin, _)) = open {
        errors.push(format!(
            "{file}:{begin}: `{BEGIN_MARKER}` without an `{END_MARKER}`"
        ));
    }
    if errors.is_empty() {
        let newline = if source.contains("\r\n") {
            "\r\n"
        } else {
            "\n"
        };
        if is_wgsl(file) {
            Ok(out)
        } else {
            Ok(quiet::quiet(&out, &todos, newline, max_width))
        }
    } else {
        Err(errors)
    }
}

/// Whether `text` is empty or ends with an empty line.
fn ends_with_blank_line(text: &str) -> bool {
    text.is_empty() || text.ends_with("\n\n") || text.ends_with("\n\r\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    const IDS: &[&str] = &["dda", "wu"];

    fn stub(source: &str) -> String {
        generate(source, "ref.rs", IDS, RUSTFMT_MAX_WIDTH)
            .unwrap_or_else(|errors| panic!("{errors:#?}"))
    }

    fn errors(source: &str) -> Vec<String> {
        generate(source, "ref.rs", IDS, RUSTFMT_MAX_WIDTH).expect_err("should be rejected")
    }

    #[test]
    fn a_wgsl_solution_becomes_a_todo_comment() {
        let source = "\
// What to write: fn twice(x: f32) -> f32.

// BEGIN SOLUTION dda: write fn twice
fn twice(x: f32) -> f32 {
    return 2.0 * x;
}
// END SOLUTION
";
        let stub = generate(source, "src/twice.wgsl", IDS, RUSTFMT_MAX_WIDTH).unwrap();
        assert_eq!(
            stub,
            "// What to write: fn twice(x: f32) -> f32.\n\n// TODO dda: write fn twice\n"
        );
    }

    #[test]
    fn marked_body_becomes_todo_at_the_begin_indentation() {
        let source = "\
/// Draws a line.
pub fn dda(a: u32) -> u32 {
    // BEGIN SOLUTION dda: draw the line with the DDA
    let b = a + 1;
    b * 2
    // END SOLUTION
}
";
        assert_eq!(
            stub(source),
            "\
/// Draws a line.
pub fn dda(a: u32) -> u32 {
    // Unused until you write the body:
    let _ = &a;
    todo!(\"dda: draw the line with the DDA\")
}
"
        );
    }

    #[test]
    fn bare_begin_removes_the_region() {
        let source = "\
// BEGIN SOLUTION
use std::f32::consts::PI;
// END SOLUTION
pub fn f() {
        // BEGIN SOLUTION wu: use Wu's algorithm
        let _ = PI;
        // END SOLUTION
}
// BEGIN SOLUTION
fn helper() {}
// END SOLUTION
";
        assert_eq!(
            stub(source),
            "pub fn f() {\n        todo!(\"wu: use Wu's algorithm\")\n}\n"
        );
    }

    #[test]
    fn a_handed_in_solution_has_no_markers() {
        let source = "/// F.\npub fn f() -> u8 {\n    // BEGIN SOLUTION f: one\n    1\n    // END SOLUTION\n}\n// BEGIN SOLUTIONS is text\n";
        assert_eq!(
            without_markers(source),
            "/// F.\npub fn f() -> u8 {\n    1\n}\n// BEGIN SOLUTIONS is text\n"
        );
    }

    #[test]
    fn removed_helpers_leave_no_double_or_trailing_blank_lines() {
        let source = "//! Doc.\n\n// BEGIN SOLUTION\nuse std::f32::consts::PI;\n// END SOLUTION\n\n/// F.\npub fn f() {}\n\n// BEGIN SOLUTION\npub fn helper() {}\n// END SOLUTION\n";
        assert_eq!(stub(source), "//! Doc.\n\n/// F.\npub fn f() {}\n");
        let leading = "// BEGIN SOLUTION\nuse a::b;\n// END SOLUTION\n\npub fn g() {}\n";
        assert_eq!(stub(leading), "pub fn g() {}\n");
        let between = "pub fn a() {}\n\n// BEGIN SOLUTION\npub fn helper() {}\n// END SOLUTION\n\npub fn b() {}\n";
        assert_eq!(stub(between), "pub fn a() {}\n\npub fn b() {}\n");
    }

    #[test]
    fn long_todo_is_split_as_rustfmt_splits_it() {
        let fits = format!(
            "    // BEGIN SOLUTION dda: {}\n    x\n    // END SOLUTION\n",
            "a".repeat(82)
        );
        assert_eq!(
            stub(&fits),
            format!("    todo!(\"dda: {}\")\n", "a".repeat(82))
        );
        let long = format!(
            "    // BEGIN SOLUTION dda: {}\n    x\n    // END SOLUTION\n",
            "a".repeat(83)
        );
        assert_eq!(
            stub(&long),
            format!("    todo!(\n        \"dda: {}\"\n    )\n", "a".repeat(83))
        );
        assert_eq!(display_width("a中b"), 4);
    }

    #[test]
    fn instruction_is_escaped_for_a_format_string_literal() {
        let source = "  // BEGIN SOLUTION dda: say \"hi\" \\ fill {x} \n  x\n  // END SOLUTION\n";
        assert_eq!(
            stub(source),
            "  todo!(\"dda: say \\\"hi\\\" \\\\ fill {{x}}\")\n"
        );
    }

    #[test]
    fn text_outside_markers_and_crlf_line_ends_are_kept() {
        let source = "//! Doc.\r\npub fn f() {\r\n\t// BEGIN SOLUTION dda: x\r\n\t1\r\n\t// END SOLUTION\r\n}";
        assert_eq!(
            stub(source),
            "//! Doc.\r\npub fn f() {\r\n\ttodo!(\"dda: x\")\r\n}"
        );
        assert_eq!(
            stub("no markers\n// BEGIN SOLUTIONS are not markers\n"),
            "no markers\n// BEGIN SOLUTIONS are not markers\n"
        );
    }

    #[test]
    fn nested_begin_is_an_error_with_its_line() {
        let errors =
            errors("// BEGIN SOLUTION dda: a\n// BEGIN SOLUTION dda: b\n// END SOLUTION\n");
        assert_eq!(errors.len(), 1, "{errors:?}");
        assert!(errors[0].starts_with("ref.rs:2: nested"), "{errors:?}");
        assert!(errors[0].contains("line 1"), "{errors:?}");
    }

    #[test]
    fn end_without_begin_is_an_error() {
        let errors = errors("fn f() {}\n    // END SOLUTION\n");
        assert!(
            errors[0].starts_with("ref.rs:2: `// END SOLUTION` without"),
            "{errors:?}"
        );
    }

    #[test]
    fn begin_without_end_is_an_error() {
        let errors = errors("\n\n// BEGIN SOLUTION dda: a\nx\n");
        assert!(
            errors[0].starts_with("ref.rs:3: `// BEGIN SOLUTION` without"),
            "{errors:?}"
        );
    }

    #[test]
    fn unknown_task_and_missing_instruction_are_errors() {
        let errors = errors(
            "// BEGIN SOLUTION bresenham: a\n// END SOLUTION\n// BEGIN SOLUTION dda\n// END SOLUTION\n// BEGIN SOLUTION wu:\n// END SOLUTION\n",
        );
        assert_eq!(errors.len(), 3, "{errors:?}");
        assert!(
            errors[0].starts_with("ref.rs:1: task `bresenham` is not a task"),
            "{errors:?}"
        );
        assert!(errors[0].contains("dda, wu"), "{errors:?}");
        assert!(errors[1].starts_with("ref.rs:3: expected"), "{errors:?}");
        assert!(
            errors[2].starts_with("ref.rs:5: the instruction"),
            "{errors:?}"
        );
    }
}
