//! `cargo xtask stubs [--check]`: the student files, generated from the
//! solutions.
//!
//! Every `reference/NN-topic/src/X.rs` is copied to `exercises/NN-topic/src/X.rs`
//! with each marked solution replaced by a `todo!`:
//!
//! ```text
//!     // BEGIN SOLUTION dda: draw the line with the DDA        todo!("dda: draw the line with the DDA")
//!     let steps = ...;                                    =>
//!     // END SOLUTION
//! ```
//!
//! The `todo!` sits at the indentation of the `BEGIN` line. A bare
//! `// BEGIN SOLUTION` (no `<task>: <instruction>`) removes its region
//! entirely: helpers and `use` lines only the solution needs. Everything
//! else, doc comments and signatures included, is copied verbatim, and
//! the stub is then kept free of the warnings its `todo!`s alone provoke
//! (see [`quiet`]).
//!
//! Markers are comments, found line by line; the Rust around them is read
//! as a syntax tree (see [`syntax`]): by the quieting of a stub, the
//! do-nothing edition, the stand-ins and the check of a crate root.
//!
//! `reference/` holds solutions only: a file there without a marker is an
//! error. Given code (and `src/lib.rs`, hand-written) exists once, in
//! `exercises/`; a stage lays `reference/*/src` over it (see `stage`).

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use syn::visit::{self, Visit};

use crate::files::is_wgsl;
use crate::stubs::BEGIN_MARKER;
use crate::topics::{self, Topic};
use syntax::Source;

mod do_nothing;
mod generate;
pub mod quiet;
pub mod stand_ins;
mod syntax;

pub use do_nothing::do_nothing;
use generate::marker;
pub use generate::{generate, rustfmt_max_width, without_markers};

/// The hand-written crate root of every exercise crate.
const CRATE_ROOT: &str = "lib.rs";

/// The number of the first line where `a` and `b` differ.
fn first_difference(a: &str, b: &str) -> usize {
    let mut a_lines = a.lines();
    let mut b_lines = b.lines();
    let mut number = 1;
    while let (Some(x), Some(y)) = (a_lines.next(), b_lines.next()) {
        if x != y {
            return number;
        }
        number += 1;
    }
    number
}

/// Lists the `.rs` and `.wgsl` files under `dir`, relative to it, sorted.
fn source_files(dir: &Path) -> Result<Vec<PathBuf>> {
    Ok(crate::files::files_under(dir)?
        .into_iter()
        .filter(|file| file.extension().is_some_and(|ext| ext == "rs") || is_wgsl(file))
        .collect())
}

/// The lines (1-based) of the attributes of a crate root that would make
/// it a switch: `#[path]`, which takes a module from another file, and
/// `cfg_attr`, which adds attributes on a condition. Attributes of the
/// code, read from its syntax tree: a comment or a string that mentions
/// them is none. `None` for text that is not Rust.
fn switches(text: &str) -> Option<Vec<usize>> {
    struct Switches<'a, 'b> {
        source: &'b Source<'a>,
        lines: Vec<usize>,
    }
    impl<'ast> Visit<'ast> for Switches<'_, '_> {
        fn visit_attribute(&mut self, attribute: &'ast syn::Attribute) {
            let path = attribute.path();
            if path.is_ident("path") || path.is_ident("cfg_attr") {
                let at = syntax::range(attribute).start;
                self.lines.push(self.source.line_of(at) + 1);
            }
            visit::visit_attribute(self, attribute);
        }
    }
    let source = Source::parse(text)?;
    let mut switches = Switches {
        source: &source,
        lines: Vec::new(),
    };
    switches.visit_file(&source.file);
    Some(switches.lines)
}

/// What happened to the stubs of one checkout.
#[derive(Debug, Default)]
pub struct Outcome {
    /// Student files whose content is not what the reference generates
    /// (`--check`, with the first line that differs) or that were rewritten.
    pub changed: Vec<(PathBuf, Option<usize>)>,
    /// Student files that were already up to date.
    pub unchanged: usize,
    /// Marker errors and files without a counterpart.
    pub errors: Vec<String>,
}

