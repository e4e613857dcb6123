//! Task 4: Goldfeather rendering with the parity test.

mod common;

use canvas::Pixel;
use common::{
    assert_frames_equal, dnf_model, example_camera, example_scene, moved_instances, moved_model,
    scene, shade_by_depth, small_camera, transformed_scene, truth, truth_of, turned_camera,
    turned_scene,
};
use csg::Vec3;
use csg::csg::{Csg, Literal, Model, Product, Scene};
use csg::goldfeather::render;
use csg::primitive::Primitive;
use csg::raster::{Camera, Face, Framebuffer, Surface};
use proptest::prelude::*;

/// Looks along −z: pixel (4, 4) of a 9 × 9 grid at 2 pixels per unit
/// looks down the z axis, depth t at z = −t.
fn straight_camera() -> Camera {
    Camera::new(9, 9, Vec3::ZERO, 0.0, 0.0, 2.0).expect("valid")
}

fn sphere(centre: Vec3, radius: f32) -> Primitive {
    Primitive::Sphere { centre, radius }
}

fn rendered(model: &Model, camera: Camera) -> (Framebuffer, u64) {
    let mut frame = Framebuffer::new(camera);
    let stats = render(model, &mut frame);
    (frame, stats.parity_tests)
}

#[testkit::test]
fn a_single_primitive_shows_its_front_face() {
    let camera = straight_camera();
    let ball = sphere(Vec3::ZERO, 1.6);
    let model =
        Model::new(vec![ball], vec![Product::new(vec![Literal::positive(0)])]).expect("valid");
    let (frame, tests) = rendered(&model, camera);
    assert_eq!(tests, 0, "nothing to test a single primitive against");
    for p in camera.pixels() {
        let expected = ball.interval(&camera.ray(p)).map(|s| {
            (
                s.near,
                Surface {
                    primitive: 0,
                    face: Face::Front,
                },
            )
        });
        let yours = frame
            .surface(p)
            .map(|s| (frame.depth(p).unwrap_or(f32::NAN), s));
        assert_eq!(
            yours, expected,
            "pixel {p:?}: a product of one primitive shows its front face (depth, surface) \
             wherever the ray hits it, drawn with DRAW (depth Less), and nothing elsewhere"
        );
    }
}

#[testkit::test]
fn a_dent_shows_the_back_face_of_the_subtracted_sphere() {
    //   viewer (t = −∞) ──▶  z decreasing
    //         B: z ∈ [1, 3]      A: z ∈ [−2, 2]
    //   along the axis, A − B = z ∈ [−2, 1): entered at z = 1, t = −1,
    //   through B's back face
    let camera = straight_camera();
    let a = sphere(Vec3::ZERO, 2.0);
    let b = sphere(Vec3::new(0.0, 0.0, 2.0), 1.0);
    let model = Model::new(
        vec![a, b],
        vec![Product::new(vec![
            Literal::positive(0),
            Literal::complement(1),
        ])],
    )
    .expect("valid");
    let (frame, tests) = rendered(&model, camera);
    assert_eq!(
        tests, 2,
        "A ∩ B̄: each literal's pass tests against the other one, 2 · 1 parity tests"
    );
    let centre = Pixel::new(4, 4);
    assert_eq!(
        (frame.surface(centre), frame.depth(centre)),
        (
            Some(Surface {
                primitive: 1,
                face: Face::Back
            }),
            Some(-1.0)
        ),
        "on the axis the dent's wall shows: B's back face at t = −1, kept by A's parity \
         test (inside A). Erase where the parity bit is clear for a positive literal and \
         where it is set for a complement (the seed's pseudo-code; its §4.4 prose swaps them)"
    );
    // 1.5 units right of the axis: outside B, on A's front at z = √(4 − 2.25).
    let side = Pixel::new(7, 4);
    assert_eq!(
        (frame.surface(side), frame.depth(side)),
        (
            Some(Surface {
                primitive: 0,
                face: Face::Front
            }),
            Some(-(4.0f32 - 2.25).sqrt())
        ),
        "beside the dent A's front face shows, kept by B̄'s parity test: no face of B in \
         front of it (bit clear), so for the complement B̄ it is not erased"
    );
}

#[testkit::test]
fn the_lens_of_two_spheres_shows_both_front_faces() {
    // The seed says Y ∩ X need not be drawn after X ∩ Y when Y is not a
    // complement; but the lens is bounded by both spheres' front faces.
    let camera = small_camera();
    let scene = Scene::new(
        vec![
            sphere(Vec3::new(-0.6, 0.0, 0.0), 1.5),
            sphere(Vec3::new(0.6, 0.0, 0.0), 1.5),
        ],
        Csg::intersection(Csg::leaf(0), Csg::leaf(1)),
    )
    .expect("valid");
    let (frame, _) = rendered(&dnf_model(&scene), camera);
    let shown = common::surfaces(&frame);
    for primitive in [0, 1] {
        assert!(
            shown.contains(&Surface {
                primitive,
                face: Face::Front
            }),
            "the lens X ∩ Y is bounded by both spheres' front faces, so sphere {primitive}'s \
             front face must show; yours shows {shown:?}. Every literal draws its own pass \
             (the seed's remark that Y ∩ X can be skipped is wrong)"
        );
    }
    assert_frames_equal(&frame, &truth(&scene, camera), "the lens");
}

