//! Task 4: your `shade` (Phong, two lights, texture) against a CPU rendering
//! of the same formula, and your `wireframe_edges`.

mod common;

use std::collections::BTreeSet;

use canvas::{Canvas, Pixel, Rgba};
use common::tessellate_patch;
use glam::{DVec2, Vec2, Vec3};
use gpu::Gpu;
use gpu_tessellation::patch::BezierPatch;
use gpu_tessellation::render::{DrawMesh, Scene, Shaders, brick_texture, render, vertex_buffer};
use gpu_tessellation::shading::wireframe_edges;
use gpu_tessellation::wgsl::{self, Piece};
use proptest::prelude::*;
use testkit::image::Tolerance;

/// Picture size of the shading tests: 2 pixels per texel of the 64-texel
/// brick texture, so that no texel edge passes through a pixel centre
/// (where GPU and CPU could round to different texels).
const SIZE: u32 = 128;
/// Tessellation level of the shading tests: the GPU interpolates normals
/// between vertices this far apart, the CPU uses the exact normal.
const LEVEL: usize = 32;
/// Shading tolerance: 3/255 per channel on all but 1 % of the pixels
/// (texel and highlight edges, where interpolated normals and `(u, v)`
/// differ slightly from the exact ones).
const SHADING: Tolerance = Tolerance {
    channel: 3.0 / 255.0,
    mismatched_fraction: 0.01,
};

/// The lights and eye of the shading tests (above the `z = 0` plane, so
/// that a height field seen from `+z` is lit from the front).
fn scene() -> Scene {
    let mut scene = Scene::orthographic(Vec2::splat(-1.0), Vec2::splat(1.0), 2.0);
    scene.eye = Vec3::new(0.2, -0.3, 3.0);
    scene.lights = [Vec3::new(0.0, 3.0, 2.0), Vec3::new(-2.5, -1.0, 3.0)];
    scene
}

/// A bump: heights of a height field over `[lo, hi]` (x, y linear in u, v).
fn bump(lo: Vec2, hi: Vec2, base: f32, scale: f32) -> BezierPatch {
    let h = [
        [0.0, 0.0, 0.0, 0.0],
        [0.0, 0.6, 0.3, 0.0],
        [0.0, 0.2, 0.8, 0.0],
        [0.0, 0.0, 0.0, 0.0],
    ];
    BezierPatch::height_field(
        lo.as_dvec2(),
        hi.as_dvec2(),
        h.map(|row| row.map(|z| f64::from(base + scale * z))),
    )
}

/// Renders height fields (CPU tessellated) with your shading.
fn render_patches(gpu: &Gpu, piece: Piece, patches: &[BezierPatch]) -> Canvas {
    let domain = common::grid(LEVEL);
    let buffers: Vec<_> = patches
        .iter()
        .map(|p| vertex_buffer(gpu, &tessellate_patch(p, &domain.points)))
        .collect();
    let meshes: Vec<DrawMesh<'_>> = buffers
        .iter()
        .map(|b| DrawMesh {
            vertices: b,
            triangles: &domain.triangles,
            edges: None,
        })
        .collect();
    let shaders = Shaders {
        shading: Some(piece),
        trimming: None,
    };
    render(gpu, SIZE, SIZE, &scene(), shaders, &meshes).unwrap()
}

/// The CPU picture of height fields over `[lo, hi]` rectangles: at each
/// pixel centre the nearest (largest z) patch covering it, evaluated
/// exactly, shaded by the seed's Phong formula.
fn cpu_render(patches: &[(BezierPatch, Vec2, Vec2)]) -> Canvas {
    let scene = scene();
    let texture = brick_texture();
    common::cpu_picture(SIZE, SIZE, |screen| {
        let xy = screen * 2.0 - DVec2::ONE;
        let nearest = patches
            .iter()
            .filter_map(|(patch, lo, hi)| {
                let uv = (xy - lo.as_dvec2()) / (hi.as_dvec2() - lo.as_dvec2());
                let inside = uv.cmpge(DVec2::ZERO).all() && uv.cmple(DVec2::ONE).all();
                inside.then(|| (common::patch_point(patch, uv), uv))
            })
            .max_by(|a, b| a.0.position.z.total_cmp(&b.0.position.z));
        match nearest {
            None => scene.background,
            Some((s, uv)) => common::rgba(common::phong(
                s.position,
                s.normal,
                scene.eye.as_dvec3(),
                scene.lights,
                common::brick_at(&texture, uv),
            )),
        }
    })
}

#[testkit::test]
fn phong_shading_of_a_bump_matches_the_cpu_rendering() {
    let piece = wgsl::SHADING.written();
    let Some(gpu) = common::gpu() else { return };
    let (lo, hi) = (Vec2::splat(-1.0), Vec2::splat(1.0));
    let patch = bump(lo, hi, 0.0, 0.8);
    let yours = render_patches(&gpu, piece, std::slice::from_ref(&patch));
    let cpu = cpu_render(&[(patch, lo, hi)]);
    common::assert_matches_cpu("render_phong_bump", &yours, &cpu, SHADING);
}

