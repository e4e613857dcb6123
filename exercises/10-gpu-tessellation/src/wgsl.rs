//! Your WGSL: the files `src/control.wgsl` (task 1), `src/evaluation.wgsl`
//! (task 3), `src/shading.wgsl` (task 4), `src/trimming.wgsl` (task 5) and
//! `src/pn.wgsl` (task 6),
//! compiled into the crate. They are WGSL files, so that an editor
//! highlights and checks them as WGSL; each begins with what it must
//! define.
//!
//! A pass builds its shader from your piece and the given WGSL of
//! [`crate::shaders`] with [`compose`]: your piece comes first, so that
//! its lines are the shader's lines (WGSL declarations may come in any
//! order), and the whole is checked with naga before wgpu sees it. An
//! error is reported at its file and line, yours or the given one's:
//!
//! ```text
//! src/trimming.wgsl:12:5: error: expected ';', found 'return'
//!    |
//! 12 |     return t
//!    |     ^^^^^^ expected ';'
//! ```

use naga::valid::{Capabilities, ValidationFlags, Validator};
use naga::{Span, WithSpan};

use crate::TessError;

/// One task's WGSL file.
#[derive(Clone, Copy, Debug)]
pub struct Piece {
    /// The task it belongs to (its id on the task sheet).
    pub task: &'static str,
    /// Its path in the crate.
    pub file: &'static str,
    /// What it holds.
    pub text: &'static str,
    /// The functions it must define, as the given WGSL calls them.
    pub functions: &'static [&'static str],
}

/// Task 1: the control stage's levels.
pub const CONTROL: Piece = Piece {
    task: "control",
    file: "src/control.wgsl",
    text: include_str!("control.wgsl"),
    functions: &["fn tessellation_levels(patch_index: u32) -> TessLevels"],
};

/// Task 3: the evaluation stage's de Casteljau.
pub const EVALUATION: Piece = Piece {
    task: "evaluation",
    file: "src/evaluation.wgsl",
    text: include_str!("evaluation.wgsl"),
    functions: &[
        "fn evaluate_patch(patch_index: u32, uv: vec2<f32>) -> SurfacePoint",
        "fn evaluate_triangle(patch_index: u32, uvw: vec3<f32>) -> SurfacePoint",
    ],
};

/// Task 4: Phong shading.
pub const SHADING: Piece = Piece {
    task: "render",
    file: "src/shading.wgsl",
    text: include_str!("shading.wgsl"),
    functions: &["fn shade(position: vec3<f32>, normal: vec3<f32>, uv: vec2<f32>) -> vec3<f32>"],
};

/// Task 5: the trim predicates and Newton trimming.
pub const TRIMMING: Piece = Piece {
    task: "trimming",
    file: "src/trimming.wgsl",
    text: include_str!("trimming.wgsl"),
    functions: &[
        "fn trimmed_by_rectangle(uv: vec2<f32>, u_range: vec2<f32>, v_range: vec2<f32>) -> bool",
        "fn trimmed_by_circle(uv: vec2<f32>, centre: vec2<f32>, radius: f32) -> bool",
        "fn trimmed_by_ellipse(uv: vec2<f32>, centre: vec2<f32>, radii: vec2<f32>) -> bool",
        "fn trim_curve_derivative(c: TrimCurve, t: f32) -> vec2<f32>",
        "fn newton_root(c: TrimCurve, v: f32, t0: f32) -> f32",
        "fn inside_bezier_region(uv: vec2<f32>, upper: TrimCurve, lower: TrimCurve) -> bool",
    ],
};

/// Task 6: the PN triangle built from a flat one in the control stage.
pub const PN: Piece = Piece {
    task: "pn_control",
    file: "src/pn.wgsl",
    text: include_str!("pn.wgsl"),
    functions: &["fn pn_triangle(t: FlatTriangle) -> TrianglePatch"],
};

