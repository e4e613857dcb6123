//! `cargo xtask grade --submission DIR`: grading a student's checkout
//! with the course's official tests.
//!
//! Only the task files belong to the student: the files of
//! `exercises/*/src/` the official course names as tasks (see
//! `stage::task_files`), each read once through a handle that follows no
//! link ([`take_task_files`]). Everything else that takes part in
//! grading — the given code beside them, the course library (`crates/`),
//! the tests and snapshots, the task sheets (they hold the points), the
//! manifests, the tooling — is the course's. So a submission is never
//! built where it lies: its task files are laid over a copy of the
//! official course, the *stage* (see `stage`, which also stages the
//! reference), and the stage is graded.
//!
//! ```text
//!   official course ──(no target/, .git/, reference/)──┐
//!                                                      ├──sync──> stage ──grade──> report
//!   submission ──its task files only, read once────────┘
//! ```
//!
//! The grading files of the submission are compared with the official ones
//! first; a submission where any differ, are missing or were added is
//! *flagged* in every report (the table, `report.html`, `report.json`,
//! Gradescope's output). Nothing in the submission is ever written to.
//!
//! A submission is graded into `<out>/<name>/` (its folder's name); the
//! snapshots it failed are in `<out>/<name>/snapshots/` (insta's
//! `.snap.new` files, at their paths in the course). It is graded in the
//! course's stage ([`grade_one`]). A folder of checkouts, a class, is the
//! staff's to grade, with the course repository's tools (`staff::class`,
//! which grades each member with `grade_in_slot`, in a stage of its own
//! beside the others); an edition's grader refuses it and says so.

use std::fs;
use std::path::{Path, PathBuf};
#[cfg(feature = "staff")]
use std::sync::{Arc, Mutex};

use anyhow::{Context, Result, bail};

#[cfg(feature = "staff")]
use super::Permits;
use super::adjustments::Adjustments;
use super::report::{Edition, Report};
use super::{GradeOptions, table};
use crate::edition::{Files, Source};
use crate::stage::{self, Overlay};
use crate::topics;

mod integrity;
pub(crate) mod nofollow;
mod tampering;

use integrity::is_grading_file;
pub use integrity::{Integrity, check};
use tampering::{contents_of, tampered};

/// Whether `dir` looks like a course checkout.
pub(crate) fn is_checkout(dir: &Path) -> bool {
    // A link among a class's members is no member: it could name another.
    let linked = fs::symlink_metadata(dir).is_ok_and(|m| m.file_type().is_symlink());
    !linked && dir.join("exercises").is_dir() && dir.join("Cargo.toml").is_file()
}

/// A class slot: where one submission of a class is staged and its tests
/// run from, beside the other slots (the staff's class).
#[cfg(feature = "staff")]
pub(crate) struct Slot<'a> {
    /// The slot's folder (see `stage::class_home`).
    pub(crate) home: PathBuf,
    /// The one build cache of all slots.
    pub(crate) target_dir: PathBuf,
    /// Held while a slot syncs its stage and builds.
    pub(crate) turn: &'a Mutex<()>,
    /// The tests that may run at once, in all slots.
    pub(crate) permits: Arc<Permits>,
}

/// Grades one submission against the official course at `official` in
/// the course's stage: compare, stage, grade the stage into
/// `options.out`, keep its failed snapshots. The report files carry the
/// submission's path and its integrity.
pub(crate) fn grade_one(
    official: &Path,
    submission: &Path,
    options: &GradeOptions,
) -> Result<Report> {
    let intake = Intake::take(official, submission, options)?;
    let target_dir = options
        .target_dir
        .clone()
        .unwrap_or_else(|| submissions_build(official));
    let staged = stage::stage_plan(official, &intake.files, Some(&target_dir))?;
    let events = super::Terminal::new(options.progress);
    let prepared = super::flow::prepare(
        &intake.in_stage(&staged),
        Edition::Student,
        intake.setting(),
        &events,
    )?;
    intake.graded(official, &staged, prepared, &events)
}

