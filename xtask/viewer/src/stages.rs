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

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::Arc;

use canvas::{Canvas, Fragment, Pixel, Vertex, Viewport};
use scene::ClipVertex;

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
pub type TrimStage = dyn Fn(&crate::surfaces::TrimSetup) -> Result<TrimFn, String> + Send + Sync;
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
pub type TessellateStage = dyn Fn(
        &crate::tessellation::TessSetup,
        Option<&Decomposed>,
    ) -> Result<crate::tessellation::Tessellated, String>
    + Send
    + Sync;

/// Draws the GPU scene with topic 10's passes: the set-up, and the
/// patches of its NURBS surface when it is one.
pub type GpuStage = dyn Fn(&crate::gpu_scene::GpuSetup, Option<&Decomposed>) -> crate::gpu_scene::GpuDrawing
    + Send
    + Sync;

/// A NURBS surface split into rational Bézier patches, laid out as topic
/// 09's `PatchGrid` lays them: patch `(row, col)` at `row · cols + col`,
/// `col` the span along `u` and `row` the span along `v`.
#[derive(Clone, Debug, PartialEq)]
pub struct Decomposed {
    /// Spans along `v`.
    pub rows: usize,
    /// Spans along `u`.
    pub cols: usize,
    /// The patches.
    pub patches: Vec<freeform::RationalPatch>,
}

impl Decomposed {
    /// The grid of `patches` in topic 08's order (by `u` span, then `v`
    /// span: patch `(a, b)` at `a · spans_v + b`) for a surface of
    /// `spans_u × spans_v` spans.
    ///
    /// # Errors
    /// Not `spans_u · spans_v` patches.
    pub fn from_u_major(
        (spans_u, spans_v): (usize, usize),
        patches: Vec<freeform::RationalPatch>,
    ) -> Result<Self, String> {
        if patches.len() != spans_u * spans_v {
            return Err(format!(
                "{} patches for {spans_u} × {spans_v} spans",
                patches.len()
            ));
        }
        let patches = (0..spans_v)
            .flat_map(|b| (0..spans_u).map(move |a| a * spans_v + b))
            .map(|k| patches[k].clone())
            .collect();
        Ok(Self {
            rows: spans_v,
            cols: spans_u,
            patches,
        })
    }
}

/// The patches of `data` split by `stages`' decomposition, and how that
/// fared: the first link of the chain.
#[must_use]
pub fn decompose(
    stages: &Stages,
    data: &freeform::NurbsSurfaceData,
) -> (Option<Decomposed>, Status) {
    let Some(run) = &stages.decompose.run else {
        return (None, Status::Missing);
    };
    let mut status = Status::Unused;
    match guarded(&mut status, || run(data)) {
        Some(Ok(patches)) => (Some(patches), status),
        Some(Err(error)) => (None, Status::Failed(error)),
        None => (None, status),
    }
}

/// How the surface scene renders: what topic 07's `RenderSettings` holds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceView {
    /// Grid cells per side of the parameter square.
    pub level: u32,
    /// The tessellation grid over the surface.
    pub wireframe: bool,
    /// Where the camera stands (y up, 40° vertical field of view).
    pub eye: glam::DVec3,
    /// What it looks at.
    pub target: glam::DVec3,
    /// The colour where there is no surface.
    pub background: canvas::Rgba,
}

/// One stage: where it comes from, and the code if its topic is built in.
pub struct Stage<F: ?Sized> {
    /// What it does, for the screen: "lines".
    pub name: &'static str,
    /// Where it comes from: "01-lines · dda::dda_line".
    pub source: &'static str,
    /// The code; `None` when its topic is not part of the build.
    pub run: Option<Arc<F>>,
}

