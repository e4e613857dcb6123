//! The render pass: depth-tested triangles shaded by a fragment shader that
//! trims in `(u, v)` (seed 000 §4.2), with an optional wireframe drawn over
//! them. Given code: it pastes your shading (task 4) and trimming (task 5)
//! WGSL between the pieces of [`crate::shaders`].

use bytemuck::{Pod, Zeroable};
use canvas::{Canvas, Rgba};
use glam::{Mat4, Vec2, Vec3, Vec4};
use gpu::{COLOUR_FORMAT, DEPTH_FORMAT, Gpu, OffscreenTarget, wgpu};
use wgpu::util::DeviceExt;

use crate::TessError;
use crate::patch::GpuVertex;
use crate::shaders;
use crate::wgsl::{self, Part, Piece};

/// The first light of seed 000's fragment shader (Listing 13, line 53).
pub const LIGHT_0: Vec3 = Vec3::new(0.0, 10.0, 0.0);
/// The second light (Listing 13, line 54).
pub const LIGHT_1: Vec3 = Vec3::new(0.0, -10.0, 0.0);
/// Side length of the procedural brick texture in texels.
pub const TEXTURE_SIZE: u32 = 64;
/// Depth bias of the surface under a wireframe (polygon offset, seed 002):
/// the lines lie exactly on the surface and would otherwise z-fight.
const WIREFRAME_BIAS: wgpu::DepthBiasState = wgpu::DepthBiasState {
    constant: 16,
    slope_scale: 2.0,
    clamp: 0.0,
};
/// The most trim shapes and trim curves one render takes.
pub const MAX_TRIM_SHAPES: usize = 8;
/// See [`MAX_TRIM_SHAPES`].
pub const MAX_TRIM_CURVES: usize = 8;

/// Camera, lights and colours of a picture.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scene {
    /// World to clip space.
    pub view_proj: Mat4,
    /// Eye position in world space (for the specular term).
    pub eye: Vec3,
    /// The two light positions.
    pub lights: [Vec3; 2],
    /// Clear colour.
    pub background: Rgba,
    /// Colour of the flat shading used when task 4 is not involved.
    pub base_colour: Rgba,
    /// Colour of wireframe lines.
    pub wire_colour: Rgba,
}

impl Scene {
    /// An orthographic view of the box `[lo, hi] × [-depth, depth]` seen
    /// from `+z` (x right, y up), eye on the `+z` axis, the seed's lights.
    #[must_use]
    pub fn orthographic(lo: Vec2, hi: Vec2, depth: f32) -> Self {
        Self {
            view_proj: glam::camera::rh::proj::directx::orthographic(
                lo.x, hi.x, lo.y, hi.y, -depth, depth,
            ),
            eye: Vec3::new(0.5 * (lo.x + hi.x), 0.5 * (lo.y + hi.y), 100.0),
            lights: [LIGHT_0, LIGHT_1],
            background: Rgba::BLACK,
            base_colour: Rgba::WHITE,
            wire_colour: Rgba::new(1.0, 0.85, 0.2, 1.0),
        }
    }

    /// A perspective view from `eye` towards `target` (y up), 45° vertical
    /// field of view, for a `width × height` picture.
    #[must_use]
    pub fn perspective(eye: Vec3, target: Vec3, width: u32, height: u32) -> Self {
        let aspect = width.max(1) as f32 / height.max(1) as f32;
        let proj =
            glam::camera::rh::proj::directx::perspective(45f32.to_radians(), aspect, 0.1, 100.0);
        Self {
            view_proj: proj * glam::camera::rh::view::look_at_mat4(eye, target, Vec3::Y),
            eye,
            ..Self::orthographic(Vec2::ZERO, Vec2::ONE, 1.0)
        }
    }
}

/// WGSL `Scene` (144 bytes).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
struct GpuScene {
    view_proj: [[f32; 4]; 4],
    eye: Vec4,
    light0: Vec4,
    light1: Vec4,
    base_colour: Vec4,
    wire_colour: Vec4,
}

fn rgba(c: Rgba) -> Vec4 {
    Vec4::new(c.r, c.g, c.b, c.a)
}

