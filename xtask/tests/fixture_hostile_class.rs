//! A member is the unit of failure: a class of the tiny fixture course in
//! which each member's checkout or tests leave what once stopped a whole
//! class with no gradebook, or reached past the report or the terminal —
//!
//! | member | what it leaves | what stopped, or leaked |
//! |---|---|---|
//! | `deep-folders` | a chain of 16,000 folders in a test's scratch folder, 2,100 in its picture folder | the grader's recursive removal overflowed its stack (exit 134); `gradebook merge` failed, "File name too long" |
//! | `long-path` | a path of 5,000 bytes (past `PATH_MAX`) in its checkout | the fingerprint's walk failed and `?` ended the class |
//! | `floods-pictures` | a sparse file of 1 TiB in its checkout; 360 MiB of pictures | `fs::read` of it: out of memory; every byte kept in the report |
//! | `sparse-task-file` | its task file a sparse file of 1 TiB | (read whole, as any task file) |
//! | `leaves-links` | a link to a solution, and a pipe, in its picture and pending-snapshot folders | `zip -r` of the report follows the link |
//! | `evil⏎total 20.0 ∕ 20 ok␛[2J` | its name, and a grading file's, hold a line break and a terminal escape | a fake total line in the tutor's terminal |
//! | `gradebook.json` | its name, the class's gradebook's | its report folder took the gradebook's place: no gradebook was written |
//! | `twin-\xfe`, `twin-\xff` | names that are not UTF-8 | decoded lossily, one name: both graded into one folder at once |
//! | `=HYPERLINK("…")` | its name a formula | a live formula in the tutor's spreadsheet |
//!
//! — beside an honest member, who must be graded in full; the gradebook
//! and a merge of it must be written; each hostile member gets its grade
//! or its reason.

mod common;

#[test]
fn hostile_members_cost_the_class_nothing() {
    #[cfg(target_os = "linux")]
    linux::hostile_members_cost_the_class_nothing();
    #[cfg(not(target_os = "linux"))]
    eprintln!(
        "not run: the plants need Linux (symbolic links, pipes, file names with line breaks)"
    );
}

#[cfg(target_os = "linux")]
mod linux {
    use std::fs;
    use std::path::{Path, PathBuf};

    use super::common::class::{member, ops};
    use super::common::{fixture, read_json, stdout, xtask};

    /// The name of the member whose name is an attack on the terminal (a
    /// file name holds no `/`: its fake total divides with U+2215).
    const EVIL: &str = "evil\ntotal 20.0 \u{2215} 20 ok\u{1b}[2J";

    /// The name of the member whose name is a spreadsheet formula.
    const FORMULA: &str = "=HYPERLINK(\"http:∕∕example.com\")";

    /// What the grader keeps of one grade's pictures, snapshots and logs
    /// (`files::KEPT_BUDGET`).
    const KEPT_BUDGET: u64 = 256 << 20;

    /// `dir/top` made a chain of `depth` folders named `name` with short
    /// paths only (each step moves the chain into a new folder), as a
    /// student's `mkdir x; cd x` loop makes it.
    fn chain(dir: &Path, top: &str, depth: usize, name: &str) {
        let (chain, next) = (dir.join(top), dir.join(".next"));
        fs::create_dir_all(&chain).unwrap();
        for _ in 1..depth {
            fs::create_dir(&next).unwrap();
            fs::rename(&chain, next.join(name)).unwrap();
            fs::rename(&next, &chain).unwrap();
        }
    }

    /// Every entry under `dir` that is neither a plain file nor a folder,
    /// and the deepest folder's depth: read with relative steps only
    /// (`dir` stays the starting point), so that a chain the grader left
    /// behind is seen however deep it goes.
    fn odd_entries_and_depth(dir: &Path) -> (Vec<PathBuf>, usize) {
        let mut odd = Vec::new();
        let mut deepest = 0;
        let mut stack = vec![(dir.to_path_buf(), 0)];
        while let Some((folder, depth)) = stack.pop() {
            deepest = deepest.max(depth);
            let Ok(entries) = fs::read_dir(&folder) else {
                odd.push(folder);
                continue;
            };
            for entry in entries.flatten() {
                let kind = entry.file_type().unwrap();
                if kind.is_dir() {
                    stack.push((entry.path(), depth + 1));
                } else if !kind.is_file() {
                    odd.push(entry.path());
                }
            }
        }
        (odd, deepest)
    }

