//! `#[testkit::test]`: a `#[test]` that tells the grader, over a channel
//! the code under test cannot write, that it ran to its end.
//!
//! A graded test runs the student's code in its own process, so whatever
//! the process prints or its exit status could come from the student's
//! code: a function can print libtest's `test result: ok. 1 passed` and
//! call `std::process::exit(0)`. The grader therefore gives each test run
//! a fresh random token in a file named by [`VERDICT_FILE_VAR`], in the
//! test's own scratch folder. The first thing the wrapped test does, before
//! any student code has run in its process, is read that file and delete
//! it; the last thing, after every assertion has held, is print
//! [`VERDICT_PREFIX`] and the token. A student's code never sees the token:
//!
//! - there is no code before `main` in safe Rust, and `unsafe` is
//!   forbidden in the course's crates (the workspace lint), so the test
//!   body reads the file before the student's code is first called;
//! - the token lives only in the wrapped test's local variable, which safe
//!   code cannot reach, and the grader's sandbox mounts no `/proc` (no
//!   `/proc/self/mem`, no `/proc/self/environ`) and shows each test only
//!   its own scratch folder.
//!
//! Safe code *can* reach it through a soundness hole of the compiler
//! (rust-lang/rust#25860, the `cve-rs` crate), so for a topic decided by
//! replay the grader gives the token only to a second process, which
//! replays a record of the student's code and never ran it (see the
//! `transcript` crate); this macro is the same in both.
//!
//! A test whose process exits early (a forged summary and `exit(0)`), whose
//! assertions fail, or that is not wrapped prints no token and fails. Run
//! outside the grader (`cargo test`), the variable is unset and the test
//! is an ordinary `#[test]`.
//!
//! The wrapped function must take no arguments and return `()`; it may
//! carry other attributes (`#[ignore]`, doc comments). `#[should_panic]`
//! is refused: its pass is a panic, after which no token can be printed
//! safely; assert with `std::panic::catch_unwind` instead. Property tests
//! put `#[testkit::test]` where `proptest!` expects `#[test]`.

use proc_macro::{Delimiter, Group, Span, TokenStream, TokenTree};

use wire::{VERDICT_FILE_VAR, VERDICT_PREFIX};

/// Marks a test whose pass the grader can authenticate (see the crate
/// documentation).
#[proc_macro_attribute]
pub fn test(attr: TokenStream, item: TokenStream) -> TokenStream {
    match wrap(attr, item) {
        Ok(tokens) => tokens,
        Err((message, span)) => compile_error(&message, span),
    }
}

type Error = (String, Span);

fn wrap(attr: TokenStream, item: TokenStream) -> Result<TokenStream, Error> {
    if let Some(first) = attr.into_iter().next() {
        return Err(("`#[testkit::test]` takes no arguments".into(), first.span()));
    }
    let mut tokens: Vec<TokenTree> = item.into_iter().collect();
    let body = match tokens.pop() {
        Some(TokenTree::Group(body)) if body.delimiter() == Delimiter::Brace => body,
        other => {
            let span = other.map_or_else(Span::call_site, |t| t.span());
            return Err(("`#[testkit::test]` goes on a function".into(), span));
        }
    };
    let name = check_signature(&tokens)?;
    // The body keeps its own spans, so panics and snapshots name the
    // test's real lines; it becomes a nested function of the test's own
    // name (insta names snapshots after the function they are taken in),
    // so that an early `return` still reaches the verdict only through a
    // normal end.
    let prologue: TokenStream = format!(
        "let __testkit_token = ::std::env::var_os({VERDICT_FILE_VAR:?}).and_then(|file| {{
             let token = ::std::fs::read_to_string(&file).ok();
             let _ = ::std::fs::remove_file(&file);
             token
         }});
         fn {name}()"
    )
    .parse()
    .expect("the prologue is valid Rust");
    let epilogue: TokenStream = format!(
        "{name}();
         if let ::std::option::Option::Some(token) = __testkit_token {{
             use ::std::io::Write as _;
             let mut out = ::std::io::stdout().lock();
             let _ = ::std::writeln!(out, \"\\n{VERDICT_PREFIX}{{}}\", token.trim());
             let _ = out.flush();
         }}"
    )
    .parse()
    .expect("the epilogue is valid Rust");
    let mut inner = prologue;
    inner.extend([TokenTree::Group(body)]);
    inner.extend(epilogue);
    let mut out: TokenStream = "#[test]".parse().expect("`#[test]` is valid Rust");
    out.extend(tokens);
    out.extend([TokenTree::Group(Group::new(Delimiter::Brace, inner))]);
    Ok(out)
}

/// The name of `fn name()`: no arguments, no return type, no generics; no
/// `#[should_panic]` or second `#[test]` among the attributes.
fn check_signature(tokens: &[TokenTree]) -> Result<String, Error> {
    let fn_at = tokens
        .iter()
        .position(|t| matches!(t, TokenTree::Ident(i) if i.to_string() == "fn"))
        .ok_or_else(|| {
            (
                "`#[testkit::test]` goes on a function".to_owned(),
                Span::call_site(),
            )
        })?;
    for token in &tokens[..fn_at] {
        if let TokenTree::Group(group) = token
            && let Some(TokenTree::Ident(name)) = group.stream().into_iter().next()
        {
            let name = name.to_string();
            if name == "should_panic" || name == "test" {
                return Err((
                    format!(
                        "`#[testkit::test]` cannot be combined with `#[{name}]`{}",
                        if name == "should_panic" {
                            ": assert the panic with `std::panic::catch_unwind`"
                        } else {
                            ""
                        }
                    ),
                    group.span(),
                ));
            }
        }
    }
    let rest = &tokens[fn_at + 1..];
    if let [TokenTree::Ident(name), TokenTree::Group(args)] = rest
        && args.delimiter() == Delimiter::Parenthesis
        && args.stream().is_empty()
    {
        Ok(name.to_string())
    } else {
        let span = rest.first().map_or_else(Span::call_site, TokenTree::span);
        Err((
            "a `#[testkit::test]` function takes no arguments and returns nothing".into(),
            span,
        ))
    }
}

fn compile_error(message: &str, span: Span) -> TokenStream {
    let mut tokens: TokenStream = format!("::core::compile_error!({message:?});")
        .parse()
        .expect("compile_error! is valid Rust");
    // Point the error at the offending tokens.
    tokens = tokens
        .into_iter()
        .map(|mut token| {
            token.set_span(span);
            token
        })
        .collect();
    tokens
}
