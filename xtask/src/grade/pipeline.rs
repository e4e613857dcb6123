//! The report's "Your pipeline" section: the shipped meshes drawn by the
//! student's own stages (clipping, lines, fill, depth test) through the
//! course viewer (`xtask/viewer`, built without its window), beside the
//! pictures the solutions draw (`xtask/viewer/expected/`). No points
//! depend on it; it is there to be looked at.
//!
//! The viewer is student code: it is built and run by the one runner
//! ([`crate::sandbox`]) as the tests are, with their limits.

use std::ffi::OsString;
use std::fs;
use std::path::{Path, PathBuf};
use std::time::Duration;

use anyhow::{Context, Result};
use serde::{Deserialize, Serialize};

use super::build::Builder;
use crate::sandbox::{Jail, Job, Limits, Purpose};

/// The viewer's package.
pub const VIEWER: &str = "course-viewer";

/// The viewer's manifest, relative to the course: each feature that
/// builds a topic's stages in is marked `# topic NN-name` on its line, the
/// one place where features and topics are paired.
pub const VIEWER_MANIFEST: &str = "xtask/viewer/Cargo.toml";

/// The viewer's features and the topics they draw with, in the order of
/// its manifest ([`VIEWER_MANIFEST`]); none where the course has no viewer.
#[must_use]
pub fn viewer_topics(root: &Path) -> Vec<(String, String)> {
    let Ok(manifest) = fs::read_to_string(root.join(VIEWER_MANIFEST)) else {
        return Vec::new();
    };
    feature_topics(&manifest)
}

/// The `feature = [...] # topic NN-name` lines of a manifest's `[features]`.
fn feature_topics(manifest: &str) -> Vec<(String, String)> {
    let mut in_features = false;
    let mut pairs = Vec::new();
    for line in manifest.lines() {
        let line = line.trim();
        if line.starts_with('[') {
            in_features = line == "[features]";
        } else if in_features
            && let Some((code, topic)) = line.split_once("# topic ")
            && let Some((feature, _)) = code.split_once('=')
        {
            pairs.push((feature.trim().to_owned(), topic.trim().to_owned()));
        }
    }
    pairs
}

/// The topics of the mesh pipeline's pictures.
const MESH_TOPICS: [&str; 4] = ["01-lines", "03-fill", "04-clipping", "05-buffers"];
/// The topics of the NURBS chain's picture.
const CHAIN_TOPICS: [&str; 2] = ["08-nurbs", "09-tessellation"];

/// How long one picture may take.
const TIME_LIMIT: Duration = Duration::from_secs(30);

/// One picture: its file name, what it shows, the viewer's arguments and
/// the topics it draws with.
struct Scene {
    file: &'static str,
    what: &'static str,
    args: &'static [&'static str],
    needs: Needs,
}

/// Which graded topics a picture is drawn for.
#[derive(Clone, Copy)]
enum Needs {
    /// Any of these: a mesh picture names the stages that are missing.
    Any(&'static [&'static str]),
    /// All of these: the chain has nothing to show without either.
    All(&'static [&'static str]),
}

impl Needs {
    /// Whether an assignment of the `graded` topics holds the stages.
    fn met(self, graded: &[&str]) -> bool {
        match self {
            Self::Any(topics) => topics.iter().any(|t| graded.contains(t)),
            Self::All(topics) => topics.iter().all(|t| graded.contains(t)),
        }
    }
}

/// The pictures, in the report's order (as `course_viewer::scenes::mesh::REPORT_SCENES`
/// and `course_viewer::scenes::tessellation::REPORT_CHAIN`, whose tests pin
/// `xtask/viewer/expected/` to them): seed 004's figures of the star and
/// the torus, the clipped torus with and without clipping, and the NURBS
/// chain of seed 001 (NURBS → Bézier patches → triangles).
const SCENES: [Scene; 5] = [
    Scene {
        file: "star-wireframe.png",
        what: "star.ply, wireframe: clipping, lines, depth test",
        args: &["--mesh", "star.ply", "--mode", "wireframe"],
        needs: Needs::Any(&MESH_TOPICS),
    },
    Scene {
        file: "torus-filled.png",
        what: "torus.ply, filled: clipping, fill, depth test",
        args: &["--mesh", "torus.ply", "--mode", "filled"],
        needs: Needs::Any(&MESH_TOPICS),
    },
    Scene {
        file: "clipped-torus.png",
        what: "clipped_torus.ply, filled and clipped",
        args: &["--mesh", "clipped_torus.ply", "--mode", "filled"],
        needs: Needs::Any(&MESH_TOPICS),
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
        needs: Needs::Any(&MESH_TOPICS),
    },
    Scene {
        file: "nurbs-chain-vase.png",
        what: "the NURBS vase (single interior knots) split into 12 Bézier patches by your topic 08, \
               tessellated by your topic 09 (uniform, 4 × 4 cells a patch)",
        args: &["--chain", "vase"],
        needs: Needs::All(&CHAIN_TOPICS),
    },
];

