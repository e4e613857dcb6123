//! Task 5: layered Goldfeather — depth complexity, layer extraction, one
//! parity test per layer and literal.

mod common;

use common::{
    assert_frames_equal, dnf_model, example_camera, example_scene, moved_instances, moved_model,
    scene, small_camera, transformed_scene, truth, truth_of, turned_camera, turned_scene,
};
use csg::Vec3;
use csg::csg::{Csg, Literal, Model, Product, Scene};
use csg::layered::{depth_complexity, render};
use csg::primitive::Primitive;
use csg::raster::{Camera, Framebuffer};
use proptest::prelude::*;

fn sphere(x: f32, y: f32, z: f32, radius: f32) -> Primitive {
    Primitive::Sphere {
        centre: Vec3::new(x, y, z),
        radius,
    }
}

/// A plate with `holes` spherical dents in a row along its front face:
/// `plate − S₁ − S₂ − …`. Seen from the front, each pixel is covered by
/// the plate's front face and at most one sphere's back face: depth
/// complexity 2 however many holes there are.
fn drilled_plate(holes: usize) -> Scene {
    let width = holes.max(1) as f32;
    let mut primitives = vec![Primitive::Cuboid {
        min: Vec3::new(-width, -0.6, -0.5),
        max: Vec3::new(width, 0.6, 0.5),
    }];
    let mut tree = Csg::leaf(0);
    for k in 0..holes {
        let x = -width + 1.0 + 2.0 * k as f32;
        primitives.push(sphere(x, 0.0, 0.6, 0.45));
        tree = Csg::difference(tree, Csg::leaf(k + 1));
    }
    Scene::new(primitives, tree).expect("valid")
}

/// `n` balls on a line along the view direction, all overlapping: their
/// intersection needs `n` layers.
fn skewered_balls(n: usize) -> Scene {
    let primitives: Vec<Primitive> = (0..n)
        .map(|k| sphere(0.05 * k as f32, 0.0, -0.1 * k as f32, 1.0))
        .collect();
    let tree = (1..n).fold(Csg::leaf(0), |t, k| Csg::intersection(t, Csg::leaf(k)));
    Scene::new(primitives, tree).expect("valid")
}

/// Looks along −z at 4 pixels per unit, `2·units + 2` units wide and 4
/// high: a plate of `units` holes fits, and so do the balls with 1.
fn front_camera(width_units: usize) -> Camera {
    let w = (8 * width_units.max(1) + 8) as u32;
    Camera::new(w, 16, Vec3::ZERO, 0.0, 0.0, 4.0).expect("valid")
}

#[testkit::test]
fn depth_complexity_counts_entry_faces_per_pixel() {
    let scene = example_scene();
    let camera = example_camera();
    let model = dnf_model(&scene);
    let product = &model.products()[0];
    let mut buffer = Framebuffer::new(camera);
    let k = depth_complexity(&model, product, &mut buffer);
    // As the seed's Abbildung 11 ("Bestimmung der Tiefenkomplexität"; its
    // Abbildung 10 shows depth complexity on another scene): each pixel's
    // count as a grey level, 0 black and k white; first, so that a failing
    // check below still leaves it.
    let mut counts = canvas::Canvas::new(camera.width(), camera.height());
    for p in camera.pixels() {
        let count = f32::from(buffer.stencil(p).unwrap_or(0));
        counts.set(p, canvas::Rgba::grey(count / f32::from(k.max(1))));
    }
    let picture = testkit::image::check_image(
        "layered_depth_complexity",
        &counts,
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/images/layered_depth_complexity.png"
        ),
        testkit::image::Tolerance::EXACT,
    );
    assert_eq!(
        k,
        common::depth_complexity(&model, product, &camera),
        "depth_complexity returns the largest count of entry faces over a pixel"
    );
    for p in camera.pixels() {
        let ray = camera.ray(p);
        let count = product
            .literals
            .iter()
            .filter(|l| model.primitives()[l.primitive].interval(&ray).is_some())
            .count();
        assert_eq!(
            buffer.stencil(p),
            Some(count as u8),
            "pixel {p:?}: the stencil counts the entry faces over it, one per literal whose \
             primitive the ray crosses (front face of a primitive, back face of a complement; \
             depth Always, stencil op Increment); both faces would count twice"
        );
        assert_eq!(
            buffer.surface(p),
            None,
            "pixel {p:?}: counting draws with colour writes off"
        );
    }
    picture.assert_matches();
}

