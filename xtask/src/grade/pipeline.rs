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
pub const VIEWER_TOPICS: [(&str, &str); 6] = [
    STAGES[0],
    ("circles", "02-circles"),
    STAGES[1],
    STAGES[2],
    STAGES[3],
    ("bezier", "07-bezier"),
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
    let output = match run_with_limit(command) {
        Ok(output) => output,
        Err(error) => {
            result.error = Some(format!("{error:#}"));
            return result;
        }
    };
    let stdout = String::from_utf8_lossy(&output.stdout);
    result.stages = stdout
        .lines()
        .filter(|line| !line.starts_with("wrote "))
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

/// Runs `command` to its end or [`TIME_LIMIT`].
fn run_with_limit(mut command: Command) -> Result<std::process::Output> {
    let mut child = command.spawn().context("cannot start the viewer")?;
    let started = Instant::now();
    loop {
        if child
            .try_wait()
            .context("cannot wait for the viewer")?
            .is_some()
        {
            return child
                .wait_with_output()
                .context("cannot read the viewer's output");
        }
        if started.elapsed() > TIME_LIMIT {
            let _ = child.kill();
            let _ = child.wait();
            anyhow::bail!(
                "the picture took longer than {} s (an endless loop in a stage?)",
                TIME_LIMIT.as_secs()
            );
        }
        std::thread::sleep(Duration::from_millis(50));
    }
}