/// The pictures' size in pixels.
const SIZE: &str = "200";

/// The expected pictures, relative to the course.
pub const EXPECTED_DIR: &str = "xtask/viewer/expected";

/// One picture of the section.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct PipelinePicture {
    /// Its file name (`star-wireframe.png`).
    pub file: String,
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
    /// The graded topics: a picture is drawn when they hold its stages.
    pub graded: &'a [&'a str],
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
    /// Not built: no stage of the pictures' topics passes a test yet, so
    /// the pictures would show nothing of the student's (a grade built
    /// topic by topic, the student's own: the viewer's first build takes
    /// about half a minute, the first grade's longest wait after the
    /// dependencies).
    NotYet,
}

/// Whether the student's stages can draw anything yet: some topic whose
/// stages the pictures draw with passes a test (`passed`: each graded
/// topic and the tests it passes).
#[must_use]
pub fn worth_drawing(passed: &[(&str, usize)]) -> bool {
    passed.iter().any(|&(topic, passed)| {
        passed > 0 && (MESH_TOPICS.contains(&topic) || CHAIN_TOPICS.contains(&topic))
    })
}

/// Builds the viewer of the staged course at `root` with the stages of the
/// `compiled` topics, when the course has one and a pipeline topic is
/// among the `graded`.
pub fn build_viewer(builder: &Builder, graded: &[&str], compiled: &[&str]) -> Viewer {
    let has_viewer = builder
        .root
        .join("xtask")
        .join("viewer")
        .join("Cargo.toml")
        .is_file();
    if !has_viewer || !SCENES.iter().any(|scene| scene.needs.met(graded)) {
        return Viewer::None;
    }
    // The features of the pictures' stages whose topics compile.
    let pairs = viewer_topics(&builder.root);
    let features: Vec<&str> = pairs
        .iter()
        .filter(|(_, topic)| {
            (MESH_TOPICS.contains(&topic.as_str()) || CHAIN_TOPICS.contains(&topic.as_str()))
                && compiled.contains(&topic.as_str())
        })
        .map(|(feature, _)| feature.as_str())
        .collect();
    match build(builder, &features) {
        Ok(binary) => Viewer::Built(binary),
        Err(error) => Viewer::Failed(format!("{error:#}")),
    }
}