impl Piece {
    /// This task's WGSL, with `text` in place of the file's (for trying
    /// out a variant: the tests' planted mistakes).
    #[must_use]
    pub const fn with_text(self, text: &'static str) -> Self {
        Self { text, ..self }
    }

    /// Whether the file holds code yet: anything but comments.
    #[must_use]
    pub fn started(&self) -> bool {
        !without_comments(self.text).trim().is_empty()
    }

    /// This piece, once written.
    ///
    /// # Panics
    /// With "not yet implemented" and the file's `// TODO` line, as
    /// `todo!()` does, when the file holds nothing but comments: the task is
    /// not started.
    #[must_use]
    pub fn written(self) -> Self {
        if !self.started() {
            let instruction = self
                .text
                .lines()
                .find_map(|line| line.trim().strip_prefix("// TODO "))
                .map_or_else(|| format!("write {}", self.file), str::to_owned);
            panic!("not yet implemented: {instruction}");
        }
        self
    }

    /// The functions of [`Piece::functions`] the file does not define.
    fn missing(&self) -> Vec<&'static str> {
        let code = without_comments(self.text);
        self.functions
            .iter()
            .copied()
            .filter(|signature| {
                let name = signature
                    .strip_prefix("fn ")
                    .and_then(|s| s.split('(').next())
                    .unwrap_or(signature);
                !defines(&code, name)
            })
            .collect()
    }
}

/// A part of a shader: a task's piece or given WGSL.
#[derive(Clone, Copy, Debug)]
pub enum Part<'a> {
    /// Your file.
    Yours(Piece),
    /// Given WGSL, named as errors call it (e.g. `crate::shaders::RENDER`).
    Given(&'a str, &'a str),
}

impl Part<'_> {
    fn name(&self) -> &str {
        match self {
            Part::Yours(piece) => piece.file,
            Part::Given(name, _) => name,
        }
    }

    fn text(&self) -> &str {
        match self {
            Part::Yours(piece) => piece.text,
            Part::Given(_, text) => text,
        }
    }
}

/// The shader made of `parts` (your pieces first), checked with naga: its
/// WGSL, or the errors at their files and lines
/// ([`TessError::Wgsl`]).
///
/// # Panics
/// When one of your pieces is not started (see [`Piece::written`]).
pub fn compose(parts: &[Part<'_>]) -> Result<String, TessError> {
    for part in parts {
        if let Part::Yours(piece) = part {
            let _ = piece.written();
        }
    }
    let mut source = String::new();
    let mut starts = Vec::with_capacity(parts.len());
    for part in parts {
        starts.push(source.len());
        source.push_str(part.text());
        if !source.ends_with('\n') {
            source.push('\n');
        }
    }
    let at = Located {
        parts,
        starts: &starts,
        source: &source,
    };
    let module = match naga::front::wgsl::parse_str(&source) {
        Ok(module) => module,
        Err(error) => {
            let labels: Vec<(Span, String)> = error
                .labels()
                .map(|(span, label)| (span, label.to_owned()))
                .collect();
            let mut notes: Vec<String> = error.notes().map(str::to_owned).collect();
            notes.extend(at.missing_functions(&labels));
            return Err(TessError::Wgsl(at.render(error.message(), &labels, &notes)));
        }
    };
    let mut validator = Validator::new(ValidationFlags::all(), Capabilities::default());
    if let Err(error) = validator.validate(&module) {
        return Err(TessError::Wgsl(at.render_validation(&error)));
    }
    Ok(source)
}

/// The parts of a shader and where each begins in its source.
struct Located<'a> {
    parts: &'a [Part<'a>],
    starts: &'a [usize],
    source: &'a str,
}