/// A trim shape in `(u, v)` (seed 000 §3): what is inside is cut away.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TrimShape {
    /// `u1 ≤ u ≤ u2 ∧ v1 ≤ v ≤ v2` (the seed's `trimValuesx`, `trimValuesy`).
    Rectangle {
        /// `(u1, u2)`.
        u: Vec2,
        /// `(v1, v2)`.
        v: Vec2,
    },
    /// `distance(uv, centre) < radius`.
    Circle {
        /// Centre in `(u, v)`.
        centre: Vec2,
        /// Radius.
        radius: f32,
    },
    /// `(u − c₁)²/a² + (v − c₂)²/b² ≤ 1`.
    Ellipse {
        /// Centre in `(u, v)`.
        centre: Vec2,
        /// `(a, b)`: the radii along u and v.
        radii: Vec2,
    },
    /// The region between an upper and a lower Bézier curve with common end
    /// points on one horizontal line (the seed's limit), trimmed by Newton.
    Bezier {
        /// The curve above the end points' line.
        upper: TrimCurve,
        /// The curve below it.
        lower: TrimCurve,
    },
    /// The ring between an outer and an inner Bézier region: the outer one
    /// is cut, the inner island is kept (seed 000, figure 12).
    Nested {
        /// Outer region: upper and lower curve.
        outer: [TrimCurve; 2],
        /// Inner region: upper and lower curve.
        inner: [TrimCurve; 2],
    },
}

/// A quadratic or cubic Bézier curve in `(u, v)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TrimCurve {
    /// Three control points.
    Quadratic([Vec2; 3]),
    /// Four control points.
    Cubic([Vec2; 4]),
}

/// WGSL `TrimShape` (48 bytes).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
struct GpuTrimShape {
    kind: u32,
    curves: [u32; 4],
    pad: [u32; 3],
    params: Vec4,
}

/// WGSL `TrimCurve` (80 bytes).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
struct GpuTrimCurve {
    degree: u32,
    pad: [u32; 3],
    points: [Vec4; 4],
}

/// WGSL `Trimming` (1040 bytes).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
struct GpuTrimming {
    shapes: [GpuTrimShape; MAX_TRIM_SHAPES],
    curves: [GpuTrimCurve; MAX_TRIM_CURVES],
    shape_count: u32,
    iterations: u32,
    epsilon: f32,
    pad: u32,
}

/// Trim shapes with the Newton settings (seed 000 Listing 10: 10 iterations,
/// ε = 0.001).
#[derive(Clone, Debug, PartialEq)]
pub struct Trimming {
    /// The shapes; a fragment inside any of them is discarded.
    pub shapes: Vec<TrimShape>,
    /// Newton iterations at most.
    pub iterations: u32,
    /// Newton stops when a step is shorter than this.
    pub epsilon: f32,
}

impl Default for Trimming {
    fn default() -> Self {
        Self {
            shapes: Vec::new(),
            iterations: 10,
            epsilon: 0.001,
        }
    }
}

impl Trimming {
    fn to_gpu(&self) -> Result<GpuTrimming, TessError> {
        let mut out = GpuTrimming::zeroed();
        if self.shapes.len() > MAX_TRIM_SHAPES {
            return Err(TessError::Invalid(format!(
                "{} trim shapes, at most {MAX_TRIM_SHAPES}",
                self.shapes.len()
            )));
        }
        if !(self.epsilon.is_finite() && self.epsilon >= 0.0) {
            return Err(TessError::Invalid(format!(
                "the Newton epsilon must be finite and ≥ 0, not {}",
                self.epsilon
            )));
        }
        let mut curves = Vec::new();
        let mut add_curve = |c: &TrimCurve| -> Result<u32, TessError> {
            let (degree, pts): (u32, Vec<Vec2>) = match c {
                TrimCurve::Quadratic(p) => (2, p.to_vec()),
                TrimCurve::Cubic(p) => (3, p.to_vec()),
            };
            if pts.iter().any(|p| !p.is_finite()) {
                return Err(TessError::Invalid(
                    "a trim curve point is not finite".into(),
                ));
            }
            if curves.len() == MAX_TRIM_CURVES {
                return Err(TessError::Invalid(format!(
                    "more than {MAX_TRIM_CURVES} trim curves"
                )));
            }
            let mut points = [Vec4::ZERO; 4];
            for (slot, p) in points.iter_mut().zip(&pts) {
                *slot = p.extend(0.0).extend(0.0);
            }
            curves.push(GpuTrimCurve {
                degree,
                pad: [0; 3],
                points,
            });
            Ok((curves.len() - 1) as u32)
        };
        for (slot, shape) in out.shapes.iter_mut().zip(&self.shapes) {
            let (kind, params, ids) = match shape {
                TrimShape::Rectangle { u, v } => (1, Vec4::new(u.x, u.y, v.x, v.y), [0; 4]),
                TrimShape::Circle { centre, radius } => {
                    (2, centre.extend(*radius).extend(0.0), [0; 4])
                }
                TrimShape::Ellipse { centre, radii } => {
                    (3, Vec4::new(centre.x, centre.y, radii.x, radii.y), [0; 4])
                }
                TrimShape::Bezier { upper, lower } => {
                    (4, Vec4::ZERO, [add_curve(upper)?, add_curve(lower)?, 0, 0])
                }
                TrimShape::Nested { outer, inner } => (
                    5,
                    Vec4::ZERO,
                    [
                        add_curve(&outer[0])?,
                        add_curve(&outer[1])?,
                        add_curve(&inner[0])?,
                        add_curve(&inner[1])?,
                    ],
                ),
            };
            if !params.is_finite() {
                return Err(TessError::Invalid(
                    "a trim shape parameter is not finite".into(),
                ));
            }
            *slot = GpuTrimShape {
                kind,
                curves: ids,
                pad: [0; 3],
                params,
            };
        }
        for (slot, c) in out.curves.iter_mut().zip(curves) {
            *slot = c;
        }
        out.shape_count = self.shapes.len() as u32;
        out.iterations = self.iterations;
        out.epsilon = self.epsilon;
        Ok(out)
    }
}

