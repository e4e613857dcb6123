//! The given WGSL around your shader code: declarations, bindings and entry
//! points. Your functions (tasks 1, 3, 4 and 5) are pasted between these
//! pieces by [`crate::passes`] and [`crate::render`]; read this file to see
//! what your WGSL may use and what it must define.
//!
//! Layouts follow WGSL's host-shareable rules (std430-like): every struct
//! here has a `#[repr(C)]` twin in Rust with the same size.

/// Patch types, shared by every pass.
pub const COMMON: &str = r"
// A bicubic Bézier patch: points[4j + i] is column i (along u) of row j (along v).
struct Patch { points: array<vec4<f32>, 16> }
// A cubic Bézier triangle: P300 P210 P201 P120 P111 P102 P030 P021 P012 P003.
struct TrianglePatch { points: array<vec4<f32>, 10> }
// A surface point and its unit normal (zero where the tangents are parallel).
struct SurfacePoint { position: vec3<f32>, normal: vec3<f32> }
// The evaluation output and render input.
struct Vertex { position: vec4<f32>, normal: vec4<f32>, param: vec4<f32> }
// Tessellation levels as the primitive generator reads them (32 bytes).
struct TessLevels { outer: vec4<f32>, inner: vec2<f32>, _pad: vec2<f32> }
const MAX_TESS_LEVEL: f32 = 64.0;
// Cross products shorter than this give a zero normal.
const NORMAL_EPSILON: f32 = 1e-12;
";

/// Task 1's surroundings: the control pass.
pub const CONTROL: &str = r"
// How levels are chosen: every level equal, or from projected edge length.
const MODE_UNIFORM: u32 = 0u;
const MODE_ADAPTIVE: u32 = 1u;
// Clip-space w at or below this counts as behind the eye: maximal level.
const W_EPSILON: f32 = 1e-6;
struct ControlParams {
    view_proj: mat4x4<f32>,
    viewport: vec2<f32>,          // width, height in pixels
    mode: u32,                    // MODE_UNIFORM or MODE_ADAPTIVE
    uniform_level: f32,           // the level in MODE_UNIFORM
    pixels_per_segment: f32,      // the target segment length in MODE_ADAPTIVE
    _pad0: f32, _pad1: f32, _pad2: f32,
}
@group(0) @binding(0) var<storage, read> patches: array<Patch>;
@group(0) @binding(1) var<uniform> control: ControlParams;
@group(0) @binding(2) var<storage, read_write> levels: array<TessLevels>;

@compute @workgroup_size(64)
fn control_main(@builtin(global_invocation_id) id: vec3<u32>) {
    if id.x >= arrayLength(&patches) { return; }
    levels[id.x] = tessellation_levels(id.x);
}
";

/// Task 6's surroundings: the PN pass, one invocation per flat triangle,
/// as the control stage of seed 001 §4.1 builds each PN triangle before
/// the evaluation stage evaluates it.
pub const PN: &str = r"
// A flat triangle with a normal per vertex: corners[i].xyz and
// normals[i].xyz (w unused; the normals need not be unit length).
struct FlatTriangle { corners: array<vec4<f32>, 3>, normals: array<vec4<f32>, 3> }
@group(0) @binding(0) var<storage, read> flat_triangles: array<FlatTriangle>;
@group(0) @binding(1) var<storage, read_write> pn_triangles: array<TrianglePatch>;

@compute @workgroup_size(64)
fn pn_main(@builtin(global_invocation_id) id: vec3<u32>) {
    if id.x >= arrayLength(&flat_triangles) { return; }
    pn_triangles[id.x] = pn_triangle(flat_triangles[id.x]);
}
";

/// Task 3's surroundings: the evaluation pass, one invocation per
/// (patch, domain point).
pub const EVALUATION: &str = r"
// Patch p's domain points are domain[job.x .. job.x + job.y]; its vertices
// go to vertices[job.z ..].
struct Job { domain_offset: u32, point_count: u32, vertex_offset: u32, _pad: u32 }
@group(0) @binding(0) var<storage, read> patches: array<Patch>;
@group(0) @binding(1) var<storage, read> triangles: array<TrianglePatch>;
@group(0) @binding(2) var<storage, read> domain: array<vec4<f32>>;
@group(0) @binding(3) var<storage, read> jobs: array<Job>;
@group(0) @binding(4) var<storage, read_write> vertices: array<Vertex>;

@compute @workgroup_size(64)
fn evaluate_quads(@builtin(global_invocation_id) id: vec3<u32>) {
    let job = jobs[id.y];
    if id.x >= job.point_count { return; }
    let d = domain[job.domain_offset + id.x];
    let s = evaluate_patch(id.y, d.xy);
    vertices[job.vertex_offset + id.x] = Vertex(vec4(s.position, 1.0), vec4(s.normal, 0.0), vec4(d.xy, 0.0, 0.0));
}

@compute @workgroup_size(64)
fn evaluate_triangles(@builtin(global_invocation_id) id: vec3<u32>) {
    let job = jobs[id.y];
    if id.x >= job.point_count { return; }
    let d = domain[job.domain_offset + id.x];
    let s = evaluate_triangle(id.y, d.xyz);
    vertices[job.vertex_offset + id.x] = Vertex(vec4(s.position, 1.0), vec4(s.normal, 0.0), vec4(d.xyz, 0.0));
}
";