impl Located<'_> {
    /// The part a byte offset of the source lies in, and the offset in it.
    fn part_at(&self, offset: usize) -> (&Part<'_>, usize) {
        let index = self
            .starts
            .iter()
            .rposition(|&start| start <= offset)
            .unwrap_or(0);
        (&self.parts[index], offset - self.starts[index])
    }

    /// `message` with each labelled place shown in its part:
    /// `file:line:column: error: message`, the line and a caret.
    fn render(&self, message: &str, labels: &[(Span, String)], notes: &[String]) -> String {
        let mut out = String::new();
        let places: Vec<(&Part<'_>, usize, usize, &str)> = labels
            .iter()
            .filter_map(|(span, label)| {
                let range = span.to_range()?;
                let (part, offset) = self.part_at(range.start.min(self.source.len()));
                Some((part, offset, range.len(), label.as_str()))
            })
            .collect();
        match places.first() {
            Some((part, offset, _, _)) => {
                let (line, column) = line_and_column(part.text(), *offset);
                out.push_str(&format!(
                    "{}:{line}:{column}: error: {message}\n",
                    part.name()
                ));
            }
            None => out.push_str(&format!("error: {message}\n")),
        }
        for (part, offset, length, label) in places {
            let text = part.text();
            let (line, column) = line_and_column(text, offset);
            let source_line = text.lines().nth(line - 1).unwrap_or("");
            let number = line.to_string();
            let gutter = " ".repeat(number.len());
            let width = length.clamp(1, source_line.len().saturating_sub(column - 1).max(1));
            let caret = format!("{}{} {label}", " ".repeat(column - 1), "^".repeat(width));
            out.push_str(&format!(
                "{gutter} --> {}:{line}:{column}\n{gutter} |\n{number} | {source_line}\n{gutter} | {}\n",
                part.name(),
                caret.trim_end()
            ));
        }
        for note in notes {
            out.push_str(&format!("note: {note}\n"));
        }
        out.trim_end().to_owned()
    }

    /// A validation error, with the errors it comes from as notes.
    fn render_validation(&self, error: &WithSpan<naga::valid::ValidationError>) -> String {
        // Its labels name naga's own handles (`naga::ir::Expression [1]`):
        // the place alone says more.
        let labels: Vec<(Span, String)> = error
            .spans()
            .map(|(span, label)| {
                let label = if label.starts_with("naga::") {
                    ""
                } else {
                    label
                };
                (*span, label.to_owned())
            })
            .collect();
        let mut notes = Vec::new();
        let mut cause = std::error::Error::source(error);
        while let Some(inner) = cause {
            notes.push(inner.to_string());
            cause = inner.source();
        }
        notes.extend(self.missing_functions(&labels));
        self.render(&error.to_string(), &labels, &notes)
    }

    /// Where an error lies in given WGSL: the functions your pieces should
    /// define and do not, which is the likely cause.
    fn missing_functions(&self, labels: &[(Span, String)]) -> Vec<String> {
        let in_given = labels.iter().any(|(span, _)| {
            span.to_range()
                .is_some_and(|range| matches!(self.part_at(range.start).0, Part::Given(..)))
        });
        if !in_given {
            return Vec::new();
        }
        self.parts
            .iter()
            .filter_map(|part| match part {
                Part::Yours(piece) => Some(piece),
                Part::Given(..) => None,
            })
            .flat_map(|piece| {
                piece.missing().into_iter().map(move |signature| {
                    format!(
                        "{} does not define `{signature}`, which the given WGSL calls",
                        piece.file
                    )
                })
            })
            .collect()
    }
}

/// The 1-based line and column of a byte offset.
fn line_and_column(text: &str, offset: usize) -> (usize, usize) {
    let offset = offset.min(text.len());
    let before = &text[..offset];
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |n| n + 1);
    (line, before[line_start..].chars().count() + 1)
}

/// `code` without its `//` and `/* */` comments.
fn without_comments(code: &str) -> String {
    let mut out = String::with_capacity(code.len());
    let mut rest = code;
    while !rest.is_empty() {
        if let Some(after) = rest.strip_prefix("//") {
            rest = after.find('\n').map_or("", |n| &after[n..]);
        } else if let Some(after) = rest.strip_prefix("/*") {
            rest = after.find("*/").map_or("", |n| &after[n + 2..]);
            out.push(' ');
        } else {
            let c = rest.chars().next().expect("not empty");
            out.push(c);
            rest = &rest[c.len_utf8()..];
        }
    }
    out
}