/// Generates (or with `check`, compares) the stubs of every topic in `root`.
/// Returns what it found; only failures to read or write are `Err`.
pub fn sync(root: &Path, check: bool) -> Result<Outcome> {
    let reference_root = root.join("reference");
    if !reference_root.is_dir() {
        bail!(
            "{} does not exist: stubs are generated from the tutor edition's solutions",
            reference_root.display()
        );
    }
    let max_width = rustfmt_max_width(root)?;
    let mut outcome = Outcome::default();
    let workspace = root.join("Cargo.toml");
    let forbids_unsafe = fs::read_to_string(&workspace)
        .ok()
        .and_then(|text| toml::from_str::<toml::Value>(&text).ok())
        .is_some_and(|manifest| {
            let lint = ["workspace", "lints", "rust", "unsafe_code"]
                .iter()
                .try_fold(&manifest, |v, key| v.get(key));
            lint.and_then(toml::Value::as_str) == Some("forbid")
        });
    if !forbids_unsafe {
        outcome.errors.push(format!(
            "{}: the workspace forbids unsafe code (`[workspace.lints.rust] unsafe_code = \"forbid\"`): the grader's verdict relies on it",
            workspace.display()
        ));
    }
    for topic in topics::discover(root)? {
        sync_topic(root, &topic, check, max_width, &mut outcome)?;
    }
    Ok(outcome)
}

fn sync_topic(
    root: &Path,
    topic: &Topic,
    check: bool,
    max_width: usize,
    outcome: &mut Outcome,
) -> Result<()> {
    let relative = |path: &Path| {
        path.strip_prefix(root)
            .unwrap_or(path)
            .display()
            .to_string()
    };
    let reference_src = root.join("reference").join(&topic.name).join("src");
    let exercise_src = topic.dir.join("src");
    if !reference_src.is_dir() {
        outcome.errors.push(format!(
            "{} has no solutions: {} is missing",
            topic.name,
            relative(&reference_src)
        ));
        return Ok(());
    }
    let ids: Vec<&str> = topic.sheet.tasks.iter().map(|t| t.id.as_str()).collect();
    // A plain crate: which code is compiled is decided by what is staged,
    // never by a switch in the crate root or a feature in its manifest.
    let crate_root = exercise_src.join(CRATE_ROOT);
    if let Ok(text) = fs::read_to_string(&crate_root) {
        match switches(&text) {
            Some(lines) => {
                for number in lines {
                    outcome.errors.push(format!(
                        "{}:{number}: a crate root declares its modules plainly (`pub mod x;`), without `#[path]` or `cfg_attr`",
                        relative(&crate_root),
                    ));
                }
            }
            None => outcome.errors.push(format!(
                "{}: a crate root is Rust, and this one cannot be read as Rust",
                relative(&crate_root)
            )),
        }
    }
    let manifest = topic.dir.join("Cargo.toml");
    let manifest_text = fs::read_to_string(&manifest).unwrap_or_default();
    if manifest_text.lines().any(|l| l.trim() == "[features]") {
        outcome.errors.push(format!(
            "{}: an exercise crate has no features (a feature would be unified across the workspace and switch the code students build)",
            relative(&manifest)
        ));
    }
    // The grader's verdict relies on student code being safe Rust (see
    // crates/testkit-macros): the workspace forbids `unsafe`, and every
    // exercise crate takes the workspace's lints.
    let lints_inherited = toml::from_str::<toml::Table>(&manifest_text).is_ok_and(|t| {
        t.get("lints")
            .and_then(|l| l.get("workspace"))
            .and_then(toml::Value::as_bool)
            == Some(true)
    });
    if !lints_inherited {
        outcome.errors.push(format!(
            "{}: an exercise crate takes the workspace's lints (`[lints] workspace = true`), which forbid `unsafe` in student code",
            relative(&manifest)
        ));
    }
    let reference_files = source_files(&reference_src)?;
    for file in &reference_files {
        let source_path = reference_src.join(file);
        let target_path = exercise_src.join(file);
        if file == Path::new(CRATE_ROOT) {
            outcome.errors.push(format!(
                "{}: the crate root is hand-written in {} and has no reference copy",
                relative(&source_path),
                relative(&target_path)
            ));
            continue;
        }
        let source = fs::read_to_string(&source_path)
            .with_context(|| format!("cannot read {}", source_path.display()))?;
        if !source.lines().any(|line| marker(line).is_some()) {
            outcome.errors.push(format!(
                "{} holds no `{BEGIN_MARKER}`: given code belongs in {} alone",
                relative(&source_path),
                relative(&target_path)
            ));
            continue;
        }
        let generated = match generate(&source, &relative(&source_path), &ids, max_width) {
            Ok(generated) => generated,
            Err(errors) => {
                outcome.errors.extend(errors);
                continue;
            }
        };
        let current = fs::read_to_string(&target_path).ok();
        if current.as_deref() == Some(generated.as_str()) {
            outcome.unchanged += 1;
            continue;
        }
        if check {
            if current.is_none() {
                outcome.errors.push(format!(
                    "{} has no student file {}",
                    relative(&source_path),
                    relative(&target_path)
                ));
            } else {
                let line = first_difference(current.as_deref().unwrap_or_default(), &generated);
                outcome.changed.push((target_path, Some(line)));
            }
            continue;
        }
        crate::files::write_file(&target_path, generated)?;
        outcome.changed.push((target_path, None));
    }
    Ok(())
}

