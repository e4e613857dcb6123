//! Task 4: knot insertion (Boehm) and Bézier decomposition of surfaces.

mod common;

use canvas::Rgba;
use common::{
    assert_close, circle, curve_point, homogeneous_point, nurbs_curve, nurbs_surface,
    rational_patch_point, spans, surface_point, torus, torus_distance,
};
use glam::{DVec3, DVec4};
use nurbs::{ControlNet, KnotVector, NurbsCurve, NurbsError, NurbsSurface, homogeneous};
use proptest::prelude::*;
use testkit::image::{Tolerance, check_image};
use testkit::proptest_config;

/// Refined descriptions of curves with coordinates up to 10 agree with the
/// original to this.
const TOLERANCE: f64 = 1e-9;

/// A parameter strictly inside the domain, at the fraction `t` of it.
fn inside(knots: &KnotVector, t: f64) -> f64 {
    let d = knots.domain();
    d.lerp(0.01 + 0.98 * t)
}

#[testkit::test]
fn inserting_the_middle_of_a_quadratic_bezier_halves_its_legs() {
    // U = {0,0,0,1,1,1}; inserting ½ once gives de Casteljau's midpoint
    // subdivision in homogeneous space:
    //
    //        P1                    Q1 = (P0ʷ + P1ʷ)/2
    //       ╱  ╲                   Q2 = (P1ʷ + P2ʷ)/2
    //     P0    P2                 Q0 = P0, Q3 = P2
    let p = [
        homogeneous(DVec3::new(0.0, 0.0, 0.0), 1.0),
        homogeneous(DVec3::new(2.0, 4.0, 0.0), 3.0),
        homogeneous(DVec3::new(4.0, 0.0, 2.0), 1.0),
    ];
    let curve = NurbsCurve::try_new(KnotVector::bezier(2).unwrap(), p.to_vec()).unwrap();
    let refined = curve.insert_knot(0.5, 1).unwrap();
    assert_eq!(
        refined.knots().knots(),
        &[0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]
    );
    let expected = [p[0], (p[0] + p[1]) / 2.0, (p[1] + p[2]) / 2.0, p[2]];
    assert_eq!(refined.points().len(), 4);
    for (q, e) in refined.points().iter().zip(expected) {
        assert!((*q - e).length() < 1e-15, "{q} vs {e}");
    }
}

#[testkit::test]
fn inserting_a_knot_three_times_into_a_cubic_splits_it_into_two_bezier_pieces() {
    // Inserting ½ three times into a cubic Bézier curve makes the middle
    // control point the curve's point at ½ (two Bézier pieces sharing it).
    let p: Vec<DVec4> = [
        (DVec3::new(0.0, 0.0, 0.0), 1.0),
        (DVec3::new(1.0, 3.0, 0.0), 0.5),
        (DVec3::new(3.0, 3.0, 1.0), 2.0),
        (DVec3::new(4.0, 0.0, 0.0), 1.0),
    ]
    .iter()
    .map(|&(p, w)| homogeneous(p, w))
    .collect();
    let curve = NurbsCurve::try_new(KnotVector::bezier(3).unwrap(), p.clone()).unwrap();
    let refined = curve.insert_knot(0.5, 3).unwrap();
    assert_eq!(refined.points().len(), 7);
    let middle = refined.points()[3];
    let on_curve = curve_point(curve.knots(), &p, 0.5);
    assert_close(on_curve, middle.truncate() / middle.w, 1e-14, "P3 = C(½)");
}

#[testkit::test]
fn circle_stays_a_circle_after_insertion() {
    let refined = circle().insert_knot(0.1, 2).unwrap();
    assert_eq!(refined.points().len(), 11);
    for k in 0..=200 {
        let u = f64::from(k) / 200.0;
        let p = curve_point(refined.knots(), refined.points(), u);
        assert!((p.length() - 1.0).abs() < 1e-14, "u = {u}: {p}");
    }
}

