//! Task 1: the six planes of the clip volume, `inside` and `intersect`.

mod common;

use canvas::Vec4;
use clipping::clip_planes::clip_planes;
use clipping::{CLIP_NUDGE, ClipPlane};
use proptest::prelude::*;

/// The plane `x ≤ w`, written out in `common` (not taken from
/// `clip_planes()`), so that `inside` and `intersect` are tested on their
/// own.
const RIGHT: ClipPlane = common::VOLUME_PLANES[0];
/// The plane `−z ≤ w` (near).
const NEAR: ClipPlane = common::VOLUME_PLANES[5];

fn p(x: f32, y: f32, z: f32, w: f32) -> Vec4 {
    Vec4::new(x, y, z, w)
}

/// Where `a → b` really crosses `plane`, in `f64`.
fn exact_t(plane: ClipPlane, a: Vec4, b: Vec4) -> f64 {
    let l = |v: Vec4| -> f64 {
        (0..4)
            .map(|i| f64::from(v[i]) * f64::from(plane.vector[i]))
            .sum()
    };
    l(a) / (l(a) - l(b))
}

#[testkit::test]
fn the_six_planes_are_the_faces_of_the_cube_in_the_stated_order() {
    let expected = common::VOLUME_PLANES.map(|p| p.vector);
    assert_eq!(clip_planes().map(|p| p.vector), expected);
}

#[testkit::test]
fn each_plane_has_a_unit_outward_normal_and_distance_one() {
    for plane in clip_planes() {
        let n = plane.vector.truncate();
        assert_eq!(n.length(), 1.0, "{plane:?}: normal not of unit length");
        assert_eq!(
            plane.vector.w, -1.0,
            "{plane:?}: the last component is −d = −1"
        );
        // The centre of the face the plane bounds is on it; one step further
        // out is outside; the cube's centre is inside.
        assert_eq!(plane.distance(n.extend(1.0)), 0.0);
        assert!(plane.distance((2.0 * n).extend(1.0)) > 0.0);
        assert_eq!(plane.distance(p(0.0, 0.0, 0.0, 1.0)), -1.0);
    }
}

#[testkit::test]
fn inside_includes_points_on_the_plane() {
    //   x:  0 (inside)   1 = w (on the plane: inside)   1.5 (outside)
    assert!(RIGHT.inside(p(0.0, 0.0, 0.0, 1.0)));
    assert!(RIGHT.inside(p(1.0, 5.0, -7.0, 1.0)));
    assert!(!RIGHT.inside(p(1.5, 0.0, 0.0, 1.0)));
    // Homogeneous: x = 2, w = 2 is on the plane; x = 2, w = 1 is not.
    assert!(RIGHT.inside(p(2.0, 0.0, 0.0, 2.0)));
    assert!(!RIGHT.inside(p(2.0, 0.0, 0.0, 1.0)));
    assert!(!RIGHT.inside(p(f32::NAN, 0.0, 0.0, 1.0)));
}

#[testkit::test]
fn corners_of_the_cube_are_inside_all_planes_and_points_behind_the_eye_are_not() {
    let planes = clip_planes();
    for corner in 0..8 {
        let s = |bit: i32| if corner & bit == 0 { -1.0 } else { 1.0 };
        let v = p(s(1), s(2), s(4), 1.0);
        assert!(planes.iter().all(|pl| pl.inside(v)), "{v:?}");
        assert!(planes.iter().all(|pl| pl.inside(3.0 * v)), "{v:?} · 3");
        assert!(!planes.iter().all(|pl| pl.inside(-v)), "{v:?} · −1 (w < 0)");
    }
    assert!(!planes.iter().all(|pl| pl.inside(p(0.0, 0.0, 0.0, -1.0))));
    assert!(planes.iter().all(|pl| pl.inside(p(0.0, 0.0, 0.0, 0.0))));
}

#[testkit::test]
fn intersect_is_nudged_towards_the_inside_endpoint() {
    // a = (0, 0, 0, 1): l_a = −1;  b = (3, 0, 0, 1): l_b = 2;  t = 1/3.
    //
    //   a ●──────────|─────────────────────● b
    //     0        1/3 (x = w = 1)         1
    let (a, b) = (p(0.0, 0.0, 0.0, 1.0), p(3.0, 0.0, 0.0, 1.0));
    let t = RIGHT.intersect(a, b).expect("the edge crosses");
    let expected = 1.0 / 3.0 - f64::from(CLIP_NUDGE);
    assert!((f64::from(t) - expected).abs() < 1e-7, "a → b: t = {t}");
    let t = RIGHT.intersect(b, a).expect("the edge crosses");
    let expected = 2.0 / 3.0 + f64::from(CLIP_NUDGE);
    assert!((f64::from(t) - expected).abs() < 1e-7, "b → a: t = {t}");
}

