//! Given code that could stand in for a task: a public function of the
//! course's given code (a library crate, or a file of an exercise crate
//! that holds no task) with the signature of a task's stub. `cargo xtask
//! test` plants each one into the stub, as a call where the task's crate
//! can reach it and as a copy of its file where not, and requires the task
//! to score 0: given code never solves a task.
//!
//! Two functions have the same signature when their generics, parameter
//! types, return type and `where` clause agree token for token with paths
//! and spaces taken out (`glam::Vec2` is `Vec2`); parameter names do not
//! count. The functions are read from each file's syntax tree (see
//! [`super::syntax`]), their parts by their places in the text.

use std::fmt::Write as _;
use std::ops::Range;

use syn::visit::{self, Visit};
use syn::{FnArg, ImplItem, Item, Pat, ReturnType, Signature, Type, Visibility};

use super::syntax::{Source, inside, range};

/// A function with a body: a public free function at the top level of a
/// source file, or a function of an `impl` block (see [`Method`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Function {
    /// Its name.
    pub name: String,
    /// Its parameters, the receiver aside.
    pub parameters: Vec<Parameter>,
    /// Its signature without its name, parameter names, paths and spaces:
    /// what two functions share when one can stand in for the other.
    pub shape: String,
    /// The contents of its body, between the braces.
    pub body: Range<usize>,
    /// The task of a stub's function: the `<task>` of the first
    /// `todo!("<task>: …")` in its body, if it holds one.
    pub task: Option<String>,
}

/// A parameter of a [`Function`].
#[derive(Debug, Clone, PartialEq)]
pub struct Parameter {
    /// Its pattern, as written (`mut plot`, `[u, v]`).
    pub pattern: String,
    /// The pattern as the expression that passes the parameter's value on
    /// (`mut plot` → `plot`, `[u, v]` → `[u, v]`); `None` where the
    /// pattern binds less than it takes (`_`, `..`, `&x`, `ref x`).
    pub argument: Option<String>,
}

/// The public free functions at the top level of `source`: not methods,
/// not functions of a nested module. None for a file that is not Rust.
pub fn public_functions(source: &str) -> Vec<Function> {
    let Some(source) = Source::parse(source) else {
        return Vec::new();
    };
    source
        .file
        .items
        .iter()
        .filter_map(|item| match item {
            Item::Fn(function) if matches!(function.vis, Visibility::Public(_)) => {
                Some(read(&source, &function.sig, &function.block, None))
            }
            _ => None,
        })
        .collect()
}

/// The function of `signature` and `block`, read from `source`; in an
/// `impl` block of `self_type`, that type is named `Self` in the shape.
fn read(
    source: &Source<'_>,
    signature: &Signature,
    block: &syn::Block,
    self_type: Option<&str>,
) -> Function {
    let compact = |within: Range<usize>| source.compact(within, self_type);
    let generics = &signature.generics;
    let types: Vec<String> = signature
        .inputs
        .iter()
        .filter_map(|input| match input {
            FnArg::Typed(parameter) => Some(compact(range(&parameter.ty))),
            FnArg::Receiver(_) => None,
        })
        .collect();
    let ret = match &signature.output {
        ReturnType::Type(_, ty) => compact(range(ty)),
        ReturnType::Default => String::new(),
    };
    let clause = generics
        .where_clause
        .as_ref()
        .map_or_else(String::new, |clause| compact(range(&clause.predicates)));
    let generics = if generics.params.is_empty() {
        String::new()
    } else {
        compact(range(generics))
    };
    let parameters = signature
        .inputs
        .iter()
        .filter_map(|input| match input {
            FnArg::Typed(parameter) => Some(Parameter {
                pattern: source.text_of(&parameter.pat).to_owned(),
                argument: argument(source, &parameter.pat),
            }),
            FnArg::Receiver(_) => None,
        })
        .collect();
    let mut task = FirstTask(None);
    task.visit_block(block);
    Function {
        name: signature.ident.to_string(),
        parameters,
        shape: format!("{generics}({})->{ret} where {clause}", types.join(",")),
        body: inside(
            block.brace_token.span.open(),
            block.brace_token.span.close(),
        ),
        task: task.0,
    }
}

