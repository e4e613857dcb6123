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
    let yours = clip_planes().map(|p| p.vector);
    let names = [
        "right x ≤ w",
        "left −x ≤ w",
        "top y ≤ w",
        "bottom −y ≤ w",
        "far z ≤ w",
        "near −z ≤ w",
    ];
    for (k, name) in names.into_iter().enumerate() {
        assert_eq!(
            yours[k], expected[k],
            "clip_planes()[{k}] is the {name} plane, (n_x, n_y, n_z, −d) with the outward unit \
             normal and d = 1, in the order right, left, top, bottom, far, near"
        );
    }
}

#[testkit::test]
fn each_plane_has_a_unit_outward_normal_and_distance_one() {
    for plane in clip_planes() {
        let n = plane.vector.truncate();
        let v = plane.vector;
        assert_eq!(
            n.length(),
            1.0,
            "the plane {v}: its normal (n_x, n_y, n_z) has unit length"
        );
        assert_eq!(v.w, -1.0, "the plane {v}: the last component is −d = −1");
        // The centre of the face the plane bounds is on it; one step further
        // out is outside; the cube's centre is inside.
        let (face, beyond) = (n.extend(1.0), (2.0 * n).extend(1.0));
        assert_eq!(
            plane.distance(face),
            0.0,
            "the plane {v}: the centre {face} of the face it bounds lies on it, v · p = 0"
        );
        let out = plane.distance(beyond);
        assert!(
            out > 0.0,
            "the plane {v}: {beyond}, beyond its face, is outside (v · p > 0, the normal points \
             outwards); yours gives v · p = {out}"
        );
        assert_eq!(
            plane.distance(p(0.0, 0.0, 0.0, 1.0)),
            -1.0,
            "the plane {v}: the cube's centre (0, 0, 0, 1) is inside at distance −d = −1"
        );
    }
}

#[testkit::test]
fn inside_includes_points_on_the_plane() {
    //   x:  0 (inside)   1 = w (on the plane: inside)   1.5 (outside)
    // Homogeneous: x = 2, w = 2 is on the plane; x = 2, w = 1 is not.
    for (v, expected) in [
        (p(0.0, 0.0, 0.0, 1.0), true),
        (p(1.0, 5.0, -7.0, 1.0), true),
        (p(1.5, 0.0, 0.0, 1.0), false),
        (p(2.0, 0.0, 0.0, 2.0), true),
        (p(2.0, 0.0, 0.0, 1.0), false),
        (p(f32::NAN, 0.0, 0.0, 1.0), false),
    ] {
        let l = v.dot(RIGHT.vector);
        assert_eq!(
            RIGHT.inside(v),
            expected,
            "(x ≤ w).inside({v}): inside is v · p ≤ 0, on the plane included (a NaN is not \
             inside); here v · p = {l}"
        );
    }
}

#[testkit::test]
fn corners_of_the_cube_are_inside_all_planes_and_points_behind_the_eye_are_not() {
    let planes = clip_planes();
    for corner in 0..8 {
        let s = |bit: i32| if corner & bit == 0 { -1.0 } else { 1.0 };
        let v = p(s(1), s(2), s(4), 1.0);
        // The first plane that calls `v` outside, for the messages.
        let outside = |v: Vec4| planes.iter().find(|pl| !pl.inside(v)).map(|pl| pl.vector);
        assert!(
            planes.iter().all(|pl| pl.inside(v)),
            "the cube's corner {v} lies on three planes and inside the others (on a plane is \
             inside); yours has it outside {:?}",
            outside(v)
        );
        assert!(
            planes.iter().all(|pl| pl.inside(3.0 * v)),
            "{}, the corner {v} times 3, is the same point: inside; yours has it outside {:?}",
            3.0 * v,
            outside(3.0 * v)
        );
        assert!(
            !planes.iter().all(|pl| pl.inside(-v)),
            "{}, the corner {v} times −1, has w < 0 (behind the eye): outside some plane; yours \
             has it inside all six",
            -v
        );
    }
    assert!(
        !planes.iter().all(|pl| pl.inside(p(0.0, 0.0, 0.0, -1.0))),
        "(0, 0, 0, −1) lies behind the eye (w < 0): outside some plane; yours has it inside all six"
    );
    let origin = p(0.0, 0.0, 0.0, 0.0);
    assert!(
        planes.iter().all(|pl| pl.inside(origin)),
        "the homogeneous origin (0, 0, 0, 0) lies on all six planes, and on a plane counts as \
         inside; yours has it outside {:?}",
        planes
            .iter()
            .find(|pl| !pl.inside(origin))
            .map(|pl| pl.vector)
    );
}