#[testkit::test]
fn torus_decomposes_into_sixteen_biquadratic_patches() {
    // The circle's knots ¼, ½, ¾ already have multiplicity 2 = p: no
    // insertion is needed, the net is cut into 4 × 4 blocks of 3 × 3.
    let torus = torus();
    let patches = torus.decompose().unwrap();
    assert_eq!(patches.len(), 16);
    for (k, patch) in patches.iter().enumerate() {
        assert_eq!(
            (patch.points().degree_u(), patch.points().degree_v()),
            (2, 2)
        );
        let (a, b) = (k / 4, k % 4);
        let corner = torus.net().get(2 * a, 2 * b);
        assert!(
            (homogeneous_point(patch, 0, 0) - corner).length() < 1e-14,
            "patch {k} starts at the net's point ({}, {})",
            2 * a,
            2 * b
        );
        for (s, t) in [(0.0, 0.0), (0.3, 0.7), (1.0, 0.5)] {
            let p = rational_patch_point(patch, s, t);
            assert!(torus_distance(p) < 1e-13, "patch {k} at ({s}, {t}): {p}");
        }
    }
}

#[testkit::test]
fn the_vase_with_single_interior_knots_decomposes_into_twelve_patches() {
    // The vase (the course's surface of revolution) has the profile's
    // knots ⅓ and ⅔ once each, below its degree q = 3: each is inserted
    // twice before the net is cut into 4 × 3 blocks of 3 × 4 points.
    let vase = NurbsSurface::from_data(&freeform::NurbsSurfaceData::vase()).unwrap();
    let patches = vase.decompose().unwrap();
    assert_eq!(
        patches.len(),
        12,
        "4 quarters round the axis × 3 spans of the profile"
    );
    let (spans_u, spans_v) = (spans(vase.knots_u()), spans(vase.knots_v()));
    for (k, patch) in patches.iter().enumerate() {
        assert_eq!(
            (patch.points().degree_u(), patch.points().degree_v()),
            (2, 3),
            "patch {k}: degree 2 × 3"
        );
        // Row-major by u span, then v span: patch k covers these pieces.
        let (domain_u, domain_v) = (spans_u[k / 3], spans_v[k % 3]);
        for s in [0.0, 0.25, 0.6, 1.0] {
            for t in [0.0, 0.4, 0.75, 1.0] {
                let (u, v) = (domain_u.lerp(s), domain_v.lerp(t));
                assert_close(
                    surface_point(&vase, u, v),
                    rational_patch_point(patch, s, t),
                    TOLERANCE,
                    &format!("patch {k} at ({s}, {t}), S({u}, {v})"),
                );
            }
        }
    }
}

#[testkit::test]
fn invalid_insertions_are_errors() {
    let circle = circle();
    // ¼ already has multiplicity 2 = p.
    assert!(matches!(
        circle.insert_knot(0.25, 1),
        Err(NurbsError::MultiplicityTooHigh { .. })
    ));
    assert!(matches!(
        circle.insert_knot(0.1, 3),
        Err(NurbsError::MultiplicityTooHigh { .. })
    ));
    for u in [0.0, 1.0, -0.5, 2.0, f64::NAN] {
        assert!(
            matches!(
                circle.insert_knot(u, 1),
                Err(NurbsError::OutOfDomain { .. })
            ),
            "u = {u}"
        );
    }
    assert_eq!(circle.insert_knot(0.3, 0).unwrap(), circle);
    let torus = torus();
    assert!(matches!(
        torus.insert_knot_u(0.5, 1),
        Err(NurbsError::MultiplicityTooHigh { .. })
    ));
    assert!(matches!(
        torus.insert_knot_v(f64::NAN, 1),
        Err(NurbsError::OutOfDomain { .. })
    ));
    // Decomposition needs clamped knot vectors.
    let unclamped = KnotVector::uniform(2, 4).unwrap();
    let net = ControlNet::try_new(
        4,
        4,
        (0..16)
            .map(|k| homogeneous(DVec3::new(f64::from(k % 4), f64::from(k / 4), 0.0), 1.0))
            .collect(),
    )
    .unwrap();
    let surface = NurbsSurface::try_new(unclamped.clone(), unclamped, net).unwrap();
    assert_eq!(surface.decompose(), Err(NurbsError::NotClamped));
}