/// The task named by the first `todo!("<task>: …")` of a body, where the
/// call's first argument is a string that starts with an identifier and
/// a colon.
struct FirstTask(Option<String>);

impl<'ast> Visit<'ast> for FirstTask {
    fn visit_macro(&mut self, call: &'ast syn::Macro) {
        if self.0.is_some() || !call.path.is_ident("todo") {
            return;
        }
        let message = call.parse_body_with(|input: syn::parse::ParseStream<'_>| {
            let message: syn::LitStr = input.parse()?;
            input.parse::<proc_macro2::TokenStream>()?; // the format arguments
            Ok(message.value())
        });
        self.0 = message.ok().and_then(|message| {
            let (task, _) = message.split_once(':')?;
            syn::parse_str::<syn::Ident>(task).ok()?;
            Some(task.to_owned())
        });
    }
}

/// A parameter's pattern as the expression that passes its value on: its
/// text without its `mut`s; `None` where the pattern binds less than it
/// takes.
fn argument(source: &Source<'_>, pattern: &Pat) -> Option<String> {
    fn binds_all(pattern: &Pat) -> bool {
        match pattern {
            Pat::Ident(binding) => binding.by_ref.is_none() && binding.subpat.is_none(),
            Pat::Tuple(tuple) => tuple.elems.iter().all(binds_all),
            Pat::Slice(slice) => slice.elems.iter().all(binds_all),
            Pat::Paren(inner) => binds_all(&inner.pat),
            Pat::TupleStruct(tuple) => tuple.elems.iter().all(binds_all),
            Pat::Struct(record) => {
                record.rest.is_none() && record.fields.iter().all(|field| binds_all(&field.pat))
            }
            // `_`, `..`, `&x`, literals and ranges: not an expression of
            // the value, or not all of it.
            _ => false,
        }
    }
    /// The `mut` keywords of a pattern, by their places.
    struct Muts(Vec<Range<usize>>);
    impl<'ast> Visit<'ast> for Muts {
        fn visit_pat_ident(&mut self, binding: &'ast syn::PatIdent) {
            if let Some(keyword) = &binding.mutability {
                self.0.push(range(keyword));
            }
            visit::visit_pat_ident(self, binding);
        }
    }
    if !binds_all(pattern) {
        return None;
    }
    let mut muts = Muts(Vec::new());
    muts.visit_pat(pattern);
    // The pattern's text with each `mut` and the spaces after it cut out.
    let whole = range(pattern);
    let mut expression = String::new();
    let mut at = whole.start;
    for keyword in muts.0 {
        expression.push_str(&source.text[at..keyword.start]);
        let after = &source.text[keyword.end..whole.end];
        at = keyword.end + (after.len() - after.trim_start().len());
    }
    expression.push_str(&source.text[at..whole.end]);
    Some(expression)
}

/// The kind of a method's receiver (`self`, `mut self`, `&self`, `&'a mut
/// self`, `self: &Self`, `self: Box<Self>`): `self`, `&self` or `&mut self`.
fn receiver_kind(receiver: &syn::Receiver) -> &'static str {
    match &*receiver.ty {
        Type::Reference(reference) if reference.mutability.is_some() => "&mut self",
        Type::Reference(_) => "&self",
        _ => "self",
    }
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
            && self.function.parameters.len() == given.function.parameters.len()
            && (self.function.name == given.function.name
                || self.function.shape == given.function.shape)
    }
}

/// The functions of the `impl` blocks at the top level of `source` (not
/// those of a nested module). None for a file that is not Rust.
pub fn methods(source: &str) -> Vec<Method> {
    let Some(source) = Source::parse(source) else {
        return Vec::new();
    };
    let mut found = Vec::new();
    for item in &source.file.items {
        let Item::Impl(block) = item else {
            continue;
        };
        // `impl<T> Solid for &Placed<T>` implements for `Placed`.
        let mut ty = &*block.self_ty;
        while let Type::Reference(reference) = ty {
            ty = &reference.elem;
        }
        let self_type = match ty {
            Type::Path(path) => path
                .path
                .segments
                .last()
                .map(|segment| segment.ident.to_string())
                .unwrap_or_default(),
            _ => String::new(),
        };
        let trait_name = block
            .trait_
            .as_ref()
            .map(|(_, path, _)| source.compact(range(path), None));
        for inner in &block.items {
            let ImplItem::Fn(function) = inner else {
                continue;
            };
            let receiver = match function.sig.inputs.first() {
                Some(FnArg::Receiver(receiver)) => receiver_kind(receiver),
                _ => "",
            };
            found.push(Method {
                self_type: self_type.clone(),
                trait_name: trait_name.clone(),
                receiver: receiver.to_owned(),
                function: read(&source, &function.sig, &function.block, Some(&self_type)),
            });
        }
    }
    found
}

