//! Task 1: point classification against primitives and CSG trees.

mod common;

use canvas::{Canvas, Pixel, Rgba};
use common::{in_primitive, in_tree, point, primitive, tree};
use csg::Vec3;
use csg::classify::{Class, classify_point, contains};
use csg::csg::{Csg, Scene};
use csg::primitive::{Axis, Primitive};
use proptest::prelude::*;

fn unit_box() -> Primitive {
    Primitive::Cuboid {
        min: Vec3::new(-1.0, -2.0, -3.0),
        max: Vec3::new(1.0, 2.0, 3.0),
    }
}

#[testkit::test]
fn box_interior_faces_edges_and_outside() {
    let b = unit_box();
    for (p, expected, what) in [
        (Vec3::ZERO, Class::Inside, "the centre"),
        (
            Vec3::new(0.99, 1.99, 2.99),
            Class::Inside,
            "just inside a corner",
        ),
        (Vec3::new(1.0, 0.0, 0.0), Class::On, "on a face"),
        (Vec3::new(0.0, -2.0, 3.0), Class::On, "on an edge"),
        (Vec3::new(-1.0, -2.0, -3.0), Class::On, "on a corner"),
        (
            Vec3::new(1.01, 0.0, 0.0),
            Class::Outside,
            "beyond the face x = 1",
        ),
        (
            Vec3::new(0.0, 0.0, -3.5),
            Class::Outside,
            "beyond the face z = −3",
        ),
    ] {
        assert_eq!(
            classify_point(&b, p),
            expected,
            "classify_point(box [−1, 1] × [−2, 2] × [−3, 3], {p}), {what}: strictly between \
             min and max in every axis is Inside, equal to a bound in one axis (and within the \
             others) is On, compared exactly"
        );
    }
}

#[testkit::test]
fn sphere_centre_surface_and_outside() {
    let s = Primitive::Sphere {
        centre: Vec3::new(1.0, 2.0, 3.0),
        radius: 2.0,
    };
    // (1, 2, 3) + (0, 2, 0) and (1, 2, 3) + (−2, 0, 0): exactly on it.
    // Offsets (1.5, 0, 0): 1.5 < 2; (1.5, 1.5, 0): √4.5 > 2.
    // The corner of the bounding box is outside the ball.
    for (p, expected) in [
        (Vec3::new(1.0, 2.0, 3.0), Class::Inside),
        (Vec3::new(1.0, 4.0, 3.0), Class::On),
        (Vec3::new(-1.0, 2.0, 3.0), Class::On),
        (Vec3::new(2.5, 2.0, 3.0), Class::Inside),
        (Vec3::new(2.5, 3.5, 3.0), Class::Outside),
        (Vec3::new(2.9, 3.9, 4.9), Class::Outside),
    ] {
        let d2 = (p - Vec3::new(1.0, 2.0, 3.0)).length_squared();
        assert_eq!(
            classify_point(&s, p),
            expected,
            "classify_point(sphere at (1, 2, 3) of radius 2, {p}): |p − c|² = {d2} against r² = 4, \
             less is Inside, equal is On, more is Outside"
        );
    }
}

#[testkit::test]
fn cylinder_axis_caps_rim_and_outside_for_every_axis() {
    for (axis, e) in [(Axis::X, Vec3::X), (Axis::Y, Vec3::Y), (Axis::Z, Vec3::Z)] {
        let c = Vec3::new(0.5, -1.0, 2.0);
        let cyl = Primitive::Cylinder {
            centre: c,
            axis,
            radius: 1.0,
            half_length: 2.0,
        };
        // A unit vector across the axis.
        let across = if axis == Axis::X { Vec3::Y } else { Vec3::X };
        // Inside the bounding box, outside the round side.
        let corner = c + 0.9 * across + 0.9 * e.cross(across);
        for (p, expected, what) in [
            (c, Class::Inside, "the centre"),
            (c + 1.5 * e, Class::Inside, "on the axis inside"),
            (c + 2.0 * e, Class::On, "a cap's centre"),
            (c - 2.0 * e + 0.5 * across, Class::On, "on a cap"),
            (c + across, Class::On, "on the side"),
            (c + 2.0 * e + across, Class::On, "on the rim"),
            (c + 2.5 * e, Class::Outside, "beyond the cap"),
            (c + 1.25 * across, Class::Outside, "beside it"),
            (corner, Class::Outside, "a corner of its bounding box"),
        ] {
            assert_eq!(
                classify_point(&cyl, p),
                expected,
                "classify_point(cylinder along {axis:?} at {c}, radius 1, half length 2, {p}), \
                 {what}: |along the axis| ≤ 2 and distance² across ≤ 1, both strict for Inside, \
                 one equal for On"
            );
        }
    }
}

