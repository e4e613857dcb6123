//! Task 2: per-patch adaptive tessellation without cracks.

mod common;

use common::{
    POSITION_TOLERANCE, TORUS_MAJOR, TORUS_MINOR, assert_picture, assert_tiles_rectangle,
    bernstein_surface, closed_after_welding, patch_from, torus_distance_and_normal,
};
use proptest::prelude::*;
use tessellation::bezier::{BezierPatch, curve};
use tessellation::error::TessError;
use tessellation::patch_grid::PatchGrid;
use tessellation::per_patch::{
    MAX_SEGMENTS, MIN_INNER_SEGMENTS, curve_segments, patch_resolution, tessellate_patch_grid,
};
use tessellation::render::{Style, View};
use tessellation::{DVec2, DVec3};

fn p(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// The parabola `C(t) = (2t, 2t(1 − t), 0)`: second difference `(0, −2, 0)`,
/// `C'' = (0, −4, 0)`, so the chord error of `k` equal segments is exactly
/// `(1/k)²/8 · 4 = 1/(2k²)`.
fn parabola() -> Vec<DVec3> {
    vec![p(0.0, 0.0, 0.0), p(1.0, 1.0, 0.0), p(2.0, 0.0, 0.0)]
}

#[testkit::test]
fn parabola_gets_the_segments_its_chord_error_needs() {
    // k = ⌈sqrt(2·1·2 / (8 tol))⌉ = ⌈sqrt(1 / (2 tol))⌉.
    for (tolerance, k) in [
        (1.0 / 8.0, 2),
        (1.0 / 32.0, 4),
        (0.03, 5),
        (1.0 / 200.0, 10),
        (10.0, 1),
    ] {
        assert_eq!(
            curve_segments(&parabola(), tolerance),
            Ok(k),
            "tolerance {tolerance}"
        );
        // and the k-segment polyline is within the tolerance: 1/(2k²) ≤ tol.
        assert!(1.0 / (2.0 * (k * k) as f64) <= tolerance + 1e-15);
    }
}

#[testkit::test]
fn polyline_of_a_cubic_stays_within_the_tolerance() {
    //   an S-shaped cubic, sampled densely against its polyline
    let cubic = vec![
        p(0.0, 0.0, 0.0),
        p(1.0, 3.0, 1.0),
        p(2.0, -3.0, 0.0),
        p(3.0, 0.0, 2.0),
    ];
    for tolerance in [0.5, 0.1, 0.01, 0.002] {
        let k = curve_segments(&cubic, tolerance).unwrap();
        assert!(
            k >= 1,
            "tolerance {tolerance}: a curve has at least one segment"
        );
        let mut worst: f64 = 0.0;
        for s in 0..k {
            let (a, b) = (s as f64 / k as f64, (s + 1) as f64 / k as f64);
            let (pa, pb) = (curve(&cubic, a).0, curve(&cubic, b).0);
            for m in 1..20 {
                let t = m as f64 / 20.0;
                let on_curve = curve(&cubic, a + (b - a) * t).0;
                worst = worst.max(on_curve.distance(pa.lerp(pb, t)));
            }
        }
        assert!(
            worst <= tolerance,
            "tolerance {tolerance}: {k} segments leave {worst}"
        );
    }
}

#[testkit::test]
fn straight_curves_need_one_segment() {
    let evenly = vec![
        p(0.0, 0.0, 0.0),
        p(1.0, 1.0, 1.0),
        p(2.0, 2.0, 2.0),
        p(3.0, 3.0, 3.0),
    ];
    assert_eq!(curve_segments(&evenly, 1e-9), Ok(1));
    assert_eq!(curve_segments(&evenly[..2], 1e-9), Ok(1), "degree 1");
    assert_eq!(curve_segments(&evenly[..1], 1e-9), Ok(1), "a point");
    assert_eq!(curve_segments(&[], 1e-9), Ok(1), "no points");
}

#[testkit::test]
fn curved_curves_are_capped_and_bad_input_is_an_error() {
    assert_eq!(curve_segments(&parabola(), 1e-300), Ok(MAX_SEGMENTS));
    for tolerance in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(
            matches!(
                curve_segments(&parabola(), tolerance),
                Err(TessError::NotPositive { .. })
            ),
            "tolerance {tolerance}"
        );
    }
    let hostile = vec![p(0.0, 0.0, 0.0), p(f64::NAN, 1.0, 0.0), p(2.0, 0.0, 0.0)];
    assert!(matches!(
        curve_segments(&hostile, 0.1),
        Err(TessError::NonFinite { .. })
    ));
    let huge = vec![p(0.0, 0.0, 0.0), p(1e300, 1e300, 0.0), p(2.0, 0.0, 0.0)];
    assert_eq!(curve_segments(&huge, 0.1), Ok(MAX_SEGMENTS));
}