/// The arguments that pass a function's parameters on: each pattern as an
/// expression ([`Parameter::argument`]); `None` where a pattern binds
/// less than it takes.
pub fn arguments(function: &Function) -> Option<String> {
    let out: Option<Vec<&str>> = function
        .parameters
        .iter()
        .map(|p| p.argument.as_deref())
        .collect();
    Some(out?.join(", "))
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
    for (theirs, ours) in given
        .function
        .parameters
        .iter()
        .zip(&task.function.parameters)
    {
        let (theirs, value) = (&theirs.pattern, ours.argument.as_ref()?);
        if theirs != value {
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
        let patterns: Vec<&str> = found[0]
            .parameters
            .iter()
            .map(|p| p.pattern.as_str())
            .collect();
        assert_eq!(patterns, ["from", "to", "mut plot"]);
        assert_eq!(
            found[1].shape,
            "<T:Copy>([f64;2],&str)->Result<T,E> where T:Default"
        );
        assert_eq!(found[0].task.as_deref(), Some("dda"));
        assert_eq!(found[1].task, None);
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
        let patterns: Vec<&str> = found[0]
            .function
            .parameters
            .iter()
            .map(|p| p.pattern.as_str())
            .collect();
        assert_eq!(patterns, ["incoming", "stored"]);
        assert_eq!(found[1].function.shape, "(Self)->Self where ");
        assert_eq!(found[3].function.shape, "(&Ray)->Option<Span> where ");
        assert_eq!(found[0].function.task.as_deref(), Some("zbuffer"));
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

    #[test]
    fn functions_returning_arrays_are_found() {
        // The `;` of an array type in a return type is no end of a
        // declaration.
        let source = "\
pub fn table() -> [f32; 4] { [0.0; 4] }
pub fn edges(triangles: &[[u32; 3]]) -> Vec<[u32; 2]> { todo!(\"render: edges\") }
";
        let found = public_functions(source);
        let names: Vec<&str> = found.iter().map(|f| f.name.as_str()).collect();
        assert_eq!(names, ["table", "edges"]);
        assert_eq!(found[1].shape, "(&[[u32;3]])->Vec<[u32;2]> where ");
        assert_eq!(&source[found[1].body.clone()], " todo!(\"render: edges\") ");
    }

    #[test]
    fn shapes_keep_mut_and_name_the_implementing_type_self() {
        // `mut` is a keyword, not a path segment of `mut glam`; a type
        // after a lifetime (`&'static Recorder`) is still that type.
        let found = public_functions("pub fn a(v: &mut glam::Vec2) {}\npub fn b(v: &Vec2) {}\n");
        assert_eq!(found[0].shape, "(&mutVec2)-> where ");
        assert_ne!(found[0].shape, found[1].shape);
        let found =
            methods("impl Recorder {\n    pub fn get() -> Option<&'static Recorder> { None }\n}\n");
        assert_eq!(found[0].function.shape, "()->Option<&'staticSelf> where ");
    }

    #[test]
    fn functions_and_todos_in_strings_and_comments_are_not_code() {
        let source = "\
const FAKE: &[u8] = br#\"pub fn fake() {\"#;
/* /* pub fn hidden() {} */ */
const QUOTED: &str = \"pub fn quoted() {}\";
pub fn real() {
    let _ = \"todo!(\\\"fake: x\\\")\";
    // todo!(\"comment: y\")
    todo!(\"real: z\")
}
";
        let found = public_functions(source);
        let names: Vec<&str> = found.iter().map(|f| f.name.as_str()).collect();
        assert_eq!(names, ["real"]);
        assert_eq!(found[0].task.as_deref(), Some("real"));
    }
}
