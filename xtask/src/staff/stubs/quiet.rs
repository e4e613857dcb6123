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
//! Names are found on the stub's syntax tree and tokens (see
//! [`super::syntax`]): the function around a `todo!` is the innermost one
//! whose body holds it, its bindings are those of its parameters'
//! patterns and of the `let` statements before the `todo!` in its block,
//! and a name counts as used where the identifier occurs among the tokens
//! of the code, in a macro call's arguments too, but not in a comment or a
//! string (a format string's inline `{name}` is not seen: the borrow it
//! adds is harmless). This is not name resolution (a shadowing local
//! counts as a use of the outer name); the stubs of the course are checked
//! by clippy with `-D warnings`, which is the judge.

use std::ops::Range;

use syn::visit::{self, Visit};
use syn::{Block, FnArg, Item, Pat, Signature, Stmt, UseTree, Visibility};

use super::syntax::{Source, inside, range};

/// The comment above a borrow line.
const BORROW_COMMENT: &str = "// Unused until you write the body:";

/// A binding a stub no longer uses.
struct Binding {
    name: String,
    mutable: bool,
}

/// The bindings of a pattern that a stub could leave unused: every
/// identifier it binds (`mut plot`, `u` and `v` of `[u, v]`, `x` of
/// `Point { x, .. }`), not `_` nor `_x`, which say so already.
fn bindings(pattern: &Pat) -> Vec<Binding> {
    struct Collect(Vec<Binding>);
    impl<'ast> Visit<'ast> for Collect {
        fn visit_pat_ident(&mut self, binding: &'ast syn::PatIdent) {
            let name = binding.ident.to_string();
            if !name.starts_with('_') {
                self.0.push(Binding {
                    name,
                    // `ref mut x` is a reference already: `&x` will do.
                    mutable: binding.by_ref.is_none() && binding.mutability.is_some(),
                });
            }
            visit::visit_pat_ident(self, binding);
        }
    }
    let mut collect = Collect(Vec::new());
    collect.visit_pat(pattern);
    collect.0
}

/// The innermost function whose body holds byte `at`, and the innermost
/// block that does.
struct Around<'ast> {
    at: usize,
    function: Option<(&'ast Signature, &'ast Block)>,
    block: Option<&'ast Block>,
}

impl<'ast> Around<'ast> {
    fn holds(&self, block: &Block) -> bool {
        inside(
            block.brace_token.span.open(),
            block.brace_token.span.close(),
        )
        .contains(&self.at)
    }

    fn function(&mut self, signature: &'ast Signature, body: &'ast Block) {
        if self.holds(body) {
            self.function = Some((signature, body));
        }
    }
}

// The tree is walked from the outside in: the last function and block
// found to hold `at` are the innermost.
impl<'ast> Visit<'ast> for Around<'ast> {
    super::syntax::visit_function_bodies!();

    fn visit_block(&mut self, block: &'ast Block) {
        if self.holds(block) {
            self.block = Some(block);
        }
        visit::visit_block(self, block);
    }
}

/// The bindings of the function around the `todo!` on lines `todo` (its
/// bytes) that nothing but those lines would use: its parameters, and the
/// locals its block declares before it.
fn unused_bindings(source: &Source<'_>, todo: Range<usize>) -> Vec<Binding> {
    let mut around = Around {
        at: todo.start,
        function: None,
        block: None,
    };
    around.visit_file(&source.file);
    let (Some((signature, body)), Some(block)) = (around.function, around.block) else {
        return Vec::new();
    };
    let body_end = inside(body.brace_token.span.open(), body.brace_token.span.close()).end;
    // Used between `from` and the todo!, or after it in the body.
    let unused = |binding: &Binding, from: usize| {
        !source.mentions(&binding.name, from..todo.start)
            && !source.mentions(&binding.name, todo.end.min(body_end)..body_end)
    };
    let mut unused_bindings: Vec<Binding> = signature
        .inputs
        .iter()
        .filter_map(|input| match input {
            FnArg::Typed(parameter) => Some(bindings(&parameter.pat)),
            FnArg::Receiver(_) => None,
        })
        .flatten()
        .filter(|binding| unused(binding, range(body).start))
        .collect();
    // Locals of the todo!'s own block, declared before it.
    for statement in &block.stmts {
        let statement_range = range(statement);
        if statement_range.end > todo.start {
            break;
        }
        if let Stmt::Local(local) = statement {
            unused_bindings.extend(
                bindings(&local.pat)
                    .into_iter()
                    .filter(|binding| unused(binding, statement_range.end)),
            );
        }
    }
    unused_bindings
}

/// The names a `use` tree brings into scope (`a::{b, c as d}` → `b`, `d`;
/// `a::{self}` → `a`); globs and `_` imports bring none that could go
/// unused by name. `parent` is the last segment of the path above `tree`.
fn imported_names(tree: &UseTree, parent: Option<&syn::Ident>, names: &mut Vec<String>) {
    match tree {
        UseTree::Path(path) => imported_names(&path.tree, Some(&path.ident), names),
        UseTree::Name(name) if name.ident == "self" => {
            names.extend(parent.map(ToString::to_string));
        }
        UseTree::Name(name) => names.push(name.ident.to_string()),
        UseTree::Rename(rename) if rename.rename == "_" => {}
        UseTree::Rename(rename) => names.push(rename.rename.to_string()),
        UseTree::Glob(_) => {}
        UseTree::Group(group) => {
            for tree in &group.items {
                imported_names(tree, parent, names);
            }
        }
    }
}