#[testkit::test]
fn parity_tests_are_m_times_m_minus_one_per_product() {
    let primitives: Vec<Primitive> = (0..5)
        .map(|k| sphere(Vec3::new(k as f32 * 0.3, 0.0, 0.0), 1.0))
        .collect();
    let chain = |m: usize| {
        Product::new(
            (0..m)
                .map(|k| Literal {
                    primitive: k,
                    complement: k % 2 == 1,
                })
                .collect(),
        )
    };
    let model =
        Model::new(primitives, vec![chain(1), chain(2), chain(3), chain(5)]).expect("valid");
    let (_, tests) = rendered(&model, small_camera());
    // Products of 1, 2, 3 and 5 literals: 0 + 2 + 6 + 20.
    assert_eq!(
        tests, 28,
        "products of 1, 2, 3 and 5 literals: m·(m − 1) parity tests each, 0 + 2 + 6 + 20 \
         (each literal against every other, never against itself)"
    );
}

#[testkit::test]
fn bad_models_are_refused_the_empty_sum_draws_nothing_and_rendering_merges_z_less() {
    let camera = small_camera();
    // What a model refuses: an empty product, a product that starts with a
    // complement (an unbounded solid), a primitive named twice.
    let two = vec![sphere(Vec3::ZERO, 1.0), sphere(Vec3::X, 1.0)];
    for bad in [
        vec![],
        vec![Literal::complement(0), Literal::positive(1)],
        vec![Literal::positive(0), Literal::complement(0)],
        vec![Literal::positive(2)],
    ] {
        assert!(
            Model::new(two.clone(), vec![Product::new(bad.clone())]).is_err(),
            "Model::new refuses the product {bad:?} (empty, starting with a complement, \
             naming a primitive twice or one that does not exist)"
        );
    }
    assert!(
        Camera::new(0, 10, Vec3::ZERO, 0.0, 0.0, 1.0).is_err(),
        "Camera::new refuses a camera 0 pixels wide"
    );
    assert!(
        Camera::new(10, 10, Vec3::ZERO, f32::NAN, 0.0, 1.0).is_err(),
        "Camera::new refuses a NaN angle"
    );
    let empty = Model::new(vec![sphere(Vec3::ZERO, 1.0)], vec![]).expect("valid");
    let (frame, tests) = rendered(&empty, camera);
    assert_eq!(tests, 0, "the empty sum has no literal to test");
    assert!(
        common::surfaces(&frame).is_empty(),
        "the empty sum is the empty solid: nothing drawn"
    );
    // A frame that already holds a nearer sphere keeps it where it is in
    // front: the result is the union's.
    let near = sphere(Vec3::new(0.0, 0.0, 1.0), 0.8);
    let far = sphere(Vec3::new(0.3, 0.0, -0.5), 1.2);
    let scene = Scene::new(vec![near, far], Csg::union(Csg::leaf(0), Csg::leaf(1))).expect("valid");
    let mut frame = Framebuffer::new(camera);
    let first = Model::new(
        vec![near, far],
        vec![Product::new(vec![Literal::positive(0)])],
    )
    .expect("valid");
    let second = Model::new(
        vec![near, far],
        vec![Product::new(vec![Literal::positive(1)])],
    )
    .expect("valid");
    render(&first, &mut frame);
    render(&second, &mut frame);
    assert_frames_equal(&frame, &truth(&scene, camera), "two renderings merged");
}

#[testkit::test]
fn the_seeds_example_matches_the_ray_caster_and_the_reference_image() {
    let scene = example_scene();
    let camera = example_camera();
    let model = dnf_model(&scene);
    let (frame, tests) = rendered(&model, camera);
    let truth = truth(&scene, camera);
    // The picture first, so that a failing check below still leaves it.
    let picture = testkit::image::check_image(
        "goldfeather_example",
        &csg::shade::side_by_side(&[
            csg::shade::shade(&frame, scene.primitives()),
            csg::shade::shade(&truth, scene.primitives()),
        ]),
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/images/goldfeather_example.png"
        ),
        testkit::image::Tolerance {
            channel: 2.0 / 255.0,
            mismatched_fraction: 0.002,
        },
    );
    assert_eq!(
        tests, 20,
        "one product of five literals: 5 · 4 parity tests"
    );
    assert_frames_equal(&frame, &truth, "the example");
    picture.assert_matches();
}

