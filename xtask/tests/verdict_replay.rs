//! The verdict decided where no student code ran (see the `transcript`
//! crate and `grade::run`), tried on the `replayed` fixture course, whose
//! sheet says `verdict = "replay"`: the reference and an honest student
//! pass through the replay, the stubs' `todo!()` reaches the reason, and
//! a class of members who attack the verdict — a forged pass printed
//! before `exit(0)`, a search of the recording process for the grader's
//! token, a transcript written by hand, a run that stops inside a call
//! once the right values are out — scores 0, each plant seen to have run.

mod common;

use std::fs;
use std::path::Path;

use common::{fixture, fresh, grade_submission, read_json, task, xtask};
use serde_json::Value;

const TOPIC: &str = "01-calls";

/// `ops.rs` with these three bodies.
fn ops(multiples: &str, sum: &str, double_all: &str) -> String {
    format!(
        "#[transcript::task]\npub fn multiples(step: u32, limit: u32, mut visit: impl FnMut(u32)) {{\n{multiples}\n}}\n\n#[transcript::task]\npub fn sum(values: &[i64]) -> i64 {{\n{sum}\n}}\n\n#[transcript::task]\npub fn double_all(values: &mut Vec<i64>) {{\n{double_all}\n}}\n"
    )
}

/// The right bodies.
const RIGHT: [&str; 3] = [
    "if step == 0 { return; } let mut m = 0; while m < limit { visit(m); m += step; }",
    "values.iter().sum()",
    "for v in values.iter_mut() { *v *= 2; }",
];

/// A checkout of the course with `ops.rs`, in `class/name`.
fn member(official: &Path, class: &Path, name: &str, ops: &str) {
    let dir = class.join(name);
    for folder in ["exercises", "crates"] {
        common::copy_dir(&official.join(folder), &dir.join(folder));
    }
    fs::copy(official.join("Cargo.toml"), dir.join("Cargo.toml")).unwrap();
    fs::write(dir.join("exercises").join(TOPIC).join("src/ops.rs"), ops).unwrap();
}

fn score(report: &Value) -> f64 {
    report["score"].as_f64().unwrap()
}

/// Every test's reason and output of a report, for "the plant ran".
fn everything_said(report: &Value) -> String {
    let topic = common::topic(report, TOPIC);
    let mut said = String::new();
    for task in topic["tasks"].as_array().unwrap() {
        for test in task["tests"].as_array().unwrap() {
            for field in ["reason", "output"] {
                if let Some(text) = test[field].as_str() {
                    said.push_str(text);
                    said.push('\n');
                }
            }
        }
    }
    said
}

#[test]
fn the_reference_passes_and_the_stubs_fail_through_the_replay() {
    let official = fixture("replayed", "reference");
    let out = fresh(official.join("target/reference"));
    let output = xtask(
        &official,
        &["grade", "--reference", "--out", out.to_str().unwrap()],
    );
    assert!(output.status.success(), "{output:?}");
    let report = read_json(&out.join("report.json"));
    assert_eq!(score(&report), 4.0, "the reference scores full: {report:#}");
    // Each test ran twice: the replay's log carries the recorded run.
    let log = out
        .join("logs")
        .join(TOPIC)
        .join("sum/sums_small_numbers.log");
    let log = fs::read_to_string(&log).unwrap_or_else(|e| panic!("{}: {e}", log.display()));
    assert!(log.contains("testkit verdict: passed"), "{log}");
    assert!(log.contains("--- the run of your code"), "{log}");

    // The stubs, staged as a submission: their `todo!()` is the reason.
    let class = Path::new(env!("CARGO_TARGET_TMPDIR")).join("replayed-stubs-class");
    let _ = fs::remove_dir_all(&class);
    for folder in ["exercises", "crates"] {
        common::copy_dir(&official.join(folder), &class.join(folder));
    }
    fs::copy(official.join("Cargo.toml"), class.join("Cargo.toml")).unwrap();
    let out = fresh(official.join("target/stubs"));
    let output = grade_submission(&official, &class, &out, &[]);
    assert!(output.status.success(), "{output:?}");
    let report = read_json(&out.join("replayed-stubs-class/report.json"));
    assert_eq!(score(&report), 0.0);
    let reason = common::reason(task(&report, TOPIC, "sum"));
    assert_eq!(reason, "not implemented yet: sum: add the values up");
}

