//! Student code that the report's pipeline viewer runs, tried as a
//! determined student would (see `containment.rs`): it must be contained
//! as a test is. On Linux only, where the sandbox is bubblewrap.

mod common;

#[test]
fn student_code_in_the_reports_viewer_is_contained() {
    #[cfg(target_os = "linux")]
    linux::student_code_in_the_reports_viewer_is_contained();
    #[cfg(not(target_os = "linux"))]
    eprintln!("not run: the sandbox these attacks are contained by is Linux's (bubblewrap)");
}

/// The attacks, which need Linux (symbolic links, `/proc`, bubblewrap).
#[cfg(target_os = "linux")]
mod linux {
    use std::fs;
    use std::path::Path;
    use std::time::{Duration, Instant};

    use super::common::class::{first_reason, ops, snapshot};
    use super::common::{copy_dir, fixture, grade_submission, read_json};

    /// The report's pipeline viewer of a course whose first topic is
    /// `01-lines` (the viewer's `lines` stage): a stand-in viewer that calls
    /// the student's `double` and writes its picture where `--screenshot`
    /// says, with the expected pictures beside it.
    const VIEWER_MANIFEST: &str = "[package]\nname = \"course-viewer\"\nversion = \"0.1.0\"\nedition = \"2024\"\npublish = false\n\n\
        [features]\nlines = [\"dep:tiny\"] # topic 01-lines\n\n[dependencies]\ntiny = { path = \"../../exercises/01-lines\", optional = true }\n";
    const VIEWER_MAIN: &str = "fn main() {\n    let args: Vec<String> = std::env::args().collect();\n    \
        let at = args.iter().position(|a| a == \"--screenshot\").expect(\"--screenshot\");\n    \
        #[cfg(feature = \"lines\")]\n    assert_eq!(tiny::ops::double(21), 42);\n    \
        std::fs::write(&args[at + 1], b\"a picture\").unwrap();\n    \
        println!(\"lines  drawn  (01-lines · src/ops.rs)\");\n}\n";

    /// What the student's `double` does when the report's viewer calls it
    /// (the viewer's arguments tell the four pictures apart): fill the
    /// disk from the picture's folder (the star), take all memory (the
    /// torus), write the report's picture, the course and `/tmp` (the
    /// clipped torus, which then draws its picture; `/tmp` is its own),
    /// and leave a process
    /// behind (the unclipped torus).
    const VIEWER_ATTACK: &str = r#"    let args: Vec<String> = std::env::args().collect();
    if let Some(at) = args.iter().position(|a| a == "--screenshot") {
        let shot = std::path::PathBuf::from(&args[at + 1]);
        let dir = shot.parent().unwrap().to_path_buf();
        if args.iter().any(|a| a == "star.ply") {
            let block = vec![7u8; 1 << 20];
            let mut file = std::fs::File::create(dir.join("fill")).unwrap();
            loop {
                std::io::Write::write_all(&mut file, &block).unwrap();
            }
        }
        if args.iter().any(|a| a == "torus.ply") {
            let mut held = Vec::new();
            loop {
                held.push(vec![1u8; 64 << 20]);
            }
        }
        if args.iter().any(|a| a == "--no-clip") {
            let started = std::process::Command::new("sh")
                .args(["-c", "setsid sleep 7771 >/dev/null 2>&1 &"])
                .status()
                .is_ok_and(|s| s.success());
            eprintln!("left a process behind: {started}");
        } else {
            // The report's expected picture, the staged course and the
            // official course the stage lies in (`<course>/target/xtask/stage`).
            let report = dir.join("../../..");
            let stage = std::env::current_dir().unwrap();
            for target in [
                report.join("pipeline/expected-star-wireframe.png"),
                stage.join("Cargo.toml"),
                stage.join("../../../Cargo.toml"),
            ] {
                let denied = std::fs::write(&target, b"forged").is_err();
                eprintln!("forging {}: {}", target.display(), if denied { "denied" } else { "WRITTEN" });
            }
            // The sandbox's own `/tmp`, not the machine's.
            std::fs::write("/tmp/pipeline-escape", b"forged").unwrap();
        }
        std::fs::write(&shot, b"a picture of the attacker's").unwrap();
    }
    x * 2"#;