/// The seed's Abbildung 9: what each literal's pass contributes. The
/// frame records every second buffer your `render` merges into it; the
/// pass of literal `A` must hold `A`'s entry face wherever it lies inside
/// all the other literals, and nothing else.
#[testkit::test]
fn each_literal_merges_its_visible_fragments_into_the_frame() {
    let scene = example_scene();
    let camera = example_camera();
    let model = dnf_model(&scene);
    let product = &model.products()[0];
    let mut frame = Framebuffer::recording_merges(camera);
    render(&model, &mut frame);
    let merges = frame.merges();
    // The picture of every pass first, so that a failing check below still
    // leaves it.
    let panels: Vec<_> = merges
        .iter()
        .map(|merge| csg::shade::shade(merge, scene.primitives()))
        .collect();
    let picture = testkit::image::check_image(
        "goldfeather_fragments",
        &csg::shade::side_by_side(&panels),
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/images/goldfeather_fragments.png"
        ),
        testkit::image::Tolerance {
            channel: 2.0 / 255.0,
            mismatched_fraction: 0.002,
        },
    );
    assert_eq!(
        merges.len(),
        product.literals.len(),
        "one second buffer per literal, merged with Framebuffer::merge_less after its \
         parity tests (seed §4.4: \"copy remaining pixels using z-less to original frame \
         buffer\")"
    );
    for (a, (merge, literal)) in merges.iter().zip(&product.literals).enumerate() {
        let (_, visible) = common::pass_fragments(&model, product, camera, |_| Some(a));
        assert_frames_equal(
            merge,
            &visible,
            &format!(
                "the pass of literal {a} ({literal:?}): its entry face where it lies inside every \
                 other literal"
            ),
        );
    }
    picture.assert_matches();
}

/// Seed §2.1: a node may carry an affine map. The turned scene of task 6
/// — a turned cube, an ellipsoid cut out of it, a sheared column —
/// flattened to moved primitives (the tests' own, not your task 6) and
/// drawn by your Goldfeather must be the ray caster's frame, pixel by
/// pixel, and task 6's picture.
#[testkit::test]
fn a_transformed_tree_matches_the_ray_caster_and_the_turned_picture() {
    let (primitives, node) = turned_scene();
    let camera = turned_camera();
    let (instances, tree) = moved_instances(&node, &primitives);
    let model = moved_model(&instances, &tree);
    let mut frame = Framebuffer::new(camera);
    let stats = render(&model, &mut frame);
    let picture = testkit::image::check_image(
        "goldfeather_turned_scene",
        &shade_by_depth(&frame),
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/images/transforms_turned_scene.png"
        ),
        testkit::image::Tolerance {
            channel: 2.0 / 255.0,
            mismatched_fraction: 0.005,
        },
    );
    assert_eq!(
        stats.parity_tests, 2,
        "(cube − ellipsoid) ∪ column is the products cube ∩ ¬ellipsoid and column: \
         2 · 1 + 1 · 0 parity tests"
    );
    assert_frames_equal(
        &frame,
        &truth_of(&tree, &instances, camera),
        "the turned scene (primitives moved by the maps at the nodes)",
    );
    picture.assert_matches();
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..testkit::proptest_config() })]

    /// Random trees with random maps (scale, rotation, translation) at
    /// random nodes: the moved primitives are drawn through their spans
    /// like any others.
    #[testkit::test]
    fn random_transformed_trees_match_the_ray_caster((primitives, node) in transformed_scene(5)) {
        let camera = small_camera();
        let (instances, tree) = moved_instances(&node, &primitives);
        let model = moved_model(&instances, &tree);
        let mut frame = Framebuffer::new(camera);
        let stats = render(&model, &mut frame);
        let expected: usize = model.products().iter().map(|p| p.literals.len() * (p.literals.len() - 1)).sum();
        prop_assert_eq!(stats.parity_tests, expected as u64, "{}: a product of m literals costs m·(m − 1) parity tests, each literal against every other (left: yours, right: the sum over the products {})", tree, common::sum_text(model.products()));
        assert_frames_equal(&frame, &truth_of(&tree, &instances, camera), &format!("{tree}, each leaf a primitive moved by the maps above it"));
    }

    #[testkit::test]
    fn random_scenes_match_the_ray_caster(scene in scene(5)) {
        let camera = small_camera();
        let model = dnf_model(&scene);
        let (frame, tests) = rendered(&model, camera);
        let expected: usize = model.products().iter().map(|p| p.literals.len() * (p.literals.len() - 1)).sum();
        prop_assert_eq!(tests, expected as u64, "{}: a product of m literals costs m·(m − 1) parity tests, each literal against every other (left: yours, right: the sum over the products {})", scene.tree(), common::sum_text(model.products()));
        assert_frames_equal(&frame, &truth(&scene, camera), &scene.tree().to_string());
    }
}
