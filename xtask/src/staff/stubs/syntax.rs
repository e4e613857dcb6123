//! Rust source as the staff's stub tools read it: a syntax tree (syn) for
//! its structure, and its tokens with their places in the text for what a
//! tree leaves out (which names a stretch of code mentions, whatever macro
//! call holds them).
//!
//! Both come from proc-macro2's lexer, that is by Rust's own lexical
//! rules: a comment is no token and a literal is one token whatever it
//! holds, so a `fn` in a comment, a `{` in a raw byte string or a `todo!(`
//! in a string is no code here, as it is none to the compiler. With its
//! `span-locations` feature, outside a procedural macro, the lexer records
//! where each token lies in the text it read; [`range`] turns a node's
//! span, from its first token to its last, into bytes of that text. The
//! tools edit the text by these ranges (a body replaced, a line inserted
//! before a statement), so every byte outside an edit, formatting and
//! comments included, stays as it was.
//!
//! ```text
//!     pub fn dda(from: Vec2) -> u32 {      range(block): the braces and all
//!         todo!("dda: …")                  between them; the text is UTF-8,
//!     }                                    the ranges are byte offsets
//! ```

use std::ops::Range;

use proc_macro2::{Delimiter, Span, TokenStream, TokenTree};
use syn::spanned::Spanned;

/// The bytes of the text that `node` spans, from its first token's start
/// to its last token's end (empty at 0 for a node without tokens, such as
/// absent generics).
pub(super) fn range(node: &impl Spanned) -> Range<usize> {
    node.span().byte_range()
}

/// The bytes between a pair of delimiters (`{` and `}` of a body), the
/// delimiters left out.
pub(super) fn inside(open: Span, close: Span) -> Range<usize> {
    open.byte_range().end..close.byte_range().start
}

/// A Rust source file, read.
pub(super) struct Source<'a> {
    /// The text.
    pub text: &'a str,
    /// Its syntax tree.
    pub file: syn::File,
    /// Its tokens in the order of the text, without doc comments; a group
    /// is its two delimiters with its tokens between them.
    tokens: Vec<Token>,
    /// The byte offset at which each line starts.
    line_starts: Vec<usize>,
}

/// A token's kind and where it lies.
struct Token {
    kind: Kind,
    range: Range<usize>,
}

#[derive(Clone, Copy, PartialEq)]
enum Kind {
    Ident,
    Punct,
    Literal,
    Open,
    Close,
}

impl<'a> Source<'a> {
    /// `text` read as a Rust file; `None` where it is not one (not Rust
    /// tokens, or tokens that are no sequence of items).
    ///
    /// The text is parsed as it is (not by `syn::parse_file`, which drops a
    /// leading byte order mark or `#!` line and would shift every offset).
    pub fn parse(text: &'a str) -> Option<Self> {
        let stream: TokenStream = text.parse().ok()?;
        let file = syn::parse2(stream.clone()).ok()?;
        let mut tokens = Vec::new();
        flatten(text, stream, &mut tokens);
        let line_starts = std::iter::once(0)
            .chain(text.match_indices('\n').map(|(at, _)| at + 1))
            .collect();
        Some(Source {
            text,
            file,
            tokens,
            line_starts,
        })
    }

    /// The text of `node` ([`range`]).
    pub fn text_of(&self, node: &impl Spanned) -> &'a str {
        &self.text[range(node)]
    }

    /// The byte offset at which line `line` (0-based) starts; the end of
    /// the text past the last line.
    pub fn line_start(&self, line: usize) -> usize {
        self.line_starts
            .get(line)
            .copied()
            .unwrap_or(self.text.len())
    }

    /// The line (0-based) that holds byte `at`.
    pub fn line_of(&self, at: usize) -> usize {
        self.line_starts.partition_point(|&start| start <= at) - 1
    }

    /// The whitespace that opens line `line` (0-based).
    pub fn indent(&self, line: usize) -> &'a str {
        let text = &self.text[self.line_start(line)..];
        &text[..text.len() - text.trim_start().len()]
    }

    /// Every identifier of the text with the offset it starts at, keywords
    /// included, in the order of the text: those in macro calls too, none
    /// in a comment or a literal.
    pub fn words(&self) -> impl Iterator<Item = (&'a str, usize)> + '_ {
        self.tokens
            .iter()
            .filter(|token| token.kind == Kind::Ident)
            .map(|token| (&self.text[token.range.clone()], token.range.start))
    }

    /// Whether identifier `name` occurs in `within`.
    pub fn mentions(&self, name: &str, within: Range<usize>) -> bool {
        self.words()
            .any(|(word, at)| word == name && within.contains(&at))
    }

    /// The tokens of `within` written without spaces and without path
    /// prefixes (`glam::Vec2` is `Vec2`), with the name `self_type` written
    /// `Self`: what two signatures share when one type is written two
    /// ways.
    pub fn compact(&self, within: Range<usize>, self_type: Option<&str>) -> String {
        let tokens: Vec<&Token> = self
            .tokens
            .iter()
            .filter(|token| within.contains(&token.range.start))
            .collect();
        let text = |i: usize| tokens.get(i).map(|token| &self.text[token.range.clone()]);
        let is_ident = |i: usize| tokens.get(i).is_some_and(|token| token.kind == Kind::Ident);
        let mut out = String::new();
        let mut i = 0;
        while i < tokens.len() {
            // `a :: B`: a path segment, left out with its `::`.
            let segment = is_ident(i)
                && text(i + 1) == Some(":")
                && text(i + 2) == Some(":")
                && is_ident(i + 3);
            if segment {
                i += 3;
                continue;
            }
            match text(i) {
                Some(word) if is_ident(i) && Some(word) == self_type => out.push_str("Self"),
                Some(word) => out.push_str(word),
                None => {}
            }
            i += 1;
        }
        out
    }
}

