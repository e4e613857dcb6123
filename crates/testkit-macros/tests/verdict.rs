//! The wrapped test's side of the verdict, seen from outside: this test
//! binary runs its own `#[ignore]`d tests one per process, as the grader
//! does, with a token file, and reads what they print.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};

const TOKEN: &str = "5e1f0a9c7d2b4e6f8a0b1c2d3e4f5a6b";
use wire::VERDICT_PREFIX as PREFIX;

#[testkit_macros::test]
#[ignore = "run as a child by the tests below"]
fn holds() {
    assert_eq!(1 + 1, 2);
}

#[testkit_macros::test]
#[ignore = "run as a child by the tests below"]
fn fails() {
    assert_eq!(1 + 1, 3, "one and one");
}

#[testkit_macros::test]
#[ignore = "run as a child by the tests below"]
fn exits_before_its_assertion() {
    // What forged output looks like: libtest's summary, then status 0.
    println!("test result: ok. 1 passed; 0 failed; 0 ignored");
    std::process::exit(0);
}

#[testkit_macros::test]
#[ignore = "run as a child by the tests below"]
fn returns_early() {
    if std::hint::black_box(true) {
        return;
    }
    unreachable!("the early return ends the test normally");
}

#[testkit_macros::test]
#[ignore = "run as a child by the tests below"]
fn reads_its_own_token_file() {
    // The token file is gone by the time the body runs.
    let file = std::env::var_os("TESTKIT_VERDICT_FILE").expect("the grader's variable");
    assert!(!Path::new(&file).exists(), "the token file is still there");
}

/// Runs test `name` of this binary with a token file; returns its output
/// and whether the token file is left.
fn run(name: &str) -> (String, bool) {
    // A folder of each run's own: two tests run the same child at once.
    static RUNS: AtomicUsize = AtomicUsize::new(0);
    let run = RUNS.fetch_add(1, Ordering::Relaxed);
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("{name}-{run}"));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("token");
    std::fs::write(&file, TOKEN).unwrap();
    let output = Command::new(std::env::current_exe().unwrap())
        .args([
            "--exact",
            name,
            "--ignored",
            "--nocapture",
            "--test-threads=1",
        ])
        .env("TESTKIT_VERDICT_FILE", &file)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&output.stdout).into_owned()
        + &String::from_utf8_lossy(&output.stderr);
    (text, file.exists())
}

fn confirmed(output: &str) -> bool {
    output
        .lines()
        .any(|line| line.strip_prefix(PREFIX) == Some(TOKEN))
}

#[test]
fn a_test_that_ends_normally_prints_its_token_on_a_line_of_its_own() {
    for name in ["holds", "returns_early", "reads_its_own_token_file"] {
        let (output, left) = run(name);
        assert!(confirmed(&output), "{name}: {output}");
        assert!(!left, "{name} left its token file");
    }
}

#[test]
fn a_failing_or_exiting_test_prints_no_token() {
    for name in ["fails", "exits_before_its_assertion"] {
        let (output, left) = run(name);
        assert!(!output.contains(TOKEN), "{name}: {output}");
        assert!(!left, "{name} left its token file");
    }
}

#[test]
fn panics_name_the_line_in_the_test_body() {
    let (output, _) = run("fails");
    let line = include_str!("verdict.rs")
        .lines()
        .position(|l| l.contains("\"one and one\""))
        .unwrap()
        + 1;
    assert!(
        output.contains(&format!("tests/verdict.rs:{line}:")),
        "{output}"
    );
}

#[testkit_macros::test]
fn without_the_variable_it_is_an_ordinary_test() {
    assert!(std::env::var_os("TESTKIT_VERDICT_FILE").is_none());
}
