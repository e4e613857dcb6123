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

use std::fmt::Write as _;
use std::ops::Range;

use super::quiet::{closing, identifier, split_top_level};
use crate::stubs::quiet::mask;

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
    parse_in(masked, at, None).and_then(|(receiver, f)| receiver.is_empty().then_some(f))
}

/// The function whose name starts at byte `at` of `masked`, and its
/// receiver (`self`, `&self`, `&mut self`; empty for none). In an `impl`
/// block of `self_type`, that type is named `Self` in the shape.
fn parse_in(masked: &str, at: usize, self_type: Option<&str>) -> Option<(String, Function)> {
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
    let mut receiver = String::new();
    for (i, parameter) in split_top_level(&masked[open + 1..close])
        .into_iter()
        .enumerate()
    {
        if parameter.trim().is_empty() {
            continue;
        }
        if i == 0
            && self_type.is_some()
            && let Some(kind) = receiver_kind(parameter)
        {
            receiver = kind.to_owned();
            continue;
        }
        let (pattern, ty) = split_parameter(parameter)?;
        patterns.push(pattern.trim().to_owned());
        types.push(normalized(ty));
    }
    let tail = &masked[close + 1..body_open];
    let (ret, clause) = tail.split_once(" where").unwrap_or((tail, ""));
    let ret = ret.trim().strip_prefix("->").unwrap_or("");
    let mut shape = format!(
        "{}({})->{} where {}",
        normalized(generics),
        types.join(","),
        normalized(ret),
        normalized(clause)
    );
    if let Some(self_type) = self_type {
        shape = named_self(&shape, self_type);
    }
    let function = Function {
        name: name.to_owned(),
        patterns,
        shape,
        body: body_open + 1..body_close,
    };
    Some((receiver, function))
}

/// The kind of a receiver parameter (`self`, `mut self`, `&self`, `&'a mut
/// self`, `self: &Self`): `self`, `&self` or `&mut self`; `None` for a
/// parameter that is not one.
fn receiver_kind(parameter: &str) -> Option<&'static str> {
    let compact: String = parameter.split_whitespace().collect::<Vec<_>>().join(" ");
    let (head, ty) = compact
        .split_once(':')
        .map_or((compact.as_str(), ""), |(h, t)| (h, t));
    let head = head.trim().trim_start_matches("mut ").trim();
    if head != "self" && !head.ends_with(" self") && !head.ends_with("&self") {
        return None;
    }
    let written = if ty.is_empty() { head } else { ty.trim() };
    Some(if written.contains("&mut") || written.contains("& mut") {
        "&mut self"
    } else if written.contains('&') {
        "&self"
    } else {
        "self"
    })
}

/// `text` with every whole-word `name` replaced by `Self`.
fn named_self(text: &str, name: &str) -> String {
    if name.is_empty() {
        return text.to_owned();
    }
    let mut out = String::new();
    let mut rest = text;
    while let Some(at) = rest.find(name) {
        let before = rest[..at].bytes().next_back();
        let after = rest.as_bytes().get(at + name.len()).copied();
        out.push_str(&rest[..at]);
        if before.is_some_and(is_ident_char) || after.is_some_and(is_ident_char) {
            out.push_str(name);
        } else {
            out.push_str("Self");
        }
        rest = &rest[at + name.len()..];
    }
    out.push_str(rest);
    out
}

/// A function of an `impl` block at the top level of a source file: an
/// inherent method or associated function, public or not, or a trait's.
#[derive(Debug, Clone, PartialEq)]
pub struct Method {
    /// The implementing type's name (`DepthRange` of `impl DepthRange`).
    pub self_type: String,
    /// The trait, for `impl Trait for Type`.
    pub trait_name: Option<String>,
    /// `self`, `&self`, `&mut self`, or empty for an associated function.
    pub receiver: String,
    /// The function: its parameters without the receiver, its shape with
    /// the implementing type named `Self`.
    pub function: Function,
}

