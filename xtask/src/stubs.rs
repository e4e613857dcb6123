//! `cargo xtask stubs [--check]`: the student files, generated from the
//! solutions.
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

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};

use crate::topics::{self, Topic};

mod do_nothing;
pub mod quiet;
pub mod stand_ins;

pub use do_nothing::do_nothing;

/// Opens a solution region; may be followed by `<task>: <instruction>`.
pub const BEGIN_MARKER: &str = "// BEGIN SOLUTION";
/// Closes a solution region.
pub const END_MARKER: &str = "// END SOLUTION";
/// The hand-written crate root of every exercise crate.
const CRATE_ROOT: &str = "lib.rs";

/// What a marker line says, if it is one.
#[derive(Debug, PartialEq)]
enum Marker<'a> {
    /// `// BEGIN SOLUTION <rest>`; `rest` is trimmed, possibly empty.
    Begin { rest: &'a str },
    /// `// END SOLUTION`.
    End,
}

fn marker(line: &str) -> Option<Marker<'_>> {
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

/// The number of the first line where `a` and `b` differ.
fn first_difference(a: &str, b: &str) -> usize {
    let mut a_lines = a.lines();
    let mut b_lines = b.lines();
    let mut number = 1;
    while let (Some(x), Some(y)) = (a_lines.next(), b_lines.next()) {
        if x != y {
            return number;
        }
        number += 1;
    }
    number
}

/// Whether `text` is empty or ends with an empty line.
fn ends_with_blank_line(text: &str) -> bool {
    text.is_empty() || text.ends_with("\n\n") || text.ends_with("\n\r\n")
}

/// Whether a file is WGSL (a shader piece a student writes).
#[must_use]
pub fn is_wgsl(file: impl AsRef<Path>) -> bool {
    file.as_ref().extension().is_some_and(|ext| ext == "wgsl")
}

/// Lists the `.rs` and `.wgsl` files under `dir`, relative to it, sorted.
fn source_files(dir: &Path) -> Result<Vec<PathBuf>> {
    Ok(crate::files::files_under(dir)?
        .into_iter()
        .filter(|file| file.extension().is_some_and(|ext| ext == "rs") || is_wgsl(file))
        .collect())
}

/// What happened to the stubs of one checkout.
#[derive(Debug, Default)]
pub struct Outcome {
    /// Student files whose content is not what the reference generates
    /// (`--check`, with the first line that differs) or that were rewritten.
    pub changed: Vec<(PathBuf, Option<usize>)>,
    /// Student files that were already up to date.
    pub unchanged: usize,
    /// Marker errors and files without a counterpart.
    pub errors: Vec<String>,
}

/// Generates (or with `check`, compares) the stubs of every topic in `root`.
/// Returns what it found; only failures to read or write are `Err`.
pub fn sync(root: &Path, check: bool) -> Result<Outcome> {
    let reference_root = root.join("reference");
    if !reference_root.is_dir() {
        bail!(
            "{} does not exist: stubs are generated from the tutor edition's solutions",
            reference_root.display()
        );
    }
    let max_width = rustfmt_max_width(root)?;
    let mut outcome = Outcome::default();
    let workspace = root.join("Cargo.toml");
    let forbids_unsafe = fs::read_to_string(&workspace)
        .ok()
        .and_then(|text| toml::from_str::<toml::Value>(&text).ok())
        .is_some_and(|manifest| {
            let lint = ["workspace", "lints", "rust", "unsafe_code"]
                .iter()
                .try_fold(&manifest, |v, key| v.get(key));
            lint.and_then(toml::Value::as_str) == Some("forbid")
        });
    if !forbids_unsafe {
        outcome.errors.push(format!(
            "{}: the workspace forbids unsafe code (`[workspace.lints.rust] unsafe_code = \"forbid\"`): the grader's verdict relies on it",
            workspace.display()
        ));
    }
    for topic in topics::discover(root)? {
        sync_topic(root, &topic, check, max_width, &mut outcome)?;
    }
    Ok(outcome)
}