/// Appends the tokens of `stream` to `tokens`, groups opened; the tokens
/// of a doc comment (which the lexer hands out as a `#[doc = "…"]`
/// attribute, every token spanning the comment) are left out: a comment
/// is no code.
fn flatten(text: &str, stream: TokenStream, tokens: &mut Vec<Token>) {
    for tree in stream {
        let range = tree.span().byte_range();
        if text[range.clone()].starts_with("//") || text[range.clone()].starts_with("/*") {
            continue;
        }
        let kind = match tree {
            TokenTree::Group(group) => {
                let delimited = group.delimiter() != Delimiter::None;
                if delimited {
                    tokens.push(Token {
                        kind: Kind::Open,
                        range: group.span_open().byte_range(),
                    });
                }
                flatten(text, group.stream(), tokens);
                if delimited {
                    tokens.push(Token {
                        kind: Kind::Close,
                        range: group.span_close().byte_range(),
                    });
                }
                continue;
            }
            TokenTree::Ident(_) => Kind::Ident,
            TokenTree::Punct(_) => Kind::Punct,
            TokenTree::Literal(_) => Kind::Literal,
        };
        tokens.push(Token { kind, range });
    }
}

/// The three methods of a `syn::visit::Visit` that hand every function
/// with a body (a free function, one in an `impl`, a trait's default) to
/// the visitor's own `function(&mut self, &Signature, &Block)`, outside in,
/// and walk on into the body.
macro_rules! visit_function_bodies {
    () => {
        fn visit_item_fn(&mut self, function: &'ast syn::ItemFn) {
            self.function(&function.sig, &function.block);
            syn::visit::visit_item_fn(self, function);
        }

        fn visit_impl_item_fn(&mut self, function: &'ast syn::ImplItemFn) {
            self.function(&function.sig, &function.block);
            syn::visit::visit_impl_item_fn(self, function);
        }

        fn visit_trait_item_fn(&mut self, function: &'ast syn::TraitItemFn) {
            if let Some(body) = &function.default {
                self.function(&function.sig, body);
            }
            syn::visit::visit_trait_item_fn(self, function);
        }
    };
}
pub(super) use visit_function_bodies;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_are_bytes_of_the_text_after_wide_characters() {
        // `é` and `→` take two and three bytes: a range counted in
        // characters would cut the body short.
        let text = "/// é → ü\npub fn f(x: u8) -> u8 { x /* → */ }\n";
        let source = Source::parse(text).expect("Rust");
        let syn::Item::Fn(function) = &source.file.items[0] else {
            panic!("a function");
        };
        assert_eq!(source.text_of(&function.block), "{ x /* → */ }");
        assert_eq!(source.text_of(&function.sig), "fn f(x: u8) -> u8");
        assert_eq!(source.line_of(range(&function.block).start), 1);
    }

    #[test]
    fn words_in_comments_and_literals_are_none_of_the_code() {
        // A raw byte string, a nested block comment and a string with a
        // macro call in it: a scanner that knows none of them finds `fake`,
        // `hidden` and `todo` here.
        let text = concat!(
            "const A: &[u8] = br#\"fn fake() {\"#;\n",
            "/* /* fn hidden() { */ */\n",
            "/// fn documented() {}\n",
            "const B: &str = \"todo!(\\\"x: y\\\")\";\n",
            "fn real() { println!(\"{}\", B) }\n",
        );
        let source = Source::parse(text).expect("Rust");
        let words: Vec<&str> = source.words().map(|(word, _)| word).collect();
        assert_eq!(
            words,
            [
                "const", "A", "u8", "const", "B", "str", "fn", "real", "println", "B"
            ]
        );
        assert!(!source.mentions("fake", 0..text.len()));
    }

    #[test]
    fn compact_tokens_drop_spaces_and_path_prefixes() {
        let text =
            "fn f(a: glam :: Vec2, b: Vec<std::vec::Vec<Thing>>) -> impl FnMut(canvas::Pixel) {}";
        let source = Source::parse(text).expect("Rust");
        assert_eq!(
            source.compact(0..text.len(), Some("Thing")),
            "fnf(a:Vec2,b:Vec<Vec<Self>>)->implFnMut(Pixel){}"
        );
        assert!(Source::parse("fn f() { \"unclosed }").is_none());
        assert!(Source::parse("todo!(\"not an item\")").is_none());
    }
}