/// Whether `code` defines the function `name`.
fn defines(code: &str, name: &str) -> bool {
    code.match_indices("fn").any(|(at, _)| {
        let before_ok = code[..at]
            .chars()
            .next_back()
            .is_none_or(|c| !(c.is_alphanumeric() || c == '_'));
        let after = code[at + 2..].trim_start();
        before_ok
            && after.strip_prefix(name).is_some_and(|rest| {
                rest.trim_start().starts_with('(') || rest.trim_start().starts_with('<')
            })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const GIVEN: &str = "fn caller() -> f32 { return twice(1.0); }\n";

    /// The errors of composing `parts`, as a student reads them.
    fn errors(parts: &[Part<'_>]) -> String {
        match compose(parts) {
            Err(TessError::Wgsl(errors)) => errors,
            other => panic!("expected WGSL errors, got {other:?}"),
        }
    }

    fn piece(text: &'static str) -> Piece {
        Piece {
            task: "t",
            file: "src/t.wgsl",
            text,
            functions: &["fn twice(x: f32) -> f32"],
        }
    }

    #[test]
    fn a_parse_error_names_the_file_and_line_of_the_piece() {
        let broken = piece("// header\n\nfn twice(x: f32) -> f32 {\n    return 2.0 * x\n}\n");
        let message = errors(&[Part::Yours(broken), Part::Given("given", GIVEN)]);
        assert!(
            message.starts_with("src/t.wgsl:5:1: error: expected"),
            "{message}"
        );
        assert!(message.contains("5 | }"), "{message}");
    }

    #[test]
    fn a_validation_error_names_the_file_and_line_of_the_piece() {
        let wrong = piece("fn twice(x: f32) -> f32 {\n    return vec2(x, x);\n}\n");
        let message = errors(&[Part::Yours(wrong), Part::Given("given", GIVEN)]);
        assert!(
            message.starts_with("src/t.wgsl:1:1: error: Function [0] 'twice' is invalid"),
            "{message}"
        );
        assert!(message.contains("2 |     return vec2(x, x);"), "{message}");
        assert!(!message.contains("naga::"), "{message}");
    }

    #[test]
    fn a_missing_function_is_named_where_the_given_code_calls_it() {
        let other = piece("fn thrice(x: f32) -> f32 { return 3.0 * x; }\n");
        let message = errors(&[Part::Yours(other), Part::Given("given", GIVEN)]);
        assert!(message.starts_with("given:1:29: error:"), "{message}");
        assert!(
            message.contains("note: src/t.wgsl does not define `fn twice(x: f32) -> f32`"),
            "{message}"
        );
    }

    #[test]
    fn a_correct_piece_comes_first_in_the_shader() {
        let right = piece("fn twice(x: f32) -> f32 { return 2.0 * x; }\n");
        let source = compose(&[Part::Yours(right), Part::Given("given", GIVEN)]).unwrap();
        assert!(source.starts_with(right.text));
    }

    #[test]
    #[should_panic(expected = "not yet implemented: t: write twice")]
    fn a_piece_of_comments_only_is_not_started() {
        let stub = piece("// What to write.\n\n// TODO t: write twice\n");
        let _ = compose(&[Part::Yours(stub), Part::Given("given", GIVEN)]);
    }

    #[test]
    fn definitions_are_found_in_code_not_in_comments() {
        let code = without_comments("// fn a()\nfn b(x: f32) {}\n/* fn c() */ fn dd() {}");
        assert!(!defines(&code, "a"));
        assert!(defines(&code, "b"));
        assert!(!defines(&code, "c"));
        assert!(!defines(&code, "d"));
        assert!(defines(&code, "dd"));
    }
}
