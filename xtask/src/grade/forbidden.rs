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
//!
//! **A stop-gap: the known soundness hole.** Safe Rust has a long-known
//! soundness hole, rust-lang/rust#25860: a function whose parameter nests
//! two references with two lifetimes (`&'a &'b ()`) carries the *implied*
//! bound `'b: 'a`, which the compiler forgets when the function is turned
//! into a function pointer, so `fn(&'a &'b (), &'b T) -> &'a T` turns any
//! reference into a `&'static` one. The `cve-rs` crate builds arbitrary
//! reads and writes of the process's memory from it, with no `unsafe` at
//! all: enough to read a secret out of the test's own process, or to
//! overwrite its verdict. So a task file is also refused when it holds
//! what that trick needs (see [`soundness_hole_uses`]): a reference to a
//! type that names a second lifetime (`&'a &'b T`, `&'static &'a ()`,
//! `&'a Wrapper<'b>`, also when a `macro_rules!` builds it from `$`
//! fragments), or a trait implemented for a reference with a lifetime
//! (`impl<'b> Tr for &'b ()`, whose `&self` methods take `&'s &'b ()`).
//! The course's solutions need neither. This check reads text, and text
//! can be disguised: it closes the doors the public exploits use, it is
//! not the defence. The defence is that no pass is decided, and no secret
//! lives, in a process that ran student code (the replayed verdict).

use crate::stubs::quiet::try_mask;

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
    // Text that is not Rust tokens cannot be checked, and would not
    // compile either: refused, with the lexer's place.
    let masked = match try_mask(source) {
        Ok(masked) => masked,
        Err(why) => {
            return vec![format!(
                "{why}: the file cannot be read as Rust, so it is not checked or compiled"
            )];
        }
    };
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
    found.extend(soundness_hole_uses(&masked));
    found.extend(crate::sandbox::const_eval::lifted_bounds(&masked));
    found.sort_by_key(|f| {
        f.split(':')
            .next()
            .and_then(|n| n.parse::<usize>().ok())
            .unwrap_or(0)
    });
    found
}

/// What a refused use of the soundness hole is told.
const SOUNDNESS_HOLE: &str = "uses the lifetime-extension trick of a known soundness hole in the compiler (rust-lang/rust#25860, as in the `cve-rs` crate), which lets safe code read and write any memory: refused";

/// The lifetime (`'a`, or a macro's `$a` fragment) at the start of
/// `text`, if any; `None` for the elided `'_` and for `'static`, which
/// extend nothing when nested inside another reference.
fn lifetime_at(text: &str, macro_fragment: bool) -> Option<&str> {
    let sigil = if macro_fragment { '$' } else { '\'' };
    let rest = text.strip_prefix(sigil)?;
    let end = rest
        .find(|c: char| !(c.is_alphanumeric() || c == '_'))
        .unwrap_or(rest.len());
    let name = &text[..=end];
    (end > 0 && name != "'_" && name != "'static").then_some(name)
}