    /// The bytes of the plain files under `dir`.
    fn bytes(dir: &Path) -> u64 {
        let mut total = 0;
        let mut stack = vec![dir.to_path_buf()];
        while let Some(folder) = stack.pop() {
            for entry in fs::read_dir(&folder).into_iter().flatten().flatten() {
                let meta = entry.metadata().unwrap();
                if entry.file_type().unwrap().is_dir() {
                    stack.push(entry.path());
                } else {
                    total += meta.len();
                }
            }
        }
        total
    }

    /// `ops.rs` whose both functions first run `plant` (a statement), then
    /// answer right.
    fn planting(plant: &str) -> String {
        ops(&format!("{plant}\n    x * 2"), &format!("{plant}\n    -x"))
    }

    fn write_class(official: &Path, class: &Path) {
        member(official, class, "a-honest", Some(&ops("x * 2", "-x")));

        // (The picture chain first: the sandbox stops a test whose folders
        // nest past the walks' bound when it next measures what was written.)
        let deep = "    let back = std::env::current_dir().unwrap();\n\
             for (dir, depth, name) in [(\"TESTKIT_OUTPUT_DIR\", 2_100, \"d\"), (\"TMPDIR\", 16_000, \"a\")] {\n\
                 let dir = std::env::var(dir).unwrap();\n\
                 let _ = std::fs::create_dir_all(&dir);\n\
                 std::env::set_current_dir(&dir).unwrap();\n\
                 for _ in 0..depth {\n\
                     let _ = std::fs::create_dir(name);\n\
                     if std::env::set_current_dir(name).is_err() { break; }\n\
                 }\n\
             }\n\
             std::env::set_current_dir(back).unwrap();";
        member(official, class, "deep-folders", Some(&planting(deep)));

        let long = member(official, class, "long-path", Some(&ops("x * 2", "-x")));
        chain(&long, "notes", 20, &"n".repeat(250));

        let floods = "    let dir = std::env::var(\"TESTKIT_OUTPUT_DIR\").unwrap();\n\
             let _ = std::fs::create_dir_all(&dir);\n\
             for n in 0..2 {\n\
                 let _ = std::fs::write(format!(\"{dir}/picture-{n}.png\"), vec![7_u8; 60 << 20]);\n\
             }";
        let flooding = member(official, class, "floods-pictures", Some(&planting(floods)));
        let sparse = fs::File::create(flooding.join("notes.bin")).unwrap();
        sparse.set_len(1 << 40).unwrap();

        // Its task file itself a sparse terabyte: refused by its size.
        let sparse_task = member(official, class, "sparse-task-file", None);
        let task_file = fs::File::create(sparse_task.join("exercises/01-tiny/src/ops.rs")).unwrap();
        task_file.set_len(1 << 40).unwrap();

        let solution = official.join("reference/01-tiny/src/ops.rs");
        let links = format!(
            "    for var in [\"TESTKIT_OUTPUT_DIR\", \"INSTA_PENDING_DIR\"] {{\n\
                 let dir = std::env::var(var).unwrap();\n\
                 let _ = std::fs::create_dir_all(&dir);\n\
                 let _ = std::os::unix::fs::symlink({solution:?}, format!(\"{{dir}}/solution.rs\"));\n\
                 let _ = std::os::unix::fs::symlink(\"/\", format!(\"{{dir}}/root\"));\n\
                 let _ = std::process::Command::new(\"mkfifo\").arg(format!(\"{{dir}}/pipe\")).status();\n\
                 let _ = std::fs::write(format!(\"{{dir}}/picture.txt\"), \"one\");\n\
             }}",
            solution = solution.display().to_string()
        );
        member(official, class, "leaves-links", Some(&planting(&links)));

        member(official, class, "gradebook.json", Some(&ops("x * 2", "-x")));
        member(official, class, FORMULA, Some(&ops("x * 2", "-x")));
        for (twin, byte) in [("twin-a", 0xfe_u8), ("twin-b", 0xff)] {
            use std::os::unix::ffi::OsStrExt as _;
            let made = member(official, class, twin, Some(&ops("x * 2", "-x")));
            let name = [b"twin-".as_slice(), &[byte]].concat();
            fs::rename(made, class.join(std::ffi::OsStr::from_bytes(&name))).unwrap();
        }

        let evil = member(official, class, EVIL, Some(&ops("x * 2", "-x")));
        fs::write(
            evil.join(format!("exercises/01-tiny/tests/fake\n{}.rs", &EVIL[5..])),
            "#[test]\nfn fake() {}\n",
        )
        .unwrap();
    }

