//! Task 4: your `shade` (Phong, two lights, texture) against a CPU rendering
//! of the same formula, and your `wireframe_edges`.

mod common;

use std::collections::BTreeSet;

use canvas::{Canvas, Pixel, Rgba};
use common::tessellate_patch;
use glam::{DVec2, DVec3, Vec2, Vec3};
use gpu::Gpu;
use gpu_tessellation::patch::{BezierPatch, GpuVertex, RationalPatch};
use gpu_tessellation::render::{DrawMesh, Scene, Shaders, brick_texture, render, vertex_buffer};
use gpu_tessellation::shading::wireframe_edges;
use gpu_tessellation::wgsl::{self, Piece};
use proptest::prelude::*;
use testkit::image::Tolerance;
use testkit::oracles::tensor_bezier;

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

/// The NURBS torus of the figure: major and minor radius, lying in the
/// `z = 0` plane around the `z` axis.
const TORUS: (f64, f64) = (0.7, 0.25);
/// Picture size of the torus.
const TORUS_SIZE: u32 = 192;
/// A texture coordinate in the middle of a brick, not on mortar: a torus
/// textured there is plainly brick-red, which the CPU can shade exactly.
const PLAIN_UV: DVec2 = DVec2::new(3.5 / 64.0, 3.5 / 64.0);

/// The torus seen from above and in front, lit from the upper right and
/// from behind on the left.
fn torus_scene() -> Scene {
    let mut scene = Scene::perspective(
        Vec3::new(0.0, -1.9, 2.3),
        Vec3::new(0.0, 0.0, -0.05),
        TORUS_SIZE,
        TORUS_SIZE,
    );
    scene.lights = [Vec3::new(2.0, -1.5, 3.0), Vec3::new(-2.5, 2.0, 1.5)];
    scene
}

/// The torus's outward normal at a point `p` on it.
fn torus_normal(p: DVec3) -> DVec3 {
    let centre = TORUS.0 * DVec3::new(p.x, p.y, 0.0).normalize();
    (p - centre).normalize()
}

/// The 16 rational patches of `RationalPatch::torus` evaluated on the CPU
/// at the points of a level-`n` grid, as one mesh: positions by the
/// quotient of numerator and denominator (their definitions, the double
/// Bernstein sum), the torus's own normals, and the grid's `(u, v)` — or
/// [`PLAIN_UV`] everywhere when `plain`.
fn torus_mesh(n: usize, plain: bool) -> (Vec<GpuVertex>, Vec<[u32; 3]>) {
    let domain = common::grid(n);
    let (mut vertices, mut triangles) = (Vec::new(), Vec::new());
    for patch in RationalPatch::torus(TORUS.0, TORUS.1) {
        let (a, w) = (patch.numerator(), patch.denominator());
        let (p, q) = (a.degree_u(), a.degree_v());
        let offset = vertices.len() as u32;
        for d in &domain.points {
            let uv = [f64::from(d.x), f64::from(d.y)];
            let [numerator, ..] = tensor_bezier(p, q, |i, j| a.control_point(i, j), uv);
            let [denominator, ..] = tensor_bezier(p, q, |i, j| w.control_point(i, j), uv);
            let position = numerator / denominator.x;
            let param = if plain {
                PLAIN_UV.as_vec2()
            } else {
                d.truncate()
            };
            vertices.push(GpuVertex {
                position: position.as_vec3().extend(1.0),
                normal: torus_normal(position).as_vec3().extend(0.0),
                param: param.extend(0.0).extend(0.0),
            });
        }
        triangles.extend(domain.triangles.iter().map(|t| t.map(|k| k + offset)));
    }
    (vertices, triangles)
}

