//! The compute passes that stand in for the tessellation stages wgpu lacks:
//! the control pass (levels per patch, your task 1; PN triangles from flat
//! ones, your task 6) and the evaluation pass (surface points per domain
//! point, your task 3). Given code: it puts
//! your WGSL file and the given WGSL of [`crate::shaders`] together
//! ([`crate::wgsl::compose`]), runs it and reads the results back.
//!
//! Between the two sits the primitive generator (your task 2,
//! [`crate::domain`]): the control pass's [`QuadLevels`] go in, a domain
//! comes out, and [`Domain`] is its points as the evaluation pass reads
//! them (what GLSL calls `gl_TessCoord`).

use bytemuck::{Pod, Zeroable};
use glam::{Mat4, Vec2, Vec3, Vec4};
use gpu::{Gpu, read_buffer, wgpu};
use wgpu::util::DeviceExt;

use crate::TessError;
use crate::domain::{QuadDomain, Spacing, TriangleDomain, quad_domain};
use crate::patch::{
    BezierPatch, BezierTriangle, GpuVertex, RationalPatch, patch_to_gpu, rational_patch_to_gpu,
    triangle_to_gpu,
};
use crate::shaders;
use crate::wgsl::{Part, Piece};

/// The largest tessellation level the control pass gives: the primitive
/// generator's [`MAX_TESS_GEN_LEVEL`](crate::domain::MAX_TESS_GEN_LEVEL)
/// (`MAX_TESS_LEVEL` in the WGSL).
#[allow(clippy::cast_possible_truncation)] // 64 is exact in f32
pub const MAX_TESS_LEVEL: f32 = crate::domain::MAX_TESS_GEN_LEVEL as f32;

/// Levels of a quad patch, as the control pass writes them (GLSL
/// `gl_TessLevelOuter[0..4]`, `gl_TessLevelInner[0..2]`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuadLevels {
    /// Edges `u = 0`, `v = 0`, `u = 1`, `v = 1`.
    pub outer: [f32; 4],
    /// Interior cuts along `u` and along `v`.
    pub inner: [f32; 2],
}

impl QuadLevels {
    /// All six levels equal to `level` (the seed's TCS, Listing 1).
    #[must_use]
    pub const fn uniform(level: f32) -> Self {
        Self {
            outer: [level; 4],
            inner: [level; 2],
        }
    }

    /// The domain the primitive generator ([`crate::domain::quad_domain`],
    /// your task 2) makes of these levels, as the evaluation pass reads it.
    #[must_use]
    pub fn domain(self, spacing: Spacing) -> Domain {
        let quads = quad_domain(
            self.inner.map(f64::from),
            self.outer.map(f64::from),
            spacing,
        );
        Domain::from(&quads)
    }
}

/// Domain points as the evaluation pass reads them: `(u, v, 0)` for quads,
/// barycentric `(u, v, w)` for triangles (`gl_TessCoord`), and the
/// domain's counter-clockwise triangles.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Domain {
    /// Domain points.
    pub points: Vec<Vec3>,
    /// Counter-clockwise triangles as indices into `points`.
    pub triangles: Vec<[u32; 3]>,
}

impl From<&QuadDomain> for Domain {
    fn from(domain: &QuadDomain) -> Self {
        Self {
            points: domain
                .points
                .iter()
                .map(|p| p.as_vec2().extend(0.0))
                .collect(),
            triangles: domain.triangles.clone(),
        }
    }
}

impl From<&TriangleDomain> for Domain {
    fn from(domain: &TriangleDomain) -> Self {
        Self {
            points: domain
                .points
                .iter()
                .map(|&[u, v, w]| Vec3::new(u as f32, v as f32, w as f32))
                .collect(),
            triangles: domain.triangles.clone(),
        }
    }
}

/// The patches as the GPU reads them ([`patch_to_gpu`]).
///
/// Errors: a patch that is not bicubic ([`TessError::Invalid`]).
fn bicubic(patches: &[BezierPatch]) -> Result<Vec<[Vec4; 16]>, TessError> {
    gpu_patches(
        patches
            .iter()
            .map(|p| (patch_to_gpu(p), [p.degree_u(), p.degree_v()])),
    )
}

