//! The stages of your own pipeline that the viewer draws with, and how it
//! runs them: each call is guarded, so that a `todo!()` or a panic is
//! reported with its message and the rest of the frame still draws.
//!
//! | stage | your code |
//! |---|---|
//! | clipping | `04-clipping`: `sutherland_hodgman::clip_polygon` against `clip_planes::clip_planes()` |
//! | lines | `01-lines`: `dda::dda_line` |
//! | fill | `03-fill`: `edge_function::fill_triangle` |
//! | depth test | `05-buffers`: `zbuffer::depth_test` with OpenGL's defaults (`LESS`, writes on) |
//!
//! and, for the pixel playground, `01-lines`' `midpoint::midpoint_line`
//! and `wu::wu_line` and `02-circles`' `midpoint_circle::midpoint_circle`; for the curve
//! scene, `07-bezier`'s `de_casteljau::de_casteljau` and `08-nurbs`'
//! `NurbsCurve::point`; for the surface scene,
//! `07-bezier`'s `surface::partial_derivatives` and `surface::normal` (the
//! seed's hill, its control points raised and lowered), its trims (`simple_trim`, `newton_trim`) and
//! `render::render_surface`; for the tessellation scene, `09-tessellation`'s
//! `uniform`, `per_patch`, `fully_adaptive` and `edge_tests`. The NURBS
//! surfaces of the tessellation and GPU scenes (the course's vase and
//! torus, [`freeform::NurbsSurfaceData`]) are split into rational Bézier
//! patches by `08-nurbs`' `NurbsSurface::decompose` first: the chain
//! NURBS → your decomposition → your tessellation (CPU or GPU).
//!
//! A topic that does not compile is left out of the build (`cargo xtask
//! view` checks each one first) and its stage is shown as missing.
//!
//! This module is the registry: the stages' signatures and [`Stages::yours`].
//! What a stage takes and how your code is called for it are in its
//! submodule ([`trim`], [`surface`], [`decomposition`], [`tessellate`], [`gpu`]);
//! the scenes draw with the registry and none of it knows a scene.

use std::sync::Arc;

use canvas::{Canvas, Fragment, Pixel, Vertex, Viewport};
use scene::ClipVertex;

pub mod decomposition;
pub mod gpu;
mod status;
pub mod surface;
pub mod tessellate;
pub mod trim;

pub use decomposition::{Decomposed, decompose};
use gpu::{GpuDrawing, GpuSetup};
#[cfg(feature = "gpu-tessellation")]
pub use gpu::{GpuPieces, gpu_frame};
pub use status::{Status, WORKER_THREAD, guarded, quiet_panics};
pub use surface::SurfaceView;
use tessellate::{TessSetup, Tessellated};
use trim::TrimSetup;

/// Draws a line: `(from, to, plot)`.
pub type LineStage = dyn Fn(&Vertex, &Vertex, &mut dyn FnMut(Fragment)) + Send + Sync;
/// Fills a triangle: `(vertices, viewport, plot)`; `plot` also gets the
/// pixel's exact edge functions (03's `EdgeWeights`).
pub type FillStage =
    dyn Fn([Vertex; 3], Viewport, &mut dyn FnMut(Fragment, [i128; 3])) + Send + Sync;
/// Draws a line between two pixels: `(from, to, plot)`.
pub type PixelLineStage = dyn Fn(Pixel, Pixel, &mut dyn FnMut(Pixel)) + Send + Sync;
/// Draws an antialiased line between two pixels: `(from, to, plot)`, each
/// pixel with its intensity.
pub type AaLineStage = dyn Fn(Pixel, Pixel, &mut dyn FnMut(Pixel, f32)) + Send + Sync;
/// Draws a circle: `(centre, radius, plot)`.
pub type CircleStage = dyn Fn(Pixel, i32, &mut dyn FnMut(Pixel)) + Send + Sync;
/// Clips a polygon in clip space against the view volume.
pub type ClipStage = dyn Fn(&[ClipVertex]) -> Result<Vec<ClipVertex>, String> + Send + Sync;
/// Runs a fragment through the depth test; whether it was written.
pub type DepthStage = dyn Fn(&mut Canvas, Fragment) -> bool + Send + Sync;
/// A point of a Bézier curve: `(control points, t)`, or why not.
pub type CurveStage = dyn Fn(&[glam::DVec2], f64) -> Result<glam::DVec2, String> + Send + Sync;
/// A point of a NURBS curve: `(control points, weights, degree, u)` over
/// the clamped uniform knot vector, or why not.
pub type NurbsStage =
    dyn Fn(&[glam::DVec2], &[f64], usize, f64) -> Result<glam::DVec2, String> + Send + Sync;
