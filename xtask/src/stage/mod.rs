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
//! **Class slots.** A class graded in parallel (the staff's, see
//! `staff::class`) needs one stage per submission in flight
//! (`target/xtask/class/<slot>/stage`), all built into the one cache so
//! that the dependencies are built once. Sharing is
//! safe because the builds take turns, and because the build folder
//! remembers which stage it was last built from ([`BUILT_FROM`]): a stage
//! that was not the last has all its files touched before it builds, so
//! cargo rebuilds the course's crates from *its* files instead of taking
//! the other stage's artifacts for fresh.

use std::fs::{self, File};
use std::path::{Component, Path, PathBuf};

use anyhow::{Context, Result, bail};

use crate::edition::{Files, Source};
use crate::files::{files_under, plain_file};

mod build;
pub mod features;
pub mod replay;
mod sync;
#[cfg(test)]
mod tests;

pub use build::{claim_build, claim_checkout_build};
pub use sync::{claim, sync};
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
#[cfg(feature = "staff")]
#[must_use]
pub fn class_home(root: &Path, slot: usize) -> PathBuf {
    class_homes(root).join(slot.to_string())
}

/// The folder of every class slot's home (see [`class_home`]).
#[cfg(feature = "staff")]
#[must_use]
pub fn class_homes(root: &Path) -> PathBuf {
    home(root).join("class")
}

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
    /// The stubs with the given task files' texts laid over them, by the
    /// file's path in the course (the staff's do-nothing edition, which
    /// every task must score 0 with).
    #[cfg(feature = "staff")]
    Texts(&'a TaskTexts),
}

/// Task files' texts by their paths in the course (see [`Overlay::Texts`]).
#[cfg(feature = "staff")]
pub type TaskTexts = std::collections::BTreeMap<PathBuf, String>;

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
/// holds the stub of a task of its topic, as `cargo xtask stubs` writes it
/// ([`crate::stubs::holds_task_stub`]: decided by the course's markers,
/// never by a mention of `todo!()` in a given file's comments). These
/// alone are a student's in a submission.
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
        let topics = crate::topics::discover(root)?;
        for file in files_under(root)? {
            let stub = |file: &Path| {
                let topic = file.components().nth(1).map(|c| c.as_os_str());
                let ids: Vec<&str> = topics
                    .iter()
                    .filter(|t| Some(t.name.as_ref()) == topic)
                    .flat_map(|t| t.sheet.tasks.iter().map(|task| task.id.as_str()))
                    .collect();
                fs::read_to_string(root.join(file))
                    .is_ok_and(|text| crate::stubs::holds_task_stub(file, &text, &ids))
            };
            if is_student_file(&file) && stub(&file) {
                tasks.push(file);
            }
        }
    }
    tasks.sort();
    Ok(tasks)
}

/// The files of a stage of the course at `root`: (path in the stage,
/// file to copy), sorted by the former: the edition ([`edition_plan`]),
/// the replay packages of its replayed topics ([`replay`]) and the
/// features package ([`features`]).
pub fn plan(root: &Path, overlay: Overlay<'_>) -> Result<Files> {
    let mut files = edition_plan(root, overlay)?;
    replay::add_packages(root, &mut files)?;
    if root.join("exercises").is_dir() {
        features::add_package(&mut files)?;
    }
    files.sort();
    Ok(files)
}

/// The files of an edition of the course at `root`: (path in the stage,
/// file to copy), sorted by the former.
pub fn edition_plan(root: &Path, overlay: Overlay<'_>) -> Result<Files> {
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
        #[cfg(feature = "staff")]
        Overlay::Texts(texts) => {
            for (task_file, text) in texts {
                files.retain(|(to, _)| to != task_file);
                files.push((task_file.clone(), Source::Text(text.clone().into_bytes())));
            }
        }
        Overlay::Submission(submission) => {
            let topics = crate::topics::discover(root)?;
            let (edition, _) = crate::edition::edition_files(root, &topics)?;
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
    lean_debug_info(&mut files)?;
    files.sort();
    Ok(files)
}

/// cargo's configuration file of a workspace.
const CONFIG: &str = ".cargo/config.toml";

/// Sets the stage's `.cargo/config.toml` (the course's, or a new one) to
/// build the course's own crates with line tables only instead of full
/// debug information. A stage's build is the tooling's, which no debugger
/// reads: its tests still report panics with files and lines, and its build
/// folder is less than half the size, since every test program carries the
/// debug information of what it links. The dependencies already have none
/// (the workspace's `profile.dev.package."*"`, which this leaves alone).
fn lean_debug_info(files: &mut Files) -> Result<()> {
    let position = files.iter().position(|(to, _)| to == Path::new(CONFIG));
    let mut config: toml::Table = match position {
        Some(index) => {
            let text = String::from_utf8(files[index].1.read()?)
                .with_context(|| format!("{CONFIG} is not UTF-8"))?;
            toml::from_str(&text).with_context(|| format!("cannot parse {CONFIG}"))?
        }
        None => toml::Table::new(),
    };
    let not_a_table = |name: &str| format!("`{name}` in {CONFIG} is not a table");
    let dev = config
        .entry("profile")
        .or_insert_with(|| toml::Table::new().into())
        .as_table_mut()
        .with_context(|| not_a_table("profile"))?
        .entry("dev")
        .or_insert_with(|| toml::Table::new().into())
        .as_table_mut()
        .with_context(|| not_a_table("profile.dev"))?;
    dev.insert("debug".to_owned(), "line-tables-only".into());
    let text = toml::to_string(&config).with_context(|| format!("cannot write {CONFIG}"))?;
    let source = Source::Text(text.into_bytes());
    match position {
        Some(index) => files[index].1 = source,
        None => files.push((PathBuf::from(CONFIG), source)),
    }
    Ok(())
}

/// The lock file of a workspace.
const LOCK_FILE: &str = "Cargo.lock";

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
#[cfg(feature = "staff")]
pub fn lock(root: &Path) -> Result<File> {
    lock_stage(&home(root))
}

/// The stage in `home` holding `files`, built into `target_dir`: a class
/// slot (see [`class_home`]). The caller makes the slots' syncs and
/// builds take turns.
#[cfg(feature = "staff")]
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
    let files = &replay::with_graded_data(files);
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
        crate::edition::trim_lock_file(&stage_root)?;
    }
    let target_dir = target_dir.map_or_else(|| home.join("build"), Path::to_path_buf);
    claim_build(&stage_root, &target_dir)?;
    Ok(Stage {
        root: stage_root,
        target_dir,
        _lock: lock,
    })
}

/// `dir` made absolute, if it lies outside the course at `root` (or in its
/// build output): a folder inside would be copied into itself.
#[cfg(feature = "staff")]
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
#[cfg(feature = "staff")]
pub fn write_reference(root: &Path, dir: &Path) -> Result<()> {
    let dir = outside_course(root, dir)?;
    let files = edition_plan(root, Overlay::Reference)?;
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
