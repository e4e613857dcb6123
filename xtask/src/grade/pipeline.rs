//! The report's "Your pipeline" section: the shipped meshes drawn by the
//! student's own stages (clipping, lines, fill, depth test) through the
//! course viewer (`xtask/viewer`, built without its window), beside the
//! pictures the solutions draw (`xtask/viewer/expected/`). No points
//! depend on it; it is there to be looked at.
//!
//! The viewer is built in the build sandbox and run in the test sandbox,
//! as the tests are, with a time limit: it is student code.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use anyhow::{Context, Result};
use serde::Serialize;

use super::build::BuildSandbox;
use super::run::Sandbox;
use crate::cargo::{self, cargo};

/// The viewer's package.
pub const VIEWER: &str = "course-viewer";

/// The viewer's features and the topics whose stages they build in.
pub const STAGES: [(&str, &str); 4] = [
    ("lines", "01-lines"),
    ("fill", "03-fill"),
    ("clipping", "04-clipping"),
    ("buffers", "05-buffers"),
];

/// The viewer's features and topics in `cargo xtask view`: the pipeline's,
/// the pixel playground's circle and the curve scene's de Casteljau.
pub const VIEWER_TOPICS: [(&str, &str); 9] = [
    STAGES[0],
    ("circles", "02-circles"),
    STAGES[1],
    STAGES[2],
    STAGES[3],
    ("bezier", "07-bezier"),
    ("nurbs", "08-nurbs"),
    ("tessellation", "09-tessellation"),
    ("gpu-tessellation", "10-gpu-tessellation"),
];

/// How long one picture may take.
const TIME_LIMIT: Duration = Duration::from_secs(30);

/// One picture: its file name, what it shows and the viewer's arguments.
struct Scene {
    file: &'static str,
    what: &'static str,
    args: &'static [&'static str],
}

/// The pictures, in the report's order (as `course_viewer::render::REPORT_SCENES`,
/// whose test pins `xtask/viewer/expected/` to them): seed 004's figures of the star and
/// the torus, and the clipped torus with and without clipping.
const SCENES: [Scene; 4] = [
    Scene {
        file: "star-wireframe.png",
        what: "star.ply, wireframe: clipping, lines, depth test",
        args: &["--mesh", "star.ply", "--mode", "wireframe"],
    },
    Scene {
        file: "torus-filled.png",
        what: "torus.ply, filled: clipping, fill, depth test",
        args: &["--mesh", "torus.ply", "--mode", "filled"],
    },
    Scene {
        file: "clipped-torus.png",
        what: "clipped_torus.ply, filled and clipped",
        args: &["--mesh", "clipped_torus.ply", "--mode", "filled"],
    },
    Scene {
        file: "clipped-torus-unclipped.png",
        what: "clipped_torus.ply, filled, without clipping: what clipping removes",
        args: &[
            "--mesh",
            "clipped_torus.ply",
            "--mode",
            "filled",
            "--no-clip",
        ],
    },
];

/// The pictures' size in pixels.
const SIZE: &str = "200";

/// The expected pictures, relative to the course.
pub const EXPECTED_DIR: &str = "xtask/viewer/expected";

/// One picture of the section.
#[derive(Debug, Clone, Serialize)]
pub struct PipelinePicture {
    /// What it shows.
    pub what: String,
    /// The picture the student's stages drew, if they drew one (relative
    /// to the report folder).
    pub yours: Option<PathBuf>,
    /// What the solutions draw (a copy, relative to the report folder).
    pub expected: Option<PathBuf>,
    /// How each stage fared, one line each, as the viewer says it.
    pub stages: Vec<String>,
    /// Why there is no picture.
    pub error: Option<String>,
}

/// Where and how the viewer is run.
pub struct Plan<'a> {
    /// The staged course.
    pub root: &'a Path,
    /// The report folder.
    pub out: &'a Path,
    /// The test sandbox's program and hidden folders, if any.
    pub sandbox: Option<(&'a Path, &'a [PathBuf])>,
}

/// The viewer of a grade, built before the tests run.
#[derive(Debug)]
pub enum Viewer {
    /// The course has no viewer, or none of the pipeline's topics was graded.
    None,
    /// Its executable.
    Built(PathBuf),
    /// Why it did not build.
    Failed(String),
}

/// Builds the viewer of the staged course at `root` with the stages of the
/// `compiled` topics, when the course has one and a pipeline topic is
/// among the `graded`.
pub fn build_viewer(
    root: &Path,
    target_dir: Option<&Path>,
    build_sandbox: Option<&BuildSandbox>,
    graded: &[&str],
    compiled: &[&str],
) -> Viewer {
    let has_viewer = root
        .join("xtask")
        .join("viewer")
        .join("Cargo.toml")
        .is_file();
    if !has_viewer || !STAGES.iter().any(|(_, topic)| graded.contains(topic)) {
        return Viewer::None;
    }
    let features: Vec<&str> = STAGES
        .iter()
        .filter(|(_, topic)| compiled.contains(topic))
        .map(|(feature, _)| *feature)
        .collect();
    match build(root, target_dir, build_sandbox, &features) {
        Ok(binary) => Viewer::Built(binary),
        Err(error) => Viewer::Failed(format!("{error:#}")),
    }
}