/// [`grade_one`] in a class's `slot` instead of the course's stage: the
/// slot's stage synced and built in its turn, its tests run from the
/// slot's `bin/` as the slot's permits allow, without progress bars.
#[cfg(feature = "staff")]
pub(crate) fn grade_in_slot(
    official: &Path,
    submission: &Path,
    options: &GradeOptions,
    slot: &Slot<'_>,
) -> Result<Report> {
    let intake = Intake::take(official, submission, options)?;
    let (staged, prepared) = {
        let _turn = slot.turn.lock().expect("no slot panics while building");
        let staged = stage::stage_slot(&slot.home, &intake.files, &slot.target_dir)?;
        let mut in_stage = intake.in_stage(&staged);
        in_stage.progress = false;
        let setting = super::Setting {
            beside: Some(super::Beside {
                keep_binaries: slot.home.join("bin"),
                permits: Arc::clone(&slot.permits),
            }),
            ..intake.setting()
        };
        let prepared = super::flow::prepare(&in_stage, Edition::Student, setting, &super::Silent)?;
        (staged, prepared)
    };
    intake.graded(official, &staged, prepared, &super::Silent)
}

/// A submission compared with the official course and its task files
/// taken, ready to stage: the first part of [`grade_one`].
struct Intake {
    submission: PathBuf,
    /// The options of its grade: every topic of the assignment where
    /// none was chosen.
    options: GradeOptions,
    /// The topics of the assignment it lacks.
    absent: Vec<String>,
    integrity: Integrity,
    /// The files of its stage (see [`staged_files`]).
    files: Files,
    refused: Vec<(String, Vec<String>)>,
    unreadable: Vec<(String, String)>,
    /// The official course's files before the grade, to find what its
    /// tests changed (see `tampering`).
    course_before: Vec<(PathBuf, Vec<u8>)>,
    /// What the stage holds before the grade, likewise.
    planned: Vec<(PathBuf, Vec<u8>)>,
}

impl Intake {
    fn take(official: &Path, submission: &Path, options: &GradeOptions) -> Result<Self> {
        let integrity = check(official, submission)?;
        let mut options = options.clone();
        // The assignment is the official course's topics, whatever the
        // submission holds: a topic it lacks scores 0, with the reason.
        let all_topics = topics::discover(official)?;
        if options.topics.is_empty() {
            options.topics = all_topics.iter().map(|t| t.name.clone()).collect();
        }
        // A topic it lacks is neither built nor run: the course's stubs of
        // it would only fail, at the cost of a build and a `todo!()` per
        // test.
        let absent = all_topics
            .iter()
            .filter(|topic| !submission.join("exercises").join(&topic.name).is_dir())
            .map(|topic| topic.name.clone())
            .collect();
        let (files, taken) = staged_files(official, submission)?;
        let course_before = contents_of(official)?;
        let planned: Vec<(PathBuf, Vec<u8>)> = files
            .iter()
            .map(|(to, from)| Ok((to.clone(), from.read()?)))
            .collect::<Result<_>>()?;
        Ok(Self {
            submission: submission.to_path_buf(),
            options,
            absent,
            integrity,
            files,
            refused: taken.refused,
            unreadable: taken.unreadable,
            course_before,
            planned,
        })
    }

    /// The options of its grade in `staged`.
    fn in_stage(&self, staged: &stage::Stage) -> GradeOptions {
        let mut in_stage = self.options.clone();
        in_stage.root.clone_from(&staged.root);
        in_stage.target_dir = Some(staged.target_dir.clone());
        in_stage
    }

    fn setting(&self) -> super::Setting {
        super::Setting {
            absent: self.absent.clone(),
            #[cfg(feature = "staff")]
            beside: None,
        }
    }

    /// Runs the `prepared` grade of the submission staged in `staged`,
    /// finds what its tests changed, and makes and writes its report.
    fn graded(
        self,
        official: &Path,
        staged: &stage::Stage,
        prepared: super::flow::Prepared,
        events: &dyn super::Events,
    ) -> Result<Report> {
        let graded = prepared.finish(events)?;
        let mut integrity = self.integrity;
        integrity.tampered = tampered(official, &self.course_before, &staged.root, &self.planned)?;
        let in_course: Vec<String> = integrity
            .tampered
            .iter()
            .filter(|f| !f.starts_with("stage"))
            .map(|f| table::shown(&slashed(f)))
            .collect();
        if !in_course.is_empty() {
            eprintln!(
                "warning: the tests of {} changed files of the course itself; check them (e.g. `git status`): {}",
                table::shown(&self.submission.display().to_string()),
                in_course.join(", ")
            );
        }
        let absent = self
            .absent
            .iter()
            .map(|name| (name.clone(), super::plan::absent_reason(name)));
        let report = graded.report(Adjustments {
            shown_root: Some(self.submission),
            refused: self.refused,
            topic_errors: absent.chain(self.unreadable).collect(),
            tampered: integrity.tampered.clone(),
            integrity: Some(integrity),
        });
        super::export::write_all(&report, &self.options.out)?;
        Ok(report)
    }
}