#[testkit::test]
fn a_drilled_plate_needs_two_layers_however_many_holes() {
    for holes in [1, 3, 6] {
        let scene = drilled_plate(holes);
        let camera = front_camera(holes);
        let model = dnf_model(&scene);
        let mut buffer = Framebuffer::new(camera);
        assert_eq!(
            depth_complexity(&model, &model.products()[0], &mut buffer),
            2,
            "a plate with {holes} holes: a pixel is covered by the plate's front face and at \
             most one dent's back face (one entry face per literal), so k = 2"
        );
        let mut frame = Framebuffer::new(camera);
        let stats = render(&model, &mut frame);
        let m = holes as u64 + 1;
        assert_eq!(
            stats.layers, 2,
            "a plate with {holes} holes has depth complexity k = 2: extract k layers \
             (Stats::layers), however many holes"
        );
        assert_eq!(
            stats.parity_tests,
            2 * m,
            "{holes} holes: 2 layers · {m} literals"
        );
        assert_frames_equal(
            &frame,
            &truth(&scene, camera),
            &format!("a plate with {holes} dent(s)"),
        );
    }
}

#[testkit::test]
fn skewered_balls_need_one_layer_per_ball() {
    let scene = skewered_balls(5);
    let camera = front_camera(1);
    let model = dnf_model(&scene);
    let mut frame = Framebuffer::new(camera);
    let stats = render(&model, &mut frame);
    assert_eq!(
        (stats.layers, stats.parity_tests),
        (5, 25),
        "five balls on the view direction: depth complexity 5, so 5 layers, each \
         parity-tested against all 5 literals (k·m = 25)"
    );
    assert_frames_equal(&frame, &truth(&scene, camera), "skewered balls");
}

#[testkit::test]
fn a_product_of_one_primitive_is_one_layer_with_one_parity_test() {
    // The layer holds the primitive's own front face, tested against the
    // primitive itself: it must count as inside (the seed's §6.4).
    let camera = small_camera();
    let scene = Scene::new(vec![sphere(0.2, 0.1, 0.0, 1.3)], Csg::leaf(0)).expect("valid");
    let model = dnf_model(&scene);
    let mut frame = Framebuffer::new(camera);
    let stats = render(&model, &mut frame);
    assert_eq!(
        (stats.layers, stats.parity_tests),
        (1, 1),
        "one sphere: 1 layer, tested once against the sphere itself (k·m = 1)"
    );
    assert_frames_equal(
        &frame,
        &truth(&scene, camera),
        "one sphere (its front fragment must see its own front face at equal depth: \
         parity tests with LessEqual, seed §6.4)",
    );
}

#[testkit::test]
fn parity_tests_of_plain_and_layered_goldfeather() {
    // The sheet's table: plain Goldfeather needs m·(m − 1) parity tests per
    // product of m literals; layered needs k·m for depth complexity k.
    println!("| scene | literals m | plain m·(m−1) | layers k | layered k·m |");
    println!("|---|---:|---:|---:|---:|");
    for (name, scenes, camera_units) in [
        ("drilled plate", [1, 3, 7, 15, 31].map(drilled_plate), 32),
        ("skewered balls", [2, 4, 8, 16, 32].map(skewered_balls), 1),
    ] {
        let camera = front_camera(camera_units);
        for scene in scenes {
            let n = scene.primitives().len();
            let model = dnf_model(&scene);
            let mut frame = Framebuffer::new(camera);
            let stats = render(&model, &mut frame);
            let k = u64::from(common::depth_complexity(
                &model,
                &model.products()[0],
                &camera,
            ));
            let m = n as u64;
            assert_eq!(
                (stats.layers, stats.parity_tests),
                (k, k * m),
                "{name}, {n} primitives: depth complexity k = {k} layers, k·m = {} parity \
                 tests",
                k * m
            );
            println!("| {name} | {m} | {} | {k} | {} |", m * (m - 1), k * m);
        }
    }
}