#[testkit::test]
fn intersect_is_nudged_towards_the_inside_endpoint() {
    // a = (0, 0, 0, 1): l_a = −1;  b = (3, 0, 0, 1): l_b = 2;  t = 1/3.
    //
    //   a ●──────────|─────────────────────● b
    //     0        1/3 (x = w = 1)         1
    let (a, b) = (p(0.0, 0.0, 0.0, 1.0), p(3.0, 0.0, 0.0, 1.0));
    let t = RIGHT
        .intersect(a, b)
        .expect("(x ≤ w).intersect((0, 0, 0, 1), (3, 0, 0, 1)): a is inside, b outside, the edge crosses: Some(t)");
    let expected = 1.0 / 3.0 - f64::from(CLIP_NUDGE);
    assert!(
        (f64::from(t) - expected).abs() < 1e-7,
        "(x ≤ w).intersect((0, 0, 0, 1), (3, 0, 0, 1)): t = l_a / (l_a − l_b) = 1/3, moved by \
         CLIP_NUDGE towards the inside endpoint a: expected {expected}, yours {t}"
    );
    let t = RIGHT
        .intersect(b, a)
        .expect("(x ≤ w).intersect((3, 0, 0, 1), (0, 0, 0, 1)): b is inside, a outside, the edge crosses: Some(t)");
    let expected = 2.0 / 3.0 + f64::from(CLIP_NUDGE);
    assert!(
        (f64::from(t) - expected).abs() < 1e-7,
        "(x ≤ w).intersect((3, 0, 0, 1), (0, 0, 0, 1)): t = l_a / (l_a − l_b) = 2/3, moved by \
         CLIP_NUDGE towards the inside endpoint b: expected {expected}, yours {t}"
    );
}

#[testkit::test]
fn intersect_in_homogeneous_coordinates_and_at_the_near_plane() {
    // The near plane −z ≤ w: a = (0, 0, 0, 1) inside, b = (0, 0, −5, 3)
    // outside; l_a = −1, l_b = 2, t = 1/3, where z = −5/3 and w = 5/3.
    let (a, b) = (p(0.0, 0.0, 0.0, 1.0), p(0.0, 0.0, -5.0, 3.0));
    let t = NEAR
        .intersect(a, b)
        .expect("(−z ≤ w).intersect((0, 0, 0, 1), (0, 0, −5, 3)): a is inside, b outside, the edge crosses: Some(t)");
    let expected = 1.0 / 3.0 - f64::from(CLIP_NUDGE);
    assert!(
        (f64::from(t) - expected).abs() < 1e-7,
        "(−z ≤ w).intersect((0, 0, 0, 1), (0, 0, −5, 3)): l_a = −1, l_b = 2 with the point's own \
         w, t = 1/3 moved by CLIP_NUDGE towards a: expected {expected}, yours {t}"
    );
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
            assert_eq!(
                RIGHT.intersect(a, b),
                None,
                "(x ≤ w).intersect({a}, {b}): both endpoints inside, the edge does not cross"
            );
        }
    }
    // An edge that does cross has its crossing.
    assert!(
        RIGHT.intersect(inside[0], outside[0]).is_some(),
        "(x ≤ w).intersect({}, {}): one endpoint inside, one outside, the edge crosses: Some(t), \
         yours None",
        inside[0],
        outside[0]
    );
    for a in outside {
        for b in outside {
            assert_eq!(
                RIGHT.intersect(a, b),
                None,
                "(x ≤ w).intersect({a}, {b}): both endpoints outside, the edge does not cross"
            );
        }
    }
}