impl<F: ?Sized> Clone for Stage<F> {
    fn clone(&self) -> Self {
        Self {
            name: self.name,
            source: self.source,
            run: self.run.clone(),
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
            clip: Stage {
                name: "clipping",
                source: "04-clipping · clip_planes::clip_planes, sutherland_hodgman::clip_polygon",
                run: None,
            },
            line: Stage {
                name: "lines",
                source: "01-lines · dda::dda_line",
                run: None,
            },
            fill: Stage {
                name: "fill",
                source: "03-fill · edge_function::fill_triangle",
                run: None,
            },
            depth: Stage {
                name: "depth test",
                source: "05-buffers · zbuffer::depth_test",
                run: None,
            },
            midpoint: Stage {
                name: "midpoint line",
                source: "01-lines · midpoint::midpoint_line",
                run: None,
            },
            wu: Stage {
                name: "Wu line",
                source: "01-lines · wu::wu_line_traced (through the given wu::wu_line)",
                run: None,
            },
            circle: Stage {
                name: "midpoint circle",
                source: "02-circles · midpoint_circle::midpoint_circle",
                run: None,
            },
            curve: Stage {
                name: "de Casteljau",
                source: "07-bezier · de_casteljau::de_casteljau",
                run: None,
            },
            nurbs: Stage {
                name: "NURBS curve",
                source: "08-nurbs · NurbsCurve::point (find_span, basis_funs)",
                run: None,
            },
            decompose: Stage {
                name: "decomposition",
                source: "08-nurbs · NurbsSurface::decompose (insert_knot_u, insert_knot_v)",
                run: None,
            },
            surface: Stage {
                name: "surface",
                source: "07-bezier · surface::partial_derivatives, surface::normal",
                run: None,
            },
            trim: Stage {
                name: "trim",
                source: "07-bezier · simple_trim, newton_trim",
                run: None,
            },
            surface_render: Stage {
                name: "render",
                source: "07-bezier · render::render_surface, render::phong",
                run: None,
            },
            tessellate: Stage {
                name: "tessellation",
                source: "09-tessellation · uniform, per_patch, fully_adaptive, edge_tests",
                run: None,
            },
            gpu: Stage {
                name: "GPU passes",
                source: "10-gpu-tessellation · control, domain, evaluation, shading, trimming",
                run: None,
            },
        }
    }
}

impl Stages {
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
                    circles::midpoint_circle::midpoint_circle(centre, radius, plot);
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
            stages.surface.run = Some(Arc::new(patch_point));
            stages.trim.run = Some(Arc::new(build_trim));
            stages.surface_render.run = Some(Arc::new(render_surface));
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
            stages.tessellate.run = Some(Arc::new(tessellate));
        }
        #[cfg(feature = "gpu-tessellation")]
        {
            stages.gpu.run = Some(Arc::new(
                |setup: &crate::gpu_scene::GpuSetup, decomposed: Option<&Decomposed>| {
                    gpu_frame(setup, GpuPieces::YOURS, decomposed)
                },
            ));
        }
        stages
    }
}

/// A patch's point and unit normal by your surface code.
#[cfg(feature = "bezier")]
fn patch_point(
    net: &freeform::BezierPatch,
    uv: glam::DVec2,
) -> Result<(glam::DVec3, glam::DVec3), String> {
    let point = bezier::surface::partial_derivatives(net, uv).map_err(|e| e.to_string())?;
    let normal = bezier::surface::normal(net, uv).map_err(|e| e.to_string())?;
    Ok((point.position, normal))
}

