//! The grader's promises tried as a determined student would: a class of
//! the tiny fixture course in which each member attacks the grader in
//! another way. Every attack must be contained — no points, no hang, the
//! classmates graded, a gradebook written, nothing outside the scratch
//! folders changed — and each plant must be seen to have run, so that a
//! test here cannot pass because an attack never happened.
//!
//! On Linux the grader installs bubblewrap (as CI does); a run where the
//! sandbox could not be had fails here rather than passing, since
//! unsandboxed the promises lapse (the README says which). Elsewhere the
//! test says it was not run.

mod common;

#[test]
fn every_attack_on_the_grader_is_contained_and_the_class_is_graded() {
    #[cfg(target_os = "linux")]
    linux::every_attack_on_the_grader_is_contained_and_the_class_is_graded();
    #[cfg(not(target_os = "linux"))]
    eprintln!("not run: the sandbox these attacks are contained by is Linux's (bubblewrap)");
}

/// The attacks, which need Linux (symbolic links, `/proc`, bubblewrap).
#[cfg(target_os = "linux")]
mod linux {
    use std::fs;
    use std::path::Path;
    use std::time::{Duration, Instant};

    use super::common::class::{SECRET, first_reason, member, ops, snapshot};
    use super::common::{fixture, read_json, task};

    /// The build limit the class is graded with: the endless build is stopped
    /// at it.
    const BUILD_LIMIT_S: u64 = 40;

    /// Python that asks for the memory of its parent (the test that started
    /// it) with `process_vm_readv` and to trace it with `ptrace`, and prints
    /// both `errno`s: `1 1` (EPERM) where both are denied; a read of an
    /// unmapped page that was allowed says EFAULT (14) instead.
    const READS_PARENT: &str = r#"
    import ctypes, os
    libc = ctypes.CDLL(None, use_errno=True)
    class Iovec(ctypes.Structure):
        _fields_ = [("base", ctypes.c_void_p), ("len", ctypes.c_size_t)]
    buffer = ctypes.create_string_buffer(8)
    local = Iovec(ctypes.cast(buffer, ctypes.c_void_p), 8)
    remote = Iovec(4096, 8)
    parent = os.getppid()
    libc.process_vm_readv(parent, ctypes.byref(local), 1, ctypes.byref(remote), 1, 0)
    read = ctypes.get_errno()
    ctypes.set_errno(0)
    traced = libc.ptrace(16, parent, 0, 0)
    trace = ctypes.get_errno() if traced != 0 else 0
    print(read, trace)
    "#;

    /// `text` without the indentation its lines share (the script sits in
    /// an indented module, and Python reads indentation).
    fn dedent(text: &str) -> String {
        let indent = text
            .lines()
            .filter(|l| !l.trim().is_empty())
            .map(|l| l.len() - l.trim_start().len())
            .min()
            .unwrap_or(0);
        text.lines()
            .map(|l| l.get(indent..).unwrap_or("").to_owned() + "\n")
            .collect()
    }