#[testkit::test]
fn intersect_at_an_endpoint_on_the_plane_stays_on_the_edge() {
    // l_a = 0: a is inside (on the plane), t = 0; the nudge must not leave
    // the edge, so t stays 0. Likewise t = 1 when b is on the plane.
    let (on, out) = (p(1.0, 0.0, 0.0, 1.0), p(3.0, 0.0, 0.0, 1.0));
    assert_eq!(
        RIGHT.intersect(on, out),
        Some(0.0),
        "(x ≤ w).intersect({on}, {out}): a on the plane is inside, t = 0, and the nudge towards a \
         is kept in [0, 1]"
    );
    assert_eq!(
        RIGHT.intersect(out, on),
        Some(1.0),
        "(x ≤ w).intersect({out}, {on}): b on the plane is inside, t = 1, and the nudge towards b \
         is kept in [0, 1]"
    );
}

#[testkit::test]
fn intersect_refuses_non_finite_input() {
    let a = p(0.0, 0.0, 0.0, 1.0);
    for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        assert_eq!(
            RIGHT.intersect(a, p(bad, 0.0, 0.0, 1.0)),
            None,
            "(x ≤ w).intersect({a}, ({bad}, 0, 0, 1)): a non-finite endpoint gives None"
        );
        assert_eq!(
            RIGHT.intersect(p(0.0, bad, 0.0, 1.0), a),
            None,
            "(x ≤ w).intersect((0, {bad}, 0, 1), {a}): a non-finite endpoint gives None"
        );
    }
    // The same edges with finite coordinates cross.
    assert!(
        RIGHT.intersect(a, p(2.0, 0.0, 0.0, 1.0)).is_some(),
        "(x ≤ w).intersect({a}, (2, 0, 0, 1)): a inside, b outside, the edge crosses: Some(t), \
         yours None"
    );
    // Finite, but the distance overflows to infinity.
    let huge = p(f32::MAX, 0.0, 0.0, -f32::MAX);
    assert_eq!(
        RIGHT.intersect(a, huge),
        None,
        "(x ≤ w).intersect({a}, {huge}): b · p = f32::MAX + f32::MAX overflows to infinity, and \
         a non-finite distance gives None"
    );
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
        prop_assert_eq!(plane.inside(v), l <= 0.0, "{}.inside({}): inside is v · p ≤ 0, here v · p = {}", plane.vector, v, l);
        // A homogeneous point and its positive multiples are the same point.
        if l.abs() > 1e-4 {
            prop_assert_eq!(plane.inside(scale * v), l <= 0.0, "{}.inside({}): {} times {}, the same point, and v · p = {} for the point itself", plane.vector, scale * v, v, scale, l);
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
        prop_assert_eq!(t.is_some(), crosses, "{}.intersect({}, {}) = {:?}: Some(t) exactly when one endpoint is inside (inside: {} and {})", plane.vector, a, b, t, plane.inside(a), plane.inside(b));
        // The definition, in f64: the signs of the distances differ.
        let l = |v: Vec4| -> f64 { (0..4).map(|i| f64::from(v[i]) * f64::from(plane.vector[i])).sum() };
        prop_assert_eq!(crosses, (l(a) <= 0.0) != (l(b) <= 0.0), "{}: inside({}) = {} and inside({}) = {} disagree with the signs of v · p, {} and {} (inside is v · p ≤ 0)", plane.vector, a, plane.inside(a), b, plane.inside(b), l(a), l(b));
        if let Some(t) = t {
            let call = format!("{}.intersect({a}, {b})", plane.vector);
            prop_assert!((0.0..=1.0).contains(&t), "{}: t is kept in [0, 1], yours {}", call, t);
            let exact = exact_t(plane, a, b);
            // Within the nudge (and rounding) of the true crossing, on the
            // side of the inside endpoint.
            let off = f64::from(t) - exact;
            prop_assert!(off.abs() <= 1.5e-6, "{}: t = l_a / (l_a − l_b) = {} (in f64), nudged by CLIP_NUDGE = 1e-6; yours {} is {} off", call, exact, t, off);
            if plane.inside(a) {
                prop_assert!(f64::from(t) <= exact, "{}: a is inside, so t is moved towards a, below the crossing {}; yours {}", call, exact, t);
            } else {
                prop_assert!(f64::from(t) >= exact, "{}: b is inside, so t is moved towards b, above the crossing {}; yours {}", call, exact, t);
            }
        }
    }
}