#[testkit::test]
fn resolution_follows_each_direction_on_its_own() {
    // Curved like the parabola along u (i), straight along v (j):
    // P_ij = (i, j, parabola height) with heights 0, 1, 0.
    let patch = patch_from(2, 3, |i, j| p(i as f64, j as f64, [0.0, 1.0, 0.0][i]));
    assert_eq!(
        patch_resolution(&patch, 1.0 / 32.0),
        Ok([4, MIN_INNER_SEGMENTS])
    );
    let turned = patch_from(3, 2, |i, j| p(i as f64, j as f64, [0.0, 1.0, 0.0][j]));
    assert_eq!(
        patch_resolution(&turned, 1.0 / 200.0),
        Ok([MIN_INNER_SEGMENTS, 10])
    );
    let flat = patch_from(3, 3, |i, j| p(i as f64, j as f64, 0.0));
    assert_eq!(patch_resolution(&flat, 1e-6), Ok([MIN_INNER_SEGMENTS; 2]));
    assert!(matches!(
        patch_resolution(&flat, 0.0),
        Err(TessError::NotPositive { .. })
    ));
}

/// The patch containing global parameters `uv`, and the local parameters.
fn locate(grid: &PatchGrid, uv: DVec2) -> (&BezierPatch, DVec2) {
    let col = (uv.x.floor() as usize).min(grid.cols() - 1);
    let row = (uv.y.floor() as usize).min(grid.rows() - 1);
    (
        grid.patch(row, col),
        uv - DVec2::new(col as f64, row as f64),
    )
}

fn assert_watertight_on_surface(grid: &PatchGrid, tolerance: f64) -> tessellation::mesh::Mesh {
    let what = format!("tolerance {tolerance}");
    let mesh = tessellate_patch_grid(grid, tolerance).unwrap();
    assert_tiles_rectangle(&mesh, grid.cols() as f64, grid.rows() as f64, &what);
    for (uv, pos) in mesh.uvs.iter().zip(&mesh.positions) {
        let (patch, local) = locate(grid, *uv);
        assert!(
            pos.distance(bernstein_surface(patch, local)) < POSITION_TOLERANCE,
            "{what}: vertex at {uv} is off the surface"
        );
    }
    // No vertex twice: shared curves are evaluated once.
    let mut uvs: Vec<(i64, i64)> = mesh
        .uvs
        .iter()
        .map(|uv| ((uv.x * 1e9).round() as i64, (uv.y * 1e9).round() as i64))
        .collect();
    uvs.sort_unstable();
    let before = uvs.len();
    uvs.dedup();
    assert_eq!(
        uvs.len(),
        before,
        "{what}: a point of the surface occurs as two vertices"
    );
    mesh
}

#[testkit::test]
fn example_surface_is_watertight_at_every_tolerance() {
    let grid = PatchGrid::example();
    for tolerance in [1.0, 0.1, 0.01, 0.002, 1e-4] {
        assert_watertight_on_surface(&grid, tolerance);
    }
}

#[testkit::test]
fn curved_patch_gets_more_triangles_than_flat_ones() {
    // The example's bump sits in patch (1, 1); patch (0, 0) is nearly flat.
    let grid = PatchGrid::example();
    let mesh = tessellate_patch_grid(&grid, 0.005).unwrap();
    let mut per_patch = [0usize; 4];
    for &[a, b, c] in &mesh.triangles {
        let centre = (mesh.uvs[a as usize] + mesh.uvs[b as usize] + mesh.uvs[c as usize]) / 3.0;
        per_patch[centre.y.floor() as usize * 2 + centre.x.floor() as usize] += 1;
    }
    assert!(
        per_patch[3] > 2 * per_patch[0],
        "triangles per patch: {per_patch:?}"
    );
    let res_bump = patch_resolution(grid.patch(1, 1), 0.005).unwrap();
    let res_flat = patch_resolution(grid.patch(0, 0), 0.005).unwrap();
    assert!(
        res_bump[0] > res_flat[0] && res_bump[1] > res_flat[1],
        "{res_bump:?} vs {res_flat:?}"
    );
}