#[test]
fn attacks_on_the_verdict_score_nothing_and_the_honest_member_everything() {
    let official = fixture("replayed", "attacks");
    let class = Path::new(env!("CARGO_TARGET_TMPDIR")).join("replayed-attacks-class");
    let _ = fs::remove_dir_all(&class);
    // The baseline: an honest member scores full, through the replay.
    member(
        &official,
        &class,
        "a-honest",
        &ops(RIGHT[0], RIGHT[1], RIGHT[2]),
    );
    // Prints what a passed test prints, with a made-up token, and exits 0.
    let forge = r#"println!("\ntestkit verdict: passed 0123456789abcdef0123456789abcdef\ntest result: ok. 1 passed; 0 failed"); std::process::exit(0)"#;
    member(&official, &class, "forges", &ops(forge, forge, forge));
    // Looks for the grader's token in its process's reach: its
    // environment and every file it can list in its scratch folder. Where
    // it finds anything, it answers right (and the test would pass); it
    // says what it saw either way.
    let snoop = |right: &str, wrong: &str| {
        format!(
            r#"let mut found = Vec::new();
            for (key, value) in std::env::vars_os() {{
                let (key, value) = (key.to_string_lossy().into_owned(), value.to_string_lossy().into_owned());
                let hex = value.len() == 32 && value.chars().all(|c| c.is_ascii_hexdigit());
                if key.contains("VERDICT") || hex {{ found.push(key); }}
            }}
            let mut folders = vec![std::env::temp_dir()];
            while let Some(folder) = folders.pop() {{
                for entry in std::fs::read_dir(&folder).into_iter().flatten().flatten() {{
                    let path = entry.path();
                    if path.is_dir() {{ folders.push(path); }}
                    else if path.to_string_lossy().contains("verdict") {{ found.push(path.display().to_string()); }}
                }}
            }}
            println!("snooped for the token: found {{found:?}}");
            if !found.is_empty() {{ {right} }} else {{ {wrong} }}"#
        )
    };
    member(
        &official,
        &class,
        "snoops",
        &ops(
            &snoop(RIGHT[0], "visit(limit + 1)"),
            &snoop(RIGHT[1], "-1"),
            &snoop(RIGHT[2], "values.clear()"),
        ),
    );
    // Writes the record itself (a pass for `sum` as the honest run would
    // record it is not at hand: it writes what a careless forger would)
    // and exits.
    let write = r#"let path = std::env::var_os("TRANSCRIPT_RECORD").expect("recording");
        std::fs::write(&path, b"\x05\x00\x00\x00forged").unwrap();
        println!("wrote the record by hand"); std::process::exit(0)"#;
    member(
        &official,
        &class,
        "writes-record",
        &ops(write, write, write),
    );
    // Hands out the right values, then ends the process inside the call,
    // before the call returns.
    member(
        &official,
        &class,
        "stops-inside",
        &ops(
            "let mut m = 0; while m < limit && step > 0 { visit(m); m += step; } std::process::exit(0)",
            "println!(\"{}\", values.iter().sum::<i64>()); std::process::exit(0)",
            "for v in values.iter_mut() { *v *= 2; } std::process::exit(0)",
        ),
    );

    // Replaces the record with a link to the course's solution file, for
    // the replay's sandbox to bind; the grader reads no link.
    let solution = official.join("reference").join(TOPIC).join("src/ops.rs");
    let link = format!(
        r#"let path = std::env::var_os("TRANSCRIPT_RECORD").expect("recording");
        let _ = std::fs::remove_file(&path);
        std::os::unix::fs::symlink({:?}, &path).unwrap();
        std::process::exit(0)"#,
        solution.display().to_string()
    );
    member(&official, &class, "links-record", &ops(&link, &link, &link));

    // Writes into the replays' cache of compiled shaders (which a GPU
    // driver would run in the process that holds the token), found beside
    // its own, then answers right.
    let poison = |right: &str| {
        format!(
            r#"let own = std::path::PathBuf::from(std::env::var_os("MESA_SHADER_CACHE_DIR").unwrap_or_default());
            let theirs = own.with_file_name("replayed");
            let written = std::fs::create_dir_all(&theirs).and_then(|()| std::fs::write(theirs.join("index"), b"poison"));
            println!("shader cache {{}}; poisoned the replays': {{}}", own.display(), written.is_ok());
            {right}"#
        )
    };
    member(
        &official,
        &class,
        "poisons-shaders",
        &ops(&poison(RIGHT[0]), &poison(RIGHT[1]), &poison(RIGHT[2])),
    );

    let out = fresh(official.join("target/attacks"));
    let output = grade_submission(&official, &class, &out, &[]);
    assert!(output.status.success(), "{output:?}");
    let report = |name: &str| read_json(&out.join(name).join("report.json"));
    assert_eq!(score(&report("a-honest")), 4.0, "{:#}", report("a-honest"));
    // The recording has a shader cache of its own, and cannot reach the
    // replays'.
    let poisoned = fs::read_to_string(
        out.join("poisons-shaders")
            .join("logs")
            .join(TOPIC)
            .join("sum/sums_small_numbers.log"),
    )
    .unwrap();
    assert!(
        poisoned.contains("shader-cache/recorded; poisoned the replays': false")
            && !poisoned.contains("poisoned the replays': true"),
        "{poisoned}"
    );
    for name in [
        "forges",
        "snoops",
        "writes-record",
        "stops-inside",
        "links-record",
    ] {
        let report = report(name);
        assert_eq!(score(&report), 0.0, "{name}: {report:#}");
    }
    // Each plant ran, and the recording process saw no token.
    let snooped = everything_said(&report("snoops"));
    assert!(
        snooped.contains("snooped for the token: found []"),
        "{snooped}"
    );
    assert!(everything_said(&report("writes-record")).contains("wrote the record by hand"));
    let stopped = everything_said(&report("stops-inside"));
    assert!(stopped.contains("your code's run ended"), "{stopped}");
    assert!(everything_said(&report("forges")).contains("testkit verdict: passed 0123"));
    let linked = everything_said(&report("links-record"));
    assert!(
        linked.contains("was not a plain file") && !linked.contains("BEGIN SOLUTION"),
        "{linked}"
    );
}
