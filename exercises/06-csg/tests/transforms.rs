//! Task 6: affine transformations at the nodes of a CSG tree.

mod common;

use canvas::Canvas;
use common::{
    affine, affine_text, in_primitive, node_text, point, primitive, shade_by_depth, tree,
    turned_camera, turned_scene, with_transforms,
};
use csg::Vec3;
use csg::csg::Csg;
use csg::primitive::{Primitive, Ray, RayInterval};
use csg::raster::{Camera, Framebuffer};
use csg::raycast::intervals_by;
use csg::transforms::{Instance, Node, TransformError, contains, flatten, instance_interval};
use glam::Affine3A;
use proptest::prelude::*;

fn unit_sphere() -> Primitive {
    Primitive::Sphere {
        centre: Vec3::ZERO,
        radius: 1.0,
    }
}

/// Whether `p` lies in the solid of `node`, by definition: at a transform
/// `M`, the points `M·q` of the child's solid, found by asking the child
/// about `M⁻¹·p`.
fn in_node(node: &Node, primitives: &[Primitive], p: Vec3) -> bool {
    match node {
        Node::Leaf(i) => in_primitive(&primitives[*i], p),
        Node::Union(x, y) => in_node(x, primitives, p) || in_node(y, primitives, p),
        Node::Intersection(x, y) => in_node(x, primitives, p) && in_node(y, primitives, p),
        Node::Difference(x, y) => in_node(x, primitives, p) && !in_node(y, primitives, p),
        Node::Transform(m, x) => in_node(x, primitives, m.inverse().transform_point3(p)),
    }
}

/// Whether `p` lies in the solid of a flattened tree over `instances`.
fn in_instances(tree: &Csg, instances: &[Instance], primitives: &[Primitive], p: Vec3) -> bool {
    match tree {
        Csg::Primitive(i) => {
            let instance = instances[*i];
            in_primitive(
                &primitives[instance.primitive],
                instance.to_world.inverse().transform_point3(p),
            )
        }
        Csg::Union(x, y) => {
            in_instances(x, instances, primitives, p) || in_instances(y, instances, primitives, p)
        }
        Csg::Intersection(x, y) => {
            in_instances(x, instances, primitives, p) && in_instances(y, instances, primitives, p)
        }
        Csg::Difference(x, y) => {
            in_instances(x, instances, primitives, p) && !in_instances(y, instances, primitives, p)
        }
    }
}

fn close(a: Vec3, b: Vec3) -> bool {
    (a - b).abs().max_element() <= 1e-4
}

#[testkit::test]
fn flatten_composes_the_transforms_outermost_last() {
    let a = Affine3A::from_translation(Vec3::new(5.0, 0.0, 0.0));
    let b = Affine3A::from_scale(Vec3::splat(2.0));
    let (instances, tree) = flatten(&Node::transform(a, Node::transform(b, Node::leaf(0))));
    assert_eq!(tree, Csg::leaf(0), "one leaf, one instance");
    assert_eq!(
        instances.len(),
        1,
        "flatten(Transform(translate 5, Transform(scale 2, leaf 0))): one leaf, one instance"
    );
    let moved = instances[0].to_world.transform_point3(Vec3::X);
    assert!(
        close(moved, Vec3::new(7.0, 0.0, 0.0)),
        "in Transform(translate 5, Transform(scale 2, leaf)) the inner scale moves the \
         primitive first: (1, 0, 0) → (2, 0, 0) → (7, 0, 0), yours gives {moved} \
         (the product is outer · inner)"
    );
    assert_eq!(
        instances[0].primitive, 0,
        "the instance of leaf 0 names primitive 0"
    );
}

#[testkit::test]
fn flatten_numbers_the_leaves_left_to_right_and_keeps_the_operations() {
    let t = Affine3A::from_translation(Vec3::new(0.0, 3.0, 0.0));
    let r = Affine3A::from_rotation_z(std::f32::consts::FRAC_PI_2);
    let node = Node::difference(
        Node::transform(t, Node::union(Node::leaf(1), Node::leaf(0))),
        Node::intersection(Node::transform(r, Node::leaf(1)), Node::leaf(2)),
    );
    let (instances, tree) = flatten(&node);
    assert_eq!(
        tree,
        Csg::difference(
            Csg::union(Csg::leaf(0), Csg::leaf(1)),
            Csg::intersection(Csg::leaf(2), Csg::leaf(3))
        ),
        "the tree keeps its operations; its leaves name the instances 0, 1, 2, … \
         in the order the leaves appear"
    );
    let primitives: Vec<usize> = instances.iter().map(|i| i.primitive).collect();
    assert_eq!(
        primitives,
        [1, 0, 1, 2],
        "a primitive under two transforms is two instances"
    );
    let expected = [t, t, r, Affine3A::IDENTITY];
    for (k, (instance, m)) in instances.iter().zip(expected).enumerate() {
        assert!(
            instance.to_world.abs_diff_eq(m, 1e-6),
            "instance {k}: to_world is the product of the maps on its leaf's path, outermost \
             first: expected {}, yours {}",
            affine_text(&m),
            affine_text(&instance.to_world)
        );
    }
}