impl Method {
    /// `Type::name`, or `<Type as Trait>::name`.
    pub fn display(&self) -> String {
        match &self.trait_name {
            Some(t) => format!("<{} as {t}>::{}", self.self_type, self.function.name),
            None => format!("{}::{}", self.self_type, self.function.name),
        }
    }

    /// Whether `given` could stand in for this method: the same kind of
    /// receiver and number of parameters, and the same name or the same
    /// shape.
    pub fn could_be(&self, given: &Method) -> bool {
        self.receiver == given.receiver
            && self.function.patterns.len() == given.function.patterns.len()
            && (self.function.name == given.function.name
                || self.function.shape == given.function.shape)
    }
}

/// The functions with a body of the `impl` blocks at the top level of
/// `source` (not those of a nested module).
pub fn methods(source: &str) -> Vec<Method> {
    let masked = mask(source);
    let depth = brace_depths(&masked);
    let bytes = masked.as_bytes();
    let mut found = Vec::new();
    let mut from = 0;
    while let Some(offset) = masked[from..].find("impl") {
        let start = from + offset;
        from = start + 4;
        let word_start = start == 0 || !is_ident_char(bytes[start - 1]);
        let word_end = bytes
            .get(start + 4)
            .is_some_and(|&b| b == b'<' || b.is_ascii_whitespace());
        if !word_start || !word_end || depth[start] != 0 {
            continue;
        }
        let Some(open) = masked[start..].find('{').map(|o| start + o) else {
            break;
        };
        let Some(close) = closing(&masked, open, false) else {
            break;
        };
        let mut header = masked[start + 4..open].trim();
        if header.starts_with('<') {
            header = closing(header, 0, true).map_or(header, |end| header[end + 1..].trim());
        }
        let header = header.split(" where").next().unwrap_or(header);
        let (trait_name, self_type) = match header.split_once(" for ") {
            Some((t, ty)) => (Some(normalized(t)), normalized(ty)),
            None => (None, normalized(header)),
        };
        let self_type = identifier(self_type.trim_start_matches('&'))
            .unwrap_or_default()
            .to_owned();
        let mut at = open + 1;
        while let Some(offset) = masked[at..close].find("fn ") {
            let f = at + offset;
            at = f + 3;
            if depth[f] != 1 || (f > 0 && is_ident_char(bytes[f - 1])) {
                continue;
            }
            if let Some((receiver, function)) = parse_in(&masked, f + 3, Some(&self_type)) {
                at = function.body.end;
                found.push(Method {
                    self_type: self_type.clone(),
                    trait_name: trait_name.clone(),
                    receiver,
                    function,
                });
            }
        }
        from = close;
    }
    found
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
    let out: Option<Vec<String>> = function.patterns.iter().map(|p| argument(p)).collect();
    Some(out?.join(", "))
}