/// Distinct colours for the patches of the picture.
fn patch_colour(k: usize) -> Rgba {
    let hue = k as f32 * 0.618_034;
    let tau = std::f32::consts::TAU;
    Rgba::rgb(
        0.5 + 0.5 * (tau * hue).cos(),
        0.5 + 0.5 * (tau * (hue - 1.0 / 3.0)).cos(),
        0.5 + 0.5 * (tau * (hue - 2.0 / 3.0)).cos(),
    )
}

/// The torus refined at u = 0.1 and v = 0.6 (so that some patches are
/// narrow), shaded by the test's own evaluation, with the boundary curves
/// of its Bézier patches drawn on top, each patch in its own colour; and
/// how many patches `decompose` gave.
fn decomposition_wireframe() -> (canvas::Canvas, usize) {
    let torus = torus()
        .insert_knot_u(0.1, 1)
        .and_then(|t| t.insert_knot_v(0.6, 1))
        .unwrap();
    // The shaded surface from the definition (normals by differences).
    let (nu, nv) = (64, 32);
    let mut points = Vec::new();
    let mut colours = Vec::new();
    for i in 0..nu {
        for j in 0..nv {
            let (u, v) = (i as f64 / (nu - 1) as f64, j as f64 / (nv - 1) as f64);
            points.push(surface_point(&torus, u, v));
            const STEP: f64 = 1e-5;
            let du = surface_point(&torus, (u + STEP).min(1.0), v)
                - surface_point(&torus, (u - STEP).max(0.0), v);
            let dv = surface_point(&torus, u, (v + STEP).min(1.0))
                - surface_point(&torus, u, (v - STEP).max(0.0));
            colours.push(common::shade(du.cross(dv).normalize()));
        }
    }
    let mut canvas = common::render_grid(&points, &colours, nu, nv);
    let patches = torus.decompose().unwrap();
    const SAMPLES: usize = 200;
    for (k, patch) in patches.iter().enumerate() {
        let colour = patch_colour(k);
        for m in 0..=SAMPLES {
            let t = m as f64 / SAMPLES as f64;
            for (s, r) in [(t, 0.0), (t, 1.0), (0.0, t), (1.0, t)] {
                common::plot_on_top(&mut canvas, rational_patch_point(patch, s, r), colour);
            }
        }
    }
    (canvas, patches.len())
}

#[testkit::test]
fn decomposition_wireframe_matches_the_reference_image() {
    let reference = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/images/knot_insertion_patches.png"
    );
    let (wireframe, patches) = decomposition_wireframe();
    // The picture first, so that a failing check below still leaves it.
    let picture = check_image(
        "knot_insertion_patches",
        &wireframe,
        reference,
        Tolerance {
            channel: 3.0 / 255.0,
            mismatched_fraction: 0.002,
        },
    );
    assert_eq!(
        patches, 25,
        "the torus with one knot more in u and in v: 5 × 5 Bézier patches"
    );
    picture.assert_matches();
}