fn scene_with_transforms() -> impl Strategy<Value = (Vec<Primitive>, Node)> {
    (
        prop::collection::vec(primitive(), 1..=4),
        prop::collection::vec(prop::option::of(affine(0.5..2.0, 1.5)), 16),
    )
        .prop_flat_map(|(primitives, maps)| {
            let n = primitives.len();
            (Just(primitives), tree(n, 6), Just(maps))
        })
        .prop_map(|(primitives, tree, maps)| {
            let node = with_transforms(&tree, &mut maps.into_iter().cycle());
            (primitives, node)
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..testkit::proptest_config() })]

    /// The flattened tree over its instances is the same solid, and
    /// `contains` agrees with the definition.
    #[testkit::test]
    fn flattening_and_contains_keep_the_solid(
        (primitives, node) in scene_with_transforms(),
        points in prop::collection::vec(point(), 40),
    ) {
        let (instances, tree) = flatten(&node);
        for p in points {
            let truth = in_node(&node, &primitives, p);
            prop_assert_eq!(
                in_instances(&tree, &instances, &primitives, p),
                truth,
                "flatten({}) = {} over its instances is not the same solid at {} (left: the flattened tree, right: the definition, P ∈ M(X) ⟺ M⁻¹·P ∈ X)", node_text(&node), tree, p
            );
            let yours = contains(&node, p, &|i, q| in_primitive(&primitives[i], q));
            prop_assert_eq!(yours, truth, "contains({}, {}): the rules of task 1, and P ∈ M(X) ⟺ M⁻¹·P ∈ X at a transform (left: yours, right: the definition)", node_text(&node), p);
        }
    }
}

#[testkit::test]
fn contains_asks_the_child_about_the_inverse_point() {
    let primitives = [unit_sphere()];
    let inside = |i: usize, q: Vec3| in_primitive(&primitives[i], q);
    let moved = Node::transform(
        Affine3A::from_translation(Vec3::new(10.0, 0.0, 0.0)),
        Node::leaf(0),
    );
    assert!(
        contains(&moved, Vec3::new(10.0, 0.5, 0.0), &inside),
        "the unit sphere moved to (10, 0, 0) holds (10, 0.5, 0): ask the sphere about M⁻¹·p"
    );
    assert!(
        !contains(&moved, Vec3::ZERO, &inside),
        "the unit sphere moved to (10, 0, 0) no longer holds the origin"
    );
    let stretched = Node::transform(
        Affine3A::from_scale(Vec3::new(3.0, 1.0, 1.0)),
        Node::leaf(0),
    );
    let stretch = "the unit sphere stretched by 3 along x, (x/3)² + y² + z² ≤ 1,";
    assert!(
        contains(&stretched, Vec3::new(2.5, 0.0, 0.0), &inside),
        "{stretch} holds (2.5, 0, 0): ask the sphere about M⁻¹·p = (2.5/3, 0, 0)"
    );
    assert!(
        !contains(&stretched, Vec3::new(0.0, 1.5, 0.0), &inside),
        "{stretch} does not hold (0, 1.5, 0): M⁻¹·p = (0, 1.5, 0) is outside the sphere"
    );
    // The ellipsoid minus the sphere: the ends of the ellipsoid remain.
    let cut = Node::difference(stretched, Node::leaf(0));
    assert!(
        contains(&cut, Vec3::new(2.0, 0.0, 0.0), &inside),
        "the stretched sphere minus the unit sphere holds (2, 0, 0), an end of the ellipsoid"
    );
    assert!(
        !contains(&cut, Vec3::new(0.5, 0.0, 0.0), &inside),
        "the stretched sphere minus the unit sphere does not hold (0.5, 0, 0): the sphere cuts \
         it away (P ∈ X − Y ⟺ P ∈ X ∧ P ∉ Y)"
    );
    // What has no inverse never reaches `contains`: `check` refuses it.
    let flat = Node::transform(
        Affine3A::from_scale(Vec3::new(1.0, 0.0, 1.0)),
        Node::leaf(0),
    );
    assert_eq!(
        flat.check(1),
        Err(TransformError::Singular),
        "Node::check refuses a map without an inverse (scale 0 along y)"
    );
    let nan = Node::transform(Affine3A::from_translation(Vec3::NAN), Node::leaf(0));
    assert_eq!(
        nan.check(1),
        Err(TransformError::NotFinite),
        "Node::check refuses a map with a NaN"
    );
    assert_eq!(
        Node::leaf(3).check(1),
        Err(TransformError::UnknownPrimitive(3)),
        "Node::check refuses leaf 3 in a scene of one primitive"
    );
    assert_eq!(
        cut.check(1),
        Ok(()),
        "Node::check accepts the stretched sphere minus the sphere"
    );
}