/// A parameter's pattern as the expression that passes its value on;
/// `None` where the pattern binds less than it takes.
fn argument(pattern: &str) -> Option<String> {
    let expression = pattern.replace("mut ", "");
    let binds_all = expression
        .split(|c: char| !is_ident_char(c as u8) || !c.is_ascii())
        .all(|word| word != "_" && word != "ref")
        && !expression.contains("..")
        && !expression.contains('@')
        && !expression.contains('&');
    binds_all.then_some(expression)
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

/// `stub` with the body of its method `task` replaced by the body of the
/// given method `given` (from `given_source`): each of the given
/// parameters bound to the task's argument in its place, and the names of
/// the given module in scope, from `module` (its path, where the task's
/// crate can name it) or from a copy of the given file, appended as `mod
/// stand_in`.
pub fn plant_method(
    stub: &str,
    task: &Method,
    given: &Method,
    given_source: &str,
    module: Option<&str>,
) -> Option<String> {
    let mut body = String::from("\n");
    match module {
        Some(path) => {
            let _ = writeln!(body, "    #[allow(unused_imports)]\n    use {path}::*;");
        }
        None => body.push_str("    #[allow(unused_imports)]\n    use self::stand_in::*;\n"),
    }
    for (theirs, ours) in given.function.patterns.iter().zip(&task.function.patterns) {
        let value = argument(ours)?;
        if *theirs != value {
            let _ = writeln!(
                body,
                "    #[allow(unused_variables, unused_mut)]\n    let {theirs} = {value};"
            );
        }
    }
    body.push_str(&given_source[given.function.body.clone()]);
    body.push('\n');
    let mut out = stub.to_owned();
    out.replace_range(task.function.body.clone(), &body);
    if module.is_none() {
        out.push_str(
            "\n// The given code planted in (see `cargo xtask test`).\n\
             #[allow(dead_code, unused_imports, unused_variables, clippy::all)]\n\
             mod stand_in {\n",
        );
        out.push_str(given_source);
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

    const IMPLS: &str = "\
pub struct Compare;
impl Compare {
    pub fn passes<T: PartialOrd>(self, incoming: T, stored: T) -> bool { todo!(\"zbuffer: compare\") }
    fn private(&mut self, a: Compare) -> Compare { a }
    pub const fn new() -> Self { Self }
}
impl<T: Copy> Solid for Placed<T> where T: Default {
    fn span(&self, ray: &Ray) -> Option<Span> { None }
}
mod nested {
    impl Hidden { pub fn f(&self) {} }
}
";

    #[test]
    fn methods_of_top_level_impl_blocks_with_their_receivers() {
        let found = methods(IMPLS);
        let names: Vec<String> = found.iter().map(Method::display).collect();
        assert_eq!(
            names,
            [
                "Compare::passes",
                "Compare::private",
                "Compare::new",
                "<Placed as Solid>::span",
            ]
        );
        let receivers: Vec<&str> = found.iter().map(|m| m.receiver.as_str()).collect();
        assert_eq!(receivers, ["self", "&mut self", "", "&self"]);
        assert_eq!(found[0].function.patterns, ["incoming", "stored"]);
        assert_eq!(found[1].function.shape, "(Self)->Self where ");
        assert_eq!(found[3].function.shape, "(&Ray)->Option<Span> where ");
        assert_eq!(
            stub_task(IMPLS, &found[0].function).as_deref(),
            Some("zbuffer")
        );
    }

    #[test]
    fn a_planted_method_binds_the_given_parameters_to_the_task_arguments() {
        let task = &methods(IMPLS)[0];
        let given_source = "impl Other {\n    pub fn passes(self, a: f32, stored: f32) -> bool { a < stored }\n}\n";
        let given = &methods(given_source)[0];
        assert!(task.could_be(given));
        assert!(!task.could_be(&methods(IMPLS)[1]));
        let planted =
            plant_method(IMPLS, task, given, given_source, Some("buffers::zbuffer")).unwrap();
        assert!(planted.contains("use buffers::zbuffer::*;"), "{planted}");
        assert!(planted.contains("let a = incoming;"), "{planted}");
        assert!(!planted.contains("let stored = stored;"), "{planted}");
        assert!(planted.contains(" a < stored "), "{planted}");
        assert!(!planted.contains("todo!"), "{planted}");
        let copied = plant_method(IMPLS, task, given, given_source, None).unwrap();
        assert!(copied.contains("use self::stand_in::*;"), "{copied}");
        assert!(copied.ends_with(&format!("mod stand_in {{\n{given_source}\n}}\n")));
    }

    #[test]
    fn patterns_that_drop_a_value_cannot_be_passed_on() {
        let source = "pub fn f(_: u8, (a, ..): (u8, u8)) {}\npub fn g(_a: u8) {}\n";
        let found = public_functions(source);
        assert_eq!(arguments(&found[0]), None);
        assert_eq!(arguments(&found[1]).as_deref(), Some("_a"));
    }
}