/// Rational patches as the GPU reads them ([`rational_patch_to_gpu`]).
///
/// Errors: a patch that is neither bicubic nor `n × n` below 3
/// ([`TessError::Invalid`]).
fn homogeneous(patches: &[RationalPatch]) -> Result<Vec<[Vec4; 16]>, TessError> {
    gpu_patches(patches.iter().map(|r| {
        let net = r.points();
        (rational_patch_to_gpu(r), [net.degree_u(), net.degree_v()])
    }))
}

/// Each patch's 16 points as the GPU reads them, given with its degrees
/// for the error: [`TessError::Invalid`] naming the first patch that has
/// none (not bicubic, and for a rational patch not `n × n` below 3 either,
/// see [`rational_patch_to_gpu`]).
fn gpu_patches(
    patches: impl Iterator<Item = (Option<[Vec4; 16]>, [usize; 2])>,
) -> Result<Vec<[Vec4; 16]>, TessError> {
    patches
        .enumerate()
        .map(|(k, (points, [p, q]))| {
            points.ok_or_else(|| {
                TessError::Invalid(format!(
                    "patch {k} has degree {p} × {q}; the GPU stages take bicubic patches"
                ))
            })
        })
        .collect()
}

/// How the control pass chooses levels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LevelMode {
    /// Every level equal to this one (the seed's `tessLevel`, Listing 1).
    Uniform(f32),
    /// From each boundary curve's projected length in pixels, divided by
    /// this target segment length (seed 001 §2.1, per-patch adaptive).
    Adaptive {
        /// The wanted length of one segment on screen, in pixels.
        pixels_per_segment: f32,
    },
}

/// What the control pass needs besides the patches.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ControlSettings {
    /// World to clip space.
    pub view_proj: Mat4,
    /// Viewport size in pixels.
    pub viewport: Vec2,
    /// Uniform or adaptive levels.
    pub mode: LevelMode,
}

/// WGSL `ControlParams` (96 bytes).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
struct ControlParams {
    view_proj: [[f32; 4]; 4],
    viewport: [f32; 2],
    mode: u32,
    uniform_level: f32,
    pixels_per_segment: f32,
    pad: [f32; 3],
}

/// WGSL `TessLevels` (32 bytes).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
struct GpuLevels {
    outer: [f32; 4],
    inner: [f32; 2],
    pad: [f32; 2],
}

/// WGSL `Job`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
struct Job {
    domain_offset: u32,
    point_count: u32,
    vertex_offset: u32,
    pad: u32,
}

/// Threads per workgroup of both passes (`@workgroup_size(64)`).
const WORKGROUP_SIZE: u32 = 64;

fn storage(gpu: &Gpu, label: &str, bytes: &[u8], extra: wgpu::BufferUsages) -> wgpu::Buffer {
    // wgpu rejects empty bindings: bind at least 16 bytes.
    let mut contents = bytes.to_vec();
    contents.resize(bytes.len().max(16), 0);
    gpu.device
        .create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents: &contents,
            usage: wgpu::BufferUsages::STORAGE | extra,
        })
}

fn compute_pipeline(
    gpu: &Gpu,
    module: &wgpu::ShaderModule,
    entry: &str,
) -> Result<wgpu::ComputePipeline, TessError> {
    Ok(gpu.validated(entry, || {
        gpu.device
            .create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: Some(entry),
                layout: None,
                module,
                entry_point: Some(entry),
                compilation_options: Default::default(),
                cache: None,
            })
    })?)
}

fn bind(
    gpu: &Gpu,
    pipeline: &wgpu::ComputePipeline,
    buffers: &[(u32, &wgpu::Buffer)],
) -> Result<wgpu::BindGroup, TessError> {
    let entries: Vec<wgpu::BindGroupEntry<'_>> = buffers
        .iter()
        .map(|&(binding, buffer)| wgpu::BindGroupEntry {
            binding,
            resource: buffer.as_entire_binding(),
        })
        .collect();
    Ok(gpu.validated("bind group", || {
        gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: None,
            layout: &pipeline.get_bind_group_layout(0),
            entries: &entries,
        })
    })?)
}

fn dispatch(gpu: &Gpu, pipeline: &wgpu::ComputePipeline, group: &wgpu::BindGroup, size: [u32; 2]) {
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_compute_pass(&Default::default());
        pass.set_pipeline(pipeline);
        pass.set_bind_group(0, group, &[]);
        pass.dispatch_workgroups(size[0].div_ceil(WORKGROUP_SIZE), size[1], 1);
    }
    gpu.queue.submit([encoder.finish()]);
}