fn ray(origin: Vec3, direction: Vec3) -> Ray {
    Ray {
        origin,
        direction: direction.normalize(),
    }
}

fn close_spans(a: Option<RayInterval>, b: Option<RayInterval>) -> bool {
    match (a, b) {
        (Some(a), Some(b)) => (a.near - b.near).abs() <= 1e-4 && (a.far - b.far).abs() <= 1e-4,
        (None, None) => true,
        _ => false,
    }
}

#[testkit::test]
fn a_moved_sphere_is_met_where_the_moved_ray_meets_the_sphere() {
    let to_world = Affine3A::from_translation(Vec3::new(10.0, 0.0, 0.0));
    let r = ray(Vec3::new(10.0, 0.0, 5.0), Vec3::NEG_Z);
    let span = instance_interval(&unit_sphere(), to_world, &r);
    assert!(
        close_spans(
            span,
            Some(RayInterval {
                near: 4.0,
                far: 6.0
            })
        ),
        "a ray from (10, 0, 5) along −z meets the unit sphere moved to (10, 0, 0) \
         from depth 4 to 6, yours: {span:?}"
    );
    let miss = instance_interval(
        &unit_sphere(),
        to_world,
        &ray(Vec3::new(0.0, 0.0, 5.0), Vec3::NEG_Z),
    );
    assert_eq!(
        miss, None,
        "the ray through the origin misses the moved sphere"
    );
}