/// Adds borrow lines and `allow` attributes to a generated stub; `todos`
/// are the stub's `todo!` calls as (first line, line after the call),
/// 0-based. A stub that is not Rust is returned as it is.
pub fn quiet(stub: &str, todos: &[(usize, usize)], newline: &str, max_width: usize) -> String {
    let Some(source) = Source::parse(stub) else {
        return stub.to_owned();
    };
    // Lines to insert, each before a line of the stub (0-based).
    let mut inserts: Vec<(usize, Vec<String>)> = Vec::new();

    for &(todo, todo_end) in todos {
        let todo_bytes = source.line_start(todo)..source.line_start(todo_end);
        let bindings = unused_bindings(&source, todo_bytes);
        if bindings.is_empty() {
            continue;
        }
        let indent = source.indent(todo);
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

    // Top-level private `use` items with a name the rest of the stub never
    // mentions.
    let private = |visibility: &Visibility| matches!(visibility, Visibility::Inherited);
    let uses: Vec<&syn::ItemUse> = source
        .file
        .items
        .iter()
        .filter_map(|item| match item {
            Item::Use(item) if private(&item.vis) => Some(item),
            _ => None,
        })
        .collect();
    let use_ranges: Vec<Range<usize>> = uses.iter().map(|item| range(*item)).collect();
    let mentioned = |name: &str, except: &[Range<usize>]| {
        source
            .words()
            .any(|(word, at)| word == name && !except.iter().any(|r| r.contains(&at)))
    };
    for item in &uses {
        let mut names = Vec::new();
        imported_names(&item.tree, None, &mut names);
        if names.iter().any(|name| !mentioned(name, &use_ranges)) {
            let line = source.line_of(range(&item.use_token).start);
            let indent = source.indent(line);
            inserts.push((line, vec![format!("{indent}#[allow(unused_imports)]")]));
        }
    }

    // Top-level private helpers (`fn`, `const`) that nothing outside
    // themselves mentions. Top-level items only: a method may be a
    // trait's, called from afar.
    for item in &source.file.items {
        let (name, first_token) = match item {
            Item::Fn(function) if private(&function.vis) => {
                (&function.sig.ident, range(&function.sig).start)
            }
            Item::Const(constant) if private(&constant.vis) => {
                (&constant.ident, range(&constant.const_token).start)
            }
            _ => continue,
        };
        let name = name.to_string();
        if !name.starts_with('_') && !mentioned(&name, &[range(item)]) {
            let line = source.line_of(first_token);
            let indent = source.indent(line);
            inserts.push((line, vec![format!("{indent}#[allow(dead_code)]")]));
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
        let item: syn::ItemUse =
            syn::parse_str("use a::{b, c::D as E, f::{self, g}, h::*, i as _};").expect("a use");
        let mut names = Vec::new();
        imported_names(&item.tree, None, &mut names);
        assert_eq!(names, ["b", "E", "f", "g"]);
    }

    #[test]
    fn names_in_strings_comments_and_raw_byte_strings_are_no_use() {
        let stub = "\
pub fn f(from: u8, to: u8, by: u8, size: u8) -> u8 {
    let _bytes = br#\"from\"#;
    /* /* to */ size */
    println!(\"{}\", \"by\");
    todo!(\"t: x\")
}
";
        assert_eq!(
            quiet_all(stub),
            "\
pub fn f(from: u8, to: u8, by: u8, size: u8) -> u8 {
    let _bytes = br#\"from\"#;
    /* /* to */ size */
    println!(\"{}\", \"by\");
    // Unused until you write the body:
    let _ = (&from, &to, &by, &size);
    todo!(\"t: x\")
}
"
        );
    }

    #[test]
    fn the_function_and_block_around_a_todo_are_read_from_the_tree() {
        // The method's attribute shares its line; a local of an earlier
        // block at the todo!'s indentation is out of its scope.
        let stub = "\
impl A {
    #[must_use] pub fn f<F: Fn(u8) -> Vec<Vec<u8>>>(&self, n: u8, g: F) -> u8 where F: Copy {
        for i in 0..n {
            let step = i;
            println!(\"{step}\");
        }
        {
            todo!(\"t: x\")
        }
    }
}
";
        let quiet = quiet_all(stub);
        assert!(
            quiet.contains("        {\n            // Unused until you write the body:\n            let _ = &g;\n            todo!"),
            "{quiet}"
        );
        assert!(!quiet.contains("&step"), "{quiet}");
    }

    #[test]
    fn private_const_fns_and_helpers_used_only_by_themselves_are_allowed() {
        let stub = "\
const fn half(x: u32) -> u32 {
    x / 2
}

fn countdown(n: u32) -> u32 {
    if n == 0 { 0 } else { countdown(n - 1) }
}

/// Draws.
pub fn f() {
    todo!(\"t: x\")
}
";
        let quiet = quiet_all(stub);
        assert!(
            quiet.contains("#[allow(dead_code)]\nconst fn half"),
            "{quiet}"
        );
        assert!(
            quiet.contains("#[allow(dead_code)]\nfn countdown"),
            "{quiet}"
        );
    }
}