/// A point of a bicubic patch at `(u, v)`: its position and unit normal,
/// or why not.
pub type SurfaceStage = dyn Fn(&freeform::BezierPatch, glam::DVec2) -> Result<(glam::DVec3, glam::DVec3), String>
    + Send
    + Sync;
/// Whether a trim cuts `(u, v)` away.
pub type TrimFn = Arc<dyn Fn(glam::DVec2) -> bool + Send + Sync>;
/// Builds the trim a set-up describes, or says why not.
pub type TrimStage = dyn Fn(&TrimSetup) -> Result<TrimFn, String> + Send + Sync;
/// Renders a trimmed surface: `(canvas, surface, trims, view)`.
pub type SurfaceRenderStage = dyn Fn(
        &mut Canvas,
        &dyn Fn(glam::DVec2) -> Result<(glam::DVec3, glam::DVec3), String>,
        &dyn Fn(glam::DVec2) -> bool,
        &SurfaceView,
    ) -> Result<(), String>
    + Send
    + Sync;

/// Splits a NURBS surface into rational Bézier patches (topic 08).
pub type DecomposeStage =
    dyn Fn(&freeform::NurbsSurfaceData) -> Result<Decomposed, String> + Send + Sync;

/// Tessellates a surface and draws the triangles (the tessellation scene):
/// the set-up, and the patches of its NURBS surface when it is one.
pub type TessellateStage =
    dyn Fn(&TessSetup, Option<&Decomposed>) -> Result<Tessellated, String> + Send + Sync;

/// Draws the GPU scene with topic 10's passes: the set-up, and the
/// patches of its NURBS surface when it is one.
pub type GpuStage = dyn Fn(&GpuSetup, Option<&Decomposed>) -> GpuDrawing + Send + Sync;

/// One stage: where it comes from, and the code if its topic is built in.
pub struct Stage<F: ?Sized> {
    /// What it does, for the screen: "lines".
    pub name: &'static str,
    /// Where it comes from: "01-lines · dda::dda_line".
    pub source: &'static str,
    /// The code; `None` when its topic is not part of the build.
    pub run: Option<Arc<F>>,
    /// The course's given stand-in, which the pipeline scene draws with
    /// where the stage's topic is not in this edition (or not graded in
    /// this run): see [`Stages::with_given`].
    pub given: Option<Arc<F>>,
}

impl<F: ?Sized> Stage<F> {
    /// A stage without code.
    const fn missing(name: &'static str, source: &'static str) -> Self {
        Self {
            name,
            source,
            run: None,
            given: None,
        }
    }
}

impl<F: ?Sized> Clone for Stage<F> {
    fn clone(&self) -> Self {
        Self {
            name: self.name,
            source: self.source,
            run: self.run.clone(),
            given: self.given.clone(),
        }
    }
}

/// The four stages of the pipeline scene, and those the pixel playground
/// draws with besides.
#[derive(Clone)]
pub struct Stages {
    /// Sutherland–Hodgman clipping.
    pub clip: Stage<ClipStage>,
    /// DDA lines, for the wireframe.
    pub line: Stage<LineStage>,
    /// Edge-function triangles, for filled polygons.
    pub fill: Stage<FillStage>,
    /// The z-buffer's depth test.
    pub depth: Stage<DepthStage>,
    /// The midpoint line (the playground).
    pub midpoint: Stage<PixelLineStage>,
    /// Wu's antialiased line (the playground).
    pub wu: Stage<AaLineStage>,
    /// The midpoint circle (the playground).
    pub circle: Stage<CircleStage>,
    /// De Casteljau's algorithm (the curve scene).
    pub curve: Stage<CurveStage>,
    /// A NURBS curve's point (the curve scene).
    pub nurbs: Stage<NurbsStage>,
    /// A NURBS surface split into Bézier patches (the tessellation and
    /// GPU scenes' NURBS surfaces).
    pub decompose: Stage<DecomposeStage>,
    /// The patch's point and normal (the surface scene).
    pub surface: Stage<SurfaceStage>,
    /// The trims (the surface scene).
    pub trim: Stage<TrimStage>,
    /// Tessellating, trimming and shading the patch (the surface scene).
    pub surface_render: Stage<SurfaceRenderStage>,
    /// Cutting surfaces into triangles (the tessellation scene).
    pub tessellate: Stage<TessellateStage>,
    /// Topic 10's passes (the GPU scene).
    pub gpu: Stage<GpuStage>,
}

