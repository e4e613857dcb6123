//! What the tests compare with: definitions evaluated on the CPU in `f64`,
//! independent of the WGSL you write.
#![allow(dead_code)] // each test file uses a different part

use std::path::PathBuf;

use canvas::{Canvas, Pixel, Rgba};
use glam::{DVec2, DVec3, Vec3};
use gpu::Gpu;
use gpu_tessellation::passes::Domain;
use gpu_tessellation::patch::{
    BezierPatch, BezierTriangle, GpuVertex, NORMAL_EPSILON, SurfaceSample,
};
use proptest::prelude::*;
use testkit::image::{Tolerance, assert_image_matches};
use testkit::oracles::{tensor_bezier, triangle_bezier};

/// The device, or `None` after a skip line (see `gpu::Gpu::for_tests`).
/// Call the function under test *before* this, so that an unfinished task
/// fails even where there is no adapter.
pub fn gpu() -> Option<Gpu> {
    Gpu::for_tests()
}

/// `n` normalised, or zero where it is shorter than [`NORMAL_EPSILON`].
fn unit_or_zero(n: DVec3) -> DVec3 {
    let len = n.length();
    if len > NORMAL_EPSILON && len.is_finite() {
        n / len
    } else {
        DVec3::ZERO
    }
}

/// The patch at `uv` by its definition (the double Bernstein sum), with the
/// normal of the sheet: the cross product of the differences of the last
/// step but one, `(∂P/∂u / 3) × (∂P/∂v / 3)`, normalised.
pub fn patch_point(patch: &BezierPatch, uv: DVec2) -> SurfaceSample {
    let control = |i: usize, j: usize| patch.control_point(i, j);
    let [position, du, dv] = tensor_bezier(3, 3, control, [uv.x, uv.y]);
    SurfaceSample {
        uv,
        position,
        normal: unit_or_zero((du / 3.0).cross(dv / 3.0)),
    }
}

/// The Bézier triangle at `uvw` by its definition, with the normal of the
/// sheet: `(Q010 − Q100) × (Q001 − Q100)`, where `Q100 = ∂B/∂u / 3` and so
/// on (the three points of the last step but one), normalised.
pub fn triangle_point(triangle: &BezierTriangle, uvw: DVec3) -> SurfaceSample {
    let control = |i: usize, j: usize, k: usize| triangle.point(i, j, k);
    let [position, bu, bv, bw] = triangle_bezier(3, control, uvw.to_array());
    let (qu, qv, qw) = (bu / 3.0, bv / 3.0, bw / 3.0);
    SurfaceSample {
        uv: uvw.truncate(),
        position,
        normal: unit_or_zero((qv - qu).cross(qw - qu)),
    }
}

/// The patch evaluated on the CPU at every domain point (`f64`, stored as
/// `f32`): the mesh the render and trimming tests draw, independent of
/// your evaluation stage.
pub fn tessellate_patch(patch: &BezierPatch, points: &[Vec3]) -> Vec<GpuVertex> {
    points
        .iter()
        .map(|d| {
            let s = patch_point(patch, DVec2::new(f64::from(d.x), f64::from(d.y)));
            GpuVertex {
                position: s.position.as_vec3().extend(1.0),
                normal: s.normal.as_vec3().extend(0.0),
                param: d.extend(0.0),
            }
        })
        .collect()
}

/// Control points in `[-1, 1]³`.
pub fn point() -> impl Strategy<Value = Vec3> {
    (-1.0f32..1.0, -1.0f32..1.0, -1.0f32..1.0).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

/// The tensor grid of the parameters `us × vs` (each rising from 0 to 1)
/// as the evaluation pass reads it (`testkit::domains::grid`): built
/// without the primitive generator (task 2), so that the other tasks'
/// tests never run it.
pub fn grid_at(us: &[f64], vs: &[f64]) -> Domain {
    Domain::from(&testkit::domains::grid(us, vs))
}

/// The regular grid of `n × n` cells: the domain of a uniform level `n`
/// with equal spacing, though not triangulated the way the primitive
/// generator does it.
pub fn grid(n: usize) -> Domain {
    let cuts = testkit::domains::cuts(n);
    grid_at(&cuts, &cuts)
}

/// The regular triangle lattice of level `n` (`testkit::domains::lattice`),
/// built without the primitive generator.
pub fn lattice(n: usize) -> Domain {
    Domain::from(&testkit::domains::lattice(n))
}

/// Parameters from 0 to 1, rising, at random places in between: the cuts
/// of one side of a random [`grid_at`].
pub fn random_cuts() -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(0.0f64..1.0, 0..20).prop_map(|mut inner| {
        inner.sort_by(f64::total_cmp);
        inner.dedup();
        let mut cuts = vec![0.0];
        cuts.extend(inner.into_iter().filter(|&t| t > 0.0));
        cuts.push(1.0);
        cuts
    })
}

