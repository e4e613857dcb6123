//! The stage's tests: staging, syncing and claiming build folders.

use super::*;

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("xtask-stage-{name}-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    dir
}

fn write(path: &Path, text: &str) {
    fs::create_dir_all(path.parent().unwrap()).unwrap();
    fs::write(path, text).unwrap();
}

#[test]
fn a_checkout_built_after_another_copy_has_its_tested_files_touched() {
    let dir = scratch("claim-checkout");
    let (a, b, target) = (dir.join("a"), dir.join("b"), dir.join("shared-target"));
    let files = [
        "crates/c/src/lib.rs",
        "exercises/e/src/lib.rs",
        "xtask/src/main.rs",
    ];
    let old = std::time::SystemTime::UNIX_EPOCH + std::time::Duration::from_secs(1_000_000);
    for checkout in [&a, &b] {
        for file in files {
            write(&checkout.join(file), "pub fn f() {}\n");
            File::options()
                .write(true)
                .open(checkout.join(file))
                .unwrap()
                .set_modified(old)
                .unwrap();
        }
    }
    let touched = |checkout: &Path| -> Vec<bool> {
        files
            .iter()
            .map(|file| {
                fs::metadata(checkout.join(file))
                    .unwrap()
                    .modified()
                    .unwrap()
                    > old
            })
            .collect()
    };
    // A fresh build folder: nothing was built there, nothing to touch.
    claim_checkout_build(&a, &target).unwrap();
    assert_eq!(touched(&a), [false, false, false]);
    fs::create_dir_all(target.join("debug")).unwrap();
    // Another copy graded with the same build folder: its crates and
    // exercises are touched, its tooling is not.
    claim_checkout_build(&b, &target).unwrap();
    assert_eq!(touched(&b), [true, true, false]);
    fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_stage_built_after_another_has_its_files_touched() {
    let dir = scratch("claim-build");
    let (a, b, target) = (dir.join("a"), dir.join("b"), dir.join("build"));
    for stage in [&a, &b] {
        write(&stage.join("src/lib.rs"), "pub fn f() {}\n");
    }
    fs::create_dir_all(target.join("debug")).unwrap();
    let old = std::time::SystemTime::UNIX_EPOCH + std::time::Duration::from_secs(1_000_000);
    let age = |stage: &Path| {
        fs::metadata(stage.join("src/lib.rs"))
            .unwrap()
            .modified()
            .unwrap()
    };
    let make_old = |stage: &Path| {
        File::options()
            .write(true)
            .open(stage.join("src/lib.rs"))
            .unwrap()
            .set_modified(old)
            .unwrap();
    };
    make_old(&a);
    make_old(&b);
    // A build folder of unknown history: its stage is touched.
    claim_build(&a, &target).unwrap();
    assert!(age(&a) > old);
    // The same stage again: nothing to touch.
    make_old(&a);
    claim_build(&a, &target).unwrap();
    assert_eq!(age(&a), old);
    // Another stage, then the first again: each is touched.
    claim_build(&b, &target).unwrap();
    assert!(age(&b) > old);
    claim_build(&a, &target).unwrap();
    assert!(age(&a) > old);
    assert_eq!(
        fs::read_to_string(target.join(BUILT_FROM)).unwrap(),
        a.to_string_lossy()
    );
    fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn student_files_are_those_under_an_exercise_src() {
    assert!(is_student_file(Path::new("exercises/01-lines/src/dda.rs")));
    assert!(is_student_file(Path::new(
        "exercises/01-lines/src/sub/x.rs"
    )));
    assert!(!is_student_file(Path::new(
        "exercises/01-lines/tests/dda.rs"
    )));
    assert!(!is_student_file(Path::new("exercises/src/x.rs")));
}

#[test]
fn the_reference_overlay_replaces_only_solution_files() {
    let course = scratch("course");
    write(&course.join("Cargo.toml"), "[workspace]");
    write(
        &course.join("exercises/01-a/src/lib.rs"),
        "pub mod x; pub mod given;",
    );
    write(&course.join("exercises/01-a/src/x.rs"), "stub");
    write(&course.join("exercises/01-a/src/given.rs"), "given");
    write(&course.join("reference/01-a/src/x.rs"), "solution");
    write(&course.join("target/debug/junk"), "junk");
    let files = plan(&course, Overlay::Reference).unwrap();
    let staged: Vec<(String, String)> = files
        .iter()
        .map(|(to, from)| {
            let text = String::from_utf8(from.read().unwrap()).unwrap();
            // `/` between the parts on every system (Windows shows `\`).
            let parts: Vec<_> = to.iter().map(|p| p.to_string_lossy()).collect();
            (parts.join("/"), text)
        })
        .collect();
    assert_eq!(
        staged,
        [
            (
                ".cargo/config.toml",
                "[profile.dev]\ndebug = \"line-tables-only\"\n"
            ),
            ("Cargo.toml", "[workspace]"),
            ("exercises/01-a/src/given.rs", "given"),
            ("exercises/01-a/src/lib.rs", "pub mod x; pub mod given;"),
            ("exercises/01-a/src/x.rs", "solution"),
        ]
        .map(|(a, b)| (a.to_owned(), b.to_owned()))
    );
    assert!(plan(&course.join("exercises"), Overlay::Reference).is_err());
    fs::remove_dir_all(&course).unwrap();
}

#[test]
fn a_stage_builds_the_course_with_line_tables_and_keeps_its_cargo_configuration() {
    let course = scratch("config");
    write(&course.join("Cargo.toml"), "[workspace]");
    write(
        &course.join(".cargo/config.toml"),
        "[alias]\nxtask = \"run --package xtask --\"\n\n[profile.dev]\nopt-level = 1\n",
    );
    let files = plan(&course, Overlay::Own).unwrap();
    let (_, config) = files
        .iter()
        .find(|(to, _)| to == Path::new(".cargo/config.toml"))
        .unwrap();
    let config: toml::Table =
        toml::from_str(&String::from_utf8(config.read().unwrap()).unwrap()).unwrap();
    assert_eq!(
        config["alias"]["xtask"].as_str(),
        Some("run --package xtask --")
    );
    assert_eq!(config["profile"]["dev"]["opt-level"].as_integer(), Some(1));
    assert_eq!(
        config["profile"]["dev"]["debug"].as_str(),
        Some("line-tables-only")
    );
    // The course's own file is left as it is.
    assert!(
        !fs::read_to_string(course.join(".cargo/config.toml"))
            .unwrap()
            .contains("debug")
    );
    // A `profile` that is not a table is an error, not a silent default.
    write(&course.join(".cargo/config.toml"), "profile = 1\n");
    assert!(plan(&course, Overlay::Own).is_err());
    fs::remove_dir_all(&course).unwrap();
}

#[test]
fn sync_writes_changes_only_and_removes_what_is_gone() {
    let from = scratch("from");
    let dest = scratch("dest");
    write(&from.join("a.rs"), "a");
    write(&from.join("b/c.rs"), "c");
    let files = vec![
        (PathBuf::from("a.rs"), Source::File(from.join("a.rs"))),
        (PathBuf::from("b/c.rs"), Source::File(from.join("b/c.rs"))),
    ];
    assert_eq!(sync(&files, &dest).unwrap(), (2, vec![]));
    let before = fs::metadata(dest.join("a.rs")).unwrap().modified().unwrap();
    write(&dest.join("old/gone.rs"), "gone");
    write(&dest.join("target/kept"), "build output");
    assert_eq!(
        sync(&files, &dest).unwrap(),
        (0, vec![PathBuf::from("old/gone.rs")])
    );
    let after = fs::metadata(dest.join("a.rs")).unwrap().modified().unwrap();
    assert_eq!(before, after, "an unchanged file keeps its time");
    assert!(!dest.join("old").exists(), "emptied folders are removed");
    assert!(dest.join("target/kept").exists(), "build output is kept");
    write(&from.join("a.rs"), "a2");
    assert_eq!(sync(&files, &dest).unwrap(), (1, vec![]));
    assert_eq!(fs::read_to_string(dest.join("a.rs")).unwrap(), "a2");
    fs::remove_dir_all(&from).unwrap();
    fs::remove_dir_all(&dest).unwrap();
}

#[test]
fn a_folder_not_written_by_xtask_is_never_claimed() {
    let dir = scratch("claim");
    write(&dir.join("notes.txt"), "mine");
    let error = claim(&dir).unwrap_err().to_string();
    assert!(
        error.contains("was not written by `cargo xtask`"),
        "{error}"
    );
    assert!(dir.join("notes.txt").exists());
    fs::remove_file(dir.join("notes.txt")).unwrap();
    claim(&dir).unwrap();
    write(&dir.join("notes.txt"), "ours now");
    claim(&dir).unwrap();
    fs::remove_dir_all(&dir).unwrap();
}