/// The four stages without code: what a build without any topic shows.
impl Default for Stages {
    fn default() -> Self {
        Self {
            clip: Stage::missing(
                "clipping",
                "04-clipping · clip_planes::clip_planes, sutherland_hodgman::clip_polygon",
            ),
            line: Stage::missing("lines", "01-lines · dda::dda_line"),
            fill: Stage::missing("fill", "03-fill · edge_function::fill_triangle"),
            depth: Stage::missing("depth test", "05-buffers · zbuffer::depth_test"),
            midpoint: Stage::missing("midpoint line", "01-lines · midpoint::midpoint_line"),
            wu: Stage::missing(
                "Wu line",
                "01-lines · wu::wu_line_traced (through the given wu::wu_line)",
            ),
            circle: Stage::missing(
                "midpoint circle",
                "02-circles · midpoint_circle::midpoint_circle",
            ),
            curve: Stage::missing("de Casteljau", "07-bezier · de_casteljau::de_casteljau"),
            nurbs: Stage::missing(
                "NURBS curve",
                "08-nurbs · NurbsCurve::point (find_span, basis_funs)",
            ),
            decompose: Stage::missing(
                "decomposition",
                "08-nurbs · NurbsSurface::decompose (insert_knot_u, insert_knot_v)",
            ),
            surface: Stage::missing(
                "surface",
                "07-bezier · surface::partial_derivatives, surface::normal",
            ),
            trim: Stage::missing("trim", "07-bezier · simple_trim, newton_trim"),
            surface_render: Stage::missing(
                "render",
                "07-bezier · render::render_surface, render::phong",
            ),
            tessellate: Stage::missing(
                "tessellation",
                "09-tessellation · uniform, per_patch, fully_adaptive, edge_tests",
            ),
            gpu: Stage::missing(
                "GPU passes",
                "10-gpu-tessellation · control, domain, evaluation, shading, trimming",
            ),
        }
    }
}

/// The topics of the pipeline scene's four stages.
pub const CLIP_TOPIC: &str = "04-clipping";
/// See [`CLIP_TOPIC`].
pub const LINE_TOPIC: &str = "01-lines";
/// See [`CLIP_TOPIC`].
pub const FILL_TOPIC: &str = "03-fill";
/// See [`CLIP_TOPIC`].
pub const DEPTH_TOPIC: &str = "05-buffers";

impl Stages {
    /// These stages, and for each pipeline stage whose topic is among
    /// `topics` (those not in this edition, or not graded in this run) and
    /// not built in, the course's given code to draw with instead: polygons
    /// leaving the view volume dropped whole (`scene::pipeline::discard_outside`),
    /// the one-pixel band for lines, the coverage of `scene::raster` for
    /// triangles, a `LESS` depth test. So a student of topic 05 alone sees
    /// the torus drawn through their own depth test.
    #[must_use]
    pub fn with_given(mut self, topics: &[String]) -> Self {
        let absent = |topic: &str| topics.iter().any(|t| t == topic);
        if absent(CLIP_TOPIC) {
            self.clip.given = Some(Arc::new(|polygon: &[ClipVertex]| {
                Ok(scene::pipeline::discard_outside(&[polygon.to_vec()])
                    .pop()
                    .unwrap_or_default())
            }));
        }
        if absent(LINE_TOPIC) {
            self.line.given = Some(Arc::new(
                |from: &Vertex, to: &Vertex, plot: &mut dyn FnMut(Fragment)| {
                    let everywhere = Viewport::new(
                        -canvas::MAX_COORD,
                        -canvas::MAX_COORD,
                        canvas::MAX_COORD,
                        canvas::MAX_COORD,
                    );
                    scene::raster::band(*from, *to, everywhere, plot);
                },
            ));
        }
        if absent(FILL_TOPIC) {
            self.fill.given = Some(Arc::new(
                |vertices: [Vertex; 3],
                 viewport: Viewport,
                 plot: &mut dyn FnMut(Fragment, [i128; 3])| {
                    let corners = vertices.map(|v| v.position.as_dvec2());
                    scene::raster::cover(corners, viewport, |pixel, l| {
                        let depth: f64 = (0..3).map(|k| l[k] * f64::from(vertices[k].depth)).sum();
                        let colour = vertices[0].colour * l[0] as f32
                            + vertices[1].colour * l[1] as f32
                            + vertices[2].colour * l[2] as f32;
                        let fragment = Fragment {
                            pixel,
                            depth: depth as f32,
                            colour,
                        };
                        plot(fragment, [0; 3]);
                    });
                },
            ));
        }
        if absent(DEPTH_TOPIC) {
            self.depth.given = Some(Arc::new(|canvas: &mut Canvas, fragment: Fragment| {
                let passes = canvas
                    .depth(fragment.pixel)
                    .is_some_and(|stored| fragment.depth < stored);
                scene::raster::depth_test(canvas, fragment);
                passes
            }));
        }
        self
    }

