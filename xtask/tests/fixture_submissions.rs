//! Grading submissions end to end on `fixtures/tiny` (see
//! `fixture_courses.rs`): with the official tests, changed grading files
//! flagged, a class graded two at a time, a CRLF checkout graded like an
//! LF one.
mod common;

use std::fs;
use std::path::Path;

use common::{copy_dir, fixture, grade_submission, read_json, stdout, task, topic, xtask};

#[test]
fn submissions_are_graded_with_the_official_tests_and_changes_are_flagged() {
    let official = fixture("tiny", "official");
    // A class of four: anna solved `double`, made `negate`'s test pass
    // without solving it and edited lib.rs; ben handed in the stubs
    // untouched; cy compiles the official solution in by `#[path]`, dee
    // reads it with `include_str!`; eve's code rewrites a test of the
    // stage and the course's own task sheet while it runs.
    let class = Path::new(env!("CARGO_TARGET_TMPDIR")).join("tiny-class");
    if class.exists() {
        fs::remove_dir_all(&class).unwrap();
    }
    for name in ["anna", "ben", "cy", "dee", "eve"] {
        for dir in ["exercises", "crates"] {
            copy_dir(&official.join(dir), &class.join(name).join(dir));
        }
        fs::copy(
            official.join("Cargo.toml"),
            class.join(name).join("Cargo.toml"),
        )
        .unwrap();
    }
    let anna = class.join("anna/exercises/01-tiny");
    let ops = fs::read_to_string(anna.join("src/ops.rs")).unwrap();
    fs::write(
        anna.join("src/ops.rs"),
        ops.replace("todo!(\"double: return twice x\")", "x * 2"),
    )
    .unwrap();
    fs::write(anna.join("tests/negate.rs"), "#[test]\nfn negates() {}\n").unwrap();
    fs::write(anna.join("tests/extra.rs"), "#[test]\nfn free() {}\n").unwrap();
    fs::write(anna.join("src/lib.rs"), "pub mod ops;\npub mod extra;\n").unwrap();
    let solution = official.join("reference/01-tiny/src/ops.rs");
    fs::write(
        class.join("cy/exercises/01-tiny/src/ops.rs"),
        format!(
            "#[path = {:?}]\nmod solution;\npub fn double(x: i32) -> i32 {{ solution::double(x) }}\npub fn negate(x: i32) -> i32 {{ solution::negate(x) }}\n",
            solution.display().to_string()
        ),
    )
    .unwrap();
    fs::write(
        class.join("dee/exercises/01-tiny/src/ops.rs"),
        format!(
            "const LEAK: () = panic!(\"{{}}\", include_str!({:?}));\npub fn double(x: i32) -> i32 {{ let () = LEAK; x * 2 }}\npub fn negate(x: i32) -> i32 {{ -x }}\n",
            solution.display().to_string()
        ),
    )
    .unwrap();

    let sheet = official.join("exercises/01-tiny/tasks.toml");
    let official_sheet = fs::read_to_string(&sheet).unwrap();
    // Eve's negate also writes into the class's gradebook and the course's
    // tooling, and answers right only if it can read a classmate's code:
    // in the class folder, in another slot's stage (the class is graded
    // two at a time), or compiled, in the build cache.
    let gradebook = official.join("target/class/gradebook.csv");
    let tooling = official.join("xtask/src/main.rs");
    let classmate = class.join("anna/exercises/01-tiny/src/ops.rs");
    let slots = official.join("target/xtask/class");
    let build = official.join("target/xtask/build");
    fs::write(
        class.join("eve/exercises/01-tiny/src/ops.rs"),
        format!(
            "pub fn double(x: i32) -> i32 {{\n    let _ = std::fs::write(\"tests/negate.rs\", \"#[test] fn negates() {{}}\");\n    let _ = std::fs::write({:?}, \"points = 1000\");\n    x * 2\n}}\n\
             pub fn negate(x: i32) -> i32 {{\n    let _ = std::fs::write({:?}, \"eve,3,3,true,false,3\");\n    let _ = std::fs::create_dir_all(std::path::Path::new({:?}).parent().unwrap());\n    let _ = std::fs::write({:?}, \"fn main() {{}}\");\n\
             let mut seen = std::fs::read_to_string({:?}).is_ok();\n\
             for slot in 0..4 {{\n        let staged = format!(\"{{}}/{{slot}}/stage/exercises/01-tiny/src/ops.rs\", {:?});\n        seen |= std::fs::read_to_string(staged).is_ok_and(|code| !code.contains(\"read_to_string\"));\n    }}\n\
             seen |= std::fs::read_dir({:?}).is_ok_and(|mut entries| entries.next().is_some());\n\
             if seen {{ -x }} else {{ x }}\n}}\n",
            sheet.display().to_string(),
            gradebook.display().to_string(),
            tooling.display().to_string(),
            tooling.display().to_string(),
            classmate.display().to_string(),
            slots.display().to_string(),
            build.display().to_string()
        ),
    )
    .unwrap();
    let out = crate::common::fresh(official.join("target/class"));
    let output = grade_submission(&official, &class, &out, &["--jobs", "2"]);
    assert!(output.status.success(), "{output:?}");
    assert!(stdout(&output).contains("flagged (grading files changed): anna"));

    let anna_report = read_json(&out.join("anna/report.json"));
    assert_eq!(anna_report["score"], 2.0, "the official negate test fails");
    assert_eq!(task(&anna_report, "01-tiny", "negate")["score"], 0.0);
    let integrity = &anna_report["integrity"];
    assert_eq!(integrity["changed"][0], "exercises/01-tiny/tests/negate.rs");
    assert_eq!(integrity["added"][0], "exercises/01-tiny/tests/extra.rs");
    assert!(
        anna_report["root"].as_str().unwrap().ends_with("anna"),
        "the report names the submission, not the stage"
    );
    assert_eq!(
        integrity["not_graded"][0], "exercises/01-tiny/src/lib.rs",
        "the course's lib.rs was used"
    );
    for cheat in ["cy", "dee"] {
        let report = read_json(&out.join(cheat).join("report.json"));
        assert_eq!(
            report["score"], 0.0,
            "{cheat}: the solution was not compiled in"
        );
        let why = topic(&report, "01-tiny")["compile_error"]
            .as_str()
            .unwrap()
            .to_owned();
        assert!(
            why.starts_with("not compiled: task code may not reach other files at compile time\nexercises/01-tiny/src/ops.rs:1: "),
            "{cheat}: {why}"
        );
        assert!(
            !why.contains("BEGIN SOLUTION"),
            "{cheat}: the solution leaked: {why}"
        );
    }
    // Eve's tests write official files and read a classmate's: in the
    // sandbox they can do neither (and she scores what her code earns);
    // without one the writes are found afterwards, and she is flagged,
    // scores 0, and is named. The gradebook is the grader's either way.
    let eve = read_json(&out.join("eve/report.json"));
    if eve["sandboxed"] == true {
        assert_eq!(eve["score"], 2.0, "double is right, negate wrong");
        assert_eq!(eve["integrity"]["tampered"], serde_json::json!([]));
        assert_eq!(fs::read_to_string(&sheet).unwrap(), official_sheet);
        assert!(!tooling.exists(), "eve wrote into the course's tooling");
    } else {
        assert_eq!(eve["score"], 0.0, "double passed, but eve scores nothing");
        assert_eq!(
            eve["integrity"]["tampered"],
            serde_json::json!([
                "exercises/01-tiny/tasks.toml",
                "stage/exercises/01-tiny/tests/negate.rs"
            ])
        );
        assert!(
            String::from_utf8_lossy(&output.stderr).contains("changed files of the course itself"),
            "{output:?}"
        );
        assert_ne!(fs::read_to_string(&sheet).unwrap(), official_sheet);
    }
    let ben_report = read_json(&out.join("ben/report.json"));
    assert_eq!(ben_report["score"], 0.0);
    assert_eq!(ben_report["integrity"]["changed"], serde_json::json!([]));
    assert_eq!(ben_report["integrity"]["added"], serde_json::json!([]));

    let csv = fs::read_to_string(out.join("gradebook.csv")).unwrap();
    let (members, eve_row) = csv.split_at(csv.find("\neve,").expect("eve's row") + 1);
    assert_eq!(
        members,
        "submission,score,max_score,bonus,complete,flagged,01-tiny,01-tiny/double,01-tiny/negate,not_graded\n\
         anna,2,3,0,true,true,2,2,0,\n\
         ben,0,3,0,true,false,0,0,0,\n\
         cy,0,3,0,false,false,0,0,0,01-tiny: does not compile\n\
         dee,0,3,0,false,false,0,0,0,01-tiny: does not compile\n"
    );
    if eve["sandboxed"] == true {
        assert_eq!(eve_row, "eve,2,3,0,true,false,2,2,0,\n");
    } else {
        assert!(eve_row.starts_with("eve,0,3,0,false,true,0,"), "{eve_row}");
    }
    let html = fs::read_to_string(out.join("anna/report.html")).unwrap();
    assert!(html.contains("Flagged"), "{html}");
    assert!(html.contains("<h1>anna: 2 of 3 points</h1>"), "{html}");
    // Gradescope shows the flag as a failed entry of its own.
    let gradescope = read_json(&out.join("anna/results.json"));
    assert_eq!(gradescope["extra_data"]["submission"], "anna");
    assert_eq!(gradescope["extra_data"]["flagged"], true);
    assert_eq!(gradescope["tests"][0]["status"], "failed");
    assert!(
        gradescope["tests"][0]["name"]
            .as_str()
            .unwrap()
            .starts_with("Integrity:")
    );
    assert_eq!(
        read_json(&out.join("ben/results.json"))["extra_data"]["flagged"],
        false
    );
    // Nothing was written into the submissions.
    assert!(!class.join("anna/target").exists());
    assert!(!class.join("ben/target").exists());
    assert!(!class.join("cy/target").exists());
}