#[testkit::test]
fn the_seeds_example_matches_the_ray_caster_and_the_reference_image() {
    let scene = example_scene();
    let camera = example_camera();
    let model = dnf_model(&scene);
    let mut frame = Framebuffer::new(camera);
    let stats = render(&model, &mut frame);
    let truth = truth(&scene, camera);
    // The picture first, so that a failing check below still leaves it.
    let picture = testkit::image::check_image(
        "layered_example",
        &csg::shade::side_by_side(&[
            csg::shade::shade(&frame, scene.primitives()),
            csg::shade::shade(&truth, scene.primitives()),
        ]),
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/images/layered_example.png"
        ),
        testkit::image::Tolerance {
            channel: 2.0 / 255.0,
            mismatched_fraction: 0.002,
        },
    );
    let k = u64::from(common::depth_complexity(
        &model,
        &model.products()[0],
        &camera,
    ));
    assert_eq!(
        (stats.layers, stats.parity_tests),
        (k, 5 * k),
        "the example's product of 5 literals: k = {k} layers, k·5 parity tests"
    );
    assert_frames_equal(&frame, &truth, "the example");
    picture.assert_matches();
}

/// The seed's Abbildungen 12 and 13: the layers extracted from the
/// example's product (top row, by definition: at each pixel the n-th entry
/// face drawn there) and what your `render` merges of each (bottom row):
/// the layer's fragments that lie inside every other literal.
#[testkit::test]
fn each_layer_merges_its_visible_fragments_into_the_frame() {
    let scene = example_scene();
    let camera = example_camera();
    let model = dnf_model(&scene);
    let product = &model.products()[0];
    let k = usize::from(common::depth_complexity(&model, product, &camera));
    let mut frame = Framebuffer::recording_merges(camera);
    render(&model, &mut frame);
    let merges = frame.merges();
    let shade = |f: &Framebuffer| csg::shade::shade(f, scene.primitives());
    // Every layer by its definition and every merge of yours, pictured
    // first, so that a failing check below still leaves the picture.
    let (mut layers, mut fragments, mut visible) = (Vec::new(), Vec::new(), Vec::new());
    for (n, merge) in merges.iter().enumerate() {
        let (layer, inside) = common::pass_fragments(&model, product, camera, |ray| {
            common::nth_literal_crossed(&model, product, ray, n)
        });
        layers.push(shade(&layer));
        fragments.push(shade(merge));
        visible.push(inside);
    }
    let picture = testkit::image::check_image(
        "layered_layers",
        &common::rows(&[
            csg::shade::side_by_side(&layers),
            csg::shade::side_by_side(&fragments),
        ]),
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/images/layered_layers.png"
        ),
        testkit::image::Tolerance {
            channel: 2.0 / 255.0,
            mismatched_fraction: 0.002,
        },
    );
    assert_eq!(
        merges.len(),
        k,
        "one second buffer per layer (k = {k}), merged with Framebuffer::merge_less after its \
         parity tests"
    );
    for (n, (merge, visible)) in merges.iter().zip(&visible).enumerate() {
        assert_frames_equal(
            merge,
            visible,
            &format!(
                "layer {}: at each pixel the entry face drawn there as number {}, where it lies \
                 inside every other literal",
                n + 1,
                n + 1
            ),
        );
    }
    picture.assert_matches();
}