/// Draws the pictures with the viewer built by [`build_viewer`].
pub fn draw_all(plan: &Plan<'_>, viewer: &Viewer) -> Vec<PipelinePicture> {
    let dir = plan.out.join("pipeline");
    let _ = crate::files::remove_tree(&dir);
    let scenes: Vec<&Scene> = SCENES
        .iter()
        .filter(|scene| scene.needs.met(plan.graded))
        .collect();
    let failed = |error: String| {
        scenes
            .iter()
            .map(|scene| PipelinePicture {
                file: scene.file.to_owned(),
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
        Viewer::NotYet => {
            return failed(
                "drawn once one of your stages (clipping, lines, fill, depth test, NURBS, tessellation) passes a test"
                    .to_owned(),
            );
        }
        Viewer::Built(binary) => binary,
    };
    if let Err(error) = fs::create_dir_all(&dir) {
        return failed(format!("cannot create {}: {error}", dir.display()));
    }
    // A stage that loops costs one time limit, not one per picture.
    let mut stuck: Option<String> = None;
    scenes
        .iter()
        .map(|scene| match &stuck {
            Some(error) => PipelinePicture {
                file: scene.file.to_owned(),
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
fn build(builder: &Builder, features: &[&str]) -> Result<PathBuf> {
    // Named as the viewer's: the stage's features package is built beside.
    let features: Vec<String> = features.iter().map(|f| format!("{VIEWER}/{f}")).collect();
    let features = features.join(",");
    let mut args = vec![
        "build",
        "--package",
        VIEWER,
        // Its program alone (the features package has no program).
        "--bin",
        VIEWER,
        "--no-default-features",
        "--message-format",
        "json-render-diagnostics",
        "--color",
        "never",
    ];
    if !features.is_empty() {
        args.extend(["--features", &features]);
    }
    let args = builder.unified(args);
    let run = builder.cargo("viewer", &args, &[])?;
    if let Some(stopped) = run.stopped {
        anyhow::bail!("{stopped}");
    }
    anyhow::ensure!(
        run.success,
        "{}",
        run.stderr
            .lines()
            .filter(|l| l.starts_with("error"))
            .collect::<Vec<_>>()
            .join("; ")
    );
    run.stdout
        .lines()
        .filter_map(crate::cargo::Message::parse)
        .filter(|m| m.is_artifact() && m.target.as_ref().is_some_and(|t| t.name == VIEWER))
        .find_map(|m| m.executable)
        .context("cargo built no viewer executable")
}

/// Runs the viewer for one picture as a job of the runner, within the
/// time limit. The viewer writes into a scratch folder of its own (emptied
/// after it), never into the report: the picture is copied out as a plain
/// file of bounded size.
fn draw(plan: &Plan<'_>, binary: &Path, dir: &Path, scene: &Scene) -> PipelinePicture {
    let mut result = PipelinePicture {
        file: scene.file.to_owned(),
        what: scene.what.to_owned(),
        yours: None,
        expected: expected(plan.root, plan.out, scene),
        stages: Vec::new(),
        error: None,
    };
    let logs = plan.out.join("scratch").join("pipeline");
    let scratch = logs.join(scene.file).with_extension("tmp");
    let _ = crate::files::remove_tree(&scratch);
    let stdout = logs.join(scene.file).with_extension("out");
    let stderr = logs.join(scene.file).with_extension("err");
    let mut args: Vec<OsString> = scene.args.iter().map(OsString::from).collect();
    // A pipeline topic not graded in this run (or not in this edition) is
    // drawn by the course's given stand-in, so the picture shows what the
    // graded stages did; a graded topic that does not compile stays out.
    for topic in MESH_TOPICS.iter().filter(|t| !plan.graded.contains(t)) {
        args.extend([OsString::from("--given"), OsString::from(topic)]);
    }
    args.extend(["--size", SIZE, "--time-limit", "25", "--screenshot"].map(OsString::from));
    args.push(scratch.join(scene.file).into());
    let job = Job {
        purpose: Purpose::Run,
        program: binary.to_path_buf(),
        args,
        cwd: plan.root.to_path_buf(),
        course: plan.root.to_path_buf(),
        read_only: vec![binary.to_path_buf()],
        writable: vec![scratch.clone()],
        emptied: Vec::new(),
        env: Vec::new(),
        gpu: false,
        limits: Limits::test(TIME_LIMIT, 0),
        stdout: stdout.clone(),
        stderr: Some(stderr.clone()),
    };
    let ended = Jail::get().run(&job);
    let picture = crate::files::read_plain(&scratch, Path::new(scene.file));
    let stages_file = Path::new(scene.file).with_extension(wire::STAGES_EXTENSION);
    let stages = crate::files::read_plain(&scratch, &stages_file);
    let _ = crate::files::remove_tree(&scratch);
    let ended = match ended {
        Ok(ended) => ended,
        Err(error) => {
            result.error = Some(format!("{error:#}"));
            return result;
        }
    };
    if ended.exit.timed_out {
        result.error = Some(format!(
            "the picture took longer than {} s (an endless loop in a stage?)",
            TIME_LIMIT.as_secs()
        ));
        return result;
    }
    // The viewer's list of the stages it drew with, one line a stage in
    // the report; what the stages printed themselves is not read.
    result.stages = stages.as_deref().map(stage_lines).unwrap_or_default();
    let copied = match picture {
        Some(bytes) if ended.success() => fs::write(dir.join(scene.file), bytes).is_ok(),
        _ => false,
    };
    if copied {
        result.yours = Some(Path::new("pipeline").join(scene.file));
    } else {
        let stderr = tail(&stderr);
        result.error = Some(
            ended
                .exit
                .stop_reason(TIME_LIMIT.as_secs_f64())
                .or_else(|| {
                    stderr
                        .lines()
                        .find(|l| l.starts_with("Error") || l.starts_with("error"))
                        .map(str::to_owned)
                })
                .or_else(|| {
                    stderr
                        .contains("memory allocation of")
                        .then(|| "out of memory (an allocation failed)".to_owned())
                })
                .unwrap_or_else(|| "the viewer drew no picture".to_owned()),
        );
    }
    result
}

/// One line a stage, `name  status  (source)`, from the JSON the viewer
/// wrote beside its picture (see [`wire::STAGES_EXTENSION`]); nothing from
/// JSON that is not a list of such stages.
fn stage_lines(json: &[u8]) -> Vec<String> {
    #[derive(serde::Deserialize)]
    struct Stage {
        name: String,
        status: String,
        source: String,
    }
    serde_json::from_slice::<Vec<Stage>>(json)
        .unwrap_or_default()
        .into_iter()
        .map(|s| format!("{:<10} {}  ({})", s.name, s.status, s.source))
        .collect()
}

/// How much of the viewer's output is read back, per stream: its end,
/// where the stage report is (a stage that prints while it draws,
/// `println!` for debugging, can print far more).
const OUTPUT_KEPT: u64 = 64 * 1024;

/// The last [`OUTPUT_KEPT`] bytes of the file at `path`, lossily decoded.
fn tail(path: &Path) -> String {
    use std::io::{Read as _, Seek as _, SeekFrom};
    let Ok(mut file) = fs::File::open(path) else {
        return String::new();
    };
    let len = file.metadata().map_or(0, |m| m.len());
    let _ = file.seek(SeekFrom::Start(len.saturating_sub(OUTPUT_KEPT)));
    let mut bytes = Vec::new();
    let _ = file.read_to_end(&mut bytes);
    String::from_utf8_lossy(&bytes).into_owned()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_viewer_waits_for_a_stage_that_passes_a_test() {
        assert!(!worth_drawing(&[]));
        assert!(!worth_drawing(&[
            ("01-lines", 0),
            ("03-fill", 0),
            ("09-tessellation", 0)
        ]));
        // A topic that no picture draws with does not count.
        assert!(!worth_drawing(&[("01-lines", 0), ("02-circles", 5)]));
        assert!(worth_drawing(&[("01-lines", 1)]));
        assert!(worth_drawing(&[("02-circles", 0), ("08-nurbs", 3)]));
    }

    #[test]
    fn the_viewers_manifest_pairs_its_features_with_topics() {
        let manifest = "[features]\ndefault = [\"lines\"]\nwindow = [\"dep:eframe\"]\nlines = [\"dep:lines\"] # topic 01-lines\nfill = [] # topic 03-fill\n\n[dependencies]\nlines = { path = \"x\" } # topic 01-lines\n";
        assert_eq!(
            feature_topics(manifest),
            [("lines", "01-lines"), ("fill", "03-fill")].map(|(f, t)| (f.to_owned(), t.to_owned()))
        );
        let course = feature_topics(include_str!("../../viewer/Cargo.toml"));
        assert!(course.len() >= 9, "{course:?}");
    }

    #[test]
    fn the_stages_are_read_from_the_viewers_json() {
        let json = r#"[{"name": "lines", "status": "ok", "source": "01-lines · dda::dda_line"},
                       {"name": "clip", "status": "not written yet: clip", "source": "04-clipping · clip"}]"#;
        assert_eq!(
            stage_lines(json.as_bytes()),
            [
                "lines      ok  (01-lines · dda::dda_line)",
                "clip       not written yet: clip  (04-clipping · clip)"
            ]
        );
        assert!(
            stage_lines("lines      ok  (01-lines · dda)".as_bytes()).is_empty(),
            "a printed line is no stage"
        );
        assert!(stage_lines(br#"{"name": "lines"}"#).is_empty());
    }
}