/// The control points of a bicubic patch in the GPU's order, `P_ij` at
/// `4j + i` (the indices of the WGSL files and their comments).
pub fn gl_points(patch: &BezierPatch) -> [DVec3; 16] {
    std::array::from_fn(|k| patch.control_point(k % 4, k / 4))
}

/// The bicubic patch of 16 points given in the GPU's order (see
/// [`gl_points`]).
pub fn from_gl_points(points: [DVec3; 16]) -> BezierPatch {
    BezierPatch::from_fn(3, 3, |i, j| points[4 * j + i]).expect("16 finite points")
}

/// A random bicubic patch.
pub fn patch() -> impl Strategy<Value = BezierPatch> {
    prop::array::uniform16(point()).prop_map(|points| from_gl_points(points.map(Vec3::as_dvec3)))
}

/// A random cubic Bézier triangle.
pub fn triangle() -> impl Strategy<Value = BezierTriangle> {
    prop::array::uniform10(point())
        .prop_map(|points| BezierTriangle::from_points(points.map(Vec3::as_dvec3)))
}

/// Compares `yours` with a CPU rendering: both are written under the test
/// output folder (`yours.png`, `reference.png`, `difference.png`), and the
/// test fails if more than `tolerance.mismatched_fraction` of the pixels
/// differ by more than `tolerance.channel`.
#[track_caller]
pub fn assert_matches_cpu(name: &str, yours: &Canvas, cpu: &Canvas, tolerance: Tolerance) {
    let path: PathBuf = testkit::output_dir().join(name).join("cpu_reference.png");
    cpu.save_png(&path)
        .unwrap_or_else(|e| panic!("{name}: cannot write the CPU reference: {e}"));
    assert_image_matches(name, yours, &path, tolerance);
}

/// A canvas whose pixel `(x, y)` is `colour(u, v)` at the pixel centre's
/// `(u, v) = ((x + ½)/w, (y + ½)/h)`: what a patch filling the picture
/// under an orthographic view shows.
pub fn cpu_picture(width: u32, height: u32, colour: impl Fn(DVec2) -> Rgba) -> Canvas {
    let mut c = Canvas::new(width, height);
    for y in 0..height as i32 {
        for x in 0..width as i32 {
            let uv = DVec2::new(
                (f64::from(x) + 0.5) / f64::from(width),
                (f64::from(y) + 0.5) / f64::from(height),
            );
            c.set(Pixel::new(x, y), colour(uv));
        }
    }
    c
}

/// The brick texture at `(u, v)`, nearest texel (as the given sampler).
pub fn brick_at(texture: &Canvas, uv: DVec2) -> DVec3 {
    let size = f64::from(texture.width());
    let texel =
        |t: f64| ((t.rem_euclid(1.0) * size).floor() as i32).min(texture.width() as i32 - 1);
    let c = texture
        .get(Pixel::new(texel(uv.x), texel(uv.y)))
        .unwrap_or(Rgba::BLACK);
    DVec3::new(f64::from(c.r), f64::from(c.g), f64::from(c.b))
}

/// Seed 000's Phong model with two lights (Listing 13, lines 53-75), in f64.
pub fn phong(
    position: DVec3,
    normal: DVec3,
    eye: DVec3,
    lights: [Vec3; 2],
    diffuse: DVec3,
) -> DVec3 {
    let e = (eye - position).normalize();
    let mut colour = diffuse * 0.1;
    for light in lights {
        let l = (light.as_dvec3() - position).normalize();
        let r = -l - 2.0 * normal.dot(-l) * normal;
        colour += normal.dot(l).max(0.0) * diffuse + r.dot(e).max(0.0).powf(150.0) * DVec3::ONE;
    }
    colour
}

/// An RGBA colour from f64 channels (clamped like a framebuffer).
pub fn rgba(c: DVec3) -> Rgba {
    Rgba::new(
        c.x.clamp(0.0, 1.0) as f32,
        c.y.clamp(0.0, 1.0) as f32,
        c.z.clamp(0.0, 1.0) as f32,
        1.0,
    )
}

/// The patch filling `[-1, 1]²` at z = 0: with an identity view, pixel
/// centre `(x, y)` sees `(u, v) = ((x + ½)/w, (y + ½)/h)`.
pub fn full_screen_patch() -> BezierPatch {
    BezierPatch::flat(DVec2::splat(-1.0), DVec2::splat(1.0), 0.0)
}