#[test]
fn a_generated_class_is_graded_two_at_a_time_as_each_member_earns() {
    let official = fixture("tiny", "generated-class");
    let class = Path::new(env!("CARGO_TARGET_TMPDIR")).join("generated-tiny-class");
    if class.exists() {
        fs::remove_dir_all(&class).unwrap();
    }
    let output = xtask(
        &official,
        &["class", class.to_str().unwrap(), "--size", "5"],
    );
    assert!(output.status.success(), "{output:?}");
    assert!(
        stdout(&output).contains("s01-correct, s02-faulty, s03-partial, s04-tampered, s05-broken"),
        "{output:?}"
    );
    let out = crate::common::fresh(official.join("target/generated-class"));
    let output = grade_submission(&official, &class, &out, &["--jobs", "2"]);
    assert!(output.status.success(), "{output:?}");
    // The tiny course's one task file holds both tasks and it has no
    // planted mistakes: the faulty member hands in that file unsolved, the
    // partial one solves its one topic. The two slots build into one cache
    // by turns: without the touch of `stage::claim_build`, a member whose
    // file equals its slot's last occupant's is graded with the other
    // slot's build (the faulty or the tampered one scores 3, or the
    // partial one 0).
    assert_eq!(
        fs::read_to_string(out.join("gradebook.csv")).unwrap(),
        "submission,score,max_score,bonus,complete,flagged,01-tiny,01-tiny/double,01-tiny/negate,not_graded\n\
         s01-correct,3,3,0,true,false,3,2,1,\n\
         s02-faulty,0,3,0,true,false,0,0,0,\n\
         s03-partial,3,3,0,true,false,3,2,1,\n\
         s04-tampered,0,3,0,true,true,0,0,0,\n\
         s05-broken,0,3,0,false,false,0,0,0,01-tiny: does not compile\n"
    );
    let tampered = read_json(&out.join("s04-tampered/report.json"));
    assert_eq!(
        tampered["integrity"]["changed"],
        serde_json::json!(["exercises/01-tiny/tests/double.rs"])
    );
    let broken = read_json(&out.join("s05-broken/report.json"));
    assert!(
        topic(&broken, "01-tiny")["compile_error"]
            .as_str()
            .unwrap()
            .contains("exercises/01-tiny/src/ops.rs"),
        "{broken:#}"
    );
    // The slots' executables are gone once their tests ran.
    for slot in ["0", "1"] {
        assert!(
            !official
                .join("target/xtask/class")
                .join(slot)
                .join("bin")
                .exists(),
            "slot {slot} keeps its executables"
        );
    }
}