#[testkit::test]
fn products_are_rendered_one_after_the_other() {
    // Two separate products: the union of a dented and a plain ball.
    let camera = small_camera();
    let primitives = vec![
        sphere(-0.8, 0.0, 0.0, 1.0),
        sphere(-0.8, 0.0, 0.9, 0.5),
        sphere(1.0, 0.3, -0.4, 0.9),
    ];
    let model = Model::new(
        primitives.clone(),
        vec![
            Product::new(vec![Literal::positive(0), Literal::complement(1)]),
            Product::new(vec![Literal::positive(2)]),
        ],
    )
    .expect("valid");
    let scene = Scene::new(
        primitives,
        Csg::union(Csg::difference(Csg::leaf(0), Csg::leaf(1)), Csg::leaf(2)),
    )
    .expect("valid");
    let mut frame = Framebuffer::new(camera);
    render(&model, &mut frame);
    assert_frames_equal(&frame, &truth(&scene, camera), "two products");
}

/// Seed §2.1: the turned scene of task 6, flattened to moved primitives
/// (the tests' own, not your task 6): the products cube ∩ ¬ellipsoid
/// (depth complexity 2) and the column (1).
#[testkit::test]
fn a_transformed_tree_matches_the_ray_caster() {
    let (primitives, node) = turned_scene();
    let camera = turned_camera();
    let (instances, tree) = moved_instances(&node, &primitives);
    let model = moved_model(&instances, &tree);
    let mut frame = Framebuffer::new(camera);
    let stats = render(&model, &mut frame);
    assert_eq!(
        (stats.layers, stats.parity_tests),
        (3, 5),
        "cube ∩ ¬ellipsoid: 2 layers · 2 literals, the column: 1 layer · 1 literal"
    );
    assert_frames_equal(
        &frame,
        &truth_of(&tree, &instances, camera),
        "the turned scene (primitives moved by the maps at the nodes)",
    );
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..testkit::proptest_config() })]

    /// Random trees with random maps at random nodes, with the exact layer
    /// and test counts.
    #[testkit::test]
    fn random_transformed_trees_match_the_ray_caster((primitives, node) in transformed_scene(5)) {
        let camera = small_camera();
        let (instances, tree) = moved_instances(&node, &primitives);
        let model = moved_model(&instances, &tree);
        let mut frame = Framebuffer::new(camera);
        let stats = render(&model, &mut frame);
        let mut expected_layers = 0;
        let mut expected_tests = 0;
        for product in model.products() {
            let k = u64::from(common::depth_complexity(&model, product, &camera));
            expected_layers += k;
            expected_tests += k * product.literals.len() as u64;
        }
        prop_assert_eq!(stats.layers, expected_layers, "{}: each product needs k layers, k its depth complexity (the most entry faces over one pixel); left: yours, right: the sum over the products {}", tree, common::sum_text(model.products()));
        prop_assert_eq!(stats.parity_tests, expected_tests, "{}: each layer is parity-tested against every literal of its product, itself included, k·m per product (left: yours, right: the sum over {})", tree, common::sum_text(model.products()));
        assert_frames_equal(&frame, &truth_of(&tree, &instances, camera), &format!("{tree}, each leaf a primitive moved by the maps above it"));
    }

    #[testkit::test]
    fn random_scenes_match_the_ray_caster(scene in scene(5)) {
        let camera = small_camera();
        let model = dnf_model(&scene);
        let mut frame = Framebuffer::new(camera);
        let stats = render(&model, &mut frame);
        let mut expected_layers = 0;
        let mut expected_tests = 0;
        for product in model.products() {
            let k = u64::from(common::depth_complexity(&model, product, &camera));
            expected_layers += k;
            expected_tests += k * product.literals.len() as u64;
        }
        prop_assert_eq!(stats.layers, expected_layers, "{}: each product needs k layers, k its depth complexity (the most entry faces over one pixel); left: yours, right: the sum over the products {}", scene.tree(), common::sum_text(model.products()));
        prop_assert_eq!(stats.parity_tests, expected_tests, "{}: each layer is parity-tested against every literal of its product, itself included, k·m per product (left: yours, right: the sum over {})", scene.tree(), common::sum_text(model.products()));
        assert_frames_equal(&frame, &truth(&scene, camera), &scene.tree().to_string());
    }
}
