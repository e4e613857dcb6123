//! The viewer's command line (run it through `cargo xtask view`, which
//! builds it with the topics that compile).

use std::path::{Path, PathBuf};
use std::time::Duration;

use anyhow::{Context, Result, bail};
use clap::{Parser, ValueEnum};
use course_viewer::meshes::{self, MeshEntry, shipped_meshes};
use course_viewer::scenes::mesh::Settings;
use course_viewer::scenes::surfaces::{SurfaceSetup, TrimShape};
use course_viewer::stages::{self, Stages};

/// How polygons are drawn.
#[derive(Clone, Copy, Debug, ValueEnum)]
enum Mode {
    /// Outlines, with your lines.
    Wireframe,
    /// Filled, with your triangle fill.
    Filled,
}

/// The surface scene's trims.
#[derive(Clone, Copy, Debug, ValueEnum)]
enum Trim {
    /// Nothing cut away.
    None,
    /// `u` and `v` in intervals.
    Rectangle,
    /// A disc.
    Circle,
    /// An ellipse.
    Ellipse,
    /// Between two quadratic Bézier curves (Newton).
    Quadratic,
    /// Between two cubic Bézier curves (Newton).
    Cubic,
    /// A quadratic region with another one kept inside it.
    Nested,
}

/// The NURBS surfaces of the chain picture.
#[derive(Clone, Copy, Debug, ValueEnum)]
enum Chain {
    /// The vase (single interior knots).
    Vase,
    /// The torus from its NURBS data.
    Torus,
}

impl Trim {
    fn shape(self) -> TrimShape {
        match self {
            Self::None => TrimShape::None,
            Self::Rectangle => TrimShape::Rectangle,
            Self::Circle => TrimShape::Circle,
            Self::Ellipse => TrimShape::Ellipse,
            Self::Quadratic => TrimShape::NewtonQuadratic,
            Self::Cubic => TrimShape::NewtonCubic,
            Self::Nested => TrimShape::Nested,
        }
    }
}

/// Your own pipeline on screen: a mesh clipped, drawn and depth-tested by
/// your stages.
#[derive(Parser, Debug)]
#[command(name = "course-viewer")]
struct Args {
    /// The mesh: a shipped one's name (`star.ply`, `clipped_torus.ply`, ...)
    /// or the path of a PLY file.
    #[arg(long, default_value = "star.ply")]
    mesh: String,
    /// Wireframe or filled.
    #[arg(long, value_enum, default_value_t = Mode::Wireframe)]
    mode: Mode,
    /// Draw without clipping.
    #[arg(long)]
    no_clip: bool,
    /// Draw without the depth test.
    #[arg(long)]
    no_depth: bool,
    /// The picture's size in pixels (square, 1 to 2048).
    #[arg(long, default_value_t = 400, value_parser = clap::value_parser!(u32).range(1..=2048))]
    size: u32,
    /// Write the picture to this PNG file and exit, without a window.
    #[arg(long, value_name = "FILE")]
    screenshot: Option<PathBuf>,
    /// Open the window, save a screenshot of all of it to this PNG file
    /// once the picture shows, and close it (a smoke test of the window).
    #[arg(long, value_name = "FILE")]
    window_screenshot: Option<PathBuf>,
    /// How long a picture may take before it is given up, in seconds.
    #[arg(long, default_value_t = 30.0)]
    time_limit: f64,
    /// Open the window on the pixel playground (your lines, circle and
    /// triangle on a magnified grid, beside their definitions).
    #[arg(long, conflicts_with_all = ["curves", "surfaces", "tessellation", "gpu"])]
    pixels: bool,
    /// Open the window on the curve scene (your de Casteljau drawing a
    /// Bézier curve and its construction, beside the definition's curve).
    #[arg(long, conflicts_with_all = ["surfaces", "tessellation", "gpu"])]
    curves: bool,
    /// Open the window on the surface scene (the seed's hill evaluated,
    /// trimmed and rendered by your topic 07 code; choose the trim, its
    /// parameters and the tessellation level).
    #[arg(long, conflicts_with_all = ["tessellation", "gpu"])]
    surfaces: bool,
    /// Open the window on the tessellation scene (surfaces cut into
    /// triangles by your topic 09 code: uniform, per patch, fully
    /// adaptive).
    #[arg(long, conflicts_with = "gpu")]
    tessellation: bool,
    /// Open the window on the GPU scene (patches tessellated and drawn on
    /// the GPU by your topic 10 passes; a software adapter where there is no
    /// GPU: lavapipe on Linux, WARP on Windows).
    #[arg(long)]
    gpu: bool,
    /// The surface scene's first trim.
    #[arg(long, value_enum, default_value_t = Trim::Circle, requires = "surfaces")]
    trim: Trim,
    /// The surface scene's first tessellation level (1 to 64).
    #[arg(long, default_value_t = 24, value_parser = clap::value_parser!(u32).range(1..=64), requires = "surfaces")]
    level: u32,
    /// Start the surface scene with the wireframe on.
    #[arg(long, requires = "surfaces")]
    wireframe: bool,
    /// With `--screenshot`: draw the NURBS chain instead of a mesh — the
    /// surface split into Bézier patches by your topic 08, tessellated by
    /// your topic 09 (uniform, four cells a side per patch).
    #[arg(long, value_enum, requires = "screenshot")]
    chain: Option<Chain>,
    /// Topics left out of this build because they do not compile (set by
    /// `cargo xtask view`).
    #[arg(long = "not-compiling", value_name = "TOPIC")]
    not_compiling: Vec<String>,
    /// Topics not in this edition, or not graded in this run (set by
    /// `cargo xtask view` and the grader): the pipeline scene draws their
    /// stages with the course's given stand-ins.
    #[arg(long = "given", value_name = "TOPIC")]
    given: Vec<String>,
}