/// The trim a set-up describes, built from your types.
#[cfg(feature = "bezier")]
fn build_trim(setup: &crate::surfaces::TrimSetup) -> Result<TrimFn, String> {
    use crate::surfaces::{CUBIC, INNER, QUADRATIC, TrimShape};
    use bezier::Trim;
    use bezier::newton_trim::{NestedNewtonTrim, NewtonSettings, NewtonTrim};
    use bezier::simple_trim::{CircleTrim, EllipseTrim, IntervalTrim};
    fn shared(trim: impl Trim + Send + Sync + 'static) -> TrimFn {
        Arc::new(move |uv| trim.trims(uv))
    }
    let error = |e: bezier::BezierError| e.to_string();
    let settings = NewtonSettings {
        max_iterations: setup.iterations,
        epsilon: setup.epsilon,
    };
    let quadratic = |points| {
        NewtonTrim::quadratic(setup.curve_points(points))
            .map(|t| t.with_settings(settings))
            .map_err(error)
    };
    Ok(match setup.shape {
        TrimShape::None => Arc::new(|_| false),
        TrimShape::Rectangle => shared(
            IntervalTrim::new(setup.centre - setup.size, setup.centre + setup.size)
                .map_err(error)?,
        ),
        TrimShape::Circle => shared(CircleTrim::new(setup.centre, setup.size.x).map_err(error)?),
        TrimShape::Ellipse => shared(EllipseTrim::new(setup.centre, setup.size).map_err(error)?),
        TrimShape::NewtonQuadratic => shared(quadratic(QUADRATIC)?),
        TrimShape::NewtonCubic => shared(
            NewtonTrim::cubic(setup.curve_points(CUBIC))
                .map(|t| t.with_settings(settings))
                .map_err(error)?,
        ),
        TrimShape::Nested => shared(NestedNewtonTrim::new(
            quadratic(QUADRATIC)?,
            quadratic(INNER)?,
        )),
    })
}

/// Your `render_surface` with the viewer's surface and trim.
#[cfg(feature = "bezier")]
fn render_surface(
    canvas: &mut Canvas,
    surface: &dyn Fn(glam::DVec2) -> Result<(glam::DVec3, glam::DVec3), String>,
    trims: &dyn Fn(glam::DVec2) -> bool,
    view: &SurfaceView,
) -> Result<(), String> {
    use bezier::render::{RenderSettings, SurfaceSample};
    /// A trim that asks the viewer's closure.
    struct Asking<'a>(&'a dyn Fn(glam::DVec2) -> bool);
    impl bezier::Trim for Asking<'_> {
        fn trims(&self, uv: glam::DVec2) -> bool {
            (self.0)(uv)
        }
    }
    let settings = RenderSettings {
        camera: bezier::zbuffer::Camera {
            eye: view.eye,
            target: view.target,
            up: glam::DVec3::Y,
            fov_y_degrees: 40.0,
        },
        tess_level: view.level,
        wireframe: view.wireframe,
        background: view.background,
    };
    // The surface's own error is the surface stage's to report; the
    // render only passes it on.
    let sample = |uv| {
        surface(uv)
            .map(|(position, normal)| SurfaceSample {
                uv,
                position,
                normal,
            })
            .map_err(|_| bezier::BezierError::Empty)
    };
    bezier::render::render_surface(canvas, sample, &Asking(trims), &settings)
        .map_err(|e| e.to_string())
}