#[testkit::test]
fn single_flat_patch_is_a_fan_around_its_centre() {
    // A bilinear plane: every curve needs 1 segment, the patch 2 × 2 cells,
    // whose inner grid is the single point (½, ½): four corners, one
    // centre, four triangles (one per side).
    let plane = patch_from(1, 1, |i, j| p(i as f64, j as f64, 0.0));
    let grid = PatchGrid::try_new(1, 1, vec![plane]).unwrap();
    let mesh = tessellate_patch_grid(&grid, 0.1).unwrap();
    assert_eq!((mesh.vertex_count(), mesh.triangle_count()), (5, 4));
    assert!(mesh.uvs.contains(&DVec2::splat(0.5)));
    assert_eq!(assert_tiles_rectangle(&mesh, 1.0, 1.0, "plane"), 4);
}

#[testkit::test]
fn grids_whose_neighbours_do_not_meet_are_rejected() {
    let a = patch_from(1, 1, |i, j| p(i as f64, j as f64, 0.0));
    let b = patch_from(1, 1, |i, j| p(1.0 + i as f64, j as f64, 0.5));
    assert!(matches!(
        PatchGrid::try_new(1, 2, vec![a.clone(), b]),
        Err(TessError::NotContinuous { row: 0, col: 0, .. })
    ));
    let grid = PatchGrid::try_new(1, 1, vec![a]).unwrap();
    assert!(matches!(
        tessellate_patch_grid(&grid, f64::NAN),
        Err(TessError::NotPositive { .. })
    ));
}

#[testkit::test]
fn example_surface_matches_the_reference_image() {
    let mesh = tessellate_patch_grid(&PatchGrid::example(), 0.004).unwrap();
    let view = View {
        yaw: -0.5,
        pitch: -0.67,
    };
    assert_picture("per_patch_example", &mesh, view, Style::ShadedWireframe);
}

/// A NURBS surface per patch: the torus as a 4 × 4 grid of rational
/// patches. Every vertex lies on the torus; welded where positions agree,
/// the mesh is closed (every edge twice, in opposite directions; the
/// grid's outer curves meet where the torus closes) with V − E + F = 0.
#[testkit::test]
fn a_nurbs_torus_is_tessellated_per_patch_without_a_crack() {
    let grid = PatchGrid::torus(TORUS_MAJOR, TORUS_MINOR);
    let mesh = tessellate_patch_grid(&grid, 0.01).unwrap();
    assert!(
        mesh.triangle_count() >= 16 * 8,
        "16 patches of at least 2 × 2 cells: {} triangles",
        mesh.triangle_count()
    );
    for (k, &p) in mesh.positions.iter().enumerate() {
        let (off, _) = torus_distance_and_normal(p);
        assert!(off < 1e-9, "vertex {k} at {p} is {off} off the torus");
    }
    let (v, e, f) = closed_after_welding(&mesh);
    assert_eq!(v - e + f, 0, "V − E + F of the welded torus");
}

/// Random `rows × cols` grids of bicubic patches from random heights on a
/// shared lattice (neighbours share lattice rows, so they meet).
fn any_grid() -> impl Strategy<Value = PatchGrid> {
    (1usize..=3, 1usize..=3).prop_flat_map(|(rows, cols)| {
        let (nx, ny) = (3 * cols + 1, 3 * rows + 1);
        prop::collection::vec(-1.0f64..1.0, nx * ny).prop_map(move |heights| {
            let lattice =
                |a: usize, b: usize| p(a as f64 / 3.0, b as f64 / 3.0, heights[b * nx + a]);
            let patches = (0..rows)
                .flat_map(|r| (0..cols).map(move |c| (r, c)))
                .map(|(r, c)| patch_from(3, 3, |i, j| lattice(3 * c + i, 3 * r + j)))
                .collect();
            PatchGrid::try_new(rows, cols, patches).unwrap()
        })
    })
}

proptest! {
    #![proptest_config(testkit::strategies::proptest_config())]

    #[testkit::test]
    fn random_grids_are_watertight(grid in any_grid(), tolerance in 0.002f64..0.5) {
        assert_watertight_on_surface(&grid, tolerance);
    }
}