#[testkit::test]
fn nan_points_and_broken_primitives_are_outside_everything() {
    let p = Vec3::new(f32::NAN, 0.0, 0.0);
    assert_eq!(
        classify_point(&unit_box(), p),
        Class::Outside,
        "classify_point(box, {p}): a NaN coordinate is Outside everything"
    );
    let scene = Scene::new(vec![unit_box()], Csg::leaf(0)).expect("valid");
    assert!(
        !contains(&scene, p),
        "contains(the box alone, {p}): a NaN coordinate is outside every solid, yours says it \
         is in"
    );
    // A scene refuses broken primitives and unknown leaves; a primitive
    // classified on its own with a NaN parameter contains nothing.
    let nan_sphere = Primitive::Sphere {
        centre: Vec3::ZERO,
        radius: f32::NAN,
    };
    let flat_box = Primitive::Cuboid {
        min: Vec3::ZERO,
        max: Vec3::new(1.0, 0.0, 1.0),
    };
    for bad in [nan_sphere, flat_box] {
        assert!(
            Scene::new(vec![bad], Csg::leaf(0)).is_err(),
            "Scene::new refuses a primitive with a non-finite number or an empty extent: {bad:?}"
        );
    }
    assert!(
        Scene::new(vec![unit_box()], Csg::leaf(1)).is_err(),
        "Scene::new refuses a tree naming primitive 1 of a scene of one"
    );
    assert_eq!(
        classify_point(&nan_sphere, Vec3::ZERO),
        Class::Outside,
        "classify_point(sphere of radius NaN, (0, 0, 0)): a primitive with a NaN parameter \
         contains nothing"
    );
}

/// Two overlapping unit-ish boxes along x: A = [0, 2]³, B = [1, 3] × [0, 2]².
fn two_boxes(tree: Csg) -> Scene {
    let a = Primitive::Cuboid {
        min: Vec3::ZERO,
        max: Vec3::splat(2.0),
    };
    let b = Primitive::Cuboid {
        min: Vec3::new(1.0, 0.0, 0.0),
        max: Vec3::new(3.0, 2.0, 2.0),
    };
    Scene::new(vec![a, b], tree).expect("valid")
}

#[testkit::test]
fn the_three_rules_on_two_boxes() {
    //   x:  0 ─── 1 ─── 2 ─── 3
    //       [ A         ]
    //             [ B         ]
    let at = |x: f32| Vec3::new(x, 1.0, 1.0);
    let (a, b) = (Csg::leaf(0), Csg::leaf(1));
    let union = two_boxes(Csg::union(a.clone(), b.clone()));
    let inter = two_boxes(Csg::intersection(a.clone(), b.clone()));
    let diff = two_boxes(Csg::difference(a, b));
    for (x, u, i, d) in [
        (0.5, true, false, true),
        (1.5, true, true, false),
        (2.5, true, false, false),
        (3.5, false, false, false),
        // On B's face x = 1: in B, so not in A − B (no regularization).
        (1.0, true, true, false),
        // On A's face x = 2: in A and in B.
        (2.0, true, true, false),
        // On A's face x = 0: in A, not in B.
        (0.0, true, false, true),
    ] {
        let p = at(x);
        assert_eq!(
            contains(&union, p),
            u,
            "contains(A ∪ B, {p}), A = [0, 2]³, B = [1, 3] × [0, 2]²: P ∈ X ∪ Y ⟺ P ∈ X ∨ P ∈ Y \
             (On counts as ∈)"
        );
        assert_eq!(
            contains(&inter, p),
            i,
            "contains(A ∩ B, {p}), A = [0, 2]³, B = [1, 3] × [0, 2]²: P ∈ X ∩ Y ⟺ P ∈ X ∧ P ∈ Y \
             (On counts as ∈)"
        );
        assert_eq!(
            contains(&diff, p),
            d,
            "contains(A − B, {p}), A = [0, 2]³, B = [1, 3] × [0, 2]²: P ∈ X − Y ⟺ P ∈ X ∧ P ∉ Y, \
             On counts as ∈ (not regularized: a point on B's face is not in A − B)"
        );
    }
}