/// Your tessellation of a set-up's surface, drawn by topic 09's renderer.
#[cfg(feature = "tessellation")]
fn tessellate(
    setup: &crate::tessellation::TessSetup,
    decomposed: Option<&Decomposed>,
) -> Result<crate::tessellation::Tessellated, String> {
    use crate::tessellation::{Look, Method, Surface, Tessellated, Test};
    use tessellation::bezier::BezierPatch;
    use tessellation::edge_tests::EdgeTest;
    use tessellation::mesh::Mesh;
    use tessellation::patch_grid::{GridPatch, PatchGrid};
    use tessellation::render::{Style, View};

    /// Every patch of `grid` by the set-up's method, in one mesh.
    fn patches<P: GridPatch>(
        grid: &PatchGrid<P>,
        setup: &crate::tessellation::TessSetup,
        test: EdgeTest,
    ) -> Result<Mesh, String> {
        let error = |e: tessellation::error::TessError| e.to_string();
        if setup.method == Method::PerPatch {
            return tessellation::per_patch::tessellate_patch_grid(grid, setup.tolerance)
                .map_err(error);
        }
        let n = setup.level as usize;
        let mut mesh = Mesh::new();
        for row in 0..grid.rows() {
            for col in 0..grid.cols() {
                let patch = grid.patch(row, col);
                let mut part =
                    tessellation::uniform::tessellate_uniform(patch, n, n).map_err(error)?;
                if setup.method == Method::FullyAdaptive {
                    part = tessellation::fully_adaptive::refine(patch, &part, test, setup.depth)
                        .map_err(error)?;
                }
                let offset = u32::try_from(mesh.positions.len()).map_err(|e| e.to_string())?;
                mesh.positions.extend(&part.positions);
                mesh.normals.extend(&part.normals);
                // Global parameters: patch (row, col) covers
                // [col, col + 1] × [row, row + 1], as topic 09's grid has it.
                let corner = glam::DVec2::new(col as f64, row as f64);
                mesh.uvs.extend(part.uvs.iter().map(|&uv| uv + corner));
                mesh.triangles
                    .extend(part.triangles.iter().map(|t| t.map(|k| k + offset)));
            }
        }
        Ok(mesh)
    }

    let [t, t2] = setup.thresholds;
    let test = match setup.test {
        Test::OneEdgeNormal => EdgeTest::OneEdgeNormal { t1: t },
        Test::OneEdgeComplementary => EdgeTest::OneEdgeComplementary { t1: t, t2 },
        Test::TwoTriangle => EdgeTest::TwoTriangle { t3: t },
        Test::FirstOrderNeighbour => EdgeTest::FirstOrderNeighbour { t3: t },
        Test::VectorDeviationFlat => EdgeTest::VectorDeviationFlat { t1: t },
        Test::LocalFlat => EdgeTest::LocalFlat { t1: t },
        Test::UmbrellaFlat => EdgeTest::UmbrellaFlat { t1: t },
    };
    let single = |patch| PatchGrid::try_new(1, 1, vec![patch]).map_err(|e| e.to_string());
    let mesh = match setup.surface {
        Surface::SeedSurface => patches(&single(BezierPatch::seed_surface())?, setup, test)?,
        Surface::Hill => patches(&single(BezierPatch::seed_hill())?, setup, test)?,
        Surface::Patches => patches(&PatchGrid::example(), setup, test)?,
        Surface::Torus => patches(&PatchGrid::torus(0.7, 0.25), setup, test)?,
        Surface::NurbsTorus | Surface::Vase => {
            let decomposed = decomposed.ok_or("the surface was not split into patches")?;
            let grid =
                PatchGrid::try_new(decomposed.rows, decomposed.cols, decomposed.patches.clone())
                    .map_err(|e| format!("your decomposition's patches: {e}"))?;
            patches(&grid, setup, test)?
        }
    };
    let style = match setup.look {
        Look::Shaded => Style::Shaded,
        Look::Wireframe => Style::Wireframe,
        Look::Both => Style::ShadedWireframe,
    };
    let view = View {
        yaw: setup.yaw.to_radians(),
        pitch: setup.pitch.to_radians(),
    };
    Ok(Tessellated {
        canvas: tessellation::render::render(&mesh, view, style, setup.size, setup.size),
        vertices: mesh.vertex_count(),
        triangles: mesh.triangle_count(),
        positions: mesh.positions.clone(),
        uvs: mesh.uvs.clone(),
    })
}

/// A trim of the surface scene as topic 10's render takes it.
#[cfg(feature = "gpu-tessellation")]
fn gpu_trim(setup: &crate::surfaces::TrimSetup) -> Option<gpu_tessellation::render::TrimShape> {
    use crate::surfaces::{CUBIC, INNER, QUADRATIC, TrimShape as Shape};
    use gpu_tessellation::render::{TrimCurve, TrimShape};
    let (c, s) = (setup.centre.as_vec2(), setup.size.as_vec2());
    let quadratic = |points| {
        let p = setup.curve_points(points).map(|p| p.as_vec2());
        [
            TrimCurve::Quadratic([p[0], p[1], p[2]]),
            TrimCurve::Quadratic([p[0], p[3], p[2]]),
        ]
    };
    Some(match setup.shape {
        Shape::None => return None,
        Shape::Rectangle => TrimShape::Rectangle {
            u: glam::Vec2::new(c.x - s.x, c.x + s.x),
            v: glam::Vec2::new(c.y - s.y, c.y + s.y),
        },
        Shape::Circle => TrimShape::Circle {
            centre: c,
            radius: s.x,
        },
        Shape::Ellipse => TrimShape::Ellipse {
            centre: c,
            radii: s,
        },
        Shape::NewtonQuadratic => {
            let [upper, lower] = quadratic(QUADRATIC);
            TrimShape::Bezier { upper, lower }
        }
        Shape::NewtonCubic => {
            let p = setup.curve_points(CUBIC).map(|p| p.as_vec2());
            TrimShape::Bezier {
                upper: TrimCurve::Cubic([p[0], p[1], p[2], p[3]]),
                lower: TrimCurve::Cubic([p[0], p[4], p[5], p[3]]),
            }
        }
        Shape::Nested => TrimShape::Nested {
            outer: quadratic(QUADRATIC),
            inner: quadratic(INNER),
        },
    })
}

