//! What the tests compare with: surfaces evaluated by the explicit
//! Bernstein sums (not by de Casteljau), meshes checked edge by edge, and
//! parameter-plane areas, all written independently of the tasks.
#![allow(dead_code, unused_imports)] // each test file uses a different part

use std::collections::HashMap;

use testkit::topology::directed_edges;

use tessellation::bezier::{BezierPatch, Evaluate};
use tessellation::mesh::Mesh;
use tessellation::render::{Style, View, render};
use tessellation::{DVec2, DVec3};

/// Positions computed two ways agree to this (coordinates of order 10).
pub const POSITION_TOLERANCE: f64 = 1e-9;

pub use testkit::oracles::{bernstein, tensor_bezier};

/// `S(u, v)` of `patch` by the double Bernstein sum of Definition 1.1.4
/// (the course's oracle, [`tensor_bezier`], which also gives the partial
/// derivatives).
pub fn bernstein_surface(patch: &BezierPatch, uv: DVec2) -> DVec3 {
    let control = |i: usize, j: usize| patch.control_point(i, j);
    tensor_bezier(patch.degree_u(), patch.degree_v(), control, uv.to_array())[0]
}

/// A patch from a function of the control-point indices.
pub fn patch_from(p: usize, q: usize, point: impl Fn(usize, usize) -> DVec3) -> BezierPatch {
    let points = (0..=p)
        .flat_map(|i| (0..=q).map(move |j| (i, j)))
        .map(|(i, j)| point(i, j))
        .collect();
    BezierPatch::try_new(p, q, points).expect("a valid patch")
}

/// The plane z = 0 over `[0, 1]²` as a bilinear patch: `S(u, v) = (u, v, 0)`.
pub fn unit_plane() -> BezierPatch {
    patch_from(1, 1, |i, j| DVec3::new(i as f64, j as f64, 0.0))
}

/// The initial mesh of the fully adaptive tessellation, built here
/// independently: `samples × samples` points, two triangles per cell
/// (the cell's diagonal from `(i, j + 1)` to `(i + 1, j)`).
pub fn sample_grid(patch: &impl Evaluate, samples: usize) -> Mesh {
    let n = samples - 1;
    let mut mesh = Mesh::new();
    let mut id = HashMap::new();
    for i in 0..=n {
        for j in 0..=n {
            let uv = DVec2::new(i as f64 / n as f64, j as f64 / n as f64);
            id.insert((i, j), mesh.push_vertex(patch.sample(uv)));
        }
    }
    for i in 0..n {
        for j in 0..n {
            let (a, b, c, d) = (
                id[&(i, j)],
                id[&(i + 1, j)],
                id[&(i + 1, j + 1)],
                id[&(i, j + 1)],
            );
            mesh.triangles.push([a, b, d]);
            mesh.triangles.push([b, c, d]);
        }
    }
    mesh
}

/// Twice the signed area of a triangle in the parameter plane.
pub fn uv_area2(mesh: &Mesh, [a, b, c]: [u32; 3]) -> f64 {
    let (pa, pb, pc) = (
        mesh.uvs[a as usize],
        mesh.uvs[b as usize],
        mesh.uvs[c as usize],
    );
    (pb - pa).perp_dot(pc - pa)
}

/// Checks that the mesh tiles the parameter rectangle `[0, width] ×
/// [0, height]` without gaps, overlaps or T-junctions:
/// - every triangle is counter-clockwise with positive area in `(u, v)`;
/// - the areas add up to `width · height`;
/// - no directed edge occurs twice (consistent orientation), and an edge
///   whose reverse is missing lies on the rectangle's boundary.
///
/// Positive areas that add up to the rectangle's area mean no overlaps;
/// every inner edge having a partner means no cracks and no T-junction
/// (a vertex in the middle of a neighbour's edge leaves that edge alone).
/// Returns the number of boundary edges.
pub fn assert_tiles_rectangle(mesh: &Mesh, width: f64, height: f64, what: &str) -> usize {
    mesh.validate().unwrap_or_else(|e| panic!("{what}: {e}"));
    let mut total = 0.0;
    for &t in &mesh.triangles {
        let a = uv_area2(mesh, t);
        assert!(
            a > 0.0,
            "{what}: triangle {t:?} is not counter-clockwise in (u, v) (2·area {a})"
        );
        total += a / 2.0;
    }
    assert!(
        (total - width * height).abs() < 1e-9 * width * height,
        "{what}: the triangles cover an area of {total}, not {}",
        width * height
    );
    let edges = directed_edges(&mesh.triangles);
    let on_boundary = |p: DVec2| {
        p.x.abs() < 1e-12
            || p.y.abs() < 1e-12
            || (p.x - width).abs() < 1e-12
            || (p.y - height).abs() < 1e-12
    };
    let mut boundary = 0;
    for (&(a, b), &n) in &edges {
        assert_eq!(
            n, 1,
            "{what}: edge {a}→{b} occurs {n} times in the same direction"
        );
        if !edges.contains_key(&(b, a)) {
            let (pa, pb) = (mesh.uvs[a as usize], mesh.uvs[b as usize]);
            let along_one_side = on_boundary(pa)
                && on_boundary(pb)
                && ((pa.x - pb.x).abs() < 1e-12 || (pa.y - pb.y).abs() < 1e-12)
                && on_boundary((pa + pb) / 2.0);
            assert!(
                along_one_side,
                "{what}: edge {a}→{b} ({pa} → {pb}) has no neighbour but is not on the boundary (a crack or T-junction)"
            );
            boundary += 1;
        }
    }
    boundary
}