    /// Student code the report's pipeline viewer runs is contained as a
    /// test is: its limits hold, it writes nothing but its picture, leaves
    /// no process, and the report's other files are the grader's.
    pub fn student_code_in_the_reports_viewer_is_contained() {
        let official = fixture("tiny", "viewer");
        for side in ["exercises", "reference"] {
            fs::rename(
                official.join(side).join("01-tiny"),
                official.join(side).join("01-lines"),
            )
            .unwrap();
        }
        let manifest = official.join("Cargo.toml");
        let text = fs::read_to_string(&manifest).unwrap();
        fs::write(
            &manifest,
            text.replace(
                "members = [\"exercises/*\"]",
                "members = [\"exercises/*\", \"xtask/viewer\"]",
            ),
        )
        .unwrap();
        let viewer = official.join("xtask/viewer");
        fs::create_dir_all(viewer.join("src")).unwrap();
        fs::create_dir_all(viewer.join("expected")).unwrap();
        fs::write(viewer.join("Cargo.toml"), VIEWER_MANIFEST).unwrap();
        fs::write(viewer.join("src/main.rs"), VIEWER_MAIN).unwrap();
        let expected = b"the expected star".as_slice();
        fs::write(viewer.join("expected/star-wireframe.png"), expected).unwrap();
        let course_before = snapshot(&official);

        let class = Path::new(env!("CARGO_TARGET_TMPDIR")).join("viewer-class");
        if class.exists() {
            fs::remove_dir_all(&class).unwrap();
        }
        let checkout = class.join("attacker");
        for folder in ["exercises", "crates", "xtask"] {
            copy_dir(&official.join(folder), &checkout.join(folder));
        }
        fs::copy(&manifest, checkout.join("Cargo.toml")).unwrap();
        fs::write(
            checkout.join("exercises/01-lines/src/ops.rs"),
            ops(VIEWER_ATTACK, "-x"),
        )
        .unwrap();
        let out = crate::common::fresh(official.join("target/viewer"));
        let started = Instant::now();
        let output = grade_submission(&official, &checkout, &out, &[]);
        assert!(output.status.success());
        assert!(
            started.elapsed() < Duration::from_secs(600),
            "the grade took {:?}",
            started.elapsed()
        );
        let member = out.join("attacker");
        let report = read_json(&member.join("report.json"));
        assert_eq!(
            report["sandboxed"], true,
            "on Linux the attacks must meet the sandbox (install bubblewrap)"
        );
        assert_eq!(report["score"], 3.0, "{}", first_reason(&report));
        let pictures = report["pipeline"].as_array().expect("pipeline pictures");
        assert_eq!(pictures.len(), 4, "{report:#}");
        let scratch = member.join("scratch/pipeline");
        let error = |i: usize| pictures[i]["error"].as_str().unwrap_or_default().to_owned();
        assert!(
            error(0).contains("wrote more than 1024 MiB"),
            "the disk filler: {:#}",
            pictures[0]
        );
        assert!(
            error(1).contains("out of memory"),
            "the memory taker: {:#}",
            pictures[1]
        );
        // The pictures of the clipped torus are drawn (so the attacks ran:
        // the attacker's picture is overwritten by the viewer's after), and
        // the forged files are not.
        for (i, file) in [(2, "clipped-torus.png"), (3, "clipped-torus-unclipped.png")] {
            assert_eq!(
                pictures[i]["yours"],
                format!("pipeline/{file}"),
                "{report:#}"
            );
            assert_eq!(
                fs::read(member.join("pipeline").join(file)).unwrap(),
                b"a picture"
            );
        }
        let said = |scene: &str| {
            fs::read_to_string(scratch.join(scene).with_extension("err")).unwrap_or_default()
        };
        // The attacks ran; whether a write was refused or landed in the
        // sandbox's own `/tmp` (where the report lies under `/tmp`, as in
        // a CI checkout there), the real files are the grader's.
        let forging = said("clipped-torus");
        assert_eq!(forging.matches("forging ").count(), 3, "{forging}");
        assert!(
            said("clipped-torus-unclipped").contains("left a process behind: true"),
            "the process was not started"
        );
        assert_eq!(
            fs::read(member.join("pipeline/expected-star-wireframe.png")).unwrap(),
            expected
        );
        assert!(
            !Path::new("/tmp/pipeline-escape").exists(),
            "wrote the machine's /tmp"
        );
        assert!(snapshot(&official) == course_before, "the course changed");
        // The viewer's folders are gone, and nothing large is left.
        let left: Vec<_> = fs::read_dir(&scratch)
            .map(|entries| entries.flatten().map(|e| e.path()).collect())
            .unwrap_or_default();
        assert!(
            left.iter()
                .all(|p| p.extension().is_some_and(|e| e != "tmp")),
            "left behind: {left:?}"
        );
        // No process outlived its picture.
        let stray = fs::read_dir("/proc")
            .unwrap()
            .flatten()
            .filter_map(|e| fs::read(e.path().join("cmdline")).ok())
            .any(|cmdline| String::from_utf8_lossy(&cmdline).contains("7771"));
        assert!(!stray, "a process the viewer started outlived it");
    }
}