/// Draws the pictures with the viewer built by [`build_viewer`].
pub fn draw_all(plan: &Plan<'_>, viewer: &Viewer) -> Vec<PipelinePicture> {
    let dir = plan.out.join("pipeline");
    let _ = fs::remove_dir_all(&dir);
    let failed = |error: String| {
        SCENES
            .iter()
            .map(|scene| PipelinePicture {
                what: scene.what.to_owned(),
                yours: None,
                expected: expected(plan.root, plan.out, scene),
                stages: Vec::new(),
                error: Some(error.clone()),
            })
            .collect()
    };
    let binary = match viewer {
        Viewer::None => return Vec::new(),
        Viewer::Failed(error) => return failed(format!("the viewer did not build: {error}")),
        Viewer::Built(binary) => binary,
    };
    if let Err(error) = fs::create_dir_all(&dir) {
        return failed(format!("cannot create {}: {error}", dir.display()));
    }
    // A stage that loops costs one time limit, not one per picture.
    let mut stuck: Option<String> = None;
    SCENES
        .iter()
        .map(|scene| match &stuck {
            Some(error) => PipelinePicture {
                what: scene.what.to_owned(),
                yours: None,
                expected: expected(plan.root, plan.out, scene),
                stages: Vec::new(),
                error: Some(format!("not drawn: {error}")),
            },
            None => {
                let picture = draw(plan, binary, &dir, scene);
                if picture.yours.is_none() {
                    stuck = picture.error.clone().filter(|e| e.contains("took longer"));
                }
                picture
            }
        })
        .collect()
}

/// The expected picture of `scene`, copied into the report's `pipeline/`
/// folder (so that the report folder holds everything it shows).
fn expected(root: &Path, out: &Path, scene: &Scene) -> Option<PathBuf> {
    let relative = Path::new("pipeline").join(format!("expected-{}", scene.file));
    let target = out.join(&relative);
    fs::create_dir_all(target.parent()?).ok()?;
    fs::copy(root.join(EXPECTED_DIR).join(scene.file), &target).ok()?;
    Some(relative)
}

/// Builds the viewer without its window; its executable.
fn build(
    root: &Path,
    target_dir: Option<&Path>,
    build_sandbox: Option<&BuildSandbox>,
    features: &[&str],
) -> Result<PathBuf> {
    let mut command = cargo();
    command
        .current_dir(root)
        .args(["build", "--package", VIEWER, "--no-default-features"])
        .args([
            "--message-format",
            "json-render-diagnostics",
            "--color",
            "never",
        ]);
    if !features.is_empty() {
        command.args(["--features", &features.join(",")]);
    }
    if let Some(dir) = target_dir {
        command.env("CARGO_TARGET_DIR", dir);
    }
    let mut command = match build_sandbox {
        Some(sandbox) => sandbox.wrap(&command)?,
        None => command,
    };
    let output = command
        .output()
        .with_context(|| format!("cannot run `{}`", cargo::display(&command)))?;
    anyhow::ensure!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
            .lines()
            .filter(|l| l.starts_with("error"))
            .collect::<Vec<_>>()
            .join("; ")
    );
    String::from_utf8_lossy(&output.stdout)
        .lines()
        .filter_map(|line| serde_json::from_str::<serde_json::Value>(line).ok())
        .filter(|m| m["reason"] == "compiler-artifact" && m["target"]["name"] == VIEWER)
        .find_map(|m| m["executable"].as_str().map(PathBuf::from))
        .context("cargo built no viewer executable")
}

/// Runs the viewer for one picture, in the sandbox, within the time limit.
fn draw(plan: &Plan<'_>, binary: &Path, dir: &Path, scene: &Scene) -> PipelinePicture {
    let picture = dir.join(scene.file);
    let mut command = match plan.sandbox {
        Some((program, hidden)) => Sandbox {
            program: program.to_path_buf(),
            read_only: std::iter::once(plan.root.to_path_buf())
                .chain(binary.ancestors().nth(2).map(Path::to_path_buf))
                .collect(),
            hidden: hidden
                .iter()
                .cloned()
                .chain([plan.out.to_path_buf()])
                .collect(),
            writable: vec![dir.to_path_buf()],
        }
        .command(plan.root),
        None => {
            let mut command = Command::new("env");
            command.current_dir(plan.root);
            command
        }
    };
    command
        .arg(binary)
        .args(scene.args)
        .args(["--size", SIZE, "--time-limit", "25", "--screenshot"])
        .arg(&picture)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    let mut result = PipelinePicture {
        what: scene.what.to_owned(),
        yours: None,
        expected: expected(plan.root, plan.out, scene),
        stages: Vec::new(),
        error: None,
    };
    let output = match run_with_limit(command, TIME_LIMIT) {
        Ok(output) => output,
        Err(error) => {
            result.error = Some(format!("{error:#}"));
            return result;
        }
    };
    let stdout = String::from_utf8_lossy(&output.stdout);
    // The viewer's report, one line a stage: `name  status  (source)`;
    // anything the stages printed themselves is left out.
    result.stages = stdout
        .lines()
        .filter(|line| is_stage_line(line))
        .map(str::to_owned)
        .collect();
    if output.status.success() && picture.is_file() {
        result.yours = Some(Path::new("pipeline").join(scene.file));
    } else {
        let stderr = String::from_utf8_lossy(&output.stderr);
        result.error = Some(
            stderr
                .lines()
                .find(|l| l.starts_with("Error") || l.starts_with("error"))
                .unwrap_or("the viewer drew no picture")
                .to_owned(),
        );
    }
    result
}