/// The uses of the soundness hole's patterns in `masked` (code with
/// comments and strings blanked), as `line: what`: a reference `&'x`
/// (or `&$x` in a macro) to a type that names another lifetime before
/// the type ends, and a trait implemented `for &'x …`.
fn soundness_hole_uses(masked: &str) -> Vec<String> {
    let line_of = |at: usize| masked[..at].matches('\n').count() + 1;
    let mut found = Vec::new();
    for (at, _) in masked.match_indices('&') {
        let after = masked[at + 1..].trim_start();
        // `&'static` names no lifetime to extend, but a `&'static &'a ()`
        // still nests two: the outer one may be `'static`.
        let outer = lifetime_at(after, false)
            .or_else(|| after.strip_prefix("'static").map(|_| "'static"))
            .or_else(|| lifetime_at(after, true));
        let Some(outer) = outer else {
            continue;
        };
        // The referent: up to where its type ends at depth 0.
        let referent = &after[outer.len()..];
        let mut depth = 0i32;
        let mut end = referent.len();
        for (i, c) in referent.char_indices() {
            match c {
                '<' | '(' | '[' => depth += 1,
                '>' | ')' | ']' if depth == 0 => {
                    end = i;
                    break;
                }
                '>' | ')' | ']' => depth -= 1,
                ',' | ';' | '=' | '{' | '}' | '|' if depth == 0 => {
                    end = i;
                    break;
                }
                _ => {}
            }
        }
        // A `where` clause after a return type is no part of it.
        let referent = &referent[..end];
        let referent = referent
            .match_indices("where")
            .find(|(i, _)| referent[..*i].ends_with(char::is_whitespace))
            .map_or(referent, |(i, _)| &referent[..i]);
        let names_another = referent.char_indices().any(|(i, c)| {
            let inner = match c {
                '\'' => lifetime_at(&referent[i..], false),
                // A fragment only right after a `&`: `&$a &$b ()`.
                '$' if referent[..i].trim_end().ends_with('&') => lifetime_at(&referent[i..], true),
                _ => None,
            };
            inner.is_some_and(|inner| inner != outer)
        });
        if names_another {
            found.push(format!(
                "{}: `&{outer} …` nests a reference with another lifetime: {SOUNDNESS_HOLE}",
                line_of(at)
            ));
        }
    }
    // `impl<'b> Trait for &'b X`: its `&self` methods take `&'s &'b X`.
    for (at, _) in masked.match_indices("impl") {
        let word = !masked[..at].ends_with(|c: char| c.is_alphanumeric() || c == '_')
            && !masked[at + 4..].starts_with(|c: char| c.is_alphanumeric() || c == '_');
        if !word {
            continue;
        }
        let header_end = masked[at..].find('{').map_or(masked.len(), |n| at + n);
        let header = &masked[at..header_end];
        let for_a_reference = header.match_indices("for").any(|(i, _)| {
            let before = header[..i].ends_with(|c: char| c.is_whitespace() || c == '>');
            let rest = header[i + 3..].trim_start();
            before
                && rest
                    .strip_prefix('&')
                    .map(str::trim_start)
                    .is_some_and(|r| r.starts_with('\'') || r.starts_with('$'))
        });
        if for_a_reference {
            found.push(format!(
                "{}: a trait implemented for a reference with a lifetime (`impl … for &'b …`, whose `&self` is `&'s &'b …`): {SOUNDNESS_HOLE}",
                line_of(at)
            ));
        }
    }
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
    use std::path::Path;

    #[test]
    fn an_include_after_a_raw_byte_string_is_found() {
        // `br"\"` is a whole raw byte string (its backslash escapes
        // nothing): a scanner that took it for an escaped quote read the
        // `include!` after it as the inside of a string.
        let found = uses(
            "const A: &[u8] = br\"\\\";\nconst B: &str = include_str!(\"/etc/passwd\"); const C: &str = \"\";\n",
        );
        assert!(
            found.iter().any(|f| f.starts_with("2: `include_str!`")),
            "{found:?}"
        );
        let unlexable = uses("fn f() { \"unclosed }");
        assert!(
            unlexable.len() == 1 && unlexable[0].contains("cannot be read as Rust"),
            "{unlexable:?}"
        );
    }

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

    /// `cve-rs`'s `lifetime_expansion.rs` (github.com/Speykious/cve-rs),
    /// the heart of every exploit of rust-lang/rust#25860.
    const CVE_RS: &str = "\
pub const fn lifetime_translator<'a, 'b, T: ?Sized>(_val_a: &'a &'b (), val_b: &'b T) -> &'a T {
\tval_b
}
pub fn lifetime_translator_mut<'a, 'b, T: ?Sized>(
\t_val_a: &'a &'b (),
\tval_b: &'b mut T,
) -> &'a mut T {
\tval_b
}
pub fn expand<'a, 'b, T: ?Sized>(x: &'a T) -> &'b T {
\tlet f: fn(_, &'a T) -> &'b T = lifetime_translator;
\tf(STATIC_UNIT, x)
}
pub const STATIC_UNIT: &&() = &&();
";

    fn refused_lines(source: &str) -> Vec<usize> {
        uses(source)
            .iter()
            .filter(|u| u.contains("rust-lang/rust#25860"))
            .map(|u| u.split(':').next().unwrap().parse().unwrap())
            .collect()
    }

    #[test]
    fn the_soundness_hole_of_cve_rs_is_refused_in_each_disguise() {
        assert_eq!(refused_lines(CVE_RS), [1, 5]);
        // A function pointer type, `'static` outside, `mut` between.
        assert_eq!(
            refused_lines("fn f<'a, T>() { let g: fn(&'static &'a (), &'a T) -> &'static T = h; }"),
            [1]
        );
        assert_eq!(refused_lines("fn t<'a, 'b>(x: &'a mut &'b mut u8) {}"), [1]);
        // Through a type alias or a struct: the nested reference is where
        // it is defined, and the outer reference names it with another
        // lifetime where it is used.
        assert_eq!(
            refused_lines(
                "type Unit<'b> = &'b ();\nfn t<'a, 'b, T>(_: &'a Unit<'b>, v: &'b T) -> &'a T { v }"
            ),
            [2]
        );
        assert_eq!(refused_lines("type Both<'a, 'b> = &'a &'b ();"), [1]);
        assert_eq!(
            refused_lines(
                "struct W<'b>(std::marker::PhantomData<&'b ()>);\nfn t<'a, 'b, T>(_: &'a W<'b>, v: &'b T) -> &'a T { v }"
            ),
            [2]
        );
        // Through a trait with a method: `&self` of `&'b ()`.
        assert_eq!(
            refused_lines(
                "trait Tr<'b> { fn t<'s, T>(&'s self, v: &'b T) -> &'s T; }\nimpl<'b> Tr<'b> for &'b () {\n    fn t<'s, T>(&'s self, v: &'b T) -> &'s T { v }\n}"
            ),
            [2]
        );
        // Built by a macro from lifetime fragments.
        assert_eq!(
            refused_lines(
                "macro_rules! nest { ($a:lifetime, $b:lifetime) => { &$a &$b () } }\nfn t<'a, 'b, T>(_: nest!('a, 'b), v: &'b T) -> &'a T { v }"
            ),
            [1]
        );
    }

    #[test]
    fn ordinary_references_and_the_course_solutions_are_not_the_hole() {
        for fine in [
            "fn f<'a>(x: &'a [u8], y: &'a &'a u8) -> &'a u8 { &x[0] }",
            "fn g(x: &&u8, y: &'static str, z: &'_ Vec<&'_ u8>) {}",
            "fn h<'a>(x: &'a Vec<&'static str>) {}",
            "impl<'a> Iterator for Spans<'a> { type Item = &'a u8; }",
            "macro_rules! r { ($t:ty) => { &'static $t } }",
            "fn k(a: u8, b: u8) -> bool { a & b == 0 && a > 1 }",
            "fn w<'a, 'b>(x: &'a u8, y: &'b u8) -> &'a u8\nwhere\n    'b: 'a,\n{ x }",
        ] {
            assert!(refused_lines(fine).is_empty(), "{fine}: {:?}", uses(fine));
        }
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
        for file in crate::files::files_under(&root.join("reference")).unwrap() {
            if file.extension().is_some_and(|e| e == "rs") {
                let text = std::fs::read_to_string(root.join("reference").join(&file)).unwrap();
                assert!(
                    uses(&text).is_empty(),
                    "{}: {:?}",
                    file.display(),
                    uses(&text)
                );
            }
        }
    }
}