/// A submission's task files as the grader took them.
#[derive(Debug, Default)]
struct Taken {
    /// Every task file of the course (see `stage::task_files`): the
    /// submission's copy, read once, or the official stub where the
    /// submission's is missing, unreadable or refused.
    files: Files,
    /// Per topic, the uses of what a task file may not do (see
    /// `forbidden`): the topic is not compiled.
    refused: Vec<(String, Vec<String>)>,
    /// Per topic, the task files not read and why (a link, a pipe, a
    /// flood): their stubs were used.
    unreadable: Vec<(String, String)>,
}

/// Takes the task files of `submission`: the files the official course at
/// `official` names as tasks (`stage::task_files`), nothing else of it.
/// Each is read once, through a handle opened without following a link at
/// any component ([`nofollow`]); that copy in memory is what is checked
/// for forbidden constructs and what is staged, so a file swapped for a
/// link to a solution after this read changes nothing. Every other file
/// of the submission (given code, `lib.rs`, its manifests) is the
/// course's in the stage.
fn take_task_files(official: &Path, submission: &Path) -> Result<Taken> {
    let mut taken = Taken::default();
    let topic_of = |task_file: &Path| {
        task_file
            .components()
            .nth(1)
            .map(|c| c.as_os_str().to_string_lossy().into_owned())
            .unwrap_or_default()
    };
    let stub = |task_file: &Path| {
        (
            task_file.to_path_buf(),
            Source::File(official.join(task_file)),
        )
    };
    for task_file in stage::task_files(official)? {
        let bytes = match nofollow::read(submission, &task_file, crate::files::MAX_SUBMITTED_FILE) {
            Ok(bytes) => bytes,
            Err(nofollow::Missing) => {
                taken.files.push(stub(&task_file));
                continue;
            }
            Err(nofollow::Refusal::Refused(why)) => {
                taken.unreadable.push((
                    topic_of(&task_file),
                    format!(
                        "{}: not graded ({why}); the stub was used",
                        slashed(&task_file)
                    ),
                ));
                taken.files.push(stub(&task_file));
                continue;
            }
        };
        // A task file that reaches other files at compile time (or uses a
        // known soundness hole, see `forbidden`) is not compiled: its stub
        // is staged instead, and its topic scores 0. WGSL reaches no
        // files; Rust may, by macros. Text that is not UTF-8 is staged as
        // it is, and does not compile.
        let uses = match std::str::from_utf8(&bytes) {
            Ok(text) if !crate::files::is_wgsl(&task_file) => super::forbidden::uses(text),
            _ => Vec::new(),
        };
        if uses.is_empty() {
            taken.files.push((task_file, Source::Text(bytes)));
        } else {
            let shown = task_file.display().to_string();
            taken.refused.push((
                topic_of(&task_file),
                uses.iter().map(|u| format!("{shown}:{u}")).collect(),
            ));
            taken.files.push(stub(&task_file));
        }
    }
    Ok(taken)
}

/// The files of the stage of `submission`: the edition of the official
/// course with the submission's task files as [`take_task_files`] took
/// them (each read once, held in memory), and what it found. Nothing of
/// the submission is left to be read later: no staged file is a path
/// into it.
fn staged_files(official: &Path, submission: &Path) -> Result<(Files, Taken)> {
    let taken = take_task_files(official, submission)?;
    let mut files = stage::plan(official, Overlay::Submission(submission))?;
    files.retain(|(to, _)| !taken.files.iter().any(|(task_file, _)| task_file == to));
    files.extend(taken.files.iter().cloned());
    files.sort();
    // As staged: what the integrity check compares the stage with.
    let files = stage::replay::with_graded_data(&files);
    Ok((files, taken))
}

/// The table of a graded submission, as `cargo xtask grade` prints it.
fn table_of(report: &Report, out: &Path) -> String {
    table::render(
        report,
        out,
        table::Style::detect(),
        table::Details::EveryTask,
    )
}

/// The build cache of submissions: never the one the solutions are built
/// in, so that nothing a submission's build can read was compiled from
/// them.
pub(crate) fn submissions_build(official: &Path) -> PathBuf {
    stage::home(official).join("submissions-build")
}

