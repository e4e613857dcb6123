//! The bound on compile-time evaluation, which student code may not lift.
//!
//! rustc interprets every `const` item (and `static`, and `const` block)
//! while it compiles, and stops an evaluation that takes too long with
//! the lint `long_running_const_eval`: deny by default, it fires after a
//! number of interpreter steps — an endless `const` loop fails its build
//! in about a second (measured with rustc 1.95: 0.75 s for a bare
//! `loop {}`). A task file can lift it with
//! `#[allow(long_running_const_eval)]` (or `expect`, or `#![allow]` on
//! the module): the evaluation then runs until the build's CPU limit, 15
//! minutes of a class's time per such member.
//!
//! **Why not `-F long_running_const_eval`.** Forbidding the lint on the
//! command line was measured too (rustc 1.95): the inner `#[allow]` is
//! reported as error E0453, "incompatible with previous forbid", at
//! once, but the endless evaluation goes on all the same (120 s and still
//! running) — the error only ends the build when the evaluation does. So
//! the bound is kept by refusing to compile a task file that names the
//! lint at all, as `#[path]` and `include!` are refused. A name cannot be
//! hidden from this test: lint names in attributes are identifiers written
//! out (a `macro_rules!` that builds `#[allow($lint)]` still needs the name
//! passed in), and neither `allow(warnings)` nor any lint group lowers a
//! lint that denies by default. The course's solutions never need it.
//!
//! **The build's memory.** Evaluation that allocates instead of looping
//! — a `const` array of gigabytes — meets the build's memory cap,
//! [`Limits::build`](super::Limits::build): 8 GiB of address space per
//! process (and 8 GiB for all of the build's processes together where a
//! cgroup can be made). rustc then stops at once with "tried to allocate
//! more memory than available to compiler" (E0080). Without it, a 2 GiB
//! `const` array took rustc more than 20 GiB and two minutes.

/// The lint that bounds compile-time evaluation.
pub const LINT: &str = "long_running_const_eval";

/// Each place in `masked` (a task file with its comments and string
/// literals blanked) that names [`LINT`], as `line: what`, in the form of
/// the grader's other refused constructs.
#[must_use]
pub fn lifted_bounds(masked: &str) -> Vec<String> {
    masked
        .lines()
        .enumerate()
        .filter(|(_, line)| {
            line.split(|c: char| !(c.is_alphanumeric() || c == '_'))
                .any(|word| word == LINT)
        })
        .map(|(number, _)| {
            format!(
                "{}: `{LINT}` names the bound on compile-time evaluation, which student code may not lift",
                number + 1
            )
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn naming_the_bound_is_refused_in_every_attribute_form() {
        for source in [
            "#[allow(long_running_const_eval)]\nconst X: () = loop {};",
            "#![allow(long_running_const_eval)]",
            "#[expect(unused, long_running_const_eval)]",
            "#[cfg_attr(all(), allow(r#long_running_const_eval))]",
            "lift!(long_running_const_eval);",
        ] {
            assert_eq!(lifted_bounds(source).len(), 1, "{source}");
        }
        assert_eq!(
            lifted_bounds("#[allow(long_running_const_eval)]")[0],
            "1: `long_running_const_eval` names the bound on compile-time evaluation, which student code may not lift"
        );
    }

    #[test]
    fn longer_names_and_other_lints_pass() {
        for source in [
            "#[allow(dead_code)]",
            "const long_running_const_evaluation: u8 = 0;",
            "fn my_long_running_const_eval() {}",
        ] {
            assert!(lifted_bounds(source).is_empty(), "{source}");
        }
    }
}