#[testkit::test]
fn slice_through_the_example_at_z_zero() {
    // (cube ∩ sphere) − three cylinders, cut by the plane z = 0 and sampled
    // on a 25 × 25 grid over [−1.5, 1.5]² (step 1/8): the square [−1, 1]²
    // cut into four pieces by the slots |y| ≤ 0.55 (x cylinder) and
    // |x| ≤ 0.55 (y cylinder) — the z cylinder's hole lies inside both —
    // with the outer corners rounded off by the sphere (√2 > 1.32).
    let scene = common::example_scene();
    const N: i32 = 25;
    let mut canvas = Canvas::new(N as u32, N as u32);
    for y in 0..N {
        for x in 0..N {
            let p = Vec3::new(
                -1.5 + 3.0 * x as f32 / (N - 1) as f32,
                -1.5 + 3.0 * y as f32 / (N - 1) as f32,
                0.0,
            );
            if contains(&scene, p) {
                canvas.set(Pixel::new(x, y), Rgba::WHITE);
            }
        }
    }
    testkit::assert_raster_snapshot!("example_slice_z0", canvas);
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn primitive_classes_match_the_definition(prim in primitive(), p in point()) {
        let class = classify_point(&prim, p);
        prop_assert_eq!(class != Class::Outside, in_primitive(&prim, p), "classify_point({:?}, {}) = {:?}: a point of the closed primitive is Inside or On, any other Outside (left: yours in, right: by the definition)", prim, p, class);
    }

    #[testkit::test]
    fn points_on_a_sphere_along_the_axes_are_on(
        c in point(), r in 1u8..8, axis in 0usize..3, sign in prop::bool::ANY
    ) {
        // c ± r·e with integer r: exact in f32 when c's coordinates are small.
        let c = c.round();
        let r = f32::from(r);
        let e = [Vec3::X, Vec3::Y, Vec3::Z][axis] * if sign { 1.0 } else { -1.0 };
        let s = Primitive::Sphere { centre: c, radius: r };
        prop_assert_eq!(classify_point(&s, c + r * e), Class::On, "classify_point(sphere at {} of radius {}, {}): the point r along an axis is exactly on it, |p − c|² = r²", c, r, c + r * e);
        prop_assert_eq!(classify_point(&s, c + 0.5 * r * e), Class::Inside, "classify_point(sphere at {} of radius {}, {}): r/2 from the centre is Inside", c, r, c + 0.5 * r * e);
        prop_assert_eq!(classify_point(&s, c + 1.5 * r * e), Class::Outside, "classify_point(sphere at {} of radius {}, {}): 1.5·r from the centre is Outside", c, r, c + 1.5 * r * e);
    }

    #[testkit::test]
    fn tree_membership_matches_the_rules(
        primitives in prop::collection::vec(primitive(), 4),
        tree in tree(4, 7),
        points in prop::collection::vec(point(), 16),
    ) {
        let scene = Scene::new(primitives.clone(), tree.clone()).expect("valid");
        for p in points {
            prop_assert_eq!(contains(&scene, p), in_tree(&tree, &primitives, p), "contains({}, {}) (left: yours, right: by ∪ as ∨, ∩ as ∧, X − Y as P ∈ X ∧ P ∉ Y, On counts as ∈)", tree, p);
        }
    }
}
