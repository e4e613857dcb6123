//! The course's Rust source with comments and the contents of string and
//! character literals blanked out ([`mask`]), and the few lexical helpers
//! built on it: what the grader's checks of a task file (`todo!` stubs,
//! forbidden constructs, snapshot names) read Rust by. (The staff's stub
//! tools, in the course repository only, read it as syntax trees.)

use proc_macro2::{TokenStream, TokenTree};

/// `source` with every comment and the contents of every string and
/// character literal replaced by spaces (line breaks kept), so that byte
/// offsets and line numbers stay those of `source`; a literal keeps its
/// prefix and quotes (`b"  "`, `r#"  "#`, `' '`). Read by Rust's own
/// lexical rules (proc-macro2's lexer: nested block comments, raw and byte
/// strings, raw identifiers, lifetimes), not by a hand-written scanner.
///
/// # Errors
/// Text that is not a sequence of Rust tokens (an unclosed string, comment
/// or delimiter): no mask can be trusted then, and the caller decides.
pub fn try_mask(source: &str) -> Result<String, String> {
    let tokens: TokenStream = source.parse().map_err(|error: proc_macro2::LexError| {
        let at = error.span().start();
        format!(
            "not Rust tokens at line {}, column {}",
            at.line,
            at.column + 1
        )
    })?;
    let mut out: Vec<u8> = source
        .bytes()
        .map(|b| if b == b'\n' { b'\n' } else { b' ' })
        .collect();
    keep(source, tokens, &mut out);
    Ok(String::from_utf8(out).expect("whole tokens and single spaces were copied"))
}

/// [`try_mask`], or, for text that is not Rust tokens, every character but
/// the line breaks blanked: such a file holds no code a caller could find.
#[must_use]
pub fn mask(source: &str) -> String {
    try_mask(source).unwrap_or_else(|_| {
        source
            .bytes()
            .map(|b| if b == b'\n' { '\n' } else { ' ' })
            .collect()
    })
}

/// Copies the text of `tokens` from `source` into `out`: whole tokens,
/// literals with their contents blanked; a doc comment (which the lexer
/// hands out as a `#[doc = "…"]` attribute spanning the comment) stays
/// blank. Groups are walked with a stack of their own, not by recursion:
/// a task file of a hundred thousand nested parentheses is a student's to
/// write, and must not overflow the grader's stack.
fn keep(source: &str, tokens: TokenStream, out: &mut [u8]) {
    let copy = |out: &mut [u8], range: std::ops::Range<usize>| {
        out[range.clone()].copy_from_slice(&source.as_bytes()[range]);
    };
    let mut pending = vec![tokens.into_iter()];
    while let Some(tokens) = pending.last_mut() {
        let Some(token) = tokens.next() else {
            pending.pop();
            continue;
        };
        let range = token.span().byte_range();
        let text = &source[range.clone()];
        if text.starts_with("//") || text.starts_with("/*") {
            continue; // a doc comment
        }
        match token {
            TokenTree::Group(group) => {
                copy(out, group.span_open().byte_range());
                copy(out, group.span_close().byte_range());
                pending.push(group.stream().into_iter());
            }
            TokenTree::Literal(_) => {
                copy(out, range.clone());
                // The contents: after the first quote up to the last one
                // (a raw string's hashes lie outside both).
                if let (Some(open), Some(close)) = (text.find(['"', '\'']), text.rfind(['"', '\'']))
                    && open < close
                {
                    for b in &mut out[range.start + open + 1..range.start + close] {
                        if *b != b'\n' {
                            *b = b' ';
                        }
                    }
                }
            }
            TokenTree::Ident(_) | TokenTree::Punct(_) => copy(out, range),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn masking_blanks_comments_strings_and_chars_but_not_lifetimes() {
        let source = "a // b\n\"c\\\"d\" r#\"e\"# 'f' '\\n' &'g x /* h /* i */ j */ k";
        assert_eq!(
            mask(source),
            "a     \n\"    \" r#\" \"# ' ' '  ' &'g x                   k"
        );
    }

    #[test]
    fn a_file_of_deeply_nested_delimiters_is_masked_without_recursion() {
        // A student's task file of 200 000 nested parentheses: the walk
        // over its groups must not overflow the grader's stack.
        let depth = 200_000;
        let source = format!("fn f() {{ {}x{} }}", "(".repeat(depth), ")".repeat(depth));
        let masked = try_mask(&source).expect("balanced delimiters are tokens");
        assert_eq!(masked, source);
    }

    #[test]
    fn byte_and_c_strings_raw_or_not_doc_comments_and_raw_identifiers() {
        // A raw byte string ends at its first quote: the backslash in it
        // escapes nothing, so `include!` after it is code.
        let source = "br\"\\\"; include!(\"x\"); cr#\"y\"# b'z' c\"w\"\n/// doc include!\nr#type";
        assert_eq!(
            mask(source),
            "br\" \"; include!(\" \"); cr#\" \"# b' ' c\" \"\n                \nr#type"
        );
        assert!(try_mask("\"unclosed").is_err());
        assert!(try_mask("fn f() { /* unclosed }").is_err());
    }
}