/// The render pass: scene uniforms, the diffuse texture, the vertex stage.
pub const RENDER: &str = r"
struct Scene {
    view_proj: mat4x4<f32>,
    eye: vec4<f32>,          // eye position (w = 1)
    light0: vec4<f32>,       // first light position
    light1: vec4<f32>,       // second light position
    base_colour: vec4<f32>,  // colour of the flat shading
    wire_colour: vec4<f32>,  // colour of wireframe lines
}
@group(0) @binding(0) var<uniform> scene: Scene;
@group(0) @binding(1) var diffuse_map: texture_2d<f32>;
@group(0) @binding(2) var diffuse_sampler: sampler;

// The brick texture at (u, v): nearest texel, v = 0 at the bottom row (the
// texture's rows run top-down, hence 1 - v).
fn diffuse_colour(uv: vec2<f32>) -> vec3<f32> {
    return textureSampleLevel(diffuse_map, diffuse_sampler, vec2(uv.x, 1.0 - uv.y), 0.0).rgb;
}

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) param: vec3<f32>,
}

@vertex
fn vs_main(@location(0) position: vec4<f32>, @location(1) normal: vec4<f32>, @location(2) param: vec4<f32>) -> VertexOut {
    return VertexOut(scene.view_proj * position, position.xyz, normal.xyz, param.xyz);
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    let uv = in.param.xy;
    if is_trimmed(uv) { discard; }
    // Interpolated normals are no longer unit; a zero normal stays zero.
    let len = length(in.normal);
    let n = select(vec3(0.0), in.normal / len, len > 0.0);
    return vec4(shade(in.world, n, uv), 1.0);
}

@fragment
fn fs_wire(in: VertexOut) -> @location(0) vec4<f32> {
    return scene.wire_colour;
}
";

/// Shading without task 4: the flat `scene.base_colour`.
pub const FLAT_SHADING: &str = r"
fn shade(position: vec3<f32>, normal: vec3<f32>, uv: vec2<f32>) -> vec3<f32> {
    return scene.base_colour.rgb;
}
";

/// Rendering without task 5: nothing is trimmed.
pub const NO_TRIMMING: &str = r"
fn is_trimmed(uv: vec2<f32>) -> bool { return false; }
";

/// Task 5's surroundings: trim shapes and curves as a uniform block, the
/// curve point, and the loop over shapes that calls your predicates.
pub const TRIMMING: &str = r"
const MAX_TRIM_SHAPES: u32 = 8u;
const MAX_TRIM_CURVES: u32 = 8u;
const TRIM_RECTANGLE: u32 = 1u;   // params = (u1, u2, v1, v2)
const TRIM_CIRCLE: u32 = 2u;      // params = (cu, cv, r, -)
const TRIM_ELLIPSE: u32 = 3u;     // params = (cu, cv, a, b)
const TRIM_BEZIER: u32 = 4u;      // the region between curves a (upper) and b (lower)
const TRIM_NESTED: u32 = 5u;      // region (a, b) minus region (c, d)
struct TrimShape { kind: u32, a: u32, b: u32, c: u32, d: u32, _p0: u32, _p1: u32, _p2: u32, params: vec4<f32> }
// A quadratic (degree 2, points[0..3]) or cubic (degree 3) Bézier curve in (u, v).
struct TrimCurve { degree: u32, _p0: u32, _p1: u32, _p2: u32, points: array<vec4<f32>, 4> }
struct Trimming {
    shapes: array<TrimShape, 8>,
    curves: array<TrimCurve, 8>,
    shape_count: u32,
    iterations: u32,   // Newton iterations at most
    epsilon: f32,      // Newton stops when the step |h| < epsilon
    _pad: u32,
}
@group(0) @binding(3) var<uniform> trim: Trimming;

// The curve point B(t) by de Casteljau (2D, in (u, v)).
fn trim_curve_point(c: TrimCurve, t: f32) -> vec2<f32> {
    var p = array(c.points[0].xy, c.points[1].xy, c.points[2].xy, c.points[3].xy);
    for (var d = c.degree; d > 0u; d--) {
        for (var k = 0u; k < d; k++) { p[k] = mix(p[k], p[k + 1u], t); }
    }
    return p[0];
}

fn is_trimmed(uv: vec2<f32>) -> bool {
    for (var s = 0u; s < min(trim.shape_count, MAX_TRIM_SHAPES); s++) {
        let shape = trim.shapes[s];
        var cut = false;
        switch shape.kind {
            case TRIM_RECTANGLE: { cut = trimmed_by_rectangle(uv, shape.params.xy, shape.params.zw); }
            case TRIM_CIRCLE: { cut = trimmed_by_circle(uv, shape.params.xy, shape.params.z); }
            case TRIM_ELLIPSE: { cut = trimmed_by_ellipse(uv, shape.params.xy, shape.params.zw); }
            case TRIM_BEZIER: { cut = inside_bezier_region(uv, trim.curves[shape.a], trim.curves[shape.b]); }
            case TRIM_NESTED: {
                cut = inside_bezier_region(uv, trim.curves[shape.a], trim.curves[shape.b])
                    && !inside_bezier_region(uv, trim.curves[shape.c], trim.curves[shape.d]);
            }
            default: {}
        }
        if cut { return true; }
    }
    return false;
}
";
