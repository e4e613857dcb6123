//! `cargo xtask test`'s step "given code stands in for no task", on
//! methods: a method of the given code with a task method's name is
//! planted into the task's stub (its parameters bound to the task's
//! arguments) and must score 0 there.

mod common;

use std::fs;

use common::{fixture, stdout, xtask};

/// The fixture's `negate` task as a method of `Sign`.
const SIGN: &str = "//! Two small operations.

/// `2 x`.
pub fn double(x: i32) -> i32 {
    // BEGIN SOLUTION double: return twice x
    x * 2
    // END SOLUTION
}

/// A sign to apply.
pub struct Sign;

impl Sign {
    /// `-x`.
    pub fn negate(&self, x: i32) -> i32 {
        // BEGIN SOLUTION negate: return minus x
        -x
        // END SOLUTION
    }
}
";

#[test]
fn a_given_method_that_solves_a_task_method_fails_the_step() {
    let root = fixture("tiny", "stand-in-method");
    fs::write(root.join("reference/01-tiny/src/ops.rs"), SIGN).unwrap();
    fs::write(
        root.join("exercises/01-tiny/tests/negate.rs"),
        "#[testkit::test]\nfn negates() {\n    assert_eq!(tiny::ops::Sign.negate(3), -3);\n}\n",
    )
    .unwrap();
    let output = xtask(&root, &["stubs"]);
    assert!(output.status.success(), "{}", stdout(&output));
    let lib = root.join("exercises/01-tiny/src/lib.rs");
    let mut crate_root = fs::read_to_string(&lib).unwrap();
    crate_root.push_str("pub mod helpers;\n");
    fs::write(&lib, crate_root).unwrap();
    let helpers = root.join("exercises/01-tiny/src/helpers.rs");

    // Given code whose method has another name and shape: nothing to plant.
    fs::write(
        &helpers,
        "//! Given helpers.\n\n/// Sums.\npub struct Sum;\n\nimpl Sum {\n    /// `a + b`.\n    pub fn of(&self, a: i32, b: i32) -> i32 {\n        a + b\n    }\n}\n",
    )
    .unwrap();
    let output = xtask(&root, &["test", "--step", "9"]);
    let text = stdout(&output);
    assert!(output.status.success(), "{text}");

    // A given method with the task's name, its parameter named otherwise:
    // planted in, it solves the task, and the step says which.
    fs::write(
        &helpers,
        "//! Given helpers.\n\n/// A number's opposite.\npub struct Opposite;\n\nimpl Opposite {\n    /// Minus `value`.\n    pub fn negate(&self, value: i32) -> i32 {\n        -value\n    }\n}\n",
    )
    .unwrap();
    let output = xtask(&root, &["test", "--step", "9"]);
    let text = stdout(&output);
    assert!(!output.status.success(), "{text}");
    assert!(
        text.contains(
            "exercises/01-tiny/src/helpers.rs: Opposite::negate scores 1 of 1 points in place of 01-tiny / negate"
        ),
        "{text}"
    );
}