/// `cargo xtask stubs [--check]`: prints what it did; fails when `check`
/// finds a difference or when any file has a marker error.
pub fn run(root: &Path, check: bool) -> Result<()> {
    let outcome = sync(root, check)?;
    let relative = |path: &Path| {
        path.strip_prefix(root)
            .unwrap_or(path)
            .display()
            .to_string()
    };
    let mut message = String::new();
    for (path, line) in &outcome.changed {
        let line = match line {
            Some(line) => format!("{}:{line}: out of date (first difference)", relative(path)),
            None => format!("wrote {}", relative(path)),
        };
        writeln!(message, "{line}").expect("writing to a String");
    }
    for error in &outcome.errors {
        writeln!(message, "error: {error}").expect("writing to a String");
    }
    print!("{message}");
    let stale = check && !outcome.changed.is_empty();
    if stale || !outcome.errors.is_empty() {
        let mut problems = Vec::new();
        if stale {
            problems.push(format!(
                "{} student file(s) differ from what `cargo xtask stubs` generates",
                outcome.changed.len()
            ));
        }
        if !outcome.errors.is_empty() {
            problems.push(format!("{} error(s)", outcome.errors.len()));
        }
        bail!(
            "stubs are not in sync with reference/: {}",
            problems.join(", ")
        );
    }
    if check {
        println!(
            "stubs: all {} student file(s) match reference/",
            outcome.unchanged
        );
    } else {
        println!(
            "stubs: wrote {} file(s), {} already up to date",
            outcome.changed.len(),
            outcome.unchanged
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_crate_root_switch_is_an_attribute_not_a_mention() {
        // A comment, a doc comment and a string may name `#[path]` and
        // `cfg_attr(`; only the attributes themselves are switches.
        let text = "\
//! Modules are declared plainly: no #[path = \"x\"], no cfg_attr(test, …).
// #[path = \"elsewhere.rs\"]
pub const NOTE: &str = \"#[path] and cfg_attr( are not used here\";
pub mod dda;
#[path = \"other.rs\"]
pub mod wu;
#[cfg_attr(test, path = \"mock.rs\")]
pub mod mock;
";
        assert_eq!(switches(text), Some(vec![5, 7]));
        assert_eq!(switches("pub mod dda;\n"), Some(vec![]));
        assert_eq!(switches("pub mod {"), None);
    }
}