/// Whether `line` is one of the viewer's stage lines (`--screenshot`
/// prints one per stage: its name, how it fared, and where its code is,
/// `(04-clipping · …)`).
fn is_stage_line(line: &str) -> bool {
    line.ends_with(')') && line.contains("  (") && line.contains(" · ")
}

/// How much of the viewer's output is kept, per stream: its end, where the
/// stage report is (a stage that prints while it draws, `println!` for
/// debugging, can print far more).
const OUTPUT_KEPT: usize = 64 * 1024;

/// Runs `command` to its end or `limit`, reading its output while it runs
/// (a pipe nobody reads fills up and stops the writer, which would look
/// like an endless loop) and keeping the last [`OUTPUT_KEPT`] bytes of each
/// stream.
fn run_with_limit(mut command: Command, limit: Duration) -> Result<std::process::Output> {
    let mut child = command.spawn().context("cannot start the viewer")?;
    let stdout = drain(child.stdout.take());
    let stderr = drain(child.stderr.take());
    let started = Instant::now();
    loop {
        if let Some(status) = child.try_wait().context("cannot wait for the viewer")? {
            let collect =
                |reader: std::thread::JoinHandle<Vec<u8>>| reader.join().unwrap_or_default();
            return Ok(std::process::Output {
                status,
                stdout: collect(stdout),
                stderr: collect(stderr),
            });
        }
        if started.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            anyhow::bail!(
                "the picture took longer than {} s (an endless loop in a stage?)",
                limit.as_secs_f64()
            );
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// Reads `pipe` to its end on a thread of its own; the last
/// [`OUTPUT_KEPT`] bytes.
fn drain(pipe: Option<impl std::io::Read + Send + 'static>) -> std::thread::JoinHandle<Vec<u8>> {
    std::thread::spawn(move || {
        let mut kept = Vec::new();
        let Some(mut pipe) = pipe else {
            return kept;
        };
        let mut buffer = [0; 8192];
        loop {
            match pipe.read(&mut buffer) {
                Ok(0) | Err(_) => break,
                Ok(n) => {
                    kept.extend_from_slice(&buffer[..n]);
                    if kept.len() > 2 * OUTPUT_KEPT {
                        kept.drain(..kept.len() - OUTPUT_KEPT);
                    }
                }
            }
        }
        if kept.len() > OUTPUT_KEPT {
            kept.drain(..kept.len() - OUTPUT_KEPT);
        }
        kept
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shell(script: &str) -> Command {
        let mut command = Command::new("sh");
        command
            .args(["-c", script])
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped());
        command
    }

    #[test]
    fn a_picture_that_never_ends_is_stopped_at_the_limit() {
        let started = Instant::now();
        let error = run_with_limit(shell("while :; do :; done"), Duration::from_millis(300))
            .unwrap_err()
            .to_string();
        assert!(error.contains("took longer"), "{error}");
        assert!(started.elapsed() < Duration::from_secs(10));
    }

    /// A stage that prints while it draws (println! for debugging) must
    /// not look like an endless loop: a pipe nobody read would fill after
    /// 64 KiB and stop the viewer until the limit.
    #[test]
    fn a_stage_that_prints_a_lot_still_finishes_and_its_report_is_kept() {
        let script = "head -c 3000000 /dev/zero | tr '\\\\0' 'x'; echo; \
                      echo 'lines      ok  (01-lines · dda::dda_line)'; \
                      head -c 300000 /dev/zero >&2";
        let output = run_with_limit(shell(script), Duration::from_secs(20)).unwrap();
        assert!(output.status.success());
        assert!(output.stdout.len() <= OUTPUT_KEPT && output.stderr.len() <= OUTPUT_KEPT);
        let stdout = String::from_utf8_lossy(&output.stdout);
        let stages: Vec<&str> = stdout.lines().filter(|l| is_stage_line(l)).collect();
        assert_eq!(stages, ["lines      ok  (01-lines · dda::dda_line)"]);
        assert!(
            !is_stage_line("(x, y) = (1, 2)"),
            "a student's print is not a stage line"
        );
    }
}
