//! Task 3: de Casteljau in WGSL, compared with the CPU evaluation in f64
//! (`src/patch.rs`) and with exact known answers.

mod common;

use glam::{DVec2, DVec3, Vec3};
use gpu::Gpu;
use gpu_tessellation::passes::{Domain, Patches, run_evaluation};
use gpu_tessellation::patch::{
    BezierPatch, BezierTriangle, GpuVertex, RationalPatch, SurfaceSample,
};
use gpu_tessellation::wgsl::{self, Piece};
use proptest::prelude::*;

/// Largest position difference from the f64 evaluation (control points in
/// `[-1, 1]³`: a few f32 rounding steps).
const POSITION_TOLERANCE: f64 = 1e-5;
/// Largest normal difference (f32 cross products of short tangents).
const NORMAL_TOLERANCE: f64 = 1e-3;
/// Normals are compared only where the CPU's unnormalised cross product is
/// at least this long: near a degenerate point f32 and f64 may disagree.
const WELL_DEFINED_CROSS: f64 = 1e-2;

fn evaluate_quads(
    gpu: &Gpu,
    piece: Piece,
    patches: &[BezierPatch],
    domains: &[Domain],
) -> Vec<GpuVertex> {
    let refs: Vec<&Domain> = domains.iter().collect();
    run_evaluation(gpu, piece, Patches::Quads(patches), &refs)
        .unwrap()
        .read(gpu)
        .unwrap()
}

fn evaluate_triangles(
    gpu: &Gpu,
    piece: Piece,
    triangles: &[BezierTriangle],
    domains: &[Domain],
) -> Vec<GpuVertex> {
    let refs: Vec<&Domain> = domains.iter().collect();
    run_evaluation(gpu, piece, Patches::Triangles(triangles), &refs)
        .unwrap()
        .read(gpu)
        .unwrap()
}

/// Checks one GPU vertex against the CPU point; `cross_length` is the CPU's
/// unnormalised normal length (normals are skipped where it is tiny).
fn check(
    got: &GpuVertex,
    expected: SurfaceSample,
    cross_length: f64,
    what: &str,
) -> Result<(), TestCaseError> {
    let position = got.position.truncate().as_dvec3();
    prop_assert!(
        position.distance(expected.position) <= POSITION_TOLERANCE,
        "{}: position {:?}, expected {:?}",
        what,
        position,
        expected.position
    );
    if cross_length >= WELL_DEFINED_CROSS {
        let normal = got.normal.truncate().as_dvec3();
        prop_assert!(
            normal.distance(expected.normal) <= NORMAL_TOLERANCE,
            "{}: normal {:?}, expected {:?}",
            what,
            normal,
            expected.normal
        );
    }
    Ok(())
}

/// ∂P/∂u × ∂P/∂v by central differences, independent of de Casteljau.
fn patch_cross(patch: &BezierPatch, uv: DVec2) -> DVec3 {
    const H: f64 = 1e-4;
    let p = |u: f64, v: f64| common::patch_point(patch, DVec2::new(u, v)).position;
    let du = (p(uv.x + H, uv.y) - p(uv.x - H, uv.y)) / (2.0 * H);
    let dv = (p(uv.x, uv.y + H) - p(uv.x, uv.y - H)) / (2.0 * H);
    du.cross(dv)
}

/// The length of [`patch_cross`], to decide whether the normal is well defined.
fn patch_cross_length(patch: &BezierPatch, uv: DVec2) -> f64 {
    patch_cross(patch, uv).length()
}

fn triangle_cross_length(t: &BezierTriangle, uvw: DVec3) -> f64 {
    const H: f64 = 1e-4;
    let p = |d: DVec3| common::triangle_point(t, d).position;
    // Directions within the plane u + v + w = 1.
    let dv = (p(uvw + DVec3::new(-H, H, 0.0)) - p(uvw - DVec3::new(-H, H, 0.0))) / (2.0 * H);
    let dw = (p(uvw + DVec3::new(-H, 0.0, H)) - p(uvw - DVec3::new(-H, 0.0, H))) / (2.0 * H);
    dv.cross(dw).length()
}

#[testkit::test]
fn patch_corners_are_the_corner_control_points() {
    let piece = wgsl::EVALUATION.written();
    let Some(gpu) = common::gpu() else { return };
    let points: [Vec3; 16] = std::array::from_fn(|k| {
        Vec3::new(
            k as f32 * 0.1,
            (k % 5) as f32 * 0.3 - 0.5,
            (k % 3) as f32 - 1.0,
        )
    });
    let patch = common::from_gl_points(points.map(Vec3::as_dvec3));
    let domain = common::grid(1);
    let got = evaluate_quads(&gpu, piece, &[patch], std::slice::from_ref(&domain));
    for (d, v) in domain.points.iter().zip(&got) {
        let corner = match (d.x as u32, d.y as u32) {
            (0, 0) => 0,
            (1, 0) => 3,
            (0, 1) => 12,
            _ => 15,
        };
        assert_eq!(v.position.truncate(), points[corner], "corner at {d}");
        assert_eq!(v.param.truncate(), *d, "the domain point is passed on");
    }
}