/// Runs the control pass with `control` (task 1, [`crate::wgsl::CONTROL`])
/// over `patches` and returns one set of levels per patch.
///
/// Errors: a level or target that is not a positive finite number, a
/// non-finite matrix or viewport ([`TessError::Invalid`]); WGSL that does
/// not compile or validate ([`TessError::Wgsl`]).
pub fn run_control(
    gpu: &Gpu,
    control: Piece,
    patches: &[BezierPatch],
    settings: &ControlSettings,
) -> Result<Vec<QuadLevels>, TessError> {
    let (mode, uniform_level, pixels_per_segment) = match settings.mode {
        LevelMode::Uniform(level) => (0, level, 1.0),
        LevelMode::Adaptive { pixels_per_segment } => (1, 1.0, pixels_per_segment),
    };
    for (what, x) in [
        ("the uniform level", uniform_level),
        ("pixels per segment", pixels_per_segment),
    ] {
        if !(x.is_finite() && x > 0.0) {
            return Err(TessError::Invalid(format!(
                "{what} must be a positive finite number, not {x}"
            )));
        }
    }
    if !settings.view_proj.is_finite() || !settings.viewport.is_finite() {
        return Err(TessError::Invalid(
            "the view-projection matrix and the viewport must be finite".into(),
        ));
    }
    if patches.is_empty() {
        return Ok(Vec::new());
    }
    let source = crate::wgsl::compose(&[
        Part::Yours(control),
        Part::Given("crate::shaders::COMMON", shaders::COMMON),
        Part::Given("crate::shaders::CONTROL", shaders::CONTROL),
    ])?;
    let module = gpu.shader("control", &source)?;
    let pipeline = compute_pipeline(gpu, &module, "control_main")?;
    let gpu_patches = bicubic(patches)?;
    let patch_buffer = storage(
        gpu,
        "patches",
        bytemuck::cast_slice(&gpu_patches),
        wgpu::BufferUsages::empty(),
    );
    let params = ControlParams {
        view_proj: settings.view_proj.to_cols_array_2d(),
        viewport: settings.viewport.to_array(),
        mode,
        uniform_level,
        pixels_per_segment,
        pad: [0.0; 3],
    };
    let params_buffer = gpu
        .device
        .create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("control params"),
            contents: bytemuck::bytes_of(&params),
            usage: wgpu::BufferUsages::UNIFORM,
        });
    let zeros = vec![GpuLevels::zeroed(); patches.len()];
    let levels_buffer = storage(
        gpu,
        "levels",
        bytemuck::cast_slice(&zeros),
        wgpu::BufferUsages::COPY_SRC,
    );
    let group = bind(
        gpu,
        &pipeline,
        &[(0, &patch_buffer), (1, &params_buffer), (2, &levels_buffer)],
    )?;
    dispatch(gpu, &pipeline, &group, [patches.len() as u32, 1]);
    let levels: Vec<GpuLevels> = read_buffer(gpu, &levels_buffer)?;
    Ok(levels[..patches.len()]
        .iter()
        .map(|l| QuadLevels {
            outer: l.outer,
            inner: l.inner,
        })
        .collect())
}

/// A flat triangle with a normal at each vertex: what the PN pass (task 6)
/// turns into a cubic Bézier triangle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlatTriangle {
    /// `P1, P2, P3`.
    pub corners: [Vec3; 3],
    /// `N1, N2, N3`, any non-zero length.
    pub normals: [Vec3; 3],
}

/// WGSL `FlatTriangle` (96 bytes).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
struct GpuFlatTriangle {
    corners: [[f32; 4]; 3],
    normals: [[f32; 4]; 3],
}

