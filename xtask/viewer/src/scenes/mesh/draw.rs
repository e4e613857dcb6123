//! What the pipeline scene draws: a frame of the mesh by your stages, and
//! how each fared.

use canvas::{Canvas, Fragment, Rgba, Vertex};
use glam::Vec3;
use glam::camera::rh::view;
use scene::{ClipVertex, Mesh, Mode, Pipeline};

use crate::camera::orbit_direction;
use crate::stages::{Stage, Stages, Status, guarded};
use crate::worker::Worker;

/// The worker that draws frames of the pipeline scene.
pub type FrameWorker = Worker<(std::sync::Arc<Mesh>, Settings), Frame>;

/// Starts a worker that draws frames with `stages`.
#[must_use]
pub fn frame_worker(stages: Stages) -> FrameWorker {
    Worker::start(move |(mesh, settings): (std::sync::Arc<Mesh>, Settings)| {
        render(&mesh, &settings, &stages)
    })
}

/// What the pipeline scene draws, and how.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// Wireframe or filled.
    pub mode: Mode,
    /// Clip in clip space (with your Sutherland–Hodgman) before the divide.
    pub clip: bool,
    /// Run every fragment through your depth test; without it, later
    /// fragments overwrite earlier ones (the painter's order of the faces).
    pub depth_test: bool,
    /// The camera's angle around the vertical axis, in degrees.
    pub yaw: f32,
    /// The camera's angle above the horizontal, in degrees.
    pub pitch: f32,
    /// The camera's distance from the origin (the course camera: 4).
    pub distance: f32,
    /// The picture's width in pixels.
    pub width: u32,
    /// The picture's height in pixels.
    pub height: u32,
}

impl Default for Settings {
    /// The course camera (`scene::Pipeline::for_mesh`), wireframe, clipped,
    /// depth-tested, 400 × 400.
    fn default() -> Self {
        Self {
            mode: Mode::Line,
            clip: true,
            depth_test: true,
            yaw: 0.0,
            pitch: 0.0,
            distance: scene::pipeline::EYE.z,
            width: 400,
            height: 400,
        }
    }
}

impl Settings {
    /// Where the eye stands: on a sphere around the origin.
    #[must_use]
    pub fn eye(&self) -> Vec3 {
        self.distance * orbit_direction(f64::from(self.yaw), f64::from(self.pitch)).as_vec3()
    }

    /// The course pipeline for `mesh`, with this camera.
    #[must_use]
    pub fn pipeline(&self, mesh: &Mesh) -> Pipeline {
        let mut pipeline = Pipeline::for_mesh(mesh, self.width, self.height);
        // Near the poles y is no longer "up": look with z up there instead.
        let up = if self.pitch.abs() > 89.0 {
            Vec3::Z
        } else {
            Vec3::Y
        };
        pipeline.view = view::look_at_mat4(self.eye(), scene::pipeline::TARGET, up);
        pipeline
    }
}

/// The pictures of the grade report's "Your pipeline" section (`cargo
/// xtask grade` draws them with your stages, beside `xtask/viewer/expected/`):
/// file name, mesh, mode, clipping; 200 × 200 pixels, the course camera.
pub const REPORT_SCENES: [(&str, &str, Mode, bool); 4] = [
    ("star-wireframe.png", "star.ply", Mode::Line, true),
    ("torus-filled.png", "torus.ply", Mode::Fill, true),
    ("clipped-torus.png", "clipped_torus.ply", Mode::Fill, true),
    (
        "clipped-torus-unclipped.png",
        "clipped_torus.ply",
        Mode::Fill,
        false,
    ),
];

/// The pictures' size in pixels.
pub const REPORT_SIZE: u32 = 200;

/// One stage's line in a frame's report.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StageReport {
    /// The stage ("lines").
    pub name: &'static str,
    /// Where it comes from ("01-lines · dda::dda_line").
    pub source: &'static str,
    /// How it fared.
    pub status: Status,
}

/// A picture and how each stage fared drawing it.
#[derive(Clone, Debug)]
pub struct Frame {
    /// The picture.
    pub canvas: Canvas,
    /// Clipping, lines, fill and depth test, in that order.
    pub stages: Vec<StageReport>,
    /// Polygons of the mesh, and how many reached the rasterizer.
    pub polygons: (usize, usize),
    /// The polygons your clipping returned, in pixel coordinates of the
    /// picture (`y` up, pixel centres at integers), for an outline drawn
    /// by the window itself (not by any rasterizer of the course); empty
    /// unless your clipping ran.
    pub clipped: Vec<Vec<[f32; 2]>>,
}