    /// The members of the class: the name, and `ops.rs`, or what to do to
    /// the checkout.
    fn write_class(official: &Path, class: &Path) {
        let solution = official.join("reference/01-tiny/src/ops.rs");
        let quoted = |path: &Path| format!("{:?}", path.display().to_string());
        let home = std::env::var("HOME").unwrap_or_else(|_| "/root".into());
        // The honest member: the baseline that grading works.
        member(official, class, "a-honest", Some(&ops("x * 2", "-x")));

        // The task folder is a link: to the solutions, and to a classmate.
        let linked = member(official, class, "links-solutions", None);
        fs::remove_dir_all(linked.join("exercises/01-tiny/src")).unwrap();
        std::os::unix::fs::symlink(
            official.join("reference/01-tiny/src"),
            linked.join("exercises/01-tiny/src"),
        )
        .unwrap();
        let linked = member(official, class, "links-classmate", None);
        fs::remove_dir_all(linked.join("exercises/01-tiny/src")).unwrap();
        std::os::unix::fs::symlink(
            "../../../a-honest/exercises/01-tiny/src",
            linked.join("exercises/01-tiny/src"),
        )
        .unwrap();

        // `#[path]` built by a macro from a `meta` fragment: no `#[path =`
        // for a textual check to find; only the sandbox keeps the file away.
        member(
            official,
            class,
            "macro-path",
            Some(&format!(
                "macro_rules! module {{ ($attribute:meta) => {{ #[$attribute] mod solution; }}; }}\n\
                 module!(path = {});\n\
                 pub fn double(x: i32) -> i32 {{ solution::double(x) }}\n\
                 pub fn negate(x: i32) -> i32 {{ solution::negate(x) }}\n",
                quoted(&solution)
            )),
        );

        // Right only where it can see the course's history, its solutions,
        // the grader's home folder or a classmate's checkout.
        let sees = format!(
            "    let seen = std::path::Path::new({git}).exists()\n\
             || std::fs::read_to_string({solution}).is_ok()\n\
             || std::fs::read_dir({home}).is_ok_and(|mut e| e.next().is_some())\n\
             || std::fs::read_to_string({classmate}).is_ok();\n\
             assert!(seen, \"saw nothing of the machine\");",
            git = quoted(&official.join(".git/HEAD")),
            solution = quoted(&solution),
            home = quoted(Path::new(&home)),
            classmate = quoted(&class.join("a-honest/exercises/01-tiny/src/ops.rs")),
        );
        member(
            official,
            class,
            "reads-machine",
            Some(&ops(
                &format!("{sees}\n    x * 2"),
                &format!("{sees}\n    -x"),
            )),
        );

        // Right only where the grader's environment reaches it; it prints
        // what it finds into its failure, which the reports keep.
        let secret = "    let found: Vec<String> = std::env::vars()\n\
             .filter(|(k, _)| k.contains(\"TOKEN\") || k.contains(\"SECRET\"))\n\
             .map(|(k, v)| format!(\"{k}={v}\"))\n\
             .collect();\n\
             assert!(!found.is_empty(), \"no secret in {:?}\", std::env::vars().map(|(k, _)| k).collect::<Vec<_>>());\n\
             println!(\"{found:?}\");";
        member(
            official,
            class,
            "reads-secret",
            Some(&ops(
                &format!("{secret}\n    x * 2"),
                &format!("{secret}\n    -x"),
            )),
        );

        // A child reads the test's memory, or traces it.
        let forge = format!(
            "    let out = std::process::Command::new(\"/usr/bin/python3\").args([\"-c\", {script:?}]).output().expect(\"python3 runs\");\n\
             let errnos = String::from_utf8_lossy(&out.stdout).trim().to_owned();\n\
             assert!(errnos != \"1 1\", \"denied: {{errnos}}\");\n\
             assert!(!errnos.is_empty(), \"python3 failed: {{}}\", String::from_utf8_lossy(&out.stderr));",
            script = dedent(READS_PARENT)
        );
        member(
            official,
            class,
            "reads-memory",
            Some(&ops(
                &format!("{forge}\n    x * 2"),
                &format!("{forge}\n    -x"),
            )),
        );

        // A build that never ends.
        member(
            official,
            class,
            "endless-build",
            Some(&format!(
                "#[allow(long_running_const_eval)]\n\
                 const FOREVER: i32 = {{ let mut i: i32 = 0; loop {{ i = i.wrapping_add(1); }} }};\n{}",
                ops("x * 2 + FOREVER * 0", "-x")
            )),
        );

        // Fills the sandbox's root, `/dev`, `/dev/shm`, `/tmp` and its scratch
        // folder: right only if 3 GiB fit.
        let fill = "    use std::io::Write as _;\n\
             let chunk = vec![7_u8; 1 << 20];\n\
             let mut written = 0;\n\
             let scratch = std::env::var(\"TMPDIR\").unwrap_or_default();\n\
             for dir in [\"/\", \"/dev\", \"/dev/shm\", \"/tmp\", scratch.as_str()] {\n\
                 for n in 0..2048 {\n\
                     let Ok(mut file) = std::fs::File::create(format!(\"{dir}/fill-{n}\")) else { break };\n\
                     if file.write_all(&chunk).is_err() { break; }\n\
                     written += 1;\n\
                 }\n\
             }\n\
             assert!(written >= 3072, \"wrote {written} MiB\");";
        member(
            official,
            class,
            "fills-disk",
            Some(&ops(
                &format!("{fill}\n    x * 2"),
                &format!("{fill}\n    -x"),
            )),
        );

        // Three children of 900 MiB each: right only if all three ran.
        let children = "    let children: Vec<_> = (0..3).map(|_| std::process::Command::new(\"/usr/bin/python3\")\n\
             .args([\"-c\", \"b = bytearray(900 << 20); import time; time.sleep(1)\"]).spawn().expect(\"python3 runs\")).collect();\n\
             let all = children.into_iter().all(|mut c| c.wait().is_ok_and(|s| s.success()));\n\
             assert!(all, \"a child was stopped\");";
        member(
            official,
            class,
            "many-children",
            Some(&ops(
                &format!("{children}\n    x * 2"),
                &format!("{children}\n    -x"),
            )),
        );

        // Threads without end: right only if 300 could be started at once
        // (the limit is 256 processes and threads together).
        let threads = "    let started: Vec<_> = (0..300).map(|_| std::thread::Builder::new()\n\
             .spawn(|| std::thread::sleep(std::time::Duration::from_secs(2)))).collect();\n\
             let refused = started.iter().filter(|s| s.is_err()).count();\n\
             assert_eq!(refused, 0, \"{refused} of 300 threads were refused\");";
        member(
            official,
            class,
            "many-threads",
            Some(&ops(
                &format!("{threads}\n    x * 2"),
                &format!("{threads}\n    -x"),
            )),
        );

        // Links without end where the grader lists a test's pictures; right.
        let loops = "    for dir in [std::env::var(\"TESTKIT_OUTPUT_DIR\").unwrap(), std::env::var(\"TMPDIR\").unwrap()] {\n\
             let _ = std::fs::create_dir_all(&dir);\n\
             let _ = std::os::unix::fs::symlink(\".\", format!(\"{dir}/a\"));\n\
             let _ = std::os::unix::fs::symlink(\".\", format!(\"{dir}/b\"));\n\
             let _ = std::fs::write(format!(\"{dir}/picture.txt\"), \"one\");\n\
             }";
        member(
            official,
            class,
            "link-loop",
            Some(&ops(
                &format!("{loops}\n    x * 2"),
                &format!("{loops}\n    -x"),
            )),
        );

        // Without its topic's folder: graded on the assignment's topics all
        // the same.
        let dropped = member(official, class, "drops-topic", None);
        fs::remove_dir_all(dropped.join("exercises/01-tiny")).unwrap();
    }