/// The instrument of the rescaled depth: scaled by 2, the unit sphere is
/// the sphere of radius 2, met at the same depths. Without dividing by
/// `|M⁻¹·d|` the depths come out halved, and with a direction that is not
/// a unit vector the sphere's formula is wrong.
#[testkit::test]
fn a_scaled_instance_is_met_at_world_depths() {
    let to_world = Affine3A::from_scale(Vec3::splat(2.0));
    let big = Primitive::Sphere {
        centre: Vec3::ZERO,
        radius: 2.0,
    };
    for (origin, direction) in [
        (Vec3::new(0.0, 0.0, 6.0), Vec3::NEG_Z),
        (Vec3::new(0.7, -0.4, 6.0), Vec3::new(0.1, 0.05, -1.0)),
        (Vec3::new(-5.0, 1.0, 0.5), Vec3::new(1.0, -0.2, 0.0)),
    ] {
        let r = ray(origin, direction);
        let yours = instance_interval(&unit_sphere(), to_world, &r);
        let expected = big.interval(&r);
        assert!(
            expected.is_some() && close_spans(yours, expected),
            "ray from {origin} along {direction}: the unit sphere scaled by 2 is met at \
             {expected:?} (the radius-2 sphere), yours: {yours:?}"
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..testkit::proptest_config() })]

    /// A quarter turn about z of a box is the box with x and y extents
    /// exchanged.
    #[testkit::test]
    fn a_turned_box_is_the_box_with_its_extents_exchanged(
        origin in (-4.0f32..4.0, -4.0f32..4.0, -4.0f32..4.0),
        direction in (-1.0f32..1.0, -1.0f32..1.0, -1.0f32..1.0),
    ) {
        let Some(direction) = Vec3::new(direction.0, direction.1, direction.2).try_normalize() else {
            return Ok(());
        };
        let r = Ray { origin: Vec3::new(origin.0, origin.1, origin.2), direction };
        let local = Primitive::Cuboid { min: Vec3::new(-1.0, -2.0, -3.0), max: Vec3::new(1.0, 2.0, 3.0) };
        let turned = Primitive::Cuboid { min: Vec3::new(-2.0, -1.0, -3.0), max: Vec3::new(2.0, 1.0, 3.0) };
        let quarter = Affine3A::from_rotation_z(std::f32::consts::FRAC_PI_2);
        let (yours, expected) = (instance_interval(&local, quarter, &r), turned.interval(&r));
        // Grazing rays may round either way.
        let grazing = expected.is_some_and(|s| s.far - s.near < 1e-3);
        prop_assert!(grazing || close_spans(yours, expected), "instance_interval(box [−1, 1] × [−2, 2] × [−3, 3], a quarter turn about z, ray from {} along {}): the turned box is [−2, 2] × [−1, 1] × [−3, 3], met at {:?}; yours {:?} (to 1e-4)", r.origin, r.direction, expected, yours);
    }

    /// Stretched by 3 along x, the unit sphere is the ellipsoid
    /// `(x/3)² + y² + z² ≤ 1`: the ends of the interval lie on it, its
    /// middle inside.
    #[testkit::test]
    fn a_stretched_sphere_is_met_on_the_ellipsoid(
        origin in (-2.0f32..2.0, -0.6f32..0.6, 4.0f32..6.0),
        aim in (-2.0f32..2.0, -0.6f32..0.6),
    ) {
        let stretch = Affine3A::from_scale(Vec3::new(3.0, 1.0, 1.0));
        let start = Vec3::new(origin.0, origin.1, origin.2);
        let r = ray(start, Vec3::new(aim.0, aim.1, 0.0) - start);
        let ellipsoid = |p: Vec3| (p.x / 3.0).powi(2) + p.y * p.y + p.z * p.z;
        match instance_interval(&unit_sphere(), stretch, &r) {
            Some(span) => {
                prop_assert!((ellipsoid(r.at(span.near)) - 1.0).abs() < 1e-3, "the unit sphere stretched by 3 along x, ray from {} along {}: the entry at depth {}, {}, lies on the ellipsoid (x/3)² + y² + z² = 1, yours gives {}", r.origin, r.direction, span.near, r.at(span.near), ellipsoid(r.at(span.near)));
                prop_assert!((ellipsoid(r.at(span.far)) - 1.0).abs() < 1e-3, "the unit sphere stretched by 3 along x, ray from {} along {}: the exit at depth {}, {}, lies on the ellipsoid (x/3)² + y² + z² = 1, yours gives {}", r.origin, r.direction, span.far, r.at(span.far), ellipsoid(r.at(span.far)));
                let middle = r.at(0.5 * (span.near + span.far));
                prop_assert!(ellipsoid(middle) < 1.0, "the unit sphere stretched by 3 along x, ray from {} along {}: the middle {} of yours {:?} lies inside the ellipsoid, (x/3)² + y² + z² < 1, yours gives {}", r.origin, r.direction, middle, span, ellipsoid(middle));
            }
            None => prop_assert!(false, "the unit sphere stretched by 3 along x: the ray from {} along {} aims at a point inside the ellipsoid and must meet it, yours None", r.origin, r.direction),
        }
    }
}

/// Ray casts `node` with `flatten` and `instance_interval` and shades the
/// first boundary at each pixel: a colour per instance, darker with depth,
/// back faces (the walls of a cut) darker still.
fn picture(primitives: &[Primitive], node: &Node, camera: Camera) -> Canvas {
    let (instances, tree) = flatten(node);
    let mut frame = Framebuffer::new(camera);
    for p in camera.pixels() {
        let r = camera.ray(p);
        let span = |i: usize| {
            let instance = instances.get(i)?;
            instance_interval(primitives.get(instance.primitive)?, instance.to_world, &r)
        };
        if let Some(b) = intervals_by(&tree, &span).first()
            && b.t.is_finite()
        {
            frame.write_less(p, b.t, b.surface);
        }
    }
    shade_by_depth(&frame)
}

#[testkit::test]
fn the_turned_scene_matches_the_reference_image() {
    let (primitives, node) = turned_scene();
    let camera = turned_camera();
    testkit::image::assert_image_matches(
        "transforms_turned_scene",
        &picture(&primitives, &node, camera),
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/images/transforms_turned_scene.png"
        ),
        testkit::image::Tolerance {
            channel: 2.0 / 255.0,
            mismatched_fraction: 0.005,
        },
    );
}