#[testkit::test]
fn flat_patch_has_the_planes_normal_everywhere() {
    let piece = wgsl::EVALUATION.written();
    let Some(gpu) = common::gpu() else { return };
    // The plane z = 0.5 seen from +z, u along x and v along y: normal +z.
    let patch = BezierPatch::flat(DVec2::new(-1.0, -0.5), DVec2::new(2.0, 1.5), 0.5);
    let domain = common::grid(5);
    let got = evaluate_quads(&gpu, piece, &[patch], std::slice::from_ref(&domain));
    for (d, v) in domain.points.iter().zip(&got) {
        let expected = Vec3::new(-1.0 + 3.0 * d.x, -0.5 + 2.0 * d.y, 0.5);
        assert!(
            v.position.truncate().distance(expected) < 1e-5,
            "{d}: {v:?}"
        );
        assert!(v.normal.truncate().distance(Vec3::Z) < 1e-6, "{d}: {v:?}");
    }
}

#[testkit::test]
fn normal_uses_the_surface_tangent_not_the_last_rows() {
    let piece = wgsl::EVALUATION.written();
    let Some(gpu) = common::gpu() else { return };
    // A twisted patch: row v = 1 runs along x, row v = 0 along x but rising
    // in z. At v = 0 the u tangent is (1, 0, 1)/√2-ish, not the last row's (1, 0, 0).
    let mut points = common::gl_points(&BezierPatch::flat(DVec2::ZERO, DVec2::ONE, 0.0));
    for (i, point) in points.iter_mut().take(4).enumerate() {
        point.z = i as f64 / 3.0;
    }
    let patch = common::from_gl_points(points);
    let domain = common::grid(1);
    let got = evaluate_quads(
        &gpu,
        piece,
        std::slice::from_ref(&patch),
        std::slice::from_ref(&domain),
    );
    for (d, v) in domain.points.iter().zip(&got) {
        // Central differences stay inside [0, 1]² away from the corners' sides.
        let uv = d
            .truncate()
            .as_dvec2()
            .clamp(DVec2::splat(1e-3), DVec2::splat(1.0 - 1e-3));
        let expected = patch_cross(&patch, uv).normalize();
        assert!(
            v.normal.truncate().as_dvec3().distance(expected) < 1e-2,
            "at {d}: normal {:?}, expected {expected:?}",
            v.normal,
        );
    }
}

