//! Given code that could stand in for a task: a public function of the
//! course's given code (a library crate, or a file of an exercise crate
//! that holds no task) with the signature of a task's stub. `cargo xtask
//! test` plants each one into the stub, as a call where the task's crate
//! can reach it and as a copy of its file where not, and requires the task
//! to score 0: given code never solves a task.
//!
//! Two functions have the same signature when their generics, parameter
//! types, return type and `where` clause agree with paths and spaces
//! taken out (`glam::Vec2` is `Vec2`); parameter names do not count.

use std::ops::Range;

use super::quiet::{closing, identifier, mask, split_top_level};

/// A public free function at the top level of a source file.
#[derive(Debug, Clone, PartialEq)]
pub struct Function {
    /// Its name.
    pub name: String,
    /// Its parameters' patterns, as written (`mut plot`, `[u, v]`).
    pub patterns: Vec<String>,
    /// Its signature without its name, parameter names, paths and spaces:
    /// what two functions share when one can stand in for the other.
    pub shape: String,
    /// The contents of its body, between the braces.
    pub body: Range<usize>,
}

/// The public free functions at the top level of `source`: not methods,
/// not functions of a nested module.
pub fn public_functions(source: &str) -> Vec<Function> {
    let masked = mask(source);
    let depth = brace_depths(&masked);
    let mut found = Vec::new();
    let mut from = 0;
    while let Some(offset) = masked[from..].find("pub ") {
        let start = from + offset;
        from = start + 4;
        let word_start = start == 0 || !is_ident_char(masked.as_bytes()[start - 1]);
        if !word_start || depth[start] != 0 {
            continue;
        }
        let rest = masked[start + 4..].trim_start();
        let rest = rest.strip_prefix("const ").map_or(rest, str::trim_start);
        let Some(after_fn) = rest.strip_prefix("fn ") else {
            continue;
        };
        if let Some(function) = parse(&masked, masked.len() - after_fn.len()) {
            found.push(function);
        }
    }
    found
}

/// The function whose name starts at byte `at` of `masked`.
fn parse(masked: &str, at: usize) -> Option<Function> {
    let after = masked[at..].trim_start();
    let name = identifier(after)?;
    let mut cursor = masked.len() - after.len() + name.len();
    let mut generics = "";
    if masked[cursor..].starts_with('<') {
        let end = closing(masked, cursor, true)?;
        generics = &masked[cursor..=end];
        cursor = end + 1;
    }
    let open = cursor + masked[cursor..].find('(')?;
    let close = closing(masked, open, false)?;
    let body_open = close + masked[close..].find(['{', ';'])?;
    if masked.as_bytes()[body_open] != b'{' {
        return None;
    }
    let body_close = closing(masked, body_open, false)?;
    let mut patterns = Vec::new();
    let mut types = Vec::new();
    for parameter in split_top_level(&masked[open + 1..close]) {
        if parameter.trim().is_empty() {
            continue;
        }
        let (pattern, ty) = split_parameter(parameter)?;
        patterns.push(pattern.trim().to_owned());
        types.push(normalized(ty));
    }
    let tail = &masked[close + 1..body_open];
    let (ret, clause) = tail.split_once(" where").unwrap_or((tail, ""));
    let ret = ret.trim().strip_prefix("->").unwrap_or("");
    Some(Function {
        name: name.to_owned(),
        patterns,
        shape: format!(
            "{}({})->{} where {}",
            normalized(generics),
            types.join(","),
            normalized(ret),
            normalized(clause)
        ),
        body: body_open + 1..body_close,
    })
}

/// `pattern: type` split at the colon that is not part of a path (`::`).
fn split_parameter(parameter: &str) -> Option<(&str, &str)> {
    let bytes = parameter.as_bytes();
    let colon = (0..bytes.len()).find(|&i| {
        bytes[i] == b':' && bytes.get(i + 1) != Some(&b':') && (i == 0 || bytes[i - 1] != b':')
    })?;
    Some((&parameter[..colon], &parameter[colon + 1..]))
}

/// `text` without spaces and without path prefixes (`a::b::C` → `C`).
fn normalized(text: &str) -> String {
    let compact: String = text.chars().filter(|c| !c.is_whitespace()).collect();
    let mut out = String::new();
    let mut rest = compact.as_str();
    while !rest.is_empty() {
        match identifier(rest) {
            Some(ident) => {
                rest = &rest[ident.len()..];
                match rest.strip_prefix("::") {
                    // A path segment: `glam::` in `glam::Vec2` goes.
                    Some(after) if after.starts_with(|c: char| c.is_alphabetic() || c == '_') => {
                        rest = after;
                    }
                    _ => out.push_str(ident),
                }
            }
            None => {
                let c = rest.chars().next().unwrap_or(' ');
                out.push(c);
                rest = &rest[c.len_utf8()..];
            }
        }
    }
    out
}

fn is_ident_char(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_'
}

