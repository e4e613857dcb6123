//! A class at scale, on the tiny fixture course: graded in shards and
//! merged, resumed, and one member graded again into the class.

mod common;

use std::fs;
use std::path::{Path, PathBuf};

use common::{fixture, fresh, grade_submission, stdout, xtask};

/// A generated class of six members of the tiny course.
fn class(official: &Path, name: &str) -> PathBuf {
    let class = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    if class.exists() {
        fs::remove_dir_all(&class).unwrap();
    }
    let output = xtask(official, &["class", class.to_str().unwrap(), "--size", "6"]);
    assert!(output.status.success(), "{output:?}");
    class
}

fn read(path: &Path) -> String {
    fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn two_shards_merged_give_the_gradebook_of_one_run() {
    let official = fixture("tiny", "shards");
    let class = class(&official, "tiny-shards-class");
    let target = official.join("target");
    let whole = fresh(target.join("whole"));
    let output = grade_submission(&official, &class, &whole, &[]);
    assert!(output.status.success(), "{output:?}");

    let mut parts = Vec::new();
    let mut sizes = Vec::new();
    for shard in ["1/2", "2/2"] {
        let part = fresh(target.join(format!("part-{}", &shard[..1])));
        let output = grade_submission(&official, &class, &part, &["--shard", shard]);
        assert!(output.status.success(), "{output:?}");
        let text = stdout(&output);
        let line = text
            .lines()
            .find(|l| l.starts_with(&format!("shard {shard}: ")))
            .unwrap_or_else(|| panic!("no shard line in {text}"));
        sizes.push(
            line.split_whitespace()
                .nth(2)
                .unwrap()
                .parse::<usize>()
                .unwrap(),
        );
        parts.push(part);
    }
    assert_eq!(
        sizes.iter().sum::<usize>(),
        6,
        "every member in one shard: {sizes:?}"
    );
    assert!(sizes.iter().all(|&n| n > 0), "{sizes:?}");

    let merged = fresh(target.join("merged"));
    let mut args = vec!["gradebook", "merge"];
    args.extend(parts.iter().map(|p| p.to_str().unwrap()));
    args.extend(["--out", merged.to_str().unwrap()]);
    let output = xtask(&official, &args);
    assert!(output.status.success(), "{output:?}");
    for file in [
        "gradebook.csv",
        "gradebook.json",
        "class.json",
        "class.html",
    ] {
        assert_eq!(read(&merged.join(file)), read(&whole.join(file)), "{file}");
    }
    assert!(merged.join("s03-partial/report.html").is_file());

    // A part given twice is refused: each member belongs to one shard.
    let output = xtask(
        &official,
        &[
            "gradebook",
            "merge",
            parts[0].to_str().unwrap(),
            parts[0].to_str().unwrap(),
            "--out",
            target.join("twice").to_str().unwrap(),
        ],
    );
    assert!(!output.status.success());
    assert!(
        String::from_utf8_lossy(&output.stderr).contains("is in two parts"),
        "{output:?}"
    );
}

/// A course's lock file also holds the packages only the course uses (its
/// benchmarks' peers, say): staging trims it to the edition's, and that is
/// no change a member's tests made.
fn lock_with_a_course_only_package(official: &Path) {
    let generated = std::process::Command::new(env!("CARGO"))
        .args(["generate-lockfile", "--offline"])
        .current_dir(official)
        .status()
        .unwrap();
    assert!(generated.success());
    let lock = official.join("Cargo.lock");
    let mut text = read(&lock);
    text.push_str("\n[[package]]\nname = \"course-only\"\nversion = \"0.1.0\"\n");
    fs::write(lock, text).unwrap();
}

#[test]
fn a_class_graded_again_keeps_unchanged_members_and_takes_one_member_back() {
    let official = fixture("tiny", "resume");
    lock_with_a_course_only_package(&official);
    let class = class(&official, "tiny-resume-class");
    let out = fresh(official.join("target/resume"));
    let output = grade_submission(&official, &class, &out, &[]);
    assert!(output.status.success(), "{output:?}");
    let gradebook = read(&out.join("gradebook.csv"));
    assert!(gradebook.contains("\ns02-faulty,0,3,"), "{gradebook}");
    assert!(
        gradebook.contains("\ns01-correct,3,3,0,true,false,"),
        "a correct member, not flagged: {gradebook}"
    );
    // One line a member, the details in its report.
    let text = stdout(&output);
    let line = text
        .lines()
        .find(|l| l.contains("s01-correct: "))
        .unwrap_or_else(|| panic!("no line for s01-correct in {text}"));
    assert!(
        line.contains("3 / 3 points") && line.contains("report.html"),
        "{line}"
    );

    // Graded again with nothing changed: every member kept, the same
    // gradebook.
    let output = grade_submission(&official, &class, &out, &[]);
    assert!(output.status.success(), "{output:?}");
    assert!(
        stdout(&output).contains("6 of 6 member(s) were graded before from the same files: kept"),
        "{output:?}"
    );
    assert_eq!(read(&out.join("gradebook.csv")), gradebook);

    // The faulty member hands in the solution: graded again alone into
    // the class's folder, its row in the class's gradebook follows.
    let faulty = class.join("s02-faulty/exercises/01-tiny/src/ops.rs");
    let solved = read(&class.join("s01-correct/exercises/01-tiny/src/ops.rs"));
    fs::write(&faulty, solved).unwrap();
    let output = grade_submission(&official, &class.join("s02-faulty"), &out, &[]);
    assert!(output.status.success(), "{output:?}");
    let updated = read(&out.join("gradebook.csv"));
    assert!(updated.contains("\ns02-faulty,3,3,"), "{updated}");
    assert_eq!(
        updated.replace(
            "\ns02-faulty,3,3,0,true,false,3,2,1,",
            "\ns02-faulty,0,3,0,true,false,0,0,0,"
        ),
        gradebook,
        "only its row changed"
    );

    // A class graded again now keeps all but none: the changed member was
    // graded from its new files already.
    let output = grade_submission(&official, &class, &out, &[]);
    assert!(output.status.success(), "{output:?}");
    assert!(stdout(&output).contains("6 of 6 member(s)"), "{output:?}");
    // A member whose files changed since is graded again.
    fs::write(
        &faulty,
        read(&official.join("exercises/01-tiny/src/ops.rs")),
    )
    .unwrap();
    let output = grade_submission(&official, &class, &out, &[]);
    assert!(output.status.success(), "{output:?}");
    assert!(stdout(&output).contains("5 of 6 member(s)"), "{output:?}");
    assert!(read(&out.join("gradebook.csv")).contains("\ns02-faulty,0,3,"));
}