    pub fn every_attack_on_the_grader_is_contained_and_the_class_is_graded() {
        let official = fixture("tiny", "containment");
        // Time for a test to fill its disk, and a memory limit three children
        // of 900 MiB exceed together (each alone is far below it).
        let sheet = official.join("exercises/01-tiny/tasks.toml");
        let text = fs::read_to_string(&sheet).unwrap();
        fs::write(
            &sheet,
            text.replace(
                "time_limit_s = 5",
                "time_limit_s = 20\nmemory_limit_mib = 2048",
            ),
        )
        .unwrap();
        fs::create_dir_all(official.join(".git")).unwrap();
        fs::write(official.join(".git/HEAD"), "ref: refs/heads/main\n").unwrap();
        let class = Path::new(env!("CARGO_TARGET_TMPDIR")).join("containment-class");
        if class.exists() {
            fs::remove_dir_all(&class).unwrap();
        }
        write_class(&official, &class);
        let course_before = snapshot(&official);
        let out = crate::common::fresh(official.join("target/containment"));
        let limit = BUILD_LIMIT_S.to_string();
        let started = Instant::now();
        let output = std::process::Command::new(env!("CARGO_BIN_EXE_xtask"))
            .arg("--root")
            .arg(&official)
            .args(["grade", "--submission"])
            .arg(&class)
            .arg("--out")
            .arg(&out)
            .args(["--jobs", "2", "--build-time-limit", &limit])
            .env_remove("CARGO_TARGET_DIR")
            .env_remove("RUSTFLAGS")
            .env("GITHUB_TOKEN", SECRET)
            .env("COURSE_GRADER_SECRET", SECRET)
            .env("NO_COLOR", "1")
            .output()
            .expect("xtask runs");
        let elapsed = started.elapsed();
        eprintln!(
            "{}\n{}",
            String::from_utf8_lossy(&output.stdout),
            String::from_utf8_lossy(&output.stderr)
        );
        // Every member is graded and the gradebook written, within bounds: the
        // endless build costs its limit, not the class.
        assert!(
            elapsed < Duration::from_secs(600),
            "the class took {elapsed:?}"
        );
        let gradebook = fs::read_to_string(out.join("gradebook.csv")).expect("a gradebook");
        let honest = read_json(&out.join("a-honest/report.json"));
        assert_eq!(honest["score"], 3.0, "the baseline member earns its points");
        assert_eq!(
            honest["sandboxed"], true,
            "on Linux the attacks must meet the sandbox (install bubblewrap)"
        );
        assert_eq!(honest["containment"]["seccomp"], true, "{honest:#}");

        let report = |name: &str| read_json(&out.join(name).join("report.json"));
        let zero = |name: &str| {
            let report = report(name);
            assert_eq!(
                report["score"],
                0.0,
                "{name} scored: {}",
                first_reason(&report)
            );
            first_reason(&report)
        };
        for name in ["links-solutions", "links-classmate"] {
            let why = zero(name);
            // The task folder is refused as a link (nofollow.rs's words).
            assert!(
                why.contains("is a symbolic link") || why.contains("is not a folder (a link"),
                "{name}: {why}"
            );
        }
        // The macro's path names a file the sandbox does not show.
        let why = zero("macro-path");
        assert!(why.contains("couldn't read"), "macro-path: {why}");
        let why = zero("reads-machine");
        assert!(why.contains("saw nothing of the machine"), "{why}");
        let why = zero("reads-secret");
        assert!(why.contains("no secret in"), "{why}");
        // The child did run, and was denied both calls.
        let why = zero("reads-memory");
        assert!(why.contains("denied: 1 1"), "reads-memory: {why}");
        // Refused before it builds: it lifts the bound on const evaluation
        // (see `sandbox/const_eval.rs`); the build limit is the backstop.
        let why = zero("endless-build");
        assert!(
            why.contains("long_running_const_eval")
                || why.contains(&format!("did not finish in {BUILD_LIMIT_S} s"))
                || why.contains("CPU time"),
            "endless-build: {why}"
        );
        // The root and `/dev` are read-only, `/dev/shm` and `/tmp` full at
        // their sizes; the scratch folder is stopped past the limit, and gone
        // after the test.
        let why = zero("fills-disk");
        // Under software emulation (`tests/cgroup-v2/run.sh`) a GiB is not
        // written within the test's 20 s: stopped by the time limit first.
        let emulated = std::env::var_os("XTASK_EMULATED").is_some();
        assert!(
            why.contains("wrote more than 1024 MiB")
                || (emulated && why.contains("timed out after")),
            "fills-disk: {why}"
        );
        let scratch = out.join("fills-disk/scratch/01-tiny/double/doubles_positive_numbers");
        assert!(!scratch.exists(), "a test's scratch folder is kept");
        if honest["containment"]["aggregate_limits"] == true {
            let why = zero("many-children");
            // (Emulated, the children fill their memory too slowly to reach
            // the limit within 20 s; the runner's own test of the memory of
            // processes together, `sandbox::tests`, runs there too.)
            assert!(
                why.contains("out of memory")
                    || why.contains("a child was stopped")
                    || (emulated && why.contains("timed out after")),
                "many-children: {why}"
            );
        } else {
            eprintln!(
                "not checked: no cgroup here, so the memory of a test's processes together is not limited"
            );
        }
        if honest["containment"]["aggregate_limits"] == true {
            // Refused threads past the cgroup's pids.max, and the reason
            // says which limit.
            let why = zero("many-threads");
            assert!(
                why.contains("met the limit of 256 at once"),
                "many-threads: {why}"
            );
        }
        let looped = report("link-loop");
        assert_eq!(looped["score"], 3.0, "{looped:#}");
        let images = task(&looped, "01-tiny", "double")["tests"][0]["images"].clone();
        assert_eq!(images, serde_json::json!(["picture.txt"]), "{looped:#}");
        let why = zero("drops-topic");
        assert!(
            why.contains("has no exercises/01-tiny"),
            "drops-topic: {why}"
        );
        let dropped = report("drops-topic");
        assert_eq!(dropped["max_score"], 3.0);
        // A topic the submission lacks is neither built nor run: its
        // tasks score 0 by the reason, not by the stubs' failing tests.
        let double = task(&dropped, "01-tiny", "double");
        assert_eq!(double["status"], "error", "{dropped:#}");
        assert_eq!(double["tests"], serde_json::json!([]), "{dropped:#}");

        // The secret is in no file the grade wrote.
        let mut leaked = Vec::new();
        let mut stack = vec![out.clone()];
        while let Some(dir) = stack.pop() {
            for entry in fs::read_dir(&dir).unwrap().flatten() {
                let path = entry.path();
                let kind = entry.file_type().unwrap();
                if kind.is_dir() {
                    stack.push(path);
                } else if kind.is_file()
                    && String::from_utf8_lossy(&fs::read(&path).unwrap()).contains(SECRET)
                {
                    leaked.push(path);
                }
            }
        }
        assert!(leaked.is_empty(), "the secret leaked into {leaked:?}");
        // Nothing of the course changed, and nothing was left in /tmp.
        assert!(
            snapshot(&official) == course_before,
            "the course changed while grading"
        );
        assert!(
            !Path::new("/tmp/fill-0").exists(),
            "a test's /tmp was the machine's"
        );
        assert!(gradebook.contains("a-honest,3,3"), "{gradebook}");
    }
}