/// Runs the PN pass with `pn` (task 6, [`crate::wgsl::PN`]) over
/// `triangles` and returns the PN triangle of each, read back from the
/// GPU: what seed 001's control stage hands to the evaluation stage.
///
/// Errors: a non-finite corner or normal, or a normal too short to
/// normalise in `f32` ([`TessError::Invalid`]); WGSL that does not compile
/// or validate ([`TessError::Wgsl`]).
pub fn run_pn_control(
    gpu: &Gpu,
    pn: Piece,
    triangles: &[FlatTriangle],
) -> Result<Vec<BezierTriangle>, TessError> {
    for (k, t) in triangles.iter().enumerate() {
        if !t.corners.iter().chain(&t.normals).all(|v| v.is_finite()) {
            return Err(TessError::Invalid(format!(
                "flat triangle {k} has a non-finite corner or normal"
            )));
        }
        if t.normals
            .iter()
            .any(|n| n.length_squared() < f32::MIN_POSITIVE)
        {
            return Err(TessError::Invalid(format!(
                "flat triangle {k} has a zero normal, which has no direction"
            )));
        }
    }
    if triangles.is_empty() {
        return Ok(Vec::new());
    }
    let source = crate::wgsl::compose(&[
        Part::Yours(pn),
        Part::Given("crate::shaders::COMMON", shaders::COMMON),
        Part::Given("crate::shaders::PN", shaders::PN),
    ])?;
    let module = gpu.shader("pn", &source)?;
    let pipeline = compute_pipeline(gpu, &module, "pn_main")?;
    let flat: Vec<GpuFlatTriangle> = triangles
        .iter()
        .map(|t| GpuFlatTriangle {
            corners: t.corners.map(|c| c.extend(1.0).to_array()),
            normals: t.normals.map(|n| n.extend(0.0).to_array()),
        })
        .collect();
    let flat_buffer = storage(
        gpu,
        "flat triangles",
        bytemuck::cast_slice(&flat),
        wgpu::BufferUsages::empty(),
    );
    let zeros = vec![[Vec4::ZERO; 10]; triangles.len()];
    let pn_buffer = storage(
        gpu,
        "PN triangles",
        bytemuck::cast_slice(&zeros),
        wgpu::BufferUsages::COPY_SRC,
    );
    let group = bind(gpu, &pipeline, &[(0, &flat_buffer), (1, &pn_buffer)])?;
    dispatch(gpu, &pipeline, &group, [triangles.len() as u32, 1]);
    let points: Vec<[Vec4; 10]> = read_buffer(gpu, &pn_buffer)?;
    Ok(points[..triangles.len()]
        .iter()
        .map(|p| BezierTriangle::from_points(p.map(|q| q.truncate().as_dvec3())))
        .collect())
}

/// Vertices on the GPU, as the evaluation pass wrote them: usable as a
/// vertex buffer without a round trip.
#[derive(Debug)]
pub struct GpuMesh {
    /// `vertex_count` [`GpuVertex`]es (usage `STORAGE | VERTEX | COPY_SRC`).
    pub vertices: wgpu::Buffer,
    /// Number of vertices.
    pub vertex_count: u32,
    /// Triangles, indices already offset per patch.
    pub triangles: Vec<[u32; 3]>,
}

impl GpuMesh {
    /// Copies the vertices back to the CPU.
    pub fn read(&self, gpu: &Gpu) -> Result<Vec<GpuVertex>, TessError> {
        let mut v: Vec<GpuVertex> = read_buffer(gpu, &self.vertices)?;
        v.truncate(self.vertex_count as usize);
        Ok(v)
    }
}