impl Frame {
    /// The stages that did not work, for a summary line.
    #[must_use]
    pub fn problems(&self) -> Vec<&StageReport> {
        self.stages
            .iter()
            .filter(|s| {
                !matches!(
                    s.status,
                    Status::Ok | Status::Unused | Status::NotReached | Status::Given
                )
            })
            .collect()
    }
}

/// A stage and how it fares in the frame being drawn.
struct Running<'a, F: ?Sized> {
    stage: &'a Stage<F>,
    status: Status,
}

impl<'a, F: ?Sized> Running<'a, F> {
    fn new(stage: &'a Stage<F>, needed: bool) -> Self {
        let status = match (&stage.run, &stage.given, needed) {
            (_, _, false) => Status::Unused,
            (None, None, true) => Status::Missing,
            _ => Status::NotReached,
        };
        Self { stage, status }
    }

    /// The code to draw with: the student's, or the given stand-in.
    fn run(&self) -> Option<&'a std::sync::Arc<F>> {
        self.stage.run.as_ref().or(self.stage.given.as_ref())
    }

    fn report(self) -> StageReport {
        let status = match self.status {
            Status::Ok if self.stage.run.is_none() => Status::Given,
            status => status,
        };
        StageReport {
            name: self.stage.name,
            source: self.stage.source,
            status,
        }
    }
}

/// Draws `mesh` as `settings` say, with `stages`, onto a black picture.
#[must_use]
pub fn render(mesh: &Mesh, settings: &Settings, stages: &Stages) -> Frame {
    let pipeline = settings.pipeline(mesh);
    let mut canvas = Canvas::new(settings.width, settings.height);
    canvas.clear(Rgba::BLACK);
    let mut clip = Running::new(&stages.clip, settings.clip);
    let mut line = Running::new(&stages.line, settings.mode == Mode::Line);
    let mut fill = Running::new(&stages.fill, settings.mode == Mode::Fill);
    let mut depth = Running::new(&stages.depth, settings.depth_test);

    let polygons = pipeline.clip_space(mesh);
    let total = polygons.len();
    let polygons: Vec<Vec<ClipVertex>> = if settings.clip {
        polygons
            .iter()
            .filter_map(|polygon| match clip.run() {
                None => None,
                Some(run) => match guarded(&mut clip.status, || run(polygon))? {
                    Ok(clipped) => Some(clipped),
                    Err(message) => {
                        clip.status = Status::Failed(message);
                        None
                    }
                },
            })
            .filter(|p| !p.is_empty())
            .collect()
    } else {
        polygons
    };
    let drawn = polygons.len();
    let clipped = if settings.clip && clip.status == Status::Ok {
        polygons
            .iter()
            .filter_map(|polygon| {
                polygon
                    .iter()
                    .map(|&v| pipeline.screen(v).map(|s| s.position.to_array()))
                    .collect()
            })
            .collect()
    } else {
        Vec::new()
    };

    // Every fragment goes through the depth test, or overwrites.
    let mut write = |canvas: &mut Canvas, fragment: Fragment| {
        if !settings.depth_test {
            canvas.set(fragment.pixel, fragment.colour);
            return;
        }
        if let Some(run) = depth.run() {
            let _ = guarded(&mut depth.status, || run(canvas, fragment));
        }
    };
    let viewport = canvas.viewport();
    for polygon in &polygons {
        let screen: Option<Vec<Vertex>> = polygon.iter().map(|&v| pipeline.screen(v)).collect();
        let Some(screen) = screen else { continue };
        match settings.mode {
            Mode::Line => {
                let Some(run) = line.run() else { continue };
                let n = screen.len();
                let edges = if n == 2 { 1 } else { n };
                for i in 0..edges {
                    let mut fragments = Vec::new();
                    let (a, b) = (screen[i], screen[(i + 1) % n]);
                    guarded(&mut line.status, || run(&a, &b, &mut |f| fragments.push(f)));
                    for f in fragments {
                        write(&mut canvas, f);
                    }
                }
            }
            Mode::Fill => {
                let Some(run) = fill.run() else { continue };
                if let Some((&first, rest)) = screen.split_first() {
                    for pair in rest.windows(2) {
                        let mut fragments = Vec::new();
                        let triangle = [first, pair[0], pair[1]];
                        guarded(&mut fill.status, || {
                            run(triangle, viewport, &mut |f, _| fragments.push(f));
                        });
                        for f in fragments {
                            write(&mut canvas, f);
                        }
                    }
                }
            }
        }
    }
    Frame {
        canvas,
        stages: vec![clip.report(), line.report(), fill.report(), depth.report()],
        polygons: (total, drawn),
        clipped,
    }
}