#[testkit::test]
fn flat_bezier_triangle_has_corners_and_normal_of_its_plane() {
    let piece = wgsl::EVALUATION.written();
    let Some(gpu) = common::gpu() else { return };
    let (a, b, c) = (
        Vec3::new(0.0, 0.0, 0.0),
        Vec3::new(1.0, 0.0, 0.0),
        Vec3::new(0.0, 1.0, 0.0),
    );
    let triangle = BezierTriangle::flat(a.as_dvec3(), b.as_dvec3(), c.as_dvec3());
    let domain = common::lattice(3);
    let got = evaluate_triangles(&gpu, piece, &[triangle], std::slice::from_ref(&domain));
    for (d, v) in domain.points.iter().zip(&got) {
        let expected = a * d.x + b * d.y + c * d.z;
        assert!(
            v.position.truncate().distance(expected) < 1e-6,
            "{d}: {v:?}"
        );
        assert!(v.normal.truncate().distance(Vec3::Z) < 1e-6, "{d}: {v:?}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 12, ..testkit::proptest_config() })]

    #[testkit::test]
    fn random_patches_match_the_cpu_evaluation(
        patches in prop::collection::vec(common::patch(), 1..6),
        cuts in prop::collection::vec((common::random_cuts(), common::random_cuts()), 6),
    ) {
        let piece = wgsl::EVALUATION.written();
        let Some(gpu) = common::gpu() else { return Ok(()) };
        let domains: Vec<Domain> = patches
            .iter()
            .zip(&cuts)
            .map(|(_, (us, vs))| common::grid_at(us, vs))
            .collect();
        let got = evaluate_quads(&gpu, piece, &patches, &domains);
        let mut k = 0;
        for (patch, domain) in patches.iter().zip(&domains) {
            for d in &domain.points {
                let uv = d.truncate().as_dvec2();
                check(&got[k], common::patch_point(patch, uv), patch_cross_length(patch, uv), &format!("patch at {uv}"))?;
                k += 1;
            }
        }
    }

    #[testkit::test]
    fn random_bezier_triangles_match_the_cpu_evaluation(
        triangles in prop::collection::vec(common::triangle(), 1..6),
        levels in prop::collection::vec(1usize..20, 6),
    ) {
        let piece = wgsl::EVALUATION.written();
        let Some(gpu) = common::gpu() else { return Ok(()) };
        let domains: Vec<Domain> = triangles
            .iter()
            .zip(&levels)
            .map(|(_, &n)| common::lattice(n))
            .collect();
        let got = evaluate_triangles(&gpu, piece, &triangles, &domains);
        let mut k = 0;
        for (triangle, domain) in triangles.iter().zip(&domains) {
            for d in &domain.points {
                let uvw = d.as_dvec3();
                check(&got[k], common::triangle_point(triangle, uvw), triangle_cross_length(triangle, uvw), &format!("triangle at {uvw}"))?;
                k += 1;
            }
        }
    }
}

/// A NURBS surface on the GPU: the torus's 16 rational patches (raised
/// to bicubic, uploaded homogeneous as `(w·P, w)`). Every point lies on
/// the torus and carries its normal; with the weights ignored (`.xyz`
/// alone) the points leave the torus by up to a fifth of its tube.
#[testkit::test]
fn rational_torus_patches_lie_on_the_torus() {
    let piece = wgsl::EVALUATION.written();
    let Some(gpu) = common::gpu() else { return };
    let (major, minor) = (0.7, 0.25);
    let patches = RationalPatch::torus(major, minor);
    let domains = vec![common::grid(6); patches.len()];
    let refs: Vec<&Domain> = domains.iter().collect();
    let got = run_evaluation(&gpu, piece, Patches::Rational(&patches), &refs)
        .unwrap()
        .read(&gpu)
        .unwrap();
    assert_eq!(got.len(), 16 * 49);
    for (k, v) in got.iter().enumerate() {
        let p = v.position.truncate().as_dvec3();
        let centre = major * DVec3::new(p.x, p.y, 0.0).normalize();
        let off = ((p - centre).length() - minor).abs();
        assert!(
            off < 2e-5,
            "patch {}, vertex {}: {p} is {off} off the torus; the control points are \
             homogeneous (w·P, w): run de Casteljau on all four coordinates and divide by w",
            k / 49,
            k % 49
        );
        let normal = v.normal.truncate().as_dvec3();
        let expected = (p - centre).normalize();
        assert!(
            normal.distance(expected) < 1e-3,
            "patch {}, vertex {}: normal {normal}, the torus's {expected} (a tangent T of the \
             homogeneous patch is T.xyz − P·T.w)",
            k / 49,
            k % 49
        );
    }
}

#[testkit::test]
fn pn_triangle_interpolates_its_vertices_and_normals() {
    let piece = wgsl::EVALUATION.written();
    let Some(gpu) = common::gpu() else { return };
    let vertices = [
        Vec3::new(0.0, 0.0, 0.0),
        Vec3::new(1.0, 0.0, 0.2),
        Vec3::new(0.0, 1.0, 0.1),
    ];
    let normals = [
        Vec3::new(-0.2, -0.2, 1.0),
        Vec3::new(0.3, 0.0, 1.0),
        Vec3::new(0.0, 0.3, 1.0),
    ];
    // The PN triangle of these vertices and normals (seed 001 §4.1: edge
    // points are the thirds of the edges moved into the nearest vertex's
    // tangent plane, the centre is E + (E − V)/2), its ten points written
    // out in storage order.
    let triangle = BezierTriangle::from_points(
        [
            Vec3::new(0.0, 0.0, 0.0),                    // P300
            Vec3::new(0.3333333, 0.0, 0.0666667),        // P210
            Vec3::new(-0.0061728, 0.3271605, 0.0641975), // P201
            Vec3::new(0.7125382, 0.0, 0.2862385),        // P120
            Vec3::new(0.3524323, 0.3455516, 0.2223949),  // P111
            Vec3::new(0.0, 0.7033639, 0.1889908),        // P102
            Vec3::new(1.0, 0.0, 0.2),                    // P030
            Vec3::new(0.7033639, 0.3333333, 0.2889908),  // P021
            Vec3::new(0.3333333, 0.6850153, 0.1944954),  // P012
            Vec3::new(0.0, 1.0, 0.1),                    // P003
        ]
        .map(Vec3::as_dvec3),
    );
    let domain = common::lattice(1);
    let got = evaluate_triangles(&gpu, piece, &[triangle], std::slice::from_ref(&domain));
    for (d, v) in domain.points.iter().zip(&got) {
        let corner = if d.x == 1.0 {
            0
        } else if d.y == 1.0 {
            1
        } else {
            2
        };
        assert!(
            v.position.truncate().distance(vertices[corner]) < 1e-6,
            "{d}: {v:?}"
        );
        // A PN triangle's normal at a corner is the vertex normal.
        let n = normals[corner].normalize();
        assert!(
            v.normal.truncate().distance(n) < 1e-5,
            "{d}: {:?} vs {n}",
            v.normal
        );
    }
}