/// Which patches the evaluation pass reads.
#[derive(Clone, Copy, Debug)]
pub enum Patches<'a> {
    /// Bicubic patches, `evaluate_patch`.
    Quads(&'a [BezierPatch]),
    /// Rational patches (pieces of a NURBS surface), bicubic or raised to
    /// it, uploaded homogeneous ([`rational_patch_to_gpu`]),
    /// `evaluate_patch`.
    Rational(&'a [RationalPatch]),
    /// Cubic Bézier triangles, `evaluate_triangle`.
    Triangles(&'a [BezierTriangle]),
}

impl Patches<'_> {
    fn len(&self) -> usize {
        match self {
            Patches::Quads(p) => p.len(),
            Patches::Rational(p) => p.len(),
            Patches::Triangles(t) => t.len(),
        }
    }
}

/// Runs the evaluation pass with `evaluation` (task 3,
/// [`crate::wgsl::EVALUATION`]): patch `k` is evaluated at every point of
/// `domains[k]` (quads read `(u, v)`, triangles `(u, v, w)`). Compiles
/// the pass first; to run it many times, make an [`EvaluationPass`] once.
///
/// Errors: as [`EvaluationPass::new`] and [`EvaluationPass::run`].
pub fn run_evaluation(
    gpu: &Gpu,
    evaluation: Piece,
    patches: Patches<'_>,
    domains: &[&Domain],
) -> Result<GpuMesh, TessError> {
    EvaluationPass::new(gpu, evaluation)?.run(gpu, patches, domains)
}

/// The evaluation pass, compiled: its shader and its two pipelines, made
/// once (the set-up of a frame) and run for every frame.
#[derive(Debug)]
pub struct EvaluationPass {
    quads: wgpu::ComputePipeline,
    triangles: wgpu::ComputePipeline,
}

impl EvaluationPass {
    /// Checks and compiles `evaluation` with the given WGSL.
    ///
    /// Errors: WGSL that does not compile or validate ([`TessError::Wgsl`],
    /// [`TessError::Gpu`]).
    pub fn new(gpu: &Gpu, evaluation: Piece) -> Result<Self, TessError> {
        let source = crate::wgsl::compose(&[
            Part::Yours(evaluation),
            Part::Given("crate::shaders::COMMON", shaders::COMMON),
            Part::Given("crate::shaders::EVALUATION", shaders::EVALUATION),
        ])?;
        let module = gpu.shader("evaluation", &source)?;
        Ok(Self {
            quads: compute_pipeline(gpu, &module, "evaluate_quads")?,
            triangles: compute_pipeline(gpu, &module, "evaluate_triangles")?,
        })
    }

    /// Evaluates patch `k` at every point of `domains[k]` (quads read
    /// `(u, v)`, triangles `(u, v, w)`): uploads, dispatches, and leaves
    /// the vertices on the GPU.
    ///
    /// Errors: `domains.len()` differs from the number of patches, or a
    /// domain point is not finite ([`TessError::Invalid`]); a bind group
    /// wgpu refuses ([`TessError::Gpu`]).
    pub fn run(
        &self,
        gpu: &Gpu,
        patches: Patches<'_>,
        domains: &[&Domain],
    ) -> Result<GpuMesh, TessError> {
        if domains.len() != patches.len() {
            return Err(TessError::Invalid(format!(
                "{} patches but {} domains",
                patches.len(),
                domains.len()
            )));
        }
        if domains
            .iter()
            .any(|d| d.points.iter().any(|p| !p.is_finite()))
        {
            return Err(TessError::Invalid("a domain point is not finite".into()));
        }
        let mut jobs = Vec::with_capacity(domains.len());
        let mut points: Vec<Vec4> = Vec::new();
        let mut triangles = Vec::new();
        let mut max_points = 0;
        for domain in domains {
            let offset = points.len() as u32;
            jobs.push(Job {
                domain_offset: offset,
                point_count: domain.points.len() as u32,
                vertex_offset: offset,
                pad: 0,
            });
            max_points = max_points.max(domain.points.len() as u32);
            points.extend(domain.points.iter().map(|p: &Vec3| p.extend(0.0)));
            triangles.extend(domain.triangles.iter().map(|t| t.map(|k| k + offset)));
        }
        let vertex_count = points.len() as u32;
        let zeros = vec![GpuVertex::default(); points.len()];
        let vertices = storage(
            gpu,
            "vertices",
            bytemuck::cast_slice(&zeros),
            wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_SRC,
        );
        if jobs.is_empty() || max_points == 0 {
            return Ok(GpuMesh {
                vertices,
                vertex_count,
                triangles,
            });
        }
        let none = wgpu::BufferUsages::empty();
        let domain_buffer = storage(gpu, "domain", bytemuck::cast_slice(&points), none);
        let job_buffer = storage(gpu, "jobs", bytemuck::cast_slice(&jobs), none);
        let quads = |data: Vec<[Vec4; 16]>| {
            let buffer = storage(gpu, "patches", bytemuck::cast_slice(&data), none);
            (&self.quads, 0, buffer)
        };
        let (pipeline, patch_binding, patch_buffer) = match patches {
            Patches::Quads(p) => quads(bicubic(p)?),
            Patches::Rational(p) => quads(homogeneous(p)?),
            Patches::Triangles(t) => {
                let data: Vec<[Vec4; 10]> = t.iter().map(triangle_to_gpu).collect();
                let buffer = storage(gpu, "triangles", bytemuck::cast_slice(&data), none);
                (&self.triangles, 1, buffer)
            }
        };
        let group = bind(
            gpu,
            pipeline,
            &[
                (patch_binding, &patch_buffer),
                (2, &domain_buffer),
                (3, &job_buffer),
                (4, &vertices),
            ],
        )?;
        dispatch(gpu, pipeline, &group, [max_points, jobs.len() as u32]);
        Ok(GpuMesh {
            vertices,
            vertex_count,
            triangles,
        })
    }
}
