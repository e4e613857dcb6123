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
//!
//! The stub is read as a syntax tree (see [`super::syntax`]): a `todo!()`
//! is replaced where it is the tail of a function's body, the last
//! statement with no `;` after it, and only there; a `todo!(` in a string
//! or a comment is no call.

use syn::visit::Visit;
use syn::{Block, Expr, Macro, ReturnType, Signature, Stmt, Type, TypeParamBound};

use super::syntax::{Source, range};

/// The cheapest tail expression of a function whose return type is
/// `output`; `None` where none surely exists (`!`, an `impl Trait` other
/// than an iterator).
fn cheapest(output: &ReturnType) -> Option<&'static str> {
    let ReturnType::Type(_, ty) = output else {
        return Some("");
    };
    match &**ty {
        Type::Tuple(unit) if unit.elems.is_empty() => Some(""),
        Type::Never(_) => None,
        Type::Path(path) if is_result(&path.path) => Some("Ok(Default::default())"),
        Type::ImplTrait(bounds) => bounds
            .bounds
            .iter()
            .any(is_iterator)
            .then_some("std::iter::empty()"),
        _ => Some("Default::default()"),
    }
}

/// Whether a bound of an `impl Trait` is an iterator's (`Iterator`,
/// `DoubleEndedIterator`, `IntoIterator`, …), which an empty one meets.
fn is_iterator(bound: &TypeParamBound) -> bool {
    let TypeParamBound::Trait(bound) = bound else {
        return false;
    };
    bound
        .path
        .segments
        .last()
        .is_some_and(|segment| segment.ident.to_string().contains("Iterator"))
}

/// Whether `path` names the standard `Result` with its arguments:
/// `Result<T, E>` or `std::result::Result<T, E>`. An alias such as
/// `io::Result<T>` is not recognised: its body is `Default::default()`,
/// which does not compile, and the caller keeps the `todo!()`.
fn is_result(path: &syn::Path) -> bool {
    let names: Vec<String> = path.segments.iter().map(|s| s.ident.to_string()).collect();
    let generic = path
        .segments
        .last()
        .is_some_and(|s| matches!(s.arguments, syn::PathArguments::AngleBracketed(_)));
    generic && (names == ["Result"] || names == ["std", "result", "Result"])
}

/// The `todo!(…)` that is the tail of a body: its last statement, a
/// `todo` macro with no `;` after it.
fn tail_todo(block: &Block) -> Option<&Macro> {
    let call = match block.stmts.last()? {
        Stmt::Macro(statement) if statement.semi_token.is_none() => &statement.mac,
        Stmt::Expr(Expr::Macro(expression), None) => &expression.mac,
        _ => return None,
    };
    call.path.is_ident("todo").then_some(call)
}

/// The `todo!` calls that are a function's whole result, with the
/// function's return type: every function with a body, at any depth
/// (methods, trait defaults and functions nested in bodies too).
struct Tails<'ast> {
    found: Vec<(&'ast Macro, &'ast ReturnType)>,
}

impl<'ast> Tails<'ast> {
    fn function(&mut self, signature: &'ast Signature, body: &'ast Block) {
        if let Some(call) = tail_todo(body) {
            self.found.push((call, &signature.output));
        }
    }
}

impl<'ast> Visit<'ast> for Tails<'ast> {
    super::syntax::visit_function_bodies!();
}

/// `stub` with each `todo!(…)` that is its function's whole result
/// replaced by the [`cheapest`] body, except those on the lines (1-based)
/// in `keep`. Line numbers stay those of the stub. Also returns the lines
/// replaced. A stub that is not Rust is returned as it is.
pub fn do_nothing(stub: &str, keep: &[usize]) -> (String, Vec<usize>) {
    let Some(source) = Source::parse(stub) else {
        return (stub.to_owned(), Vec::new());
    };
    let mut tails = Tails { found: Vec::new() };
    tails.visit_file(&source.file);
    let mut edits = Vec::new();
    for (call, output) in tails.found {
        // From `todo` to the closing delimiter.
        let span = range(&call.path).start..call.delimiter.span().close().byte_range().end;
        let line = source.line_of(span.start) + 1;
        if let (Some(body), false) = (cheapest(output), keep.contains(&line)) {
            edits.push((span, body, line));
        }
    }
    edits.sort_by_key(|(span, _, _)| span.start);
    let mut out = stub.to_owned();
    for (span, body, _) in edits.iter().rev() {
        // The call's line breaks stay, so that every line keeps its number.
        let breaks = stub[span.clone()].matches('\n').count();
        out.replace_range(span.clone(), &format!("{body}{}", "\n".repeat(breaks)));
    }
    (out, edits.iter().map(|edit| edit.2).collect())
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

    #[test]
    fn array_returns_and_where_clauses_with_double_angles_are_bodies() {
        // The `;` of an array type is no end of a declaration, and the
        // `>>` of nested generics closes two of them.
        let stub = "\
pub fn table() -> [f32; 4] {
    todo!(\"t: the table\")
}

pub fn edges<T>(xs: &[T]) -> Vec<[u32; 2]>
where
    T: Into<Vec<Vec<u32>>>,
{
    let _ = &xs;
    todo!()
}
";
        let (out, lines) = do_nothing(stub, &[]);
        assert_eq!(lines, [2, 10], "{out}");
        assert!(
            out.contains("[f32; 4] {\n    Default::default()\n}"),
            "{out}"
        );
        assert!(out.contains("&xs;\n    Default::default()\n}"), "{out}");
    }

    #[test]
    fn braces_and_calls_in_raw_strings_and_nested_comments_are_not_code() {
        // A brace in a raw byte string and in a nested block comment
        // closes nothing; a `todo!()` in a string, in a comment or
        // followed by `;` is no body's result.
        let stub = "\
fn a() -> u8 {
    let _s = br#\"{\"#;
    todo!()
}

fn b() -> u8 {
    /* /* } */ } todo!() */
    todo!()
}

fn c() -> &'static str {
    \"todo!()\"
}

fn d() -> u8 {
    todo!();
}
";
        let (out, lines) = do_nothing(stub, &[]);
        assert_eq!(lines, [3, 8], "{out}");
        assert!(
            out.contains("br#\"{\"#;\n    Default::default()\n}"),
            "{out}"
        );
        assert!(out.contains("*/\n    Default::default()\n}"), "{out}");
        assert!(out.contains("    \"todo!()\"\n"), "{out}");
        assert!(out.contains("    todo!();\n"), "{out}");
    }
}
