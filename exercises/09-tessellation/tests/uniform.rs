//! Task 1: uniform tessellation of a Bézier patch, polynomial or rational.

mod common;

use common::{
    POSITION_TOLERANCE, SEED_VIEW, TORUS_MAJOR, TORUS_MINOR, append, assert_picture,
    assert_tiles_rectangle, bernstein_surface, check_picture, closed_after_welding, patch_from,
    torus_distance_and_normal, unit_plane,
};
use proptest::prelude::*;
use tessellation::bezier::{BezierPatch, MAX_RESOLUTION, RationalPatch};
use tessellation::error::TessError;
use tessellation::mesh::Mesh;
use tessellation::render::Style;
use tessellation::uniform::tessellate_uniform;
use tessellation::{DVec2, DVec3};

#[testkit::test]
fn grid_of_three_by_two_cells_is_numbered_row_by_row() {
    //   v ▲ 8───9──10──11
    //     │ 4───5───6───7
    //     │ 0───1───2───3 ▶ u
    let mesh = tessellate_uniform(&unit_plane(), 3, 2).unwrap();
    assert_eq!((mesh.vertex_count(), mesh.triangle_count()), (12, 12));
    for j in 0..=2 {
        for i in 0..=3 {
            let uv = DVec2::new(i as f64 / 3.0, j as f64 / 2.0);
            assert_eq!(mesh.uvs[j * 4 + i], uv, "vertex ({i}, {j})");
            assert_eq!(
                mesh.positions[j * 4 + i],
                uv.extend(0.0),
                "vertex ({i}, {j}) on the plane"
            );
            assert_eq!(mesh.normals[j * 4 + i], DVec3::Z, "normal of the plane");
        }
    }
    // Cell (0, 0) and cell (2, 1), lower-right triangle first.
    assert_eq!(&mesh.triangles[..2], &[[0, 1, 5], [0, 5, 4]]);
    assert_eq!(&mesh.triangles[10..], &[[6, 7, 11], [6, 11, 10]]);
}

#[testkit::test]
fn seed_surface_at_25_samples_has_1152_triangles() {
    // The seed's initial mesh: sample_size = 25, i.e. 24 × 24 cells.
    let mesh = tessellate_uniform(&BezierPatch::seed_surface(), 24, 24).unwrap();
    assert_eq!((mesh.vertex_count(), mesh.triangle_count()), (625, 1152));
}

#[testkit::test]
fn every_vertex_lies_on_the_surface_with_the_surface_normal() {
    let patch = BezierPatch::seed_surface();
    let mesh = tessellate_uniform(&patch, 7, 5).unwrap();
    assert_eq!(mesh.vertex_count(), 48, "(n_u + 1)(n_v + 1) vertices");
    for k in 0..mesh.vertex_count() {
        let uv = mesh.uvs[k];
        let exact = bernstein_surface(&patch, uv);
        assert!(
            mesh.positions[k].distance(exact) < POSITION_TOLERANCE,
            "vertex {k} at {uv}"
        );
        // The normal is a unit vector perpendicular to both tangents
        // (central differences, away from the degenerate corner (0, 0)).
        let n = mesh.normals[k];
        assert!(
            (n.length() - 1.0).abs() < 1e-9,
            "normal {k} is not a unit vector"
        );
        if uv.length() > 0.2 {
            let h = 1e-5;
            let du = bernstein_surface(&patch, uv + DVec2::new(h, 0.0))
                - bernstein_surface(&patch, uv - DVec2::new(h, 0.0));
            let dv = bernstein_surface(&patch, uv + DVec2::new(0.0, h))
                - bernstein_surface(&patch, uv - DVec2::new(0.0, h));
            assert!(
                n.dot(du.normalize()).abs() < 1e-6 && n.dot(dv.normalize()).abs() < 1e-6,
                "normal {k} at {uv}"
            );
            assert!(
                n.dot(du.cross(dv)) > 0.0,
                "normal {k} points along S_u × S_v"
            );
        }
    }
}