    pub fn hostile_members_cost_the_class_nothing() {
        let official = fixture("tiny", "hostile-class");
        let class = Path::new(env!("CARGO_TARGET_TMPDIR")).join("hostile-class");
        if class.exists() {
            // (With the test's own removal: a chain an earlier run left
            // would overflow `fs::remove_dir_all` here too.)
            let _ = std::process::Command::new("rm")
                .arg("-rf")
                .arg(&class)
                .status();
        }
        write_class(&official, &class);
        let out = super::common::fresh(official.join("target/hostile"));
        let output = xtask(
            &official,
            &[
                "grade",
                "--submission",
                class.to_str().unwrap(),
                "--out",
                out.to_str().unwrap(),
                "--jobs",
                "2",
            ],
        );
        let text = stdout(&output);
        let errors = String::from_utf8_lossy(&output.stderr).into_owned();
        assert_ne!(
            output.status.code(),
            Some(134),
            "the grader aborted: {errors}"
        );

        // The class went on: the honest member is graded in full, and the
        // gradebook is written.
        let gradebook = fs::read_to_string(out.join("gradebook.csv")).expect("a gradebook");
        assert!(gradebook.contains("\na-honest,3,3,"), "{gradebook}");
        let honest = read_json(&out.join("a-honest/report.json"));
        assert_eq!(honest["score"], 3.0);

        // Members named like the class's gradebook, twins by lossy
        // decoding, a formula: each graded into a folder of its own, the
        // class's files beside them, no formula in the gradebook.
        assert!(
            out.join("gradebook.json").is_file(),
            "the class's gradebook"
        );
        for name in ["_gradebook.json", "twin-%FE", "twin-%FF"] {
            let report = read_json(&out.join(name).join("report.json"));
            assert_eq!(report["score"], 3.0, "{name}: {report:#}");
            assert!(gradebook.contains(&format!("\n{name},3,3,")), "{gradebook}");
        }
        assert!(
            gradebook.contains("\n\"'=HYPERLINK(\"\"http:∕∕example.com\"\")\",3,3,"),
            "{gradebook}"
        );
        assert!(!gradebook.contains("\n="), "{gradebook}");

        // Each hostile member has its grade, or its reason.
        for name in ["deep-folders", "floods-pictures", "leaves-links", EVIL] {
            assert!(
                out.join(name).join("report.json").is_file(),
                "{name:?} was graded: {text}\n{errors}"
            );
        }
        let sparse_task = read_json(&out.join("sparse-task-file/report.json"));
        assert_eq!(
            sparse_task["score"], 0.0,
            "the stub was graded: {sparse_task:#}"
        );

        let long = out.join("long-path");
        let graded = long.join("report.json").is_file();
        let why = fs::read_to_string(long.join("not-graded.txt")).unwrap_or_default();
        assert!(graded || !why.is_empty(), "long-path: a grade or a reason");
        if !graded {
            assert!(
                errors.contains("long-path: "),
                "its reason is said: {errors}"
            );
        }

        // What the tests left: the scratch chain is gone, no report folder
        // holds a link, a pipe or a folder deeper than the walks go.
        for name in ["deep-folders", "leaves-links", "floods-pictures"] {
            let (odd, deepest) = odd_entries_and_depth(&out.join(name));
            assert!(odd.is_empty(), "{name}: {odd:?}");
            assert!(deepest <= 32, "{name}: folders {deepest} deep");
        }
        assert!(
            !out.join("deep-folders/scratch/01-tiny/double").exists()
                || fs::read_dir(out.join("deep-folders/scratch/01-tiny/double"))
                    .unwrap()
                    .next()
                    .is_none(),
            "a test's scratch folder is removed"
        );
        assert!(
            text.lines()
                .any(|l| l.contains("leaves-links: 3 / 3 points")
                    && l.contains("left out of its report")),
            "the class's line says what was left out: {text}"
        );
        let deep = read_json(&out.join("deep-folders/report.json"));
        assert!(
            deep["left_out"]
                .to_string()
                .contains("folders nested deeper than 32"),
            "the picture chain was cut at the bound: {deep:#}"
        );
        let links = read_json(&out.join("leaves-links/report.json"));
        assert_eq!(links["score"], 3.0, "{links:#}");
        let left_out = links["left_out"].to_string();
        assert!(
            left_out.contains("solution.rs: a symbolic link"),
            "{left_out}"
        );
        assert!(left_out.contains("pipe: not a plain file"), "{left_out}");
        assert!(
            out.join("leaves-links/images/01-tiny/double")
                .read_dir()
                .is_ok(),
            "its pictures are kept"
        );

        // The pictures are kept within the budget, and what is past it is
        // named.
        let floods = read_json(&out.join("floods-pictures/report.json"));
        assert_eq!(floods["score"], 3.0, "the sparse terabyte: {floods:#}");
        let kept = bytes(&out.join("floods-pictures/images"));
        assert!(kept <= KEPT_BUDGET, "{kept} bytes of pictures kept");
        let folder = bytes(&out.join("floods-pictures"));
        assert!(
            folder <= KEPT_BUDGET + (1 << 20),
            "the member's report folder holds {folder} bytes: the budget and the reports"
        );
        assert!(
            floods["left_out"].to_string().contains("past the budget"),
            "{floods:#}"
        );

        // No line the grader printed is the submission's: the name's line
        // break and escape are shown, not obeyed.
        for printed in [&text, &errors] {
            assert!(
                !printed.contains('\u{1b}'),
                "an escape reached the terminal"
            );
            assert!(
                !printed.lines().any(|l| l.starts_with("total 20.0")),
                "a fake line: {printed}"
            );
        }
        assert!(
            text.contains("evil\\ntotal 20.0 \u{2215} 20 ok\\u{1b}[2J"),
            "{text}"
        );
        // Graded alone, the table names its added grading file: escaped.
        let alone = xtask(
            &official,
            &[
                "grade",
                "--submission",
                class.join(EVIL).to_str().unwrap(),
                "--out",
                official.join("target/hostile-alone").to_str().unwrap(),
            ],
        );
        let table = stdout(&alone);
        assert!(table.contains("FLAGGED"), "{table}");
        let totals: Vec<&str> = table.lines().filter(|l| l.starts_with("total")).collect();
        assert_eq!(totals.len(), 1, "one total line: {table}");
        assert!(!table.contains('\u{1b}'), "{table}");

        // The class's folders merge into one gradebook, the links left
        // behind by no member.
        let merged = super::common::fresh(official.join("target/hostile-merged"));
        let output = xtask(
            &official,
            &[
                "gradebook",
                "merge",
                out.to_str().unwrap(),
                "--out",
                merged.to_str().unwrap(),
            ],
        );
        let merged_book = fs::read_to_string(merged.join("gradebook.csv"))
            .unwrap_or_else(|_| panic!("a merged gradebook: {output:?}"));
        assert!(merged_book.contains("\na-honest,3,3,"), "{merged_book}");
        let (odd, _) = odd_entries_and_depth(&merged);
        assert!(odd.is_empty(), "{odd:?}");
    }
}
