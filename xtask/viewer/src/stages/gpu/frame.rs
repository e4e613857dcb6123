//! Topic 10's passes drawing one frame of the GPU scene: your control
//! pass, primitive generator, evaluation pass, shading, trimming and
//! wireframe edges, each named with how it fared.

use super::{GpuDrawing, GpuSetup, GpuStageReport, GpuSurface, Levels, STAGES, Spacing};
use crate::stages::trim::{TrimSetup, TrimShape};
use crate::stages::{Decomposed, Status, guarded};

/// A trim of the surface scene as topic 10's render takes it.
fn gpu_trim(setup: &TrimSetup) -> Option<gpu_tessellation::render::TrimShape> {
    use crate::stages::trim::{CUBIC, INNER, QUADRATIC, TrimShape as Shape};
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
/// bicubic patches): freeform's degree elevation, exact, `h'_j = j/(q+1) ·
/// h_(j−1) + (1 − j/(q+1)) · h_j` along a direction of degree `q`,
/// repeated (`RationalPatch::elevated_to`, every weight 1).
fn bicubic(patch: &freeform::BezierPatch) -> freeform::BezierPatch {
    freeform::RationalPatch::polynomial(patch.clone())
        .elevated_to(3, 3)
        .map_or_else(|_| patch.clone(), |raised| raised.points().clone())
}

/// The WGSL of topic 10's four tasks that the GPU scene runs.
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
#[must_use]
pub fn gpu_frame(
    setup: &GpuSetup,
    pieces: GpuPieces,
    decomposed: Option<&Decomposed>,
) -> GpuDrawing {
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
                4 if setup.trim.shape != TrimShape::None => {
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