/// The largest distance between the surface and the mesh, sampled at the
/// centroid and the edge midpoints of every triangle: the point of the
/// flat triangle against the surface point at the same interpolated
/// parameters.
pub fn max_deviation(mesh: &Mesh, surface: impl Fn(DVec2) -> DVec3) -> f64 {
    const WEIGHTS: [[f64; 3]; 4] = [
        [1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0],
        [0.5, 0.5, 0.0],
        [0.0, 0.5, 0.5],
        [0.5, 0.0, 0.5],
    ];
    let mut worst: f64 = 0.0;
    for &[a, b, c] in &mesh.triangles {
        let ids = [a as usize, b as usize, c as usize];
        for w in WEIGHTS {
            let uv: DVec2 = ids.iter().zip(w).map(|(&i, w)| w * mesh.uvs[i]).sum();
            let flat: DVec3 = ids.iter().zip(w).map(|(&i, w)| w * mesh.positions[i]).sum();
            worst = worst.max(surface(uv).distance(flat));
        }
    }
    worst
}

/// Renders a mesh and compares it with `tests/images/<name>.png`.
#[track_caller]
pub fn assert_picture(name: &str, mesh: &Mesh, view: View, style: Style) {
    check_picture(name, mesh, view, style).assert_matches();
}

/// Renders a mesh, writes its pictures and compares it with
/// `tests/images/<name>.png`; the verdict waits for `assert_matches`, so
/// that a test with several pictures writes them all before one fails.
pub fn check_picture(
    name: &str,
    mesh: &Mesh,
    view: View,
    style: Style,
) -> testkit::image::ImageCheck {
    let canvas = render(mesh, view, style, PICTURE_SIDE, PICTURE_SIDE);
    let reference = format!("{}/tests/images/{name}.png", env!("CARGO_MANIFEST_DIR"));
    testkit::image::check_image(name, &canvas, reference, PICTURE_TOLERANCE)
}

/// Side of the test pictures in pixels.
pub const PICTURE_SIDE: u32 = 240;

/// Pictures may differ in a few silhouette and wire pixels (float
/// rounding in another evaluation order), never in shading.
pub const PICTURE_TOLERANCE: testkit::image::Tolerance = testkit::image::Tolerance {
    channel: 3.0 / 255.0,
    mismatched_fraction: 0.002,
};

/// The view the seed's surface is drawn from.
pub const SEED_VIEW: View = View {
    yaw: -2.4,
    pitch: -0.57,
};

/// `part` appended to `all`, its indices moved past `all`'s vertices.
pub fn append(all: &mut Mesh, part: &Mesh) {
    let offset = all.vertex_count() as u32;
    all.positions.extend(&part.positions);
    all.normals.extend(&part.normals);
    all.uvs.extend(&part.uvs);
    all.triangles
        .extend(part.triangles.iter().map(|t| t.map(|i| i + offset)));
}

/// The torus of the rational-patch tests,
/// `RationalPatch::torus(TORUS_MAJOR, TORUS_MINOR)`.
pub const TORUS_MAJOR: f64 = 2.0;
/// See [`TORUS_MAJOR`].
pub const TORUS_MINOR: f64 = 0.6;

/// How far `p` lies from that torus, and the torus's outward unit normal
/// nearest to it: the direction from the tube's centre circle.
pub fn torus_distance_and_normal(p: DVec3) -> (f64, DVec3) {
    let centre = TORUS_MAJOR * DVec3::new(p.x, p.y, 0.0).normalize();
    let off = p - centre;
    ((off.length() - TORUS_MINOR).abs(), off.normalize())
}

/// Welds the vertices of `mesh` whose positions agree to 1e-7 and checks
/// that the result is closed: every edge has exactly two triangles, on
/// opposite sides. Returns `(V, E, F)` of the welded mesh.
pub fn closed_after_welding(mesh: &Mesh) -> (i64, i64, i64) {
    let key = |p: DVec3| (p * 1e7).round().as_i64vec3().to_array();
    let mut welded = HashMap::new();
    let index: Vec<u32> = mesh
        .positions
        .iter()
        .map(|&p| {
            let next = welded.len() as u32;
            *welded.entry(key(p)).or_insert(next)
        })
        .collect();
    let triangles: Vec<[u32; 3]> = mesh
        .triangles
        .iter()
        .map(|t| t.map(|i| index[i as usize]))
        .collect();
    let edges = directed_edges(&triangles);
    for (&(a, b), &count) in &edges {
        assert_eq!(
            (count, edges.get(&(b, a)).copied()),
            (1, Some(1)),
            "the edge {a}→{b} is not shared by exactly two triangles: a crack or a fold"
        );
    }
    (
        welded.len() as i64,
        edges.len() as i64 / 2,
        mesh.triangle_count() as i64,
    )
}