/// `patch` raised to degree 3 in both directions (the GPU stages take
/// bicubic patches): degree elevation, exact, `h'_j = j/(q+1) · h_(j−1) +
/// (1 − j/(q+1)) · h_j` along a direction of degree `q`, repeated.
#[cfg(feature = "gpu-tessellation")]
fn bicubic(patch: &freeform::BezierPatch) -> freeform::BezierPatch {
    fn elevate(points: &[glam::DVec3]) -> Vec<glam::DVec3> {
        let n = points.len();
        (0..=n)
            .map(|j| {
                let a = j as f64 / n as f64;
                let before = if j == 0 { points[0] } else { points[j - 1] };
                let here = if j == n { points[n - 1] } else { points[j] };
                a * before + (1.0 - a) * here
            })
            .collect()
    }
    let rows: Vec<Vec<glam::DVec3>> = (0..=patch.degree_u())
        .map(|i| {
            let mut row = patch.row(i).to_vec();
            while row.len() < 4 {
                row = elevate(&row);
            }
            row
        })
        .collect();
    let columns: Vec<Vec<glam::DVec3>> = (0..4)
        .map(|j| {
            let mut column: Vec<glam::DVec3> = rows.iter().map(|row| row[j]).collect();
            while column.len() < 4 {
                column = elevate(&column);
            }
            column
        })
        .collect();
    freeform::BezierPatch::from_fn(3, 3, |i, j| columns[j][i]).unwrap_or_else(|_| patch.clone())
}

/// The WGSL of topic 10's four tasks that the GPU scene runs.
#[cfg(feature = "gpu-tessellation")]
#[derive(Clone, Copy, Debug)]
pub struct GpuPieces {
    /// Task 1's `control.wgsl`.
    pub control: gpu_tessellation::wgsl::Piece,
    /// Task 3's `evaluation.wgsl`.
    pub evaluation: gpu_tessellation::wgsl::Piece,
    /// Task 4's `shading.wgsl`.
    pub shading: gpu_tessellation::wgsl::Piece,
    /// Task 5's `trimming.wgsl`.
    pub trimming: gpu_tessellation::wgsl::Piece,
}

#[cfg(feature = "gpu-tessellation")]
impl GpuPieces {
    /// Your files, as the topic's crate holds them.
    pub const YOURS: Self = Self {
        control: gpu_tessellation::wgsl::CONTROL,
        evaluation: gpu_tessellation::wgsl::EVALUATION,
        shading: gpu_tessellation::wgsl::SHADING,
        trimming: gpu_tessellation::wgsl::TRIMMING,
    };
}