/// The seed's brick texture (Listing 15 loads `brick.bmp`), made here:
/// red-brown bricks of 16 × 8 texels, every other row shifted by half a
/// brick, with light grey mortar lines one texel wide at the bricks' left
/// and bottom edges. Texel `(x, y)`, y up like every canvas.
#[must_use]
pub fn brick_texture() -> Canvas {
    const BRICK: (i32, i32) = (16, 8);
    let mut c = Canvas::new(TEXTURE_SIZE, TEXTURE_SIZE);
    for (p, _) in c.clone().enumerate() {
        let row = p.y / BRICK.1;
        let shift = if row % 2 == 1 { BRICK.0 / 2 } else { 0 };
        let mortar = p.y % BRICK.1 == 0 || (p.x + shift) % BRICK.0 == 0;
        let colour = if mortar {
            Rgba::from_rgba8([200, 200, 200, 255])
        } else {
            Rgba::from_rgba8([170, 74, 44, 255])
        };
        c.set(p, colour);
    }
    c
}

/// What to draw: triangles with vertices, and optionally wireframe edges.
#[derive(Debug)]
pub struct DrawMesh<'a> {
    /// The vertex buffer ([`GpuVertex`]es, usage `VERTEX`).
    pub vertices: &'a wgpu::Buffer,
    /// Triangles (counter-clockwise; both sides are drawn).
    pub triangles: &'a [[u32; 3]],
    /// Lines drawn over the surface, if any (task 4's `wireframe_edges`).
    pub edges: Option<&'a [[u32; 2]]>,
}

/// Uploads CPU vertices as a vertex buffer.
#[must_use]
pub fn vertex_buffer(gpu: &Gpu, vertices: &[GpuVertex]) -> wgpu::Buffer {
    let mut bytes = bytemuck::cast_slice(vertices).to_vec();
    bytes.resize(bytes.len().max(16), 0);
    gpu.device
        .create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("vertices"),
            contents: &bytes,
            usage: wgpu::BufferUsages::VERTEX,
        })
}

/// The WGSL of a render: your shading (`fn shade`) or the flat one, your
/// trimming predicates or none.
#[derive(Clone, Copy, Debug, Default)]
pub struct Shaders<'a> {
    /// Task 4's `shade` ([`crate::wgsl::SHADING`]); `None`: flat `base_colour`.
    pub shading: Option<Piece>,
    /// Task 5's predicates ([`crate::wgsl::TRIMMING`]) with the trim
    /// shapes; `None`: nothing is trimmed.
    pub trimming: Option<(Piece, &'a Trimming)>,
}

