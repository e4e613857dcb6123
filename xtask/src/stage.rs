//! Stages: a copy of the course in which other code is laid over the
//! student files, so that one test suite meets three kinds of code.
//!
//! ```text
//!   course (no target/, .git/, reference/) ──┐
//!   reference/*/src  or  a submission's      ├──sync──> target/xtask/stage ──cargo──> target/xtask/build
//!   exercises/*/src  over exercises/*/src ───┘
//! ```
//!
//! Grading the reference, the course's own tests, the benchmarks and the
//! grading of submissions all build a stage; a student's own `cargo test`
//! and `cargo xtask grade` build the checkout itself. Nothing decides
//! which code is compiled but which files are staged: no Cargo feature,
//! no `#[path]` switch.
//!
//! **One stage, one build cache.** Every staged edition is synced into the
//! same folder, `target/xtask/stage`, and built into `target/xtask/build`.
//! Syncing writes a file only when its contents differ and deletes what
//! the edition lacks, so switching from the reference to a submission
//! rebuilds just the crates whose files changed. It has to be one folder:
//! cargo names a workspace's artifacts by their paths *relative* to the
//! workspace root and trusts modification times, so two stages at
//! different paths sharing one target folder could each take the other's
//! artifacts for their own. For the same reason the build folder lies
//! beside the stage, not around it, and apart from the checkout's own
//! `target/debug`. A lock file keeps two `cargo xtask` runs from syncing
//! the stage at once.
//!
//! **Class slots.** A class graded in parallel needs one stage per
//! submission in flight (`target/xtask/class/<slot>/stage`), all built
//! into the one cache so that the dependencies are built once. Sharing is
//! safe because the builds take turns, and because the build folder
//! remembers which stage it was last built from ([`BUILT_FROM`]): a stage
//! that was not the last has all its files touched before it builds, so
//! cargo rebuilds the course's crates from *its* files instead of taking
//! the other stage's artifacts for fresh.

use std::fs::{self, File};
use std::path::{Component, Path, PathBuf};

use anyhow::{Context, Result, bail};

use crate::files::{files_under, plain_file, write_file};

/// Where the stage and its build cache live, under the checkout.
const STAGE_HOME: [&str; 2] = ["target", "xtask"];

/// A file written into a folder that a sync may later empty: its presence
/// says the folder is the tooling's to rewrite.
pub const STAGE_MARKER: &str = ".course-stage";

/// A file in a build folder naming the stage it was last built from (see
/// [`claim_build`]).
pub const BUILT_FROM: &str = ".course-stage-built-from";

/// Where class slot `slot` of the checkout at `root` keeps its stage
/// (`<home>/stage`) and the test executables of the submission it grades
/// (`<home>/bin`).
#[must_use]
pub fn class_home(root: &Path, slot: usize) -> PathBuf {
    home(root).join("class").join(slot.to_string())
}

/// Where a staged file's contents come from.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub enum Source {
    /// A file to copy.
    File(PathBuf),
    /// Contents made by the tooling (a rewritten manifest).
    Text(Vec<u8>),
}

impl Source {
    /// The contents.
    pub fn read(&self) -> Result<Vec<u8>> {
        match self {
            Source::File(path) => {
                fs::read(path).with_context(|| format!("cannot read {}", path.display()))
            }
            Source::Text(text) => Ok(text.clone()),
        }
    }
}

/// The files of a tree: (path in it, contents), sorted by path.
pub type Files = Vec<(PathBuf, Source)>;

/// A synced stage, locked for as long as this value lives.
#[derive(Debug)]
pub struct Stage {
    /// The staged course: a cargo workspace.
    pub root: PathBuf,
    /// cargo's `--target-dir` for it.
    pub target_dir: PathBuf,
    _lock: File,
}

impl Stage {
    /// `cargo`, run in the stage and built into its cache.
    #[must_use]
    pub fn cargo(&self) -> std::process::Command {
        let mut command = crate::cargo::cargo();
        command
            .current_dir(&self.root)
            .env("CARGO_TARGET_DIR", &self.target_dir);
        command
    }
}