/// One frame of the GPU scene: your control pass, primitive generator,
/// evaluation pass, shading, trimming and wireframe edges with `pieces`,
/// each named with how it fared.
#[cfg(feature = "gpu-tessellation")]
#[must_use]
pub fn gpu_frame(
    setup: &crate::gpu_scene::GpuSetup,
    pieces: GpuPieces,
    decomposed: Option<&Decomposed>,
) -> crate::gpu_scene::GpuDrawing {
    use crate::gpu_scene::{GpuDrawing, GpuStageReport, GpuSurface, Levels, STAGES, Spacing};
    use gpu_tessellation::passes::{self, ControlSettings, Domain, LevelMode, Patches};
    use gpu_tessellation::patch::{BezierPatch, RationalPatch};
    use gpu_tessellation::render::{self as draw, DrawMesh, Shaders, Trimming};

    static GPU: std::sync::OnceLock<Result<gpu::Gpu, String>> = std::sync::OnceLock::new();
    let mut status: [Status; 6] = std::array::from_fn(|_| Status::Unused);
    let report = |status: [Status; 6], canvas, triangles, device| GpuDrawing {
        setup: *setup,
        canvas,
        stages: STAGES
            .iter()
            .zip(status)
            .map(|(&(name, source), status)| GpuStageReport {
                name,
                source,
                status,
            })
            .collect(),
        triangles,
        device,
    };
    let gpu = match GPU.get_or_init(|| gpu::Gpu::new().map_err(|e| e.to_string())) {
        Ok(gpu) => gpu,
        Err(e) => {
            let none = Status::Failed(format!("no GPU adapter: {e}"));
            return report(std::array::from_fn(|_| none.clone()), None, 0, e.clone());
        }
    };
    let device = gpu.describe();
    let failed = |e: gpu_tessellation::TessError| Status::Failed(e.to_string());
    // The stages after one that stopped the frame: each is asked whether
    // it is written at all (a file of comments, a `todo!()` on a trivial
    // call), so that every unwritten stage is named, not only the first.
    let not_reached = |status: &mut [Status; 6], from: usize| {
        for (k, s) in status.iter_mut().enumerate().skip(from) {
            *s = Status::Unused;
            let _ = match k {
                0 => guarded(s, || pieces.control.written().started()),
                1 => guarded(s, || {
                    let domain = gpu_tessellation::domain::quad_domain(
                        [2.0; 2],
                        [2.0; 4],
                        gpu_tessellation::domain::Spacing::Equal,
                    );
                    domain.points.is_empty()
                }),
                2 => guarded(s, || pieces.evaluation.written().started()),
                3 => guarded(s, || pieces.shading.written().started()),
                4 if setup.trim.shape != crate::surfaces::TrimShape::None => {
                    guarded(s, || pieces.trimming.written().started())
                }
                5 if setup.wireframe => guarded(s, || {
                    gpu_tessellation::shading::wireframe_edges(&[[0, 1, 2]]).is_empty()
                }),
                _ => continue, // not used by this picture
            };
            if s.usable() {
                *s = Status::NotReached;
            }
        }
    };

    let (quads, rational): (Vec<BezierPatch>, Option<Vec<RationalPatch>>) = match setup.surface {
        GpuSurface::Hill => (vec![BezierPatch::seed_hill()], None),
        GpuSurface::SeedSurface => (vec![bicubic(&BezierPatch::seed_surface())], None),
        GpuSurface::Torus => {
            let torus: Vec<RationalPatch> = RationalPatch::torus(0.7, 0.25)
                .iter()
                .filter_map(|p| p.elevated().ok())
                .collect();
            (
                torus.iter().map(|p| p.points().clone()).collect(),
                Some(torus),
            )
        }
        GpuSurface::NurbsTorus | GpuSurface::Vase => {
            // Your decomposition's patches, raised to the bicubic patches
            // the GPU buffer holds (given: `RationalPatch::elevated_to`).
            let raised = decomposed
                .ok_or_else(|| "the surface was not split into patches".to_owned())
                .and_then(|d| {
                    d.patches
                        .iter()
                        .map(|p| p.elevated_to(3, 3).map_err(|e| e.to_string()))
                        .collect::<Result<Vec<RationalPatch>, String>>()
                });
            match raised {
                Ok(raised) => (
                    raised.iter().map(|p| p.points().clone()).collect(),
                    Some(raised),
                ),
                Err(e) => {
                    let stopped = Status::Failed(e);
                    return report(std::array::from_fn(|_| stopped.clone()), None, 0, device);
                }
            }
        }
    };
    // The camera looks at the middle of the control points, from a
    // distance in units of their extent.
    let points: Vec<glam::DVec3> = quads
        .iter()
        .flat_map(|p| {
            (0..=p.degree_u())
                .flat_map(move |i| (0..=p.degree_v()).map(move |j| p.control_point(i, j)))
        })
        .collect();
    let (lo, hi) = points.iter().fold(
        (glam::DVec3::splat(f64::MAX), glam::DVec3::splat(f64::MIN)),
        |(lo, hi), &p| (lo.min(p), hi.max(p)),
    );
    let target = ((lo + hi) * 0.5).as_vec3();
    let radius = ((hi - lo).length() * 0.5).max(1e-3) as f32;
    let eye = target + (setup.eye(glam::Vec3::ZERO)) * radius;
    let scene = draw::Scene::perspective(eye, target, setup.width, setup.height);

    // 1. The control pass: levels per patch.
    let settings = ControlSettings {
        view_proj: scene.view_proj,
        viewport: glam::Vec2::new(setup.width as f32, setup.height as f32),
        mode: match setup.levels {
            Levels::Uniform => LevelMode::Uniform(setup.level),
            Levels::Adaptive => LevelMode::Adaptive {
                pixels_per_segment: setup.pixels_per_segment,
            },
        },
    };
    let levels = match guarded(&mut status[0], || {
        passes::run_control(gpu, pieces.control.written(), &quads, &settings)
    }) {
        Some(Ok(levels)) => levels,
        Some(Err(e)) => {
            status[0] = failed(e);
            not_reached(&mut status, 1);
            return report(status, None, 0, device);
        }
        None => {
            not_reached(&mut status, 1);
            return report(status, None, 0, device);
        }
    };
    // 2. The primitive generator: (u, v) points and triangles per patch.
    let spacing = match setup.spacing {
        Spacing::Equal => gpu_tessellation::domain::Spacing::Equal,
        Spacing::FractionalEven => gpu_tessellation::domain::Spacing::FractionalEven,
        Spacing::FractionalOdd => gpu_tessellation::domain::Spacing::FractionalOdd,
    };
    let Some(domains) = guarded(&mut status[1], || {
        levels
            .iter()
            .map(|l| l.domain(spacing))
            .collect::<Vec<Domain>>()
    }) else {
        not_reached(&mut status, 2);
        return report(status, None, 0, device);
    };
    // 3. The evaluation pass: vertices on the GPU.
    let refs: Vec<&Domain> = domains.iter().collect();
    let patches = match &rational {
        Some(rational) => Patches::Rational(rational),
        None => Patches::Quads(&quads),
    };
    let mesh = match guarded(&mut status[2], || {
        passes::run_evaluation(gpu, pieces.evaluation.written(), patches, &refs)
    }) {
        Some(Ok(mesh)) => mesh,
        Some(Err(e)) => {
            status[2] = failed(e);
            not_reached(&mut status, 3);
            return report(status, None, 0, device);
        }
        None => {
            not_reached(&mut status, 3);
            return report(status, None, 0, device);
        }
    };
    // 4, 5. Your shading and trimming, or the given stand-ins.
    let stand_in = |status: &mut Status, instead: &str| {
        if let Status::NotYet(message) = status {
            *status = Status::NotYet(format!("{message} ({instead} meanwhile)"));
        }
    };
    let shading = guarded(&mut status[3], || pieces.shading.written());
    stand_in(&mut status[3], "drawn with the given flat colour");
    let trim = gpu_trim(&setup.trim);
    let trimming = Trimming {
        shapes: trim.into_iter().collect(),
        iterations: setup.trim.iterations,
        epsilon: setup.trim.epsilon as f32,
    };
    let trimming_piece = if trimming.shapes.is_empty() {
        None
    } else {
        let piece = guarded(&mut status[4], || pieces.trimming.written());
        stand_in(&mut status[4], "nothing trimmed");
        piece
    };
    // 6. The wireframe's edges.
    let edges = if setup.wireframe {
        guarded(&mut status[5], || {
            gpu_tessellation::shading::wireframe_edges(&mesh.triangles)
        })
    } else {
        None
    };
    let shaders = Shaders {
        shading,
        trimming: trimming_piece.map(|piece| (piece, &trimming)),
    };
    let meshes = [DrawMesh {
        vertices: &mesh.vertices,
        triangles: &mesh.triangles,
        edges: edges.as_deref(),
    }];
    match draw::render(gpu, setup.width, setup.height, &scene, shaders, &meshes) {
        Ok(canvas) => report(status, Some(canvas), mesh.triangles.len(), device),
        Err(e) => {
            let message = e.to_string();
            let culprit = if message.contains("trimming.wgsl") {
                4
            } else {
                3
            };
            status[culprit] = Status::Failed(message);
            report(status, None, 0, device)
        }
    }
}