/// Renders `meshes` into a `width × height` canvas.
///
/// Each of your pieces is checked on its own first (with the given
/// stand-in for the other), then the shader of both.
///
/// Errors: bad trimming input ([`TessError::Invalid`]), WGSL that does not
/// compile or validate ([`TessError::Wgsl`]), a failed readback
/// ([`TessError::Gpu`]).
pub fn render(
    gpu: &Gpu,
    width: u32,
    height: u32,
    scene: &Scene,
    shaders_used: Shaders<'_>,
    meshes: &[DrawMesh<'_>],
) -> Result<Canvas, TessError> {
    let trimming = match shaders_used.trimming {
        Some((_, t)) => t.to_gpu()?,
        None => Trimming::default().to_gpu()?,
    };
    let render = Part::Given("crate::shaders::RENDER", shaders::RENDER);
    let flat = Part::Given("crate::shaders::FLAT_SHADING", shaders::FLAT_SHADING);
    let no_trimming = Part::Given("crate::shaders::NO_TRIMMING", shaders::NO_TRIMMING);
    let given_trimming = Part::Given("crate::shaders::TRIMMING", shaders::TRIMMING);
    // Your pieces first, so that their lines are the shader's.
    let mut yours = Vec::new();
    let mut given = vec![render];
    match shaders_used.shading {
        Some(piece) => yours.push(Part::Yours(piece)),
        None => given.push(flat),
    }
    match shaders_used.trimming {
        Some((piece, _)) => {
            yours.push(Part::Yours(piece));
            given.push(given_trimming);
        }
        None => given.push(no_trimming),
    }
    if let [shading, trimming] = yours[..] {
        // Each on its own first: an error in one is not reported as the other's.
        wgsl::compose(&[shading, render, no_trimming])?;
        wgsl::compose(&[trimming, render, flat, given_trimming])?;
    }
    let source = wgsl::compose(&[yours, given].concat())?;
    let module = gpu.shader("render", &source)?;
    let device = &gpu.device;
    let uniform = |label, bytes: &[u8]| {
        device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents: bytes,
            usage: wgpu::BufferUsages::UNIFORM,
        })
    };
    let gpu_scene = GpuScene {
        view_proj: scene.view_proj.to_cols_array_2d(),
        eye: scene.eye.extend(1.0),
        light0: scene.lights[0].extend(1.0),
        light1: scene.lights[1].extend(1.0),
        base_colour: rgba(scene.base_colour),
        wire_colour: rgba(scene.wire_colour),
    };
    let scene_buffer = uniform("scene", bytemuck::bytes_of(&gpu_scene));
    let trim_buffer = uniform("trimming", bytemuck::bytes_of(&trimming));
    let texture = texture_from_canvas(gpu, &brick_texture());
    let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
        address_mode_u: wgpu::AddressMode::Repeat,
        address_mode_v: wgpu::AddressMode::Repeat,
        mag_filter: wgpu::FilterMode::Nearest,
        min_filter: wgpu::FilterMode::Nearest,
        ..Default::default()
    });
    let visible = wgpu::ShaderStages::VERTEX_FRAGMENT;
    let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("render"),
        entries: &[
            uniform_entry(0, visible),
            wgpu::BindGroupLayoutEntry {
                binding: 1,
                visibility: visible,
                ty: wgpu::BindingType::Texture {
                    sample_type: wgpu::TextureSampleType::Float { filterable: true },
                    view_dimension: wgpu::TextureViewDimension::D2,
                    multisampled: false,
                },
                count: None,
            },
            wgpu::BindGroupLayoutEntry {
                binding: 2,
                visibility: visible,
                ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
                count: None,
            },
            uniform_entry(3, visible),
        ],
    });
    let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("render"),
        layout: &layout,
        entries: &[
            wgpu::BindGroupEntry {
                binding: 0,
                resource: scene_buffer.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: wgpu::BindingResource::TextureView(
                    &texture.create_view(&Default::default()),
                ),
            },
            wgpu::BindGroupEntry {
                binding: 2,
                resource: wgpu::BindingResource::Sampler(&sampler),
            },
            wgpu::BindGroupEntry {
                binding: 3,
                resource: trim_buffer.as_entire_binding(),
            },
        ],
    });
    let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some("render"),
        bind_group_layouts: &[Some(&layout)],
        immediate_size: 0,
    });
    let wired = meshes.iter().any(|m| m.edges.is_some());
    let pipeline = |topology, fragment: &str, bias, compare| {
        gpu.validated(fragment, || {
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(fragment),
                layout: Some(&pipeline_layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some("vs_main"),
                    compilation_options: Default::default(),
                    buffers: &[Some(wgpu::VertexBufferLayout {
                        array_stride: size_of::<GpuVertex>() as u64,
                        step_mode: wgpu::VertexStepMode::Vertex,
                        attributes: &wgpu::vertex_attr_array![
                            0 => Float32x4, 1 => Float32x4, 2 => Float32x4
                        ],
                    })],
                },
                primitive: wgpu::PrimitiveState {
                    topology,
                    ..Default::default()
                },
                depth_stencil: Some(wgpu::DepthStencilState {
                    format: DEPTH_FORMAT,
                    depth_write_enabled: Some(true),
                    depth_compare: Some(compare),
                    stencil: Default::default(),
                    bias,
                }),
                multisample: Default::default(),
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some(fragment),
                    compilation_options: Default::default(),
                    targets: &[Some(COLOUR_FORMAT.into())],
                }),
                multiview_mask: None,
                cache: None,
            })
        })
    };
    let fill_bias = if wired {
        WIREFRAME_BIAS
    } else {
        wgpu::DepthBiasState::default()
    };
    let fill = pipeline(
        wgpu::PrimitiveTopology::TriangleList,
        "fs_main",
        fill_bias,
        wgpu::CompareFunction::Less,
    )?;
    let lines = if wired {
        Some(pipeline(
            wgpu::PrimitiveTopology::LineList,
            "fs_wire",
            wgpu::DepthBiasState::default(),
            wgpu::CompareFunction::LessEqual,
        )?)
    } else {
        None
    };
    let index = |data: &[u32]| {
        let mut bytes = bytemuck::cast_slice(data).to_vec();
        bytes.resize(bytes.len().max(16), 0);
        device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("indices"),
            contents: &bytes,
            usage: wgpu::BufferUsages::INDEX,
        })
    };
    // Per mesh: the triangle index buffer and count, and the edges' if any.
    type Indices = (wgpu::Buffer, u32);
    let buffers: Vec<(wgpu::Buffer, u32, Option<Indices>)> = meshes
        .iter()
        .map(|m| {
            let tri: Vec<u32> = m.triangles.iter().flatten().copied().collect();
            let edges = m.edges.map(|e| {
                let flat: Vec<u32> = e.iter().flatten().copied().collect();
                (index(&flat), flat.len() as u32)
            });
            (index(&tri), tri.len() as u32, edges)
        })
        .collect();
    let target = OffscreenTarget::new(gpu, width, height);
    let clear = scene.background;
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("render"),
            color_attachments: &[Some(target.colour_attachment(wgpu::Color {
                r: f64::from(clear.r),
                g: f64::from(clear.g),
                b: f64::from(clear.b),
                a: f64::from(clear.a),
            }))],
            depth_stencil_attachment: Some(target.depth_attachment()),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_bind_group(0, &group, &[]);
        for (mesh, (tri, tri_count, edges)) in meshes.iter().zip(&buffers) {
            pass.set_vertex_buffer(0, mesh.vertices.slice(..));
            pass.set_pipeline(&fill);
            pass.set_index_buffer(tri.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..*tri_count, 0, 0..1);
            if let (Some(lines), Some((edge_buffer, edge_count))) = (&lines, edges) {
                pass.set_pipeline(lines);
                pass.set_index_buffer(edge_buffer.slice(..), wgpu::IndexFormat::Uint32);
                pass.draw_indexed(0..*edge_count, 0, 0..1);
            }
        }
    }
    gpu.queue.submit([encoder.finish()]);
    Ok(target.read_colour(gpu)?)
}

fn uniform_entry(binding: u32, visibility: wgpu::ShaderStages) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

/// Uploads a canvas as an `Rgba8Unorm` texture; canvas row 0 (the bottom)
/// becomes texture row `height − 1`, so that `v = 0` samples the bottom
/// once `(u, v)` is mapped to texture coordinates `(u, 1 − v)`.
fn texture_from_canvas(gpu: &Gpu, canvas: &Canvas) -> wgpu::Texture {
    let image = canvas.to_image();
    gpu.device.create_texture_with_data(
        &gpu.queue,
        &wgpu::TextureDescriptor {
            label: Some("brick texture"),
            size: wgpu::Extent3d {
                width: canvas.width(),
                height: canvas.height(),
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: wgpu::TextureFormat::Rgba8Unorm,
            usage: wgpu::TextureUsages::TEXTURE_BINDING,
            view_formats: &[],
        },
        wgpu::util::TextureDataOrder::LayerMajor,
        image.as_raw(),
    )
}