/// What a stage holds in `exercises/*/src`.
#[derive(Debug, Clone, Copy)]
pub enum Overlay<'a> {
    /// The checkout's own student files (the stubs, in the course repository).
    Own,
    /// `reference/*/src` laid over the student files.
    Reference,
    /// Another checkout's task files (see [`task_files`]) laid over the
    /// stubs of the student edition of every topic (`cargo xtask
    /// release`): no solutions, no history, nothing of the course's
    /// tooling tests or benchmarks; everything else, `lib.rs` and given
    /// code included, stays the course's. A task file the submission
    /// lacks, or reaches through a symbolic link ([`plain_file`]), keeps
    /// its stub.
    Submission(&'a Path),
    /// The stubs with each `todo!()` replaced by the cheapest body that
    /// compiles (see `stubs::do_nothing`), except on the lines listed per
    /// task file: the edition every task must score 0 with.
    DoNothing(&'a DoNothingKeep),
}

/// Lines (1-based) of task files whose `todo!()` the do-nothing edition
/// keeps, by the file's path in the course.
pub type DoNothingKeep = std::collections::BTreeMap<PathBuf, Vec<usize>>;

/// Whether a path (relative to a course root) is a student's: inside
/// `exercises/<topic>/src/`.
#[must_use]
pub fn is_student_file(relative: &Path) -> bool {
    let parts: Vec<Component<'_>> = relative.components().collect();
    parts.len() >= 3 && parts[0].as_os_str() == "exercises" && parts[2].as_os_str() == "src"
}

/// The task files of the course at `root` (paths relative to it): the
/// files of `exercises/*/src` that hold a task, i.e. those with a solution
/// in `reference/`; in an edition without `reference/`, those whose stub
/// holds a `todo!`, and every `.wgsl` file (WGSL there is always the
/// student's: given WGSL lives in Rust). These alone are a student's in a
/// submission.
pub fn task_files(root: &Path) -> Result<Vec<PathBuf>> {
    let reference = root.join("reference");
    let mut tasks = Vec::new();
    if reference.is_dir() {
        for file in files_under(&reference)? {
            let staged = Path::new("exercises").join(&file);
            if is_student_file(&staged) {
                tasks.push(staged);
            }
        }
    } else {
        for file in files_under(root)? {
            let stub = |file: &Path| {
                crate::files::is_wgsl(file)
                    || fs::read_to_string(root.join(file)).is_ok_and(|text| text.contains("todo!("))
            };
            if is_student_file(&file) && stub(&file) {
                tasks.push(file);
            }
        }
    }
    tasks.sort();
    Ok(tasks)
}

/// The files of an edition of the course at `root`: (path in the stage,
/// file to copy), sorted by the former.
pub fn plan(root: &Path, overlay: Overlay<'_>) -> Result<Files> {
    let mut files: Files = files_under(root)?
        .into_iter()
        .map(|file| (file.clone(), Source::File(root.join(file))))
        .collect();
    match overlay {
        Overlay::Own => {}
        Overlay::Reference => {
            let reference = root.join("reference");
            if !reference.is_dir() {
                bail!(
                    "{} does not exist: this is a student edition, which has no solutions",
                    reference.display()
                );
            }
            for file in files_under(&reference)? {
                // reference/<topic>/src/<file> → exercises/<topic>/src/<file>
                let staged = Path::new("exercises").join(&file);
                if is_student_file(&staged) {
                    let source = reference.join(&file);
                    files.retain(|(to, _)| *to != staged);
                    files.push((staged, Source::File(source)));
                }
            }
        }
        Overlay::DoNothing(keep) => {
            for task_file in task_files(root)? {
                let path = root.join(&task_file);
                let stub = fs::read_to_string(&path)
                    .with_context(|| format!("cannot read {}", path.display()))?;
                let lines = keep.get(&task_file).map_or(&[][..], Vec::as_slice);
                let (text, _) = crate::stubs::do_nothing(&stub, lines);
                files.retain(|(to, _)| *to != task_file);
                files.push((task_file, Source::Text(text.into_bytes())));
            }
        }
        Overlay::Submission(submission) => {
            let topics = crate::topics::discover(root)?;
            let (edition, _) = crate::release::edition_files(root, &topics)?;
            files = edition;
            // The course's lock file, trimmed to the edition's packages by
            // cargo when it is staged (see `stage_files`).
            if root.join(LOCK_FILE).is_file() {
                files.push((PathBuf::from(LOCK_FILE), Source::File(root.join(LOCK_FILE))));
            }
            for task_file in task_files(root)? {
                // A plain file only, reached through folders only: a link
                // could point anywhere.
                if plain_file(submission, &task_file).is_ok() {
                    files.retain(|(to, _)| *to != task_file);
                    files.push((task_file.clone(), Source::File(submission.join(task_file))));
                }
            }
        }
    }
    files.sort();
    Ok(files)
}

/// The lock file of a workspace.
const LOCK_FILE: &str = "Cargo.lock";

/// Makes `dest` hold exactly `files` (besides [`crate::files::SKIPPED_FOLDERS`] and the
/// [`STAGE_MARKER`]): writes a file only when its contents differ, removes
/// the others and the folders they leave empty. Returns how many files
/// were written, and the files removed.
pub fn sync(files: &[(PathBuf, Source)], dest: &Path) -> Result<(usize, Vec<PathBuf>)> {
    fs::create_dir_all(dest).with_context(|| format!("cannot create {}", dest.display()))?;
    let mut written = 0;
    for (to, from) in files {
        let contents = from.read()?;
        let target = dest.join(to);
        if fs::read(&target).is_ok_and(|old| old == contents) {
            continue;
        }
        write_file(&target, &contents)?;
        written += 1;
    }
    let mut removed = Vec::new();
    let wanted: std::collections::HashSet<&Path> =
        files.iter().map(|(to, _)| to.as_path()).collect();
    for file in files_under(dest)? {
        if !wanted.contains(file.as_path()) && file != Path::new(STAGE_MARKER) {
            let path = dest.join(&file);
            fs::remove_file(&path).with_context(|| format!("cannot remove {}", path.display()))?;
            removed.push(file.clone());
            // Folders left empty go too (`remove_dir` refuses non-empty ones).
            let mut parent = path.parent();
            while let Some(dir) = parent.filter(|dir| *dir != dest) {
                if fs::remove_dir(dir).is_err() {
                    break;
                }
                parent = dir.parent();
            }
        }
    }
    Ok((written, removed))
}

/// Refuses to sync into `dir` unless it is empty, missing, or marked as
/// written by this tooling; then marks it.
pub fn claim(dir: &Path) -> Result<()> {
    if dir.exists() {
        let mut entries =
            fs::read_dir(dir).with_context(|| format!("cannot read {}", dir.display()))?;
        let empty = entries.next().is_none();
        if !empty && !dir.join(STAGE_MARKER).is_file() {
            bail!(
                "{} exists and was not written by `cargo xtask`; choose a new or empty folder",
                dir.display()
            );
        }
    }
    fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    fs::write(
        dir.join(STAGE_MARKER),
        "Written by `cargo xtask`: files here are replaced on the next run.\n",
    )
    .with_context(|| format!("cannot write in {}", dir.display()))
}

/// `<root>/target/xtask`: where the checkout at `root` keeps its stage.
#[must_use]
pub fn home(root: &Path) -> PathBuf {
    STAGE_HOME
        .iter()
        .fold(root.to_path_buf(), |p, part| p.join(part))
}

/// Syncs the stage of the checkout at `root` to hold `overlay` and locks
/// it. `target_dir` overrides where it is built.
pub fn stage(root: &Path, overlay: Overlay<'_>, target_dir: Option<&Path>) -> Result<Stage> {
    stage_in(&home(root), root, overlay, target_dir)
}

/// [`stage`] with the stage kept in `home` (`home/stage`, built in
/// `home/build`) rather than in `root`'s own.
pub fn stage_in(
    home: &Path,
    root: &Path,
    overlay: Overlay<'_>,
    target_dir: Option<&Path>,
) -> Result<Stage> {
    let lock = lock_stage(home)?;
    let files = plan(root, overlay)?;
    stage_files(home, &files, target_dir, lock)
}

/// The stage of the checkout at `root` holding `files` (a plan made by
/// [`plan`] and then changed), locked.
pub fn stage_plan(root: &Path, files: &Files, target_dir: Option<&Path>) -> Result<Stage> {
    let home = home(root);
    let lock = lock_stage(&home)?;
    stage_files(&home, files, target_dir, lock)
}

/// Takes the lock of the stage of the checkout at `root`, waiting for
/// another run: a class run holds it throughout, since its slots build
/// into the same cache.
pub fn lock(root: &Path) -> Result<File> {
    lock_stage(&home(root))
}

/// The stage in `home` holding `files`, built into `target_dir`: a class
/// slot (see [`class_home`]). The caller makes the slots' syncs and
/// builds take turns.
pub fn stage_slot(home: &Path, files: &Files, target_dir: &Path) -> Result<Stage> {
    let lock = lock_stage(home)?;
    stage_files(home, files, Some(target_dir), lock)
}

/// Takes the lock of the stage in `home`, waiting for another run.
fn lock_stage(home: &Path) -> Result<File> {
    fs::create_dir_all(home).with_context(|| format!("cannot create {}", home.display()))?;
    let lock_path = home.join("stage.lock");
    let lock = File::create(&lock_path)
        .with_context(|| format!("cannot create {}", lock_path.display()))?;
    if lock.try_lock().is_err() {
        eprintln!("waiting for another `cargo xtask` to finish with the stage ...");
        lock.lock()
            .with_context(|| format!("cannot lock {}", lock_path.display()))?;
    }
    Ok(lock)
}

/// Syncs the stage in `home` to hold `files`, already locked by `lock`.
fn stage_files(home: &Path, files: &Files, target_dir: Option<&Path>, lock: File) -> Result<Stage> {
    let stage_root = home.join("stage");
    claim(&stage_root)?;
    // When a manifest or the lock file changes, cargo trims the lock to
    // the stage's packages here (no student file takes part in resolving
    // them), so that the build, which cannot write the stage, finds it
    // current. Sync keeps the one cargo wrote for a course that has none.
    let mut relock = false;
    for (to, source) in files {
        let name = to.file_name().and_then(|n| n.to_str());
        if matches!(name, Some("Cargo.toml" | LOCK_FILE)) {
            relock |= fs::read(stage_root.join(to)).ok() != Some(source.read()?);
        }
    }
    sync(files, &stage_root)?;
    // A course without a lock file gets one here, where cargo may write.
    let relock = relock || !stage_root.join(LOCK_FILE).exists();
    if relock {
        crate::release::trim_lock_file(&stage_root)?;
    }
    let target_dir = target_dir.map_or_else(|| home.join("build"), Path::to_path_buf);
    claim_build(&stage_root, &target_dir)?;
    Ok(Stage {
        root: stage_root,
        target_dir,
        _lock: lock,
    })
}

/// Makes the build folder `target_dir` build the stage at `stage_root`:
/// when another stage was built there last (cargo would take that stage's
/// artifacts for this one's, see the module's documentation), every file
/// of this stage is touched, so that cargo rebuilds whatever they make.
pub fn claim_build(stage_root: &Path, target_dir: &Path) -> Result<()> {
    claim_files(stage_root, &[], target_dir)
}

/// The folders of a checkout that the test executables are built from.
const TESTED_FOLDERS: [&str; 2] = ["crates", "exercises"];

/// [`claim_build`] for a checkout graded in place (`cargo xtask grade`),
/// whose build folder may have built another copy of the course last (a
/// `CARGO_TARGET_DIR` shared between checkouts): then cargo would run that
/// copy's tests. Only the files the tests are built from are touched
/// (`crates/` and `exercises/`), so the tooling is not rebuilt.
pub fn claim_checkout_build(root: &Path, target_dir: &Path) -> Result<()> {
    claim_files(root, &TESTED_FOLDERS, target_dir)
}

/// [`claim_build`] touching only the files under `folders` of
/// `stage_root` (all of them for none).
fn claim_files(stage_root: &Path, folders: &[&str], target_dir: &Path) -> Result<()> {
    let record = target_dir.join(BUILT_FROM);
    let ours = stage_root.to_string_lossy().into_owned();
    if fs::read_to_string(&record).is_ok_and(|last| last == ours) {
        return Ok(());
    }
    if record.exists() || target_dir.join("debug").exists() {
        let now = std::time::SystemTime::now();
        let touched = files_under(stage_root)?.into_iter().filter(|file| {
            folders.is_empty() || folders.iter().any(|folder| file.starts_with(folder))
        });
        for file in touched {
            let path = stage_root.join(file);
            File::options()
                .write(true)
                .open(&path)
                .and_then(|f| f.set_modified(now))
                .with_context(|| format!("cannot touch {}", path.display()))?;
        }
    }
    write_file(&record, ours)
}

/// `dir` made absolute, if it lies outside the course at `root` (or in its
/// build output): a folder inside would be copied into itself.
pub fn outside_course(root: &Path, dir: &Path) -> Result<PathBuf> {
    let dir = std::path::absolute(dir).with_context(|| format!("cannot find {}", dir.display()))?;
    if dir.starts_with(root) && !dir.starts_with(root.join("target")) {
        bail!(
            "{} lies inside the course; choose a folder outside it",
            dir.display()
        );
    }
    Ok(dir)
}

/// `cargo xtask stage --reference DIR`: the solution workspace, written
/// to `DIR` for a tutor's editor (a folder of its own, with its own build).
pub fn write_reference(root: &Path, dir: &Path) -> Result<()> {
    let dir = outside_course(root, dir)?;
    let files = plan(root, Overlay::Reference)?;
    claim(&dir)?;
    let (written, removed) = sync(&files, &dir)?;
    println!(
        "wrote the solution workspace to {} ({written} file(s) written, {} removed)",
        dir.display(),
        removed.len()
    );
    println!("open it in your editor; `cargo test` there runs the official tests on the solutions");
    Ok(())
}

#[cfg(test)]
mod tests {
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
}