/// `--submission DIR`: grades the checkout `dir` into `<out>/<name>/`
/// (its folder's name) and prints its table. A folder of checkouts (a
/// class) is not graded here: grading a class is the staff's, with the
/// course repository's tools.
pub fn run(official: &Path, dir: &Path, options: &GradeOptions) -> Result<Report> {
    let dir = dir
        .canonicalize()
        .with_context(|| format!("cannot find the submission {}", dir.display()))?;
    if !is_checkout(&dir) {
        let members: Vec<PathBuf> = fs::read_dir(&dir)
            .with_context(|| format!("cannot read {}", dir.display()))?
            .filter_map(|entry| entry.ok().map(|e| e.path()))
            .filter(|path| is_checkout(path))
            .collect();
        let Some(member) = members.iter().min() else {
            bail!(
                "{} is neither a course checkout (with exercises/ and Cargo.toml) nor a folder of them",
                dir.display()
            );
        };
        bail!(
            "{} is a folder of {} course checkouts (a class): grading a class is done with the course repository's tools, not a student edition's; here, grade one checkout at a time (e.g. --submission {})",
            dir.display(),
            members.len(),
            member.display()
        );
    }
    let mut one = options.clone();
    one.out = options.out.join(member_name(&dir));
    let report = grade_one(official, &dir, &one)?;
    print!("{}", table_of(&report, &one.out));
    Ok(report)
}

/// The entries a class's grade folder holds of its own, beside its
/// members' folders: no member's folder is named like one of them.
pub(crate) const CLASS_ENTRIES: [&str; 6] = [
    "gradebook.csv",
    "gradebook.json",
    "class.html",
    "class.json",
    "similarity.html",
    "similarity.json",
];

/// A member's name, which is also its folder's in the class's grade
/// folder: its checkout's folder name, made one that no other member and
/// no entry of the class folder ([`CLASS_ENTRIES`]) can have.
///
/// - A byte that is not part of a UTF-8 character is written `%XX`, and
///   `%` itself `%25` (decoded lossily, `a\xff` and `a\xfe` were both
///   `a\u{fffd}`: two members graded into one folder at once).
/// - A name of the class folder's own entries (in any case: a folder
///   `Class.html` is `class.html` on macOS), or one that starts with `_`,
///   gets a `_` in front (a member `gradebook.json` stopped the class's
///   gradebook from being written).
///
/// Each step maps different names to different names, so no two members
/// share one.
pub(crate) fn member_name(submission: &Path) -> String {
    let Some(raw) = submission.file_name() else {
        return "submission".to_owned();
    };
    let mut name = String::new();
    for chunk in raw.as_encoded_bytes().utf8_chunks() {
        name.push_str(&chunk.valid().replace('%', "%25"));
        for byte in chunk.invalid() {
            name.push_str(&format!("%{byte:02X}"));
        }
    }
    let reserved = CLASS_ENTRIES
        .iter()
        .any(|entry| entry.eq_ignore_ascii_case(&name));
    if reserved || name.starts_with('_') {
        name.insert(0, '_');
    }
    name
}

