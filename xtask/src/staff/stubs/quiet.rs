//! Keeps a stub free of the warnings its `todo!()` bodies alone provoke,
//! and of nothing more: once a student writes code, the compiler speaks
//! about it as it would in any crate.
//!
//! A body replaced by `todo!()` leaves three kinds of names unused:
//!
//! - **parameters** (and locals declared before the `todo!` in its block):
//!   they are borrowed on a line of their own before the `todo!`, which
//!   the student replaces together with it:
//!
//!   ```text
//!       // Unused until you write the body:
//!       let _ = (&from, &to, &mut plot);
//!       todo!("dda: draw the line with the DDA")
//!   ```
//! - **imports** the signatures do not need but the task's code will (the
//!   sheet's hints, such as `round_half_away`): `#[allow(unused_imports)]`
//!   on that `use` item;
//! - **private helpers** (`fn`, `const`) given for the task's code to call:
//!   `#[allow(dead_code)]` on that item.
//!
//! Names are found in the source with comments and string literals
//! blanked out, by word: a name is used when it appears outside its own
//! declaration. This is a heuristic, not name resolution; the stubs of
//! the course are checked by clippy with `-D warnings`, which is the
//! judge.

use crate::stubs::quiet::mask;

/// The identifier at the start of `text`, if any.
pub(crate) fn identifier(text: &str) -> Option<&str> {
    let end = text
        .find(|c: char| !(c.is_alphanumeric() || c == '_'))
        .unwrap_or(text.len());
    let ident = &text[..end];
    ident
        .starts_with(|c: char| c.is_alphabetic() || c == '_')
        .then_some(ident)
}

/// The offset of the bracket that closes the one at `open`, counting
/// `()[]{}` (and `<>` when `angles`, where `->` is not a bracket).
pub(crate) fn closing(text: &str, open: usize, angles: bool) -> Option<usize> {
    let bytes = text.as_bytes();
    let mut depth = 0i32;
    for (i, &b) in bytes.iter().enumerate().skip(open) {
        match b {
            b'(' | b'[' | b'{' => depth += 1,
            b'<' if angles => depth += 1,
            b')' | b']' | b'}' => depth -= 1,
            b'>' if angles && (i == 0 || bytes[i - 1] != b'-') => depth -= 1,
            _ => {}
        }
        if depth == 0 {
            return Some(i);
        }
    }
    None
}

/// The comment above a borrow line.
const BORROW_COMMENT: &str = "// Unused until you write the body:";

/// Whether `word` occurs in `text` as a whole identifier.
pub fn has_word(text: &str, word: &str) -> bool {
    let is_ident = |c: char| c.is_alphanumeric() || c == '_';
    text.match_indices(word).any(|(at, _)| {
        let before = text[..at].chars().next_back();
        let after = text[at + word.len()..].chars().next();
        !before.is_some_and(is_ident) && !after.is_some_and(is_ident)
    })
}