#[testkit::test]
fn intersect_in_homogeneous_coordinates_and_at_the_near_plane() {
    // The near plane −z ≤ w: a = (0, 0, 0, 1) inside, b = (0, 0, −5, 3)
    // outside; l_a = −1, l_b = 2, t = 1/3, where z = −5/3 and w = 5/3.
    let (a, b) = (p(0.0, 0.0, 0.0, 1.0), p(0.0, 0.0, -5.0, 3.0));
    let t = NEAR.intersect(a, b).expect("the edge crosses");
    assert!((f64::from(t) - (1.0 / 3.0 - f64::from(CLIP_NUDGE))).abs() < 1e-7);
}

#[testkit::test]
fn intersect_is_none_when_the_edge_does_not_cross() {
    let inside = [
        p(0.0, 0.0, 0.0, 1.0),
        p(0.5, 0.0, 0.0, 1.0),
        p(1.0, 0.0, 0.0, 1.0),
    ];
    let outside = [p(2.0, 0.0, 0.0, 1.0), p(9.0, 1.0, 0.0, 1.0)];
    for a in inside {
        for b in inside {
            assert_eq!(RIGHT.intersect(a, b), None, "{a:?} → {b:?}, both inside");
        }
    }
    // An edge that does cross has its crossing.
    assert!(RIGHT.intersect(inside[0], outside[0]).is_some());
    for a in outside {
        for b in outside {
            assert_eq!(RIGHT.intersect(a, b), None, "{a:?} → {b:?}, both outside");
        }
    }
}

#[testkit::test]
fn intersect_at_an_endpoint_on_the_plane_stays_on_the_edge() {
    // l_a = 0: a is inside (on the plane), t = 0; the nudge must not leave
    // the edge, so t stays 0. Likewise t = 1 when b is on the plane.
    let (on, out) = (p(1.0, 0.0, 0.0, 1.0), p(3.0, 0.0, 0.0, 1.0));
    assert_eq!(RIGHT.intersect(on, out), Some(0.0));
    assert_eq!(RIGHT.intersect(out, on), Some(1.0));
}

#[testkit::test]
fn intersect_refuses_non_finite_input() {
    let a = p(0.0, 0.0, 0.0, 1.0);
    for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        assert_eq!(RIGHT.intersect(a, p(bad, 0.0, 0.0, 1.0)), None, "{bad}");
        assert_eq!(RIGHT.intersect(p(0.0, bad, 0.0, 1.0), a), None, "{bad}");
    }
    // The same edges with finite coordinates cross.
    assert!(RIGHT.intersect(a, p(2.0, 0.0, 0.0, 1.0)).is_some());
    // Finite, but the distance overflows to infinity.
    assert_eq!(RIGHT.intersect(a, p(f32::MAX, 0.0, 0.0, -f32::MAX)), None);
}

fn homogeneous_point() -> impl Strategy<Value = Vec4> {
    (-4.0f32..4.0, -4.0f32..4.0, -4.0f32..4.0, -1.0f32..4.0)
        .prop_map(|(x, y, z, w)| Vec4::new(x, y, z, w))
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn inside_is_the_sign_of_the_dot_product_and_ignores_scale(
        v in homogeneous_point(),
        k in 0usize..6,
        scale in 0.01f32..100.0,
    ) {
        let plane = common::VOLUME_PLANES[k];
        let l: f64 = (0..4).map(|i| f64::from(v[i]) * f64::from(plane.vector[i])).sum();
        prop_assert_eq!(plane.inside(v), l <= 0.0);
        // A homogeneous point and its positive multiples are the same point.
        if l.abs() > 1e-4 {
            prop_assert_eq!(plane.inside(scale * v), l <= 0.0);
        }
    }

    #[testkit::test]
    fn intersection_lies_on_the_edge_just_inside_the_plane(
        a in homogeneous_point(),
        b in homogeneous_point(),
        k in 0usize..6,
    ) {
        let plane = common::VOLUME_PLANES[k];
        let crosses = plane.inside(a) != plane.inside(b);
        let t = plane.intersect(a, b);
        prop_assert_eq!(t.is_some(), crosses);
        // The definition, in f64: the signs of the distances differ.
        let l = |v: Vec4| -> f64 { (0..4).map(|i| f64::from(v[i]) * f64::from(plane.vector[i])).sum() };
        prop_assert_eq!(crosses, (l(a) <= 0.0) != (l(b) <= 0.0), "inside disagrees with the sign of v · p");
        if let Some(t) = t {
            prop_assert!((0.0..=1.0).contains(&t), "t = {}", t);
            let exact = exact_t(plane, a, b);
            // Within the nudge (and rounding) of the true crossing, on the
            // side of the inside endpoint.
            let off = f64::from(t) - exact;
            prop_assert!(off.abs() <= 1.5e-6, "t = {} vs exact {}", t, exact);
            if plane.inside(a) {
                prop_assert!(f64::from(t) <= exact, "not moved towards a");
            } else {
                prop_assert!(f64::from(t) >= exact, "not moved towards b");
            }
        }
    }
}