/// ```text
///  +-----------------+     A: the whole picture, z around 0
///  |     +-----+     |     B: the middle, z around 0.6 (nearer the eye
///  |  A  |  B  |     |        at +z), drawn first: the depth test keeps it
///  |     +-----+     |
///  +-----------------+
/// ```
#[testkit::test]
fn the_nearer_of_two_overlapping_patches_is_kept() {
    let piece = wgsl::SHADING.written();
    let Some(gpu) = common::gpu() else { return };
    let (a_lo, a_hi) = (Vec2::splat(-1.0), Vec2::splat(1.0));
    let (b_lo, b_hi) = (Vec2::splat(-0.5), Vec2::splat(0.5));
    let a = bump(a_lo, a_hi, 0.0, 0.4);
    let b = bump(b_lo, b_hi, 0.6, 0.3);
    let yours = render_patches(&gpu, piece, &[b.clone(), a.clone()]);
    let cpu = cpu_render(&[(a, a_lo, a_hi), (b, b_lo, b_hi)]);
    common::assert_matches_cpu("render_depth_two_patches", &yours, &cpu, SHADING);
}

fn brute_force_edges(triangles: &[[u32; 3]]) -> Vec<[u32; 2]> {
    let mut set = BTreeSet::new();
    for t in triangles {
        for i in 0..3 {
            for j in 0..3 {
                if t[i] < t[j] {
                    set.insert([t[i], t[j]]);
                }
            }
        }
    }
    set.into_iter().collect()
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn wireframe_edges_are_each_edge_once_sorted(
        triangles in prop::collection::vec(prop::array::uniform3(0u32..12), 0..30),
    ) {
        prop_assert_eq!(wireframe_edges(&triangles), brute_force_edges(&triangles));
    }
}

#[testkit::test]
fn wireframe_of_a_domain_obeys_eulers_formula() {
    let domains = [
        ("grid 1", common::grid(1)),
        ("grid 2", common::grid(2)),
        ("grid 5", common::grid(5)),
        (
            "grid 3 × 7",
            common::grid_at(
                &[0.0, 0.2, 0.7, 1.0],
                &[0.0, 0.1, 0.15, 0.3, 0.6, 0.65, 0.9, 1.0],
            ),
        ),
        ("grid 32", common::grid(32)),
        ("lattice 1", common::lattice(1)),
        ("lattice 7", common::lattice(7)),
    ];
    for (what, d) in &domains {
        let edges = wireframe_edges(&d.triangles);
        // A triangulated disk: V − E + F = 1.
        assert_eq!(
            d.points.len() + d.triangles.len(),
            edges.len() + 1,
            "{what}: {} points, {} triangles, {} edges",
            d.points.len(),
            d.triangles.len(),
            edges.len()
        );
    }
}

/// Distance from point `p` to segment `a b`.
fn segment_distance(p: Vec2, a: Vec2, b: Vec2) -> f32 {
    let t = ((p - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
    p.distance(a + t * (b - a))
}

#[testkit::test]
fn wireframe_lines_lie_on_the_tessellations_edges() {
    let domain = common::grid(4);
    let edges = wireframe_edges(&domain.triangles);
    let Some(gpu) = common::gpu() else { return };
    const WIRE_SIZE: u32 = 64;
    let patch = common::full_screen_patch();
    let vertices = vertex_buffer(&gpu, &tessellate_patch(&patch, &domain.points));
    let mut scene = Scene::orthographic(Vec2::splat(-1.0), Vec2::splat(1.0), 2.0);
    scene.view_proj = glam::Mat4::IDENTITY;
    let mesh = DrawMesh {
        vertices: &vertices,
        triangles: &domain.triangles,
        edges: Some(&edges),
    };
    let picture = render(
        &gpu,
        WIRE_SIZE,
        WIRE_SIZE,
        &scene,
        Shaders::default(),
        &[mesh],
    )
    .unwrap();
    picture
        .save_png(testkit::output_dir().join("render_wireframe/yours.png"))
        .unwrap();
    // The true edges in pixel coordinates (pixel centres at integers).
    let to_pixels =
        |k: u32| domain.points[k as usize].truncate() * WIRE_SIZE as f32 - Vec2::splat(0.5);
    let segments: Vec<(Vec2, Vec2)> = brute_force_edges(&domain.triangles)
        .iter()
        .map(|&[a, b]| (to_pixels(a), to_pixels(b)))
        .collect();
    let wire = scene.wire_colour;
    let is_wire = |c: Rgba| (c.r - wire.r).abs() < 0.02 && (c.g - wire.g).abs() < 0.02;
    for (p, c) in picture.enumerate() {
        let at = Vec2::new(p.x as f32, p.y as f32);
        let nearest = segments
            .iter()
            .map(|&(a, b)| segment_distance(at, a, b))
            .fold(f32::INFINITY, f32::min);
        if nearest > 1.5 {
            assert_eq!(
                c, scene.base_colour,
                "pixel {p:?} is {nearest} px from every edge but not surface"
            );
        }
    }
    let on_border = |p: Vec2| p.min_element() < 0.0 || p.max_element() > WIRE_SIZE as f32 - 1.0;
    for &(a, b) in segments.iter().filter(|(a, b)| !on_border((*a + *b) / 2.0)) {
        // Inside the picture, a pixel within half a pixel of the edge's
        // middle is drawn in the wire colour.
        let mid = (a + b) / 2.0;
        let clamp = |x: f32| x.clamp(0.0, WIRE_SIZE as f32 - 1.0);
        let around = [-1, 0, 1]
            .iter()
            .flat_map(|&dx| [-1, 0, 1].map(move |dy| (dx, dy)));
        let found = around.into_iter().any(|(dx, dy)| {
            let p = Pixel::new(
                clamp(mid.x).round() as i32 + dx,
                clamp(mid.y).round() as i32 + dy,
            );
            picture.get(p).is_some_and(is_wire)
        });
        assert!(
            found,
            "no wire pixel next to the middle of the edge {a} – {b}"
        );
    }
}