/// The brace depth at every byte of `masked`.
fn brace_depths(masked: &str) -> Vec<u32> {
    let mut depth = 0u32;
    masked
        .bytes()
        .map(|b| {
            let here = depth;
            match b {
                b'{' => depth += 1,
                b'}' => depth = depth.saturating_sub(1),
                _ => {}
            }
            here
        })
        .collect()
}

/// The task a stub's function belongs to: the `<task>` of its body's
/// `todo!("<task>: …")`, if its body holds one.
pub fn stub_task(source: &str, function: &Function) -> Option<String> {
    let body = &source[function.body.clone()];
    let call = body.find("todo!(")?;
    let message = body[call..].split_once('"')?.1;
    let (task, _) = message.split_once(':')?;
    identifier(task)
        .filter(|id| id.len() == task.len())
        .map(str::to_owned)
}

/// The arguments that pass a function's parameters on: each pattern as an
/// expression (`mut plot` → `plot`, `[u, v]` → `[u, v]`); `None` where a
/// pattern binds less than it takes (`_`, `..`).
pub fn arguments(function: &Function) -> Option<String> {
    let mut out = Vec::new();
    for pattern in &function.patterns {
        let expression = pattern.replace("mut ", "");
        let binds_all = expression
            .split(|c: char| !is_ident_char(c as u8) || !c.is_ascii())
            .all(|word| word != "_" && word != "ref")
            && !expression.contains("..")
            && !expression.contains('@')
            && !expression.contains('&');
        if !binds_all {
            return None;
        }
        out.push(expression);
    }
    Some(out.join(", "))
}

/// `stub` with the body of `function` (one of its [`public_functions`])
/// replaced by a call of `path` with the same arguments, and `copy` (a
/// given file's text) appended as `mod stand_in` where the call needs it.
pub fn plant(stub: &str, function: &Function, path: &str, copy: Option<&str>) -> Option<String> {
    let call = format!("\n    {path}({})\n", arguments(function)?);
    let mut out = stub.to_owned();
    out.replace_range(function.body.clone(), &call);
    if let Some(copy) = copy {
        out.push_str(
            "\n// The given code planted in (see `cargo xtask test`).\n\
             #[allow(dead_code, unused_imports, unused_variables, clippy::all)]\n\
             mod stand_in {\n",
        );
        out.push_str(copy);
        out.push_str("\n}\n");
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    const SOURCE: &str = "\
//! Doc with `pub fn nothing()`.
use glam::Vec2;

/// A line.
pub fn dda_line(from: glam::Vec2, to: Vec2, mut plot: impl FnMut(canvas::Pixel)) {
    // Unused until you write the body:
    let _ = (&from, &to, &mut plot);
    todo!(\"dda: draw \\\"it\\\"\")
}

pub const fn cube<T: Copy>([u, v]: [f64; 2], s: &str) -> Result<T, E> where T: Default {
    let inner = { 1 };
    todo!()
}

fn private(a: u8) -> u8 { a }

impl Thing {
    pub fn method(&self, a: u8) -> u8 { a }
}

mod nested {
    pub fn hidden(a: u8) -> u8 { a }
}
";

    #[test]
    fn public_top_level_functions_and_their_shapes() {
        let found = public_functions(SOURCE);
        let names: Vec<&str> = found.iter().map(|f| f.name.as_str()).collect();
        assert_eq!(names, ["dda_line", "cube"]);
        assert_eq!(found[0].shape, "(Vec2,Vec2,implFnMut(Pixel))-> where ");
        assert_eq!(found[0].patterns, ["from", "to", "mut plot"]);
        assert_eq!(
            found[1].shape,
            "<T:Copy>([f64;2],&str)->Result<T,E> where T:Default"
        );
        assert_eq!(stub_task(SOURCE, &found[0]).as_deref(), Some("dda"));
        assert_eq!(stub_task(SOURCE, &found[1]), None);
    }

    #[test]
    fn a_planted_call_passes_every_argument_on() {
        let found = public_functions(SOURCE);
        let planted = plant(SOURCE, &found[0], "crate::given::line", None).unwrap();
        assert!(
            planted.contains("Pixel)) {\n    crate::given::line(from, to, plot)\n}"),
            "{planted}"
        );
        let copied = plant(
            SOURCE,
            &found[1],
            "stand_in::cube",
            Some("pub fn cube() {}"),
        )
        .unwrap();
        assert!(copied.contains("stand_in::cube([u, v], s)"), "{copied}");
        assert!(
            copied.ends_with("mod stand_in {\npub fn cube() {}\n}\n"),
            "{copied}"
        );
    }

    #[test]
    fn patterns_that_drop_a_value_cannot_be_passed_on() {
        let source = "pub fn f(_: u8, (a, ..): (u8, u8)) {}\npub fn g(_a: u8) {}\n";
        let found = public_functions(source);
        assert_eq!(arguments(&found[0]), None);
        assert_eq!(arguments(&found[1]).as_deref(), Some("_a"));
    }
}