/// A relative path with `/` separators, for messages.
pub(crate) fn slashed(path: &Path) -> String {
    path.components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect::<Vec<_>>()
        .join("/")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Members' names: plain ones as they are; no two members one name,
    /// and none the name of the class folder's own entries.
    #[test]
    fn member_names_are_distinct_and_none_is_the_class_folders() {
        let name = |n: &str| member_name(&Path::new("class").join(n));
        assert_eq!(name("anna"), "anna");
        assert_eq!(name("raster-ben.2"), "raster-ben.2");
        assert_eq!(name("gradebook.json"), "_gradebook.json");
        assert_eq!(name("Class.HTML"), "_Class.HTML");
        assert_eq!(name("_gradebook.json"), "__gradebook.json");
        assert_eq!(name("100%"), "100%25");
        assert_eq!(member_name(Path::new("/")), "submission");
        for entry in CLASS_ENTRIES {
            assert_ne!(name(entry).to_lowercase(), entry);
        }
        #[cfg(unix)]
        {
            use std::os::unix::ffi::OsStrExt as _;
            let raw = |bytes: &[u8]| {
                member_name(&Path::new("class").join(std::ffi::OsStr::from_bytes(bytes)))
            };
            assert_eq!(raw(b"a\xff"), "a%FF");
            assert_ne!(raw(b"a\xff"), raw(b"a\xfe"));
            assert_ne!(raw(b"a\xff"), name("a%FF"));
            assert_eq!(raw("zoë".as_bytes()), "zoë");
        }
    }

    /// The course this tooling ships with.
    fn course() -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
    }

    #[test]
    fn the_course_markers_name_exactly_the_files_with_a_solution() {
        // In an edition (no `reference/`) the task files are found by the
        // stubs' markers; here, where `reference/` says which they are,
        // both must agree, and the given files that mention `todo!()` in
        // their doc comments are not tasks.
        let root = course();
        if !root.join("reference").is_dir() {
            eprintln!("not run: an edition has no reference/ to compare its markers with");
            return;
        }
        for topic in topics::discover(&root).unwrap() {
            let ids: Vec<&str> = topic.sheet.tasks.iter().map(|t| t.id.as_str()).collect();
            let src = topic.dir.join("src");
            for file in crate::files::files_under(&src).unwrap() {
                let text = fs::read_to_string(src.join(&file)).unwrap();
                let solved = root
                    .join("reference")
                    .join(&topic.name)
                    .join("src")
                    .join(&file)
                    .is_file();
                assert_eq!(
                    crate::stubs::holds_task_stub(&file, &text, &ids),
                    solved,
                    "exercises/{}/src/{}",
                    topic.name,
                    file.display()
                );
            }
        }
        for given in [
            "exercises/06-csg/src/raster.rs",
            "exercises/10-gpu-tessellation/src/wgsl.rs",
        ] {
            let text = fs::read_to_string(root.join(given)).unwrap();
            assert!(
                text.contains("todo!()"),
                "{given} no longer mentions todo!()"
            );
        }
    }

    /// An edition of one topic (no `reference/`): a task file `classify.rs`
    /// and a given file `raster.rs` whose doc comment mentions `todo!()`.
    fn edition(dir: &Path) -> PathBuf {
        let official = dir.join("official");
        let topic = official.join("exercises/06-x");
        let write = |path: PathBuf, text: &str| crate::files::write_file(&path, text).unwrap();
        write(topic.join("Cargo.toml"), "[package]\nname = \"x\"\n");
        write(
            topic.join("tasks.toml"),
            "[[tasks]]\nid = \"classify\"\ntitle = \"Classify\"\npoints = 3\n",
        );
        write(
            topic.join("src/lib.rs"),
            "pub mod classify;\npub mod raster;\n",
        );
        write(
            topic.join("src/raster.rs"),
            "//! Given: a stage at `todo!()` is named on screen.\npub fn raster() -> u8 { 1 }\n",
        );
        write(
            topic.join("src/classify.rs"),
            "pub fn classify() -> u8 {\n    todo!(\"classify: say inside or outside\")\n}\n",
        );
        official
    }

    #[test]
    fn a_modified_given_file_changes_nothing_and_task_files_are_read_once() {
        let dir = std::env::temp_dir().join(format!("xtask-taken-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        let official = edition(&dir);
        let classify = PathBuf::from("exercises/06-x/src/classify.rs");
        let raster = PathBuf::from("exercises/06-x/src/raster.rs");
        assert_eq!(
            stage::task_files(&official).unwrap(),
            std::slice::from_ref(&classify)
        );
        let submission = dir.join("anna");
        let write = |path: PathBuf, text: &str| crate::files::write_file(&path, text).unwrap();
        write(
            submission.join(&classify),
            "pub fn classify() -> u8 { 2 }\n",
        );
        write(
            submission.join(&raster),
            "//! Mine now: todo!(\"classify: x\")\npub fn raster() -> u8 { 42 }\n",
        );
        let taken = take_task_files(&official, &submission).unwrap();
        assert!(taken.refused.is_empty() && taken.unreadable.is_empty());
        // Only the task file is the student's; raster.rs stays the course's.
        let files: Vec<&PathBuf> = taken.files.iter().map(|(to, _)| to).collect();
        assert_eq!(files, [&classify]);
        let checked = Source::Text(b"pub fn classify() -> u8 { 2 }\n".to_vec());
        assert_eq!(taken.files[0].1, checked);
        // A watcher swaps the task file for a link to a solution after the
        // check: what was taken is what is staged and graded.
        let solution = dir.join("solution.rs");
        write(solution.clone(), "pub fn classify() -> u8 { 1 }\n");
        fs::remove_file(submission.join(&classify)).unwrap();
        #[cfg(unix)]
        {
            std::os::unix::fs::symlink(&solution, submission.join(&classify)).unwrap();
            assert_eq!(
                taken.files[0].1.read().unwrap(),
                b"pub fn classify() -> u8 { 2 }\n"
            );
            // Taken again, the link is refused and the stub staged.
            let again = take_task_files(&official, &submission).unwrap();
            assert_eq!(again.unreadable.len(), 1, "{:?}", again.unreadable);
            assert!(again.unreadable[0].1.contains("symbolic link"));
            assert_eq!(again.files[0].1, Source::File(official.join(&classify)));
        }
        let _ = fs::remove_dir_all(&dir);
    }

    #[test]
    #[cfg_attr(
        windows,
        ignore = "stages with `cargo metadata`; there is no cargo where the Windows build runs (Wine)"
    )]
    fn a_submissions_tool_configuration_is_never_staged_nor_read_later() {
        // insta reads `insta.yaml`, `.config/insta.yaml` or `.insta.yaml`
        // in the workspace root, proptest `proptest-regressions/` beside
        // a test: a submission's are not the course's, and stay behind.
        let dir = std::env::temp_dir().join(format!("xtask-staged-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        let submission = dir.join("anna");
        // A little course of its own, whose stub names its task file
        // wherever this test runs (in a stage the course's own files are
        // the solutions, and an edition has no fixtures).
        let tiny = dir.join("tiny");
        let dda = PathBuf::from("exercises/01-tiny/src/ops.rs");
        let write = |path: PathBuf, text: &str| crate::files::write_file(&path, text).unwrap();
        write(
            tiny.join("Cargo.toml"),
            "[workspace]\nresolver = \"3\"\nmembers = [\"exercises/*\"]\n",
        );
        write(
            tiny.join("exercises/01-tiny/Cargo.toml"),
            "[package]\nname = \"tiny\"\nversion = \"0.1.0\"\nedition = \"2024\"\n",
        );
        write(
            tiny.join("exercises/01-tiny/tasks.toml"),
            "[[tasks]]\nid = \"double\"\ntitle = \"Doubling\"\npoints = 1\n",
        );
        write(tiny.join("exercises/01-tiny/src/lib.rs"), "pub mod ops;\n");
        write(
            tiny.join(&dda),
            "pub fn double(x: i32) -> i32 {\n    let _ = x;\n    todo!(\"double: twice x\")\n}\n",
        );
        write(submission.join(&dda), "// mine\n");
        for config in ["insta.yaml", ".config/insta.yaml", ".insta.yaml"] {
            write(submission.join(config), "behavior:\n  force_pass: true\n");
        }
        write(
            submission.join("exercises/01-tiny/tests/proptest-regressions/double.txt"),
            "cc 0\n",
        );
        let (files, _) = staged_files(&tiny, &submission).unwrap();
        for (to, from) in &files {
            let name = to.to_string_lossy();
            assert!(
                !name.contains("insta.yaml") && !name.contains("proptest-regressions"),
                "{name} is staged"
            );
            assert!(
                !matches!(from, Source::File(path) if path.starts_with(&submission)),
                "{name} would be read from the submission later"
            );
        }
        let staged = files
            .iter()
            .find(|(to, _)| *to == dda)
            .map(|(_, from)| from);
        assert_eq!(staged, Some(&Source::Text(b"// mine\n".to_vec())));
        let _ = fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_task_file_using_the_soundness_hole_is_refused_and_its_stub_staged() {
        let dir = std::env::temp_dir().join(format!("xtask-taken-hole-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        let official = edition(&dir);
        let classify = PathBuf::from("exercises/06-x/src/classify.rs");
        let submission = dir.join("ben");
        crate::files::write_file(
            &submission.join(&classify),
            "fn t<'a, 'b, T>(_: &'a &'b (), v: &'b T) -> &'a T { v }\npub fn classify() -> u8 { 0 }\n",
        )
        .unwrap();
        let taken = take_task_files(&official, &submission).unwrap();
        assert_eq!(taken.refused.len(), 1);
        assert!(
            taken.refused[0].1[0].contains("rust-lang/rust#25860"),
            "{:?}",
            taken.refused
        );
        assert_eq!(taken.files[0].1, Source::File(official.join(&classify)));
        let _ = fs::remove_dir_all(&dir);
    }
}
