//! Escaping, once for every page and file the tools write: text for XML
//! and HTML (JUnit, the grade report, the class's report, the figures'
//! index, the similarity page) and relative paths as URLs. Student text —
//! file names, panic messages, member names — reaches tutors' browsers
//! through these functions only.

use std::fmt::Write as _;
use std::path::Path;

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

/// Text for HTML element content and attribute values: XML's escapes
/// are HTML's too.
#[must_use]
pub fn html(text: &str) -> String {
    xml_text(text)
}

/// A relative path as a URL: `./` first (a name such as `javascript:`
/// stays a path), the characters that would end or split it
/// percent-encoded (control characters, space, `"`, `#`, `%`, `?`, `<`,
/// `>`, `\`).
#[must_use]
pub fn url(relative: &str) -> String {
    let mut encoded = String::from("./");
    for c in relative.chars() {
        if c.is_control() || matches!(c, ' ' | '"' | '#' | '%' | '?' | '<' | '>' | '\\') {
            let mut buffer = [0; 4];
            for byte in c.encode_utf8(&mut buffer).bytes() {
                let _ = write!(encoded, "%{byte:02X}");
            }
        } else {
            encoded.push(c);
        }
    }
    encoded
}

/// A relative file path as a URL ([`url`]), its components joined by `/`
/// on every system.
#[must_use]
pub fn path_url(path: &Path) -> String {
    let joined = path
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect::<Vec<_>>()
        .join("/");
    url(&joined)
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

    #[test]
    fn urls_start_relative_and_encode_what_would_break_them() {
        assert_eq!(
            path_url(Path::new("images/01-lines/dda/a b#1.png")),
            "./images/01-lines/dda/a%20b%231.png"
        );
        assert_eq!(url("a b#1/report.html"), "./a%20b%231/report.html");
        assert_eq!(url("javascript:x\\y\n"), "./javascript:x%5Cy%0A");
    }
}
