//! What a submission's code may not do at compile time: reach files other
//! than its own.
//!
//! `#[path = "..."] mod x;` compiles any file as a module of the student's
//! crate (the official solution, by a path relative to the stage or an
//! absolute one), and `include!`, `include_str!` and `include_bytes!` read
//! any file the grader's account can read into the program, or, through a
//! `const` panic, into the compiler's errors that the report shows; so do
//! the dependencies' macros built on them (`wgpu::include_wgsl!` reads a
//! file into a shader's source). A task file that names any of them is not
//! compiled: its topic scores 0 with that reason. The test is by word, in
//! the code with comments and string literals blanked out: no name
//! `include` or `include_…` may appear at all (a macro could call
//! `include!` through an identifier passed in).

use crate::stubs::quiet::mask;

/// The name of std's macro that reads a file at compile time; its kin
/// (`include_str`, `include_bytes`, the dependencies' `include_wgsl`,
/// `include_spirv`, …) are named `include_…`.
const INCLUDE: &str = "include";

/// The identifiers of `line` that are [`INCLUDE`] or start with `include_`.
fn include_names(line: &str) -> impl Iterator<Item = &str> {
    line.split(|c: char| !(c.is_alphanumeric() || c == '_'))
        .filter(|word| {
            word.strip_prefix(INCLUDE)
                .is_some_and(|rest| rest.is_empty() || rest.starts_with('_'))
        })
}

/// Each use of a forbidden construct in `source`, as `line: what`.
#[must_use]
pub fn uses(source: &str) -> Vec<String> {
    let masked = mask(source);
    let mut found = Vec::new();
    for (number, line) in masked.lines().enumerate() {
        for name in include_names(line) {
            found.push(format!(
                "{}: `{name}!` reads a file at compile time",
                number + 1
            ));
        }
    }
    // `path = ...` inside an attribute, `#[...]` or `#![...]`, which may
    // span lines.
    let bytes = masked.as_bytes();
    let mut i = 0;
    while let Some(at) = masked[i..].find('#').map(|n| i + n) {
        let mut open = at + 1;
        if bytes.get(open) == Some(&b'!') {
            open += 1;
        }
        while bytes.get(open).is_some_and(u8::is_ascii_whitespace) {
            open += 1;
        }
        i = at + 1;
        if bytes.get(open) != Some(&b'[') {
            continue;
        }
        let mut depth = 0;
        let mut end = open;
        for (k, &b) in bytes.iter().enumerate().skip(open) {
            match b {
                b'[' => depth += 1,
                b']' => depth -= 1,
                _ => {}
            }
            if depth == 0 {
                end = k;
                break;
            }
        }
        let attribute = &masked[open..=end.max(open)];
        if names_a_path(attribute) {
            let line = masked[..at].matches('\n').count() + 1;
            found.push(format!(
                "{line}: `#[path]` compiles another file as a module"
            ));
        }
        i = end.max(at + 1);
    }
    found.sort_by_key(|f| {
        f.split(':')
            .next()
            .and_then(|n| n.parse::<usize>().ok())
            .unwrap_or(0)
    });
    found
}

/// Whether an attribute's text holds `path` followed by `=`.
fn names_a_path(attribute: &str) -> bool {
    attribute.match_indices("path").any(|(at, _)| {
        let before = attribute[..at].chars().next_back();
        let is_ident = |c: char| c.is_alphanumeric() || c == '_';
        !before.is_some_and(is_ident) && attribute[at + 4..].trim_start().starts_with('=')
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn path_attributes_and_include_macros_are_found_with_their_lines() {
        let source = "\
//! include_str! in a comment is fine, and \"#[path = x]\" in a string.
#[path = \"/course/reference/01-lines/src/dda.rs\"]
mod solution;
#[cfg_attr(all(), path = \"../x.rs\")]
mod other;
#[ path
    = \"y.rs\"]
mod third;
const LEAK: &str = include_str!(\"/etc/passwd\");
macro_rules! paste { ($m:ident) => { $m!(\"f\") } }
const AGAIN: &str = paste!(include_bytes);
#[derive(Debug)] struct Xpath { path: u32 }
const WGSL: wgpu::ShaderModuleDescriptor = wgpu::include_wgsl!(\"../../reference/x.wgsl\");
";
        assert_eq!(
            uses(source),
            [
                "2: `#[path]` compiles another file as a module",
                "4: `#[path]` compiles another file as a module",
                "6: `#[path]` compiles another file as a module",
                "9: `include_str!` reads a file at compile time",
                "11: `include_bytes!` reads a file at compile time",
                "13: `include_wgsl!` reads a file at compile time",
            ]
        );
    }

    #[test]
    fn the_names_are_refused_anywhere_and_plain_code_is_fine() {
        // A macro could call `include!` with an identifier passed in, so
        // the name alone is refused, even as a variable.
        assert_eq!(
            uses("pub fn f() -> u32 {\n    let include = 1;\n    include\n}"),
            [
                "2: `include!` reads a file at compile time",
                "3: `include!` reads a file at compile time",
            ]
        );
        assert!(uses("pub fn f(path: &str) -> usize { path.len() }").is_empty());
        assert!(uses("fn included(excluded: u8) -> u8 { excluded }").is_empty());
    }
}
