//! Escaping text for XML and HTML, which every markup format of the
//! grader writes.

/// Escapes text for an XML 1.0 attribute value: markup, quotes and line
/// breaks (which attribute normalisation would otherwise turn into spaces).
#[must_use]
pub fn xml_attr(text: &str) -> String {
    escape(text, true)
}

/// Escapes text for XML 1.0 element content; line breaks stay.
#[must_use]
pub fn xml_text(text: &str) -> String {
    escape(text, false)
}

/// Characters XML 1.0 cannot hold at all (control characters such as the
/// ESC of ANSI colours) become `?`.
fn escape(text: &str, attribute: bool) -> String {
    let mut escaped = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => escaped.push_str("&amp;"),
            '<' => escaped.push_str("&lt;"),
            '>' => escaped.push_str("&gt;"),
            '"' => escaped.push_str("&quot;"),
            '\'' => escaped.push_str("&apos;"),
            '\n' if attribute => escaped.push_str("&#10;"),
            '\r' if attribute => escaped.push_str("&#13;"),
            '\t' if attribute => escaped.push_str("&#9;"),
            '\n' | '\r' | '\t' => escaped.push(c),
            c if (c as u32) < 0x20 || matches!(c, '\u{fffe}' | '\u{ffff}') => escaped.push('?'),
            c => escaped.push(c),
        }
    }
    escaped
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn xml_escape_handles_markup_quotes_and_control_characters() {
        assert_eq!(
            xml_attr("a<b & \"c\" 'd'>\n\x1b[31m"),
            "a&lt;b &amp; &quot;c&quot; &apos;d&apos;&gt;&#10;?[31m"
        );
        assert_eq!(xml_text("x < y\n\tz\u{0}"), "x &lt; y\n\tz?");
    }
}