#[testkit::test]
fn bilinear_patch_is_reproduced_exactly() {
    // A twisted bilinear patch: S(u, v) = (1−u)(1−v) P00 + u(1−v) P10 + (1−u)v P01 + uv P11.
    let corners = [
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(0.0, 2.0, 1.0),
        DVec3::new(3.0, 0.0, 1.0),
        DVec3::new(3.0, 2.0, 0.0),
    ];
    let patch = BezierPatch::try_new(1, 1, corners.to_vec()).unwrap();
    let mesh = tessellate_uniform(&patch, 4, 4).unwrap();
    assert_eq!(mesh.vertex_count(), 25, "(n_u + 1)(n_v + 1) vertices");
    assert_eq!(mesh.uvs.len(), 25, "a (u, v) per vertex");
    for (uv, p) in mesh.uvs.iter().zip(&mesh.positions) {
        let (u, v) = (uv.x, uv.y);
        let exact = (1.0 - u) * (1.0 - v) * corners[0]
            + (1.0 - u) * v * corners[1]
            + u * (1.0 - v) * corners[2]
            + u * v * corners[3];
        assert!(p.distance(exact) < 1e-12, "{uv}");
    }
}

#[testkit::test]
fn one_cell_is_two_triangles() {
    let mesh = tessellate_uniform(&unit_plane(), 1, 1).unwrap();
    assert_eq!(mesh.triangles, [[0, 1, 3], [0, 3, 2]]);
    let mut obj = Vec::new();
    mesh.write_obj(&mut obj).unwrap();
    let obj = String::from_utf8(obj).unwrap();
    assert!(
        obj.contains("v 1 1 0\n") && obj.contains("f 1/1/1 2/2/2 4/4/4\n"),
        "{obj}"
    );
    // Writing never panics, not even for an index the mesh does not have.
    let mut broken = mesh.clone();
    broken.triangles.push([0, 1, u32::MAX]);
    let mut obj = Vec::new();
    broken.write_obj(&mut obj).unwrap();
    assert!(
        String::from_utf8(obj)
            .unwrap()
            .ends_with("f 1/1/1 2/2/2 4294967296/4294967296/4294967296\n")
    );
}

#[testkit::test]
fn zero_and_huge_resolutions_are_errors() {
    let patch = unit_plane();
    assert_eq!(
        tessellate_uniform(&patch, 0, 3),
        Err(TessError::Resolution(0))
    );
    assert_eq!(
        tessellate_uniform(&patch, 3, 0),
        Err(TessError::Resolution(0))
    );
    assert_eq!(
        tessellate_uniform(&patch, MAX_RESOLUTION + 1, 1),
        Err(TessError::Resolution(MAX_RESOLUTION + 1))
    );
}

#[testkit::test]
fn seed_surface_shaded_matches_the_reference_image() {
    let mesh = tessellate_uniform(&BezierPatch::seed_surface(), 24, 24).unwrap();
    assert_picture("uniform_seed_shaded", &mesh, SEED_VIEW, Style::Shaded);
}

#[testkit::test]
fn seed_surface_wireframe_matches_the_reference_image() {
    let mesh = tessellate_uniform(&BezierPatch::seed_surface(), 12, 12).unwrap();
    assert_picture("uniform_seed_wireframe", &mesh, SEED_VIEW, Style::Wireframe);
}

/// Random patches of degree 1..=4 × 1..=4 with coordinates in [−5, 5].
fn any_patch() -> impl Strategy<Value = BezierPatch> {
    (1usize..=4, 1usize..=4).prop_flat_map(|(p, q)| {
        prop::collection::vec(
            (-5.0f64..5.0, -5.0f64..5.0, -5.0f64..5.0),
            (p + 1) * (q + 1),
        )
        .prop_map(move |c| {
            patch_from(p, q, |i, j| {
                let (x, y, z) = c[i * (q + 1) + j];
                DVec3::new(x, y, z)
            })
        })
    })
}

