//! The do-nothing edition: each `todo!()` of a stub replaced by the
//! cheapest body that compiles, so that a test which passes against it is
//! seen to pay for nothing. `cargo xtask test` grades it and requires 0
//! points on every task.
//!
//! The cheapest body of a function is what a student who skips the task
//! but wants the code to compile would write: nothing (for `()`),
//! `Default::default()` (zero, `false`, an empty collection, `None`),
//! `Ok(Default::default())` for a `Result`, an empty iterator for `impl
//! Iterator`. Where that does not compile (a type without `Default`), the
//! caller names the line in `keep` and the `todo!()` stays.

use super::quiet::{closing, identifier};
use crate::stubs::quiet::mask;

/// The cheapest tail expression of a function whose return type is `ret`
/// (the text after `->`, empty for none); `None` where none surely exists.
fn cheapest(ret: &str) -> Option<&'static str> {
    let ret = ret.trim();
    if ret.is_empty() || ret == "()" {
        Some("")
    } else if ret.starts_with("Result<") || ret.starts_with("std::result::Result<") {
        Some("Ok(Default::default())")
    } else if let Some(bound) = ret.strip_prefix("impl ") {
        bound.contains("Iterator").then_some("std::iter::empty()")
    } else if ret == "!" {
        None
    } else {
        Some("Default::default()")
    }
}

/// A function's return type and body, as byte ranges of the source.
struct Function {
    ret: std::ops::Range<usize>,
    body_close: usize,
}

/// The innermost function whose body holds byte `at` of `masked`.
fn enclosing_fn(masked: &str, at: usize) -> Option<Function> {
    let mut found = None;
    let mut from = 0;
    while let Some(offset) = masked[from..at].find("fn") {
        let start = from + offset;
        from = start + 2;
        if masked[..start].ends_with(|c: char| c.is_alphanumeric() || c == '_')
            || masked[start + 2..].starts_with(|c: char| c.is_alphanumeric() || c == '_')
        {
            continue;
        }
        let after = masked[start + 2..].trim_start();
        let Some(name) = identifier(after) else {
            continue; // `fn(..)`, a function pointer type
        };
        let mut cursor = masked.len() - after.len() + name.len();
        if masked[cursor..].starts_with('<') {
            let Some(end) = closing(masked, cursor, true) else {
                continue;
            };
            cursor = end + 1;
        }
        let Some(open) = masked[cursor..].find('(').map(|n| cursor + n) else {
            continue;
        };
        let Some(close) = closing(masked, open, false) else {
            continue;
        };
        let Some(body_open) = masked[close..].find(['{', ';']).map(|n| close + n) else {
            continue;
        };
        if masked.as_bytes()[body_open] != b'{' {
            continue; // a declaration without a body
        }
        let Some(body_close) = closing(masked, body_open, false) else {
            continue;
        };
        if body_open < at && at < body_close {
            let signature_end = masked[close + 1..body_open]
                .find(" where")
                .map_or(body_open, |n| close + 1 + n);
            let arrow = masked[close + 1..signature_end]
                .find("->")
                .map_or(signature_end, |n| close + 1 + n + 2);
            found = Some(Function {
                ret: arrow..signature_end,
                body_close,
            });
        }
    }
    found
}

/// `stub` with each `todo!(…)` that is its function's whole result
/// replaced by the [`cheapest`] body, except those on the lines (1-based)
/// in `keep`. Line numbers stay those of the stub. Also returns the lines
/// replaced.
pub fn do_nothing(stub: &str, keep: &[usize]) -> (String, Vec<usize>) {
    let masked = mask(stub);
    let mut edits = Vec::new();
    let mut search = 0;
    while let Some(found) = masked[search..].find("todo!(") {
        let start = search + found;
        search = start + 1;
        let line = masked[..start].matches('\n').count() + 1;
        let Some(close) = closing(&masked, start + "todo!".len(), false) else {
            continue;
        };
        let Some(function) = enclosing_fn(&masked, start) else {
            continue;
        };
        let is_result = masked[close + 1..function.body_close].trim().is_empty();
        let body = cheapest(&masked[function.ret.clone()]);
        if let (true, Some(body), false) = (is_result, body, keep.contains(&line)) {
            edits.push((start, close + 1, body, line));
        }
    }
    let mut out = stub.to_owned();
    for &(start, end, body, _) in edits.iter().rev() {
        // The call's line breaks stay, so that every line keeps its number.
        let breaks = stub[start..end].matches('\n').count();
        out.replace_range(start..end, &format!("{body}{}", "\n".repeat(breaks)));
    }
    (out, edits.iter().map(|e| e.3).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_return_type_gets_its_cheapest_body() {
        let stub = "\
pub fn plot(canvas: &mut Canvas) {
    let _ = (&canvas,);
    todo!(\"dda: plot\")
}

pub fn count<T: Copy>(xs: &[T]) -> usize where T: Default {
    todo!(
        \"count: the {xs:?} that todo!( would \\\"miss\\\"\"
    )
}

fn new(w: u32) -> Result<Self, Error> {
    todo!()
}

fn pixels(&self) -> impl Iterator<Item = Pixel> + '_ {
    todo!()
}

fn inner() -> u8 {
    let f = |x: fn(u8) -> u8| x(1);
    todo!()
}
";
        let (out, lines) = do_nothing(stub, &[]);
        assert_eq!(lines, [3, 7, 13, 17, 22]);
        assert_eq!(out.lines().count(), stub.lines().count(), "{out}");
        assert!(out.contains("    let _ = (&canvas,);\n    \n}"), "{out}");
        assert!(
            out.contains("where T: Default {\n    Default::default()\n\n\n}"),
            "{out}"
        );
        assert!(
            out.contains("Result<Self, Error> {\n    Ok(Default::default())\n}"),
            "{out}"
        );
        assert!(out.contains("'_ {\n    std::iter::empty()\n}"), "{out}");
        assert!(out.contains("x(1);\n    Default::default()\n}"), "{out}");
        assert!(!out.contains("todo!"), "{out}");
    }

    #[test]
    fn kept_lines_and_todos_that_are_not_the_result_stay() {
        let stub = "\
fn a() -> u8 {
    todo!()
}

fn b() -> u8 {
    let x = todo!();
    x
}

fn c() -> ! {
    todo!()
}
";
        let (out, lines) = do_nothing(stub, &[2]);
        assert!(lines.is_empty(), "{lines:?}");
        assert_eq!(out, stub);
    }
}