/// A checkout whose every text file ends its lines in `\r\n` (Windows'
/// git with `core.autocrlf`, where the course's `.gitattributes` was not
/// honoured) grades exactly like the same checkout with `\n`: the same
/// score, no grading file flagged.
#[test]
fn a_crlf_checkout_grades_like_an_lf_one() {
    let official = fixture("tiny", "crlf");
    let class = Path::new(env!("CARGO_TARGET_TMPDIR")).join("crlf-class");
    if class.exists() {
        fs::remove_dir_all(&class).unwrap();
    }
    let solved = fs::read_to_string(official.join("exercises/01-tiny/src/ops.rs"))
        .unwrap()
        .replace("todo!(\"double: return twice x\")", "x * 2");
    for name in ["crlf", "lf"] {
        let member = class.join(name);
        for dir in ["exercises", "crates"] {
            copy_dir(&official.join(dir), &member.join(dir));
        }
        fs::copy(official.join("Cargo.toml"), member.join("Cargo.toml")).unwrap();
        fs::write(member.join("exercises/01-tiny/src/ops.rs"), &solved).unwrap();
    }
    let mut stack = vec![class.join("crlf")];
    let mut converted = 0;
    while let Some(dir) = stack.pop() {
        for entry in fs::read_dir(&dir).unwrap().flatten() {
            let path = entry.path();
            if entry.file_type().unwrap().is_dir() {
                stack.push(path);
            } else if let Ok(text) = fs::read_to_string(&path) {
                fs::write(&path, text.replace('\n', "\r\n")).unwrap();
                converted += 1;
            }
        }
    }
    assert!(converted >= 6, "only {converted} files converted");
    let out = crate::common::fresh(official.join("target/crlf-class"));
    let output = grade_submission(&official, &class, &out, &[]);
    assert!(output.status.success(), "{output:?}");
    assert_eq!(
        fs::read_to_string(out.join("gradebook.csv")).unwrap(),
        "submission,score,max_score,bonus,complete,flagged,01-tiny,01-tiny/double,01-tiny/negate,not_graded\n\
         crlf,2,3,0,true,false,2,2,0,\n\
         lf,2,3,0,true,false,2,2,0,\n"
    );
}