proptest! {
    #![proptest_config(proptest_config())]

    #[testkit::test]
    fn insertion_leaves_the_curve_unchanged(
        curve in nurbs_curve(),
        at in 0.0f64..=1.0,
        times in 1usize..=4,
        samples in prop::collection::vec(0.0f64..=1.0, 8),
    ) {
        let u = inside(curve.knots(), at);
        let p = curve.degree();
        let s = curve.knots().multiplicity(u);
        prop_assume!(s + times <= p);
        let refined = curve.insert_knot(u, times).unwrap();
        // The knot vector gains u, `times` times; the net `times` points.
        let mut expected_knots = curve.knots().knots().to_vec();
        expected_knots.extend(std::iter::repeat_n(u, times));
        expected_knots.sort_by(f64::total_cmp);
        prop_assert_eq!(refined.knots().knots(), &expected_knots[..]);
        prop_assert_eq!(refined.points().len(), curve.points().len() + times);
        prop_assert_eq!(refined.knots().degree(), p);
        for t in samples.into_iter().chain([0.0, 1.0]) {
            let x = curve.domain().lerp(t);
            let before = curve_point(curve.knots(), curve.points(), x);
            let after = curve_point(refined.knots(), refined.points(), x);
            prop_assert!(before.distance(after) <= TOLERANCE, "C({x}): {before} vs {after}");
        }
    }

    #[testkit::test]
    fn surface_insertion_leaves_the_surface_unchanged(
        surface in nurbs_surface(),
        at in 0.0f64..=1.0,
        along_v in any::<bool>(),
        samples in prop::collection::vec((0.0f64..=1.0, 0.0f64..=1.0), 6),
    ) {
        let refined = if along_v {
            let v = inside(surface.knots_v(), at);
            prop_assume!(surface.knots_v().multiplicity(v) < surface.knots_v().degree());
            surface.insert_knot_v(v, 1).unwrap()
        } else {
            let u = inside(surface.knots_u(), at);
            prop_assume!(surface.knots_u().multiplicity(u) < surface.knots_u().degree());
            surface.insert_knot_u(u, 1).unwrap()
        };
        let (rows, columns) = (surface.net().rows(), surface.net().columns());
        let grown = (refined.net().rows(), refined.net().columns());
        prop_assert_eq!(grown, if along_v { (rows, columns + 1) } else { (rows + 1, columns) });
        for (s, t) in samples {
            let (u, v) = (surface.domain_u().lerp(s), surface.domain_v().lerp(t));
            let before = surface_point(&surface, u, v);
            let after = surface_point(&refined, u, v);
            prop_assert!(before.distance(after) <= TOLERANCE, "S({u}, {v}): {before} vs {after}");
        }
    }

    #[testkit::test]
    fn bezier_patches_reproduce_the_surface(
        surface in nurbs_surface(),
        samples in prop::collection::vec((0.0f64..=1.0, 0.0f64..=1.0), 4),
    ) {
        prop_assume!(surface.knots_u().is_clamped() && surface.knots_v().is_clamped());
        let patches = surface.decompose().unwrap();
        let (spans_u, spans_v) = (spans(surface.knots_u()), spans(surface.knots_v()));
        prop_assert_eq!(patches.len(), spans_u.len() * spans_v.len());
        let (p, q) = (surface.knots_u().degree(), surface.knots_v().degree());
        for (k, patch) in patches.iter().enumerate() {
            prop_assert_eq!((patch.points().degree_u(), patch.points().degree_v()), (p, q));
            // Patches tile the domain, row-major by u span then v span.
            let (a, b) = (k / spans_v.len(), k % spans_v.len());
            if b > 0 {
                // Neighbours along v share their boundary column of control points.
                for i in 0..=p {
                    let (mine, theirs) = (homogeneous_point(patch, i, 0), homogeneous_point(&patches[k - 1], i, q));
                    prop_assert!((mine - theirs).length() <= TOLERANCE * (1.0 + theirs.length()));
                }
            }
            if a > 0 {
                // Neighbours along u share their boundary row of control points.
                let above = &patches[k - spans_v.len()];
                for j in 0..=q {
                    let (mine, theirs) = (homogeneous_point(patch, 0, j), homogeneous_point(above, p, j));
                    prop_assert!((mine - theirs).length() <= TOLERANCE * (1.0 + theirs.length()));
                }
            }
            for &(s, t) in &samples {
                let expected = surface_point(&surface, spans_u[a].lerp(s), spans_v[b].lerp(t));
                let actual = rational_patch_point(patch, s, t);
                prop_assert!(expected.distance(actual) <= TOLERANCE, "patch {k} at ({s}, {t}): {expected} vs {actual}");
            }
        }
    }
}