/// The topics whose pipeline stages the course's given code draws
/// (`--given`).
static GIVEN: std::sync::OnceLock<Vec<String>> = std::sync::OnceLock::new();

/// Your stages, the given stand-ins where `--given` says.
fn your_stages() -> Stages {
    Stages::yours().with_given(GIVEN.get().map_or(&[][..], Vec::as_slice))
}

fn main() -> Result<()> {
    let args = Args::parse();
    let _ = GIVEN.set(args.given.clone());
    stages::quiet_panics();
    let (mut meshes, problems) = shipped_meshes();
    for problem in problems {
        eprintln!("warning: cannot read a shipped mesh: {problem}");
    }
    let index = match meshes.iter().position(|m| m.name == args.mesh) {
        Some(index) => index,
        None => {
            let entry = meshes::load(Path::new(&args.mesh)).with_context(|| {
                format!(
                    "`{}` is neither a shipped mesh nor a PLY file that loads",
                    args.mesh
                )
            })?;
            meshes.push(entry);
            meshes.len() - 1
        }
    };
    let settings = Settings {
        mode: match args.mode {
            Mode::Wireframe => scene::Mode::Line,
            Mode::Filled => scene::Mode::Fill,
        },
        clip: !args.no_clip,
        depth_test: !args.no_depth,
        width: args.size,
        height: args.size,
        ..Settings::default()
    };
    let limit = Duration::from_secs_f64(args.time_limit.max(0.1));
    if let (Some(chain), Some(path)) = (args.chain, &args.screenshot) {
        let surface = match chain {
            Chain::Vase => course_viewer::scenes::tessellation::Surface::Vase,
            Chain::Torus => course_viewer::scenes::tessellation::Surface::NurbsTorus,
        };
        return chain_screenshot(surface, args.size, limit, path);
    }
    match args.screenshot {
        Some(path) => screenshot(&meshes[index], settings, limit, &path),
        None => window(
            meshes,
            index,
            settings,
            args.not_compiling,
            args.window_screenshot,
            if args.pixels {
                Start::Pixels
            } else if args.curves {
                Start::Curves
            } else if args.surfaces {
                let mut surface = SurfaceSetup {
                    level: args.level,
                    wireframe: args.wireframe,
                    ..SurfaceSetup::default()
                };
                surface.trim.shape = args.trim.shape();
                Start::Surfaces(Box::new(surface))
            } else if args.tessellation {
                Start::Tessellation
            } else if args.gpu {
                Start::Gpu
            } else {
                Start::Pipeline
            },
        ),
    }
}

/// Draws one picture with your stages and writes it to `path`.
fn screenshot(mesh: &MeshEntry, settings: Settings, limit: Duration, path: &Path) -> Result<()> {
    let mut worker = course_viewer::scenes::mesh::frame_worker(your_stages());
    worker.request((std::sync::Arc::clone(&mesh.mesh), settings));
    let Some(frame) = worker.wait(limit) else {
        bail!(
            "your stages did not finish the picture within {:.0} s (an endless loop?)",
            limit.as_secs_f64()
        );
    };
    let stages: Vec<[String; 3]> = frame
        .stages
        .iter()
        .map(|stage| {
            [
                stage.name.to_string(),
                stage.status.describe(),
                stage.source.to_string(),
            ]
        })
        .collect();
    write_stages(&stages, path)?;
    frame
        .canvas
        .save_png(path)
        .with_context(|| format!("cannot write {}", path.display()))?;
    println!("wrote {}", path.display());
    Ok(())
}