    /// Your stages: those of every topic this build holds.
    #[must_use]
    pub fn yours() -> Self {
        #[allow(unused_mut)] // without any topic, nothing is set
        let mut stages = Self::default();
        #[cfg(feature = "clipping")]
        {
            stages.clip.run = Some(Arc::new(|polygon: &[ClipVertex]| {
                let planes = clipping::clip_planes::clip_planes();
                clipping::sutherland_hodgman::clip_polygon(polygon, &planes)
                    .map_err(|e| e.to_string())
            }));
        }
        #[cfg(feature = "lines")]
        {
            stages.line.run = Some(Arc::new(
                |from: &Vertex, to: &Vertex, plot: &mut dyn FnMut(Fragment)| {
                    lines::dda::dda_line(from, to, plot);
                },
            ));
            stages.midpoint.run = Some(Arc::new(
                |from: Pixel, to: Pixel, plot: &mut dyn FnMut(Pixel)| {
                    lines::midpoint::midpoint_line(from, to, plot);
                },
            ));
            stages.wu.run = Some(Arc::new(
                |from: Pixel, to: Pixel, plot: &mut dyn FnMut(Pixel, f32)| {
                    lines::wu::wu_line(from, to, plot);
                },
            ));
        }
        #[cfg(feature = "circles")]
        {
            stages.circle.run = Some(Arc::new(
                |centre: Pixel, radius: i32, plot: &mut dyn FnMut(Pixel)| {
                    circles::midpoint_circle::midpoint_circle(centre, radius, plot, |_, _, _| {});
                },
            ));
        }
        #[cfg(feature = "fill")]
        {
            stages.fill.run = Some(Arc::new(
                |vertices: [Vertex; 3],
                 viewport: Viewport,
                 plot: &mut dyn FnMut(Fragment, [i128; 3])| {
                    fill::edge_function::fill_triangle(vertices, viewport, plot);
                },
            ));
        }
        #[cfg(feature = "buffers")]
        {
            stages.depth.run = Some(Arc::new(|canvas: &mut Canvas, fragment: Fragment| {
                buffers::zbuffer::depth_test(
                    canvas,
                    fragment,
                    &buffers::zbuffer::DepthState::DEFAULT,
                )
            }));
        }
        #[cfg(feature = "bezier")]
        {
            stages.curve.run = Some(Arc::new(|points: &[glam::DVec2], t: f64| {
                bezier::de_casteljau::de_casteljau(points, t).map_err(|e| e.to_string())
            }));
            stages.surface.run = Some(Arc::new(surface::patch_point));
            stages.trim.run = Some(Arc::new(trim::build_trim));
            stages.surface_render.run = Some(Arc::new(surface::render_surface));
        }
        #[cfg(feature = "nurbs")]
        {
            stages.nurbs.run = Some(Arc::new(
                |points: &[glam::DVec2], weights: &[f64], degree: usize, u: f64| {
                    let error = |e: nurbs::NurbsError| e.to_string();
                    let knots =
                        nurbs::KnotVector::clamped_uniform(degree, points.len()).map_err(error)?;
                    let points: Vec<glam::DVec3> = points.iter().map(|p| p.extend(0.0)).collect();
                    let curve =
                        nurbs::NurbsCurve::from_points(knots, &points, weights).map_err(error)?;
                    curve.point(u).map(glam::DVec3::truncate).map_err(error)
                },
            ));
            stages.decompose.run = Some(Arc::new(|data: &freeform::NurbsSurfaceData| {
                let error = |e: nurbs::NurbsError| e.to_string();
                let surface = nurbs::NurbsSurface::from_data(data).map_err(error)?;
                let patches = surface.decompose().map_err(error)?;
                Decomposed::from_u_major(data.pieces(), patches)
            }));
        }
        #[cfg(feature = "tessellation")]
        {
            stages.tessellate.run = Some(Arc::new(tessellate::tessellate));
        }
        #[cfg(feature = "gpu-tessellation")]
        {
            stages.gpu.run = Some(Arc::new(
                |setup: &GpuSetup, decomposed: Option<&Decomposed>| {
                    gpu_frame(setup, GpuPieces::YOURS, decomposed)
                },
            ));
        }
        stages
    }
}