/// Splits at the commas that are not inside any bracket.
pub(crate) fn split_top_level(text: &str) -> Vec<&str> {
    let bytes = text.as_bytes();
    let mut parts = Vec::new();
    let mut depth = 0i32;
    let mut start = 0;
    for (i, &b) in bytes.iter().enumerate() {
        match b {
            b'(' | b'[' | b'{' | b'<' => depth += 1,
            b')' | b']' | b'}' => depth -= 1,
            b'>' if i == 0 || bytes[i - 1] != b'-' => depth -= 1,
            b',' if depth == 0 => {
                parts.push(&text[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&text[start..]);
    parts
}

/// The bindings of a pattern: a plain identifier, or a tuple or array of
/// them (`[u, v, w]`).
fn pattern_bindings(pattern: &str) -> Vec<Binding> {
    let pattern = pattern.trim();
    let inner = pattern
        .strip_prefix('[')
        .and_then(|p| p.strip_suffix(']'))
        .or_else(|| pattern.strip_prefix('(').and_then(|p| p.strip_suffix(')')));
    match inner {
        Some(inner) => split_top_level(inner)
            .into_iter()
            .flat_map(pattern_bindings)
            .collect(),
        None => simple_binding(pattern).into_iter().collect(),
    }
}

/// A binding a stub no longer uses.
struct Binding {
    name: String,
    mutable: bool,
}

/// `mut name` or `name` (a plain identifier pattern), not `self` or `_x`.
fn simple_binding(pattern: &str) -> Option<Binding> {
    let pattern = pattern.trim();
    let (mutable, name) = match pattern.strip_prefix("mut ") {
        Some(rest) => (true, rest.trim()),
        None => (false, pattern),
    };
    let ident = identifier(name)?;
    (ident == name && ident != "self" && !ident.starts_with('_')).then(|| Binding {
        name: ident.to_owned(),
        mutable,
    })
}

/// Line start offsets of `text`.
fn line_starts(text: &str) -> Vec<usize> {
    std::iter::once(0)
        .chain(text.match_indices('\n').map(|(i, _)| i + 1))
        .collect()
}

fn indent_of(line: &str) -> usize {
    line.len() - line.trim_start().len()
}

/// The bindings of the function around line `todo` that nothing but the
/// `todo!` lines (`todo..todo_end`) would use.
fn unused_bindings(masked: &str, starts: &[usize], todo: usize, todo_end: usize) -> Vec<Binding> {
    let lines: Vec<&str> = masked.lines().collect();
    let indent = indent_of(lines[todo]);
    // The nearest `fn` above, less indented than the todo!.
    let Some(fn_line) = (0..todo).rev().find(|&l| {
        indent_of(lines[l]) < indent && {
            let code = lines[l].trim_start();
            code.split_whitespace().take_while(|w| *w != "fn").all(|w| {
                ["pub", "const", "async", "unsafe", "extern"].contains(&w) || w.starts_with("pub(")
            }) && has_word(code, "fn")
        }
    }) else {
        return Vec::new();
    };
    let from = starts[fn_line] + lines[fn_line].find("fn").expect("a fn line") + 2;
    let after_name = from
        + masked[from..]
            .find(|c: char| !(c.is_whitespace() || c.is_alphanumeric() || c == '_'))
            .unwrap_or(0);
    let mut open = after_name;
    if masked[open..].starts_with('<') {
        let Some(end) = closing(masked, open, true) else {
            return Vec::new();
        };
        open = end + 1;
    }
    let Some(open) = masked[open..].find('(').map(|n| open + n) else {
        return Vec::new();
    };
    let Some(close) = closing(masked, open, false) else {
        return Vec::new();
    };
    let Some(body_open) = masked[close..].find('{').map(|n| close + n) else {
        return Vec::new();
    };
    let Some(body_close) = closing(masked, body_open, false) else {
        return Vec::new();
    };
    let todo_start = starts[todo];
    let todo_stop = starts.get(todo_end).copied().unwrap_or(masked.len());
    if !(body_open < todo_start && todo_start < body_close) {
        return Vec::new();
    }
    // The body without the todo! lines.
    let before = &masked[body_open + 1..todo_start];
    let after = &masked[todo_stop.min(body_close)..body_close];
    let mut bindings: Vec<Binding> = split_top_level(&masked[open + 1..close])
        .into_iter()
        .flat_map(|param| pattern_bindings(param.split(':').next().unwrap_or_default()))
        .filter(|b| !has_word(before, &b.name) && !has_word(after, &b.name))
        .collect();
    // Locals of the todo!'s own block, declared before it.
    for l in (0..todo).filter(|&l| starts[l] > body_open) {
        let code = lines[l].trim_start();
        if indent_of(lines[l]) != indent {
            continue;
        }
        let Some(rest) = code.strip_prefix("let ") else {
            continue;
        };
        let pattern = rest.split([':', '=', ';']).next().unwrap_or_default();
        let Some(binding) = simple_binding(pattern) else {
            continue;
        };
        let later = &masked[starts[l + 1]..todo_start];
        if !has_word(later, &binding.name) && !has_word(after, &binding.name) {
            bindings.push(binding);
        }
    }
    bindings
}

/// The names a `use` item brings into scope (`a::{b, c as d}` → `b`, `d`;
/// `a::{self}` → `a`); globs and `_` imports bring none that could go
/// unused by name.
fn imported_names(item: &str) -> Vec<String> {
    fn tree(text: &str, parent: Option<&str>, names: &mut Vec<String>) {
        for leaf in split_top_level(text) {
            let leaf = leaf.trim();
            if let Some(open) = leaf.find('{') {
                let prefix = leaf[..open].trim_end_matches("::");
                let inner = leaf[open + 1..].trim_end().trim_end_matches('}');
                tree(inner, prefix.rsplit("::").next(), names);
                continue;
            }
            let name = match leaf.rsplit_once(" as ") {
                Some((_, alias)) => alias.trim(),
                None => leaf.rsplit("::").next().unwrap_or(leaf).trim(),
            };
            let name = if name == "self" {
                parent.unwrap_or("")
            } else {
                name
            };
            if !(name.is_empty() || name == "_" || name == "*") {
                names.push(name.to_owned());
            }
        }
    }
    let body = item.trim();
    let body = body
        .strip_prefix("use")
        .unwrap_or(body)
        .trim()
        .trim_end_matches(';');
    let mut names = Vec::new();
    tree(body, None, &mut names);
    names
}

/// Adds borrow lines and `allow` attributes to a generated stub; `todos`
/// are the stub's `todo!` calls as (first line, line after the call).
pub fn quiet(stub: &str, todos: &[(usize, usize)], newline: &str, max_width: usize) -> String {
    let masked = mask(stub);
    let starts = line_starts(&masked);
    let masked_lines: Vec<&str> = masked.lines().collect();
    let mut inserts: Vec<(usize, Vec<String>)> = Vec::new();

    for &(todo, todo_end) in todos {
        let bindings = unused_bindings(&masked, &starts, todo, todo_end);
        if bindings.is_empty() {
            continue;
        }
        let indent = " ".repeat(indent_of(masked_lines[todo]));
        let borrows: Vec<String> = bindings
            .iter()
            .map(|b| format!("&{}{}", if b.mutable { "mut " } else { "" }, b.name))
            .collect();
        let mut lines = vec![format!("{indent}{BORROW_COMMENT}")];
        if let [one] = borrows.as_slice() {
            lines.push(format!("{indent}let _ = {one};"));
        } else {
            let one_line = format!("{indent}let _ = ({});", borrows.join(", "));
            if one_line.len() <= max_width {
                lines.push(one_line);
            } else {
                lines.push(format!("{indent}let _ = ("));
                lines.extend(borrows.iter().map(|b| format!("{indent}    {b},")));
                lines.push(format!("{indent});"));
            }
        }
        inserts.push((todo, lines));
    }

    // Top-level private `use` items with a name the stub never mentions.
    let mut uses: Vec<(usize, usize)> = Vec::new(); // (first line, line after)
    let mut l = 0;
    while l < masked_lines.len() {
        if masked_lines[l].starts_with("use ") {
            let mut end = l;
            while end < masked_lines.len() && !masked_lines[end].contains(';') {
                end += 1;
            }
            uses.push((l, end + 1));
            l = end + 1;
        } else {
            l += 1;
        }
    }
    let without_uses: String = masked_lines
        .iter()
        .enumerate()
        .filter(|(n, _)| !uses.iter().any(|&(a, b)| (a..b).contains(n)))
        .map(|(_, line)| format!("{line}\n"))
        .collect();
    for &(first, after) in &uses {
        let item = masked_lines[first..after].join(" ");
        if imported_names(&item)
            .iter()
            .any(|name| !has_word(&without_uses, name))
        {
            inserts.push((first, vec!["#[allow(unused_imports)]".to_owned()]));
        }
    }

    // Private helpers nothing in the stub calls.
    for (n, line) in masked_lines.iter().enumerate() {
        // Top-level items only: a method may be a trait's, called from afar.
        let code = *line;
        let name = code
            .strip_prefix("fn ")
            .or_else(|| code.strip_prefix("const "))
            .and_then(identifier);
        let Some(name) = name else { continue };
        let rest: String = masked_lines
            .iter()
            .enumerate()
            .filter(|&(m, _)| m != n)
            .map(|(_, line)| format!("{line}\n"))
            .collect();
        if !has_word(&rest, name) {
            let indent = " ".repeat(indent_of(line));
            inserts.push((n, vec![format!("{indent}#[allow(dead_code)]")]));
        }
    }

    if inserts.is_empty() {
        return stub.to_owned();
    }
    inserts.sort_by_key(|(line, _)| *line);
    let mut out = String::with_capacity(stub.len() + 256);
    let mut next = inserts.iter().peekable();
    for (n, line) in stub.split_inclusive('\n').enumerate() {
        while let Some((_, lines)) = next.next_if(|(at, _)| *at == n) {
            for inserted in lines {
                out.push_str(inserted);
                out.push_str(newline);
            }
        }
        out.push_str(line);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn quiet_all(stub: &str) -> String {
        let todos: Vec<(usize, usize)> = stub
            .lines()
            .enumerate()
            .filter(|(_, l)| l.trim_start().starts_with("todo!("))
            .map(|(n, _)| (n, n + 1))
            .collect();
        quiet(stub, &todos, "\n", 100)
    }

    #[test]
    fn unused_parameters_are_borrowed_before_the_todo() {
        let stub = "\
/// Uses `from` in a comment only.
pub fn line<F: FnMut(Pixel) -> bool>(from: Vec2, to: Vec2, mut plot: F, [u, _v]: [f64; 2]) {
    todo!(\"dda: the from and to of it\")
}
";
        assert_eq!(
            quiet_all(stub),
            "\
/// Uses `from` in a comment only.
pub fn line<F: FnMut(Pixel) -> bool>(from: Vec2, to: Vec2, mut plot: F, [u, _v]: [f64; 2]) {
    // Unused until you write the body:
    let _ = (&from, &to, &mut plot, &u);
    todo!(\"dda: the from and to of it\")
}
"
        );
    }

    #[test]
    fn used_parameters_self_and_underscored_ones_are_left_alone() {
        let stub = "\
impl A {
    pub fn f(&self, a: u32, _b: u32, c: u32) -> u32 {
        let d = a + 1;
        let e = 2;
        todo!(\"t: x\");
        e
    }
}
";
        assert_eq!(
            quiet_all(stub),
            "\
impl A {
    pub fn f(&self, a: u32, _b: u32, c: u32) -> u32 {
        let d = a + 1;
        let e = 2;
        // Unused until you write the body:
        let _ = (&c, &d);
        todo!(\"t: x\");
        e
    }
}
"
        );
    }

    #[test]
    fn unused_imports_and_helpers_are_allowed() {
        let stub = "\
use canvas::{Pixel, round_half_away};
use std::fmt::Write as _;
pub use glam::Vec2;

const STEP: f64 = 0.5;

fn helper(p: Pixel) -> Pixel {
    p
}

/// Draws.
pub fn f(p: Pixel) -> Pixel {
    let s = \"round_half_away STEP helper\";
    todo!(\"t: x\")
}
";
        let quiet = quiet_all(stub);
        assert!(
            quiet.starts_with("#[allow(unused_imports)]\nuse canvas::{Pixel, round_half_away};\nuse std::fmt::Write as _;\npub use glam::Vec2;"),
            "{quiet}"
        );
        assert!(quiet.contains("#[allow(dead_code)]\nconst STEP"), "{quiet}");
        assert!(quiet.contains("#[allow(dead_code)]\nfn helper"), "{quiet}");
        assert!(quiet.contains("let _ = (&p, &s);"), "{quiet}");
    }

    #[test]
    fn imported_names_follow_paths_aliases_and_self() {
        assert_eq!(
            imported_names("use a::{b, c::D as E, f::{self, g}, h::*, i as _};"),
            ["b", "E", "f", "g"]
        );
    }
}