proptest! {
    #![proptest_config(testkit::strategies::proptest_config())]

    #[testkit::test]
    fn mesh_tiles_the_parameter_square_and_lies_on_the_surface(patch in any_patch(), n_u in 1usize..12, n_v in 1usize..12) {
        let mesh = tessellate_uniform(&patch, n_u, n_v).unwrap();
        prop_assert_eq!(mesh.vertex_count(), (n_u + 1) * (n_v + 1));
        prop_assert_eq!(mesh.triangle_count(), 2 * n_u * n_v);
        let boundary = assert_tiles_rectangle(&mesh, 1.0, 1.0, "uniform");
        prop_assert_eq!(boundary, 2 * (n_u + n_v));
        for (uv, p) in mesh.uvs.iter().zip(&mesh.positions) {
            prop_assert!(p.distance(bernstein_surface(&patch, *uv)) < POSITION_TOLERANCE);
        }
    }
}

#[testkit::test]
fn multi_patch_surface_matches_the_reference_image() {
    // Every patch of the example grid at the same 8 × 8 cells: neighbours
    // share their boundary points because they share the resolution.
    let grid = tessellation::patch_grid::PatchGrid::example();
    let mut all = tessellation::mesh::Mesh::new();
    for row in 0..grid.rows() {
        for col in 0..grid.cols() {
            append(
                &mut all,
                &tessellate_uniform(grid.patch(row, col), 8, 8).unwrap(),
            );
        }
    }
    let view = tessellation::render::View {
        yaw: -0.5,
        pitch: -0.67,
    };
    assert_picture("uniform_example", &all, view, Style::ShadedWireframe);
}

// ---------------------------------------------------------------------------
// A NURBS surface through the tessellation: the torus as the 16 rational
// biquadratic patches its NURBS form splits into (`RationalPatch::torus`).

/// Every torus patch tessellated uniformly at `n × n`, the meshes appended.
fn torus_mesh(n: usize) -> Mesh {
    let mut all = Mesh::new();
    for patch in RationalPatch::torus(TORUS_MAJOR, TORUS_MINOR) {
        append(&mut all, &tessellate_uniform(&patch, n, n).unwrap());
    }
    all
}

#[testkit::test]
fn a_rational_torus_tessellates_onto_the_torus() {
    let mesh = torus_mesh(6);
    assert_eq!(mesh.triangle_count(), 16 * 2 * 36);
    for (k, (&p, &normal)) in mesh.positions.iter().zip(&mesh.normals).enumerate() {
        let (distance, expected) = torus_distance_and_normal(p);
        assert!(
            distance < 1e-9,
            "vertex {k} at {p} is {distance} off the torus: evaluate the rational patch \
             (Evaluate::sample), not its control net"
        );
        assert!(
            normal.distance(expected) < 1e-9,
            "vertex {k} at {p}: normal {normal}, the torus's {expected}"
        );
    }
}

/// The 16 patches meet without a crack: welded where positions agree
/// (`closed_after_welding`), the mesh is closed (every edge has exactly two triangles, on
/// opposite sides) and has the Euler characteristic of a torus, 0.
#[testkit::test]
fn the_torus_patches_meet_without_a_crack() {
    let mesh = torus_mesh(5);
    let (v, e, f) = closed_after_welding(&mesh);
    assert_eq!(v - e + f, 0, "V − E + F of the welded torus");
    assert_eq!(v, 16 * 25, "5 × 5 cells per patch, boundaries shared");
}

#[testkit::test]
fn a_rational_torus_matches_the_reference_images() {
    let mesh = torus_mesh(8);
    let view = tessellation::render::View {
        yaw: -0.4,
        pitch: -0.57,
    };
    // Both pictures before either verdict, so that a wrong shaded picture
    // still leaves the wireframe to compare with.
    let shaded = check_picture("uniform_nurbs_torus_shaded", &mesh, view, Style::Shaded);
    let wireframe = check_picture(
        "uniform_nurbs_torus_wireframe",
        &mesh,
        view,
        Style::Wireframe,
    );
    shaded.assert_matches();
    wireframe.assert_matches();
}