fn sync_topic(
    root: &Path,
    topic: &Topic,
    check: bool,
    max_width: usize,
    outcome: &mut Outcome,
) -> Result<()> {
    let relative = |path: &Path| {
        path.strip_prefix(root)
            .unwrap_or(path)
            .display()
            .to_string()
    };
    let reference_src = root.join("reference").join(&topic.name).join("src");
    let exercise_src = topic.dir.join("src");
    if !reference_src.is_dir() {
        outcome.errors.push(format!(
            "{} has no solutions: {} is missing",
            topic.name,
            relative(&reference_src)
        ));
        return Ok(());
    }
    let ids: Vec<&str> = topic.sheet.tasks.iter().map(|t| t.id.as_str()).collect();
    // A plain crate: which code is compiled is decided by what is staged,
    // never by a switch in the crate root or a feature in its manifest.
    let crate_root = exercise_src.join(CRATE_ROOT);
    if let Ok(text) = fs::read_to_string(&crate_root) {
        for (number, line) in text.lines().enumerate() {
            if line.contains("#[path") || line.contains("cfg_attr(") {
                outcome.errors.push(format!(
                    "{}:{}: a crate root declares its modules plainly (`pub mod x;`), without `#[path]` or `cfg_attr`",
                    relative(&crate_root),
                    number + 1
                ));
            }
        }
    }
    let manifest = topic.dir.join("Cargo.toml");
    let manifest_text = fs::read_to_string(&manifest).unwrap_or_default();
    if manifest_text.lines().any(|l| l.trim() == "[features]") {
        outcome.errors.push(format!(
            "{}: an exercise crate has no features (a feature would be unified across the workspace and switch the code students build)",
            relative(&manifest)
        ));
    }
    // The grader's verdict relies on student code being safe Rust (see
    // crates/testkit-macros): the workspace forbids `unsafe`, and every
    // exercise crate takes the workspace's lints.
    let lints_inherited = toml::from_str::<toml::Table>(&manifest_text).is_ok_and(|t| {
        t.get("lints")
            .and_then(|l| l.get("workspace"))
            .and_then(toml::Value::as_bool)
            == Some(true)
    });
    if !lints_inherited {
        outcome.errors.push(format!(
            "{}: an exercise crate takes the workspace's lints (`[lints] workspace = true`), which forbid `unsafe` in student code",
            relative(&manifest)
        ));
    }
    let reference_files = source_files(&reference_src)?;
    for file in &reference_files {
        let source_path = reference_src.join(file);
        let target_path = exercise_src.join(file);
        if file == Path::new(CRATE_ROOT) {
            outcome.errors.push(format!(
                "{}: the crate root is hand-written in {} and has no reference copy",
                relative(&source_path),
                relative(&target_path)
            ));
            continue;
        }
        let source = fs::read_to_string(&source_path)
            .with_context(|| format!("cannot read {}", source_path.display()))?;
        if !source.lines().any(|line| marker(line).is_some()) {
            outcome.errors.push(format!(
                "{} holds no `{BEGIN_MARKER}`: given code belongs in {} alone",
                relative(&source_path),
                relative(&target_path)
            ));
            continue;
        }
        let generated = match generate(&source, &relative(&source_path), &ids, max_width) {
            Ok(generated) => generated,
            Err(errors) => {
                outcome.errors.extend(errors);
                continue;
            }
        };
        let current = fs::read_to_string(&target_path).ok();
        if current.as_deref() == Some(generated.as_str()) {
            outcome.unchanged += 1;
            continue;
        }
        if check {
            if current.is_none() {
                outcome.errors.push(format!(
                    "{} has no student file {}",
                    relative(&source_path),
                    relative(&target_path)
                ));
            } else {
                let line = first_difference(current.as_deref().unwrap_or_default(), &generated);
                outcome.changed.push((target_path, Some(line)));
            }
            continue;
        }
        crate::files::write_file(&target_path, generated)?;
        outcome.changed.push((target_path, None));
    }
    Ok(())
}

/// `cargo xtask stubs [--check]`: prints what it did; fails when `check`
/// finds a difference or when any file has a marker error.
pub fn run(root: &Path, check: bool) -> Result<()> {
    let outcome = sync(root, check)?;
    let relative = |path: &Path| {
        path.strip_prefix(root)
            .unwrap_or(path)
            .display()
            .to_string()
    };
    let mut message = String::new();
    for (path, line) in &outcome.changed {
        let line = match line {
            Some(line) => format!("{}:{line}: out of date (first difference)", relative(path)),
            None => format!("wrote {}", relative(path)),
        };
        writeln!(message, "{line}").expect("writing to a String");
    }
    for error in &outcome.errors {
        writeln!(message, "error: {error}").expect("writing to a String");
    }
    print!("{message}");
    let stale = check && !outcome.changed.is_empty();
    if stale || !outcome.errors.is_empty() {
        let mut problems = Vec::new();
        if stale {
            problems.push(format!(
                "{} student file(s) differ from what `cargo xtask stubs` generates",
                outcome.changed.len()
            ));
        }
        if !outcome.errors.is_empty() {
            problems.push(format!("{} error(s)", outcome.errors.len()));
        }
        bail!(
            "stubs are not in sync with reference/: {}",
            problems.join(", ")
        );
    }
    if check {
        println!(
            "stubs: all {} student file(s) match reference/",
            outcome.unchanged
        );
    } else {
        println!(
            "stubs: wrote {} file(s), {} already up to date",
            outcome.changed.len(),
            outcome.unchanged
        );
    }
    Ok(())
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