/// Where the ray through pixel centre `(x, y)` first meets the exact torus
/// (sphere tracing its distance function), if it does.
fn torus_hit(scene: &Scene, x: i32, y: i32) -> Option<DVec3> {
    let size = f64::from(TORUS_SIZE);
    let ndc = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5) / size * 2.0 - DVec2::ONE;
    let inverse = scene.view_proj.as_dmat4().inverse();
    let near = inverse.project_point3(ndc.extend(0.0));
    let far = inverse.project_point3(ndc.extend(1.0));
    let direction = (far - near).normalize();
    let (major, minor) = TORUS;
    let distance = |p: DVec3| DVec2::new(p.truncate().length() - major, p.z).length() - minor;
    let mut t = 0.0;
    for _ in 0..1000 {
        let p = near + t * direction;
        let d = distance(p);
        if d < 1e-9 {
            return Some(p);
        }
        t += d;
        if t > near.distance(far) {
            return None;
        }
    }
    None
}

/// Seed 001's subject on the GPU: a NURBS torus, 16 rational Bézier
/// patches, drawn by your Phong shading. Its vertices are evaluated on
/// the CPU (task 3's GPU evaluation of the same patches is tested in
/// `evaluation.rs`), plain brick-red; at every pixel whose neighbours all
/// see the same thing the picture must match the exact torus shaded on
/// the CPU. The figure puts it next to the textured torus with your
/// wireframe over it.
#[testkit::test]
fn a_nurbs_torus_is_shaded_like_the_exact_torus() {
    let piece = wgsl::SHADING.written();
    let (wire_vertices, wire_triangles) = torus_mesh(4, false);
    let edges = wireframe_edges(&wire_triangles);
    let Some(gpu) = common::gpu() else { return };
    let scene = torus_scene();
    let draw = |vertices: &[GpuVertex], triangles: &[[u32; 3]], edges: Option<&[[u32; 2]]>| {
        let buffer = vertex_buffer(&gpu, vertices);
        let mesh = DrawMesh {
            vertices: &buffer,
            triangles,
            edges,
        };
        let shaders = Shaders {
            shading: Some(piece),
            trimming: None,
        };
        render(&gpu, TORUS_SIZE, TORUS_SIZE, &scene, shaders, &[mesh]).unwrap()
    };
    let (vertices, triangles) = torus_mesh(LEVEL, true);
    let yours = draw(&vertices, &triangles, None);

    let hits: Vec<Vec<Option<DVec3>>> = (0..TORUS_SIZE as i32)
        .map(|y| {
            (0..TORUS_SIZE as i32)
                .map(|x| torus_hit(&scene, x, y))
                .collect()
        })
        .collect();
    let brick = common::brick_at(&brick_texture(), PLAIN_UV);
    let mut cpu = Canvas::new(TORUS_SIZE, TORUS_SIZE);
    let last = TORUS_SIZE as i32 - 1;
    for y in 0..=last {
        for x in 0..=last {
            let p = Pixel::new(x, y);
            let neighbours = (-1..=1).flat_map(|dy| (-1..=1).map(move |dx| (x + dx, y + dy)));
            let hit = hits[y as usize][x as usize];
            let on_the_rim = neighbours.into_iter().any(|(nx, ny)| {
                let n = hits[ny.clamp(0, last) as usize][nx.clamp(0, last) as usize];
                n.is_some() != hit.is_some()
            });
            let colour = match hit {
                // The silhouette: which pixel centres a chord covers is
                // the tessellation's, not the torus's.
                _ if on_the_rim => yours.get(p).unwrap_or(Rgba::BLACK),
                None => scene.background,
                Some(s) => common::rgba(common::phong(
                    s,
                    torus_normal(s),
                    scene.eye.as_dvec3(),
                    scene.lights,
                    brick,
                )),
            };
            cpu.set(p, colour);
        }
    }
    // The figure is written before the verdict, so that a wrong shading
    // still shows beside its wireframe.
    let wireframe = draw(&wire_vertices, &wire_triangles, Some(&edges));
    let mut figure = Canvas::new(2 * TORUS_SIZE + 4, TORUS_SIZE);
    for (p, c) in yours.enumerate() {
        figure.set(p, c);
    }
    for (p, c) in wireframe.enumerate() {
        figure.set(Pixel::new(p.x + TORUS_SIZE as i32 + 4, p.y), c);
    }
    figure
        .save_png(
            testkit::output_dir()
                .join("render_nurbs_torus_figure")
                .join("yours.png"),
        )
        .unwrap();
    common::assert_matches_cpu("render_nurbs_torus", &yours, &cpu, SHADING);
}