/// How a stage fared in one frame.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Status {
    /// Not needed by this frame (lines in a filled picture, say).
    Unused,
    /// Needed, but nothing reached it: a stage before it drew nothing.
    NotReached,
    /// Every call returned.
    Ok,
    /// Its topic is not part of the build (it does not compile).
    Missing,
    /// It reached a `todo!()`: the message.
    NotYet(String),
    /// It panicked: the message.
    Panicked(String),
    /// It returned an error: the message.
    Failed(String),
}

impl Status {
    /// Whether the stage can still be called in this frame.
    #[must_use]
    pub fn usable(&self) -> bool {
        matches!(self, Self::Unused | Self::NotReached | Self::Ok)
    }

    /// One line for the screen.
    #[must_use]
    pub fn describe(&self) -> String {
        match self {
            Self::Unused => "not used by this picture".to_owned(),
            Self::NotReached => "not reached: nothing came through the stages before it".to_owned(),
            Self::Ok => "ok".to_owned(),
            Self::Missing => {
                "left out: its topic is not in this build (it does not compile, or was not graded with it)"
                    .to_owned()
            }
            Self::NotYet(message) => format!("not written yet: {message}"),
            Self::Panicked(message) => format!("panicked: {message}"),
            Self::Failed(message) => format!("returned an error: {message}"),
        }
    }
}