/// Prints the `stages` a picture was drawn with, one line each (name,
/// how it fared, where its code is), and writes them as JSON beside the
/// picture at `path` (see [`wire::STAGES_EXTENSION`]), making its folder.
fn write_stages(stages: &[[String; 3]], path: &Path) -> Result<()> {
    for [name, status, source] in stages {
        println!("{name:<10} {status}  ({source})");
    }
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    }
    let json: Vec<serde_json::Value> = stages
        .iter()
        .map(|[name, status, source]| {
            serde_json::json!({ "name": name, "status": status, "source": source })
        })
        .collect();
    let beside = path.with_extension(wire::STAGES_EXTENSION);
    std::fs::write(&beside, serde_json::to_string_pretty(&json)?)
        .with_context(|| format!("cannot write {}", beside.display()))
}

/// Draws the NURBS chain of `surface` with your stages and writes it to
/// `path`: one line a stage, as [`screenshot`] prints them.
fn chain_screenshot(
    surface: course_viewer::scenes::tessellation::Surface,
    size: u32,
    limit: Duration,
    path: &Path,
) -> Result<()> {
    use course_viewer::scenes::tessellation::{self as tess, chain_setup};
    let mut worker = tess::worker(your_stages());
    worker.request(chain_setup(surface, size));
    let Some(drawing) = worker.wait(limit) else {
        bail!(
            "your stages did not finish the picture within {:.0} s (an endless loop?)",
            limit.as_secs_f64()
        );
    };
    let named = Stages::default();
    write_stages(
        &[
            [
                named.decompose.name.to_string(),
                drawing.decomposition.describe(),
                named.decompose.source.to_string(),
            ],
            [
                named.tessellate.name.to_string(),
                drawing.status.describe(),
                drawing.setup.method.source().to_string(),
            ],
        ],
        path,
    )?;
    // A chain that stopped at a stage draws nothing, as the mesh pipeline
    // does: the empty picture, with the stage named above.
    let canvas = drawing.result.map_or_else(
        || {
            let mut empty = canvas::Canvas::new(size, size);
            empty.clear(canvas::Rgba::WHITE);
            empty
        },
        |result| result.canvas,
    );
    canvas
        .save_png(path)
        .with_context(|| format!("cannot write {}", path.display()))?;
    println!("wrote {}", path.display());
    Ok(())
}

/// The scene the window opens on.
#[cfg_attr(not(feature = "window"), allow(dead_code))] // no window to open
enum Start {
    Pipeline,
    Pixels,
    Curves,
    Surfaces(Box<SurfaceSetup>),
    Tessellation,
    Gpu,
}

/// Opens the window.
#[cfg(feature = "window")]
fn window(
    meshes: Vec<MeshEntry>,
    index: usize,
    settings: Settings,
    not_compiling: Vec<String>,
    window_screenshot: Option<PathBuf>,
    start: Start,
) -> Result<()> {
    use eframe::egui;
    let display = ["DISPLAY", "WAYLAND_DISPLAY"]
        .iter()
        .any(|v| std::env::var_os(v).is_some_and(|d| !d.is_empty()));
    if cfg!(target_os = "linux") && !display {
        bail!(
            "there is no display here (neither DISPLAY nor WAYLAND_DISPLAY is set): \
             `--screenshot FILE` draws the picture without a window, and \
             `xvfb-run cargo xtask view` opens the window on a virtual display"
        );
    }
    let name = meshes[index].name.clone();
    let mut app = course_viewer::ViewerApp::new(meshes, your_stages(), not_compiling);
    app.select_mesh(&name);
    *app.settings_mut() = settings;
    match start {
        Start::Pipeline => {}
        Start::Pixels => app.set_scene(course_viewer::Scene::Pixels),
        Start::Curves => app.set_scene(course_viewer::Scene::Curves),
        Start::Surfaces(setup) => {
            app.set_scene(course_viewer::Scene::Surfaces);
            *app.surfaces_mut() = *setup;
        }
        Start::Tessellation => app.set_scene(course_viewer::Scene::Tessellation),
        Start::Gpu => app.set_scene(course_viewer::Scene::Gpu),
    }
    if let Some(path) = window_screenshot {
        app.screenshot_window_to(path);
    }
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("Your pipeline · cargo xtask view")
            .with_inner_size([1100.0, 760.0]),
        ..Default::default()
    };
    eframe::run_native("course-viewer", options, Box::new(|_| Ok(Box::new(app))))
        .map_err(|e| anyhow::anyhow!("cannot open the window: {e}"))
}

/// Without the `window` feature there is no window to open.
#[cfg(not(feature = "window"))]
fn window(
    _: Vec<MeshEntry>,
    _: usize,
    _: Settings,
    _: Vec<String>,
    _: Option<PathBuf>,
    _: Start,
) -> Result<()> {
    bail!("this viewer was built without its window (feature `window`): use --screenshot FILE")
}