/// The text of a panic's payload.
fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| (*s).to_owned())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "(a panic without a message)".to_owned())
}

/// Runs `call` unless the stage has already failed in this frame; a panic
/// becomes the stage's status (a `todo!()` is [`Status::NotYet`]).
pub fn guarded<R>(status: &mut Status, call: impl FnOnce() -> R) -> Option<R> {
    if !status.usable() {
        return None;
    }
    match catch_unwind(AssertUnwindSafe(call)) {
        Ok(value) => {
            *status = Status::Ok;
            Some(value)
        }
        Err(payload) => {
            let message = panic_message(payload.as_ref());
            *status = match message.strip_prefix("not yet implemented") {
                Some(rest) => Status::NotYet(rest.strip_prefix(": ").unwrap_or(rest).to_owned()),
                None => Status::Panicked(message),
            };
            None
        }
    }
}

/// The name worker threads carry: panics there are reported on screen, so
/// [`quiet_panics`] keeps them off the terminal.
pub const WORKER_THREAD: &str = "viewer-stages";

/// Installs a panic hook that is silent on [`WORKER_THREAD`] threads (their
/// panics are caught and shown) and prints as usual elsewhere.
pub fn quiet_panics() {
    let default = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        if std::thread::current().name() != Some(WORKER_THREAD) {
            default(info);
        }
    }));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_todo_is_not_yet_written_and_a_panic_is_a_panic() {
        let mut status = Status::Unused;
        assert_eq!(guarded(&mut status, || 3), Some(3));
        assert_eq!(status, Status::Ok);
        let mut status = Status::Unused;
        let got: Option<()> = guarded(&mut status, || todo!("dda: plot one fragment per column"));
        assert_eq!(got, None);
        assert_eq!(
            status,
            Status::NotYet("dda: plot one fragment per column".to_owned())
        );
        // Once failed, the stage is not called again in this frame.
        assert_eq!(guarded(&mut status, || 4), None);
        let mut status = Status::Unused;
        let _ = guarded(&mut status, || -> u8 { panic!("index {} out of range", 7) });
        assert_eq!(status, Status::Panicked("index 7 out of range".to_owned()));
        assert!(status.describe().starts_with("panicked: index 7"));
    }
}
