//! What the tests compare with: membership and the sum of products by
//! their definitions, written differently from the sheet's algorithms,
//! random scenes, and the seed's example.
#![allow(dead_code)] // each test file uses a different part

use csg::Vec3;
use csg::csg::{Csg, Literal, Model, Product, Scene};
use csg::primitive::{Axis, Primitive};
use csg::primitive::{Ray, RayInterval};
use csg::raster::{Camera, Face, Framebuffer, Solid, Surface};
use csg::transforms::Node;
use glam::{Affine3A, Quat};
use proptest::prelude::*;

// ---------------------------------------------------------------------------
// Membership by definition.

/// Whether `p` lies in the closed primitive: each primitive as the set of
/// points with a non-positive "excess" in every constraint.
pub fn in_primitive(primitive: &Primitive, p: Vec3) -> bool {
    let excess: Vec<f32> = match *primitive {
        Primitive::Cuboid { min, max } => (0..3)
            .flat_map(|i| [min[i] - p[i], p[i] - max[i]])
            .collect(),
        Primitive::Sphere { centre, radius } => {
            vec![(p - centre).length_squared() - radius * radius]
        }
        Primitive::Cylinder {
            centre,
            axis,
            radius,
            half_length,
        } => {
            let k = match axis {
                Axis::X => 0,
                Axis::Y => 1,
                Axis::Z => 2,
            };
            let d = p - centre;
            let across: f32 = (0..3).filter(|&i| i != k).map(|i| d[i] * d[i]).sum();
            vec![d[k].abs() - half_length, across - radius * radius]
        }
    };
    excess.iter().all(|&e| e <= 0.0)
}

/// Whether `p` lies in the solid of `tree`, by the seed's rules.
pub fn in_tree(tree: &Csg, primitives: &[Primitive], p: Vec3) -> bool {
    match tree {
        Csg::Primitive(i) => in_primitive(&primitives[*i], p),
        Csg::Union(x, y) => in_tree(x, primitives, p) || in_tree(y, primitives, p),
        Csg::Intersection(x, y) => in_tree(x, primitives, p) && in_tree(y, primitives, p),
        Csg::Difference(x, y) => in_tree(x, primitives, p) && !in_tree(y, primitives, p),
    }
}

/// Whether `p` lies in the union of the products.
pub fn in_sum(products: &[Product], primitives: &[Primitive], p: Vec3) -> bool {
    products.iter().any(|product| {
        product
            .literals
            .iter()
            .all(|l| in_primitive(&primitives[l.primitive], p) != l.complement)
    })
}

// ---------------------------------------------------------------------------
// The sum of products by expansion (disjunctive normal form), not by the
// nine rules: a sum is a list of products, a product a list of literals.

fn complement_of_sum(sum: &[Vec<Literal>]) -> Vec<Vec<Literal>> {
    // ¬(P₁ ∪ P₂ ∪ …) = ¬P₁ ∩ ¬P₂ ∩ …, and ¬(l₁ ∩ l₂ ∩ …) = ¬l₁ ∪ ¬l₂ ∪ …
    let mut result: Vec<Vec<Literal>> = vec![Vec::new()];
    for product in sum {
        let negated: Vec<Vec<Literal>> = product
            .iter()
            .map(|l| {
                vec![Literal {
                    primitive: l.primitive,
                    complement: !l.complement,
                }]
            })
            .collect();
        result = times(&result, &negated);
    }
    result
}

fn times(x: &[Vec<Literal>], y: &[Vec<Literal>]) -> Vec<Vec<Literal>> {
    let mut out = Vec::new();
    for a in x {
        for b in y {
            out.push(a.iter().chain(b.iter()).copied().collect());
        }
    }
    out
}

fn expand(tree: &Csg) -> Vec<Vec<Literal>> {
    match tree {
        Csg::Primitive(i) => vec![vec![Literal::positive(*i)]],
        Csg::Union(x, y) => {
            let mut s = expand(x);
            s.extend(expand(y));
            s
        }
        Csg::Intersection(x, y) => times(&expand(x), &expand(y)),
        Csg::Difference(x, y) => times(&expand(x), &complement_of_sum(&expand(y))),
    }
}

/// The products of `tree` by expansion, each with a positive literal
/// first, products naming a primitive twice simplified (`A ∩ A = A`,
/// `A ∩ Ā = ∅`).
pub fn dnf(tree: &Csg) -> Vec<Product> {
    expand(tree)
        .into_iter()
        .filter_map(|mut literals| {
            literals.sort_by_key(|l| (l.complement, l.primitive));
            literals.dedup();
            let contradictory = literals.iter().any(|l| {
                literals
                    .iter()
                    .any(|m| m.primitive == l.primitive && m.complement != l.complement)
            });
            let has_positive = literals.first().is_some_and(|l| !l.complement);
            (!contradictory && has_positive).then(|| Product::new(literals))
        })
        .collect()
}

/// Whether `tree` is in normal form: a union of products, each a
/// left-deep chain of ∩/− with primitives as right operands.
pub fn is_normal(tree: &Csg) -> bool {
    fn is_product(t: &Csg) -> bool {
        match t {
            Csg::Primitive(_) => true,
            Csg::Union(..) => false,
            Csg::Intersection(x, y) | Csg::Difference(x, y) => y.is_primitive() && is_product(x),
        }
    }
    match tree {
        Csg::Union(x, y) => is_normal(x) && is_normal(y),
        t => is_product(t),
    }
}

/// Reads a product back as a tree (left-deep).
pub fn product_tree(product: &Product) -> Csg {
    let mut literals = product.literals.iter();
    let first = literals.next().expect("a product is not empty");
    let mut tree = Csg::leaf(first.primitive);
    for l in literals {
        tree = if l.complement {
            Csg::difference(tree, Csg::leaf(l.primitive))
        } else {
            Csg::intersection(tree, Csg::leaf(l.primitive))
        };
    }
    tree
}

// ---------------------------------------------------------------------------
// Frames.

/// What a frame shows at a pixel, in words: `P1's back face at depth −1`
/// or `nothing`.
pub fn shown(frame: &Framebuffer, p: canvas::Pixel) -> String {
    match (frame.surface(p), frame.depth(p)) {
        (Some(s), Some(d)) => format!("P{}'s {:?} face at depth {d}", s.primitive, s.face),
        (Some(s), None) => format!("P{}'s {:?} face at no depth", s.primitive, s.face),
        (None, _) => "nothing".to_string(),
    }
}

/// The pixels where two frames disagree in surface or depth, each as
/// `pixel (x, y): yours …, truth …`.
pub fn frame_differences(a: &Framebuffer, b: &Framebuffer) -> Vec<String> {
    a.camera()
        .pixels()
        .filter_map(|p| {
            let (sa, sb) = (a.surface(p), b.surface(p));
            let (da, db) = (a.depth(p), b.depth(p));
            (sa != sb || (sa.is_some() && da != db))
                .then(|| format!("pixel {p}: yours {}, truth {}", shown(a, p), shown(b, p)))
        })
        .collect()
}

/// Panics with the first few differing pixels unless the frames agree.
#[track_caller]
pub fn assert_frames_equal(yours: &Framebuffer, truth: &Framebuffer, what: &str) {
    let diff = frame_differences(yours, truth);
    assert!(
        diff.is_empty(),
        "{what}: {} pixels differ from the ray caster (the truth: the first entry into the \
         solid along each pixel's ray), first ones:\n{}",
        diff.len(),
        diff[..diff.len().min(8)].join("\n")
    );
}

/// A sum of products in one line, `P0 ∩ P1 − P2 ∪ P3`, or `∅` for none.
pub fn sum_text(products: &[Product]) -> String {
    if products.is_empty() {
        return "∅ (no products)".to_string();
    }
    products
        .iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join("  ∪  ")
}

/// Asserts that `yours` is the sum `expected`, product for product and
/// literal for literal; on failure names `what` and shows both sums as
/// `P0 ∩ P1 − P2 ∪ …` rather than dumping the structs.
#[track_caller]
pub fn assert_sum_eq(yours: &[Product], expected: &[Product], what: &str) {
    assert!(
        yours == expected,
        "{what}\n  expected: {}\n  yours:    {}",
        sum_text(expected),
        sum_text(yours)
    );
}

/// An affine map in one line: its 3 × 4 matrix, rows `a b c | t`, to 3
/// decimals.
pub fn affine_text(m: &Affine3A) -> String {
    let rows: Vec<String> = (0..3)
        .map(|r| {
            let row = m.matrix3.row(r);
            format!(
                "{:.3} {:.3} {:.3} | {:.3}",
                row.x, row.y, row.z, m.translation[r]
            )
        })
        .collect();
    format!("M[{}]", rows.join("; "))
}

/// A transformed tree in one line, like `Csg`'s display, a transform as
/// `M[…](X)` (see [`affine_text`]).
pub fn node_text(node: &Node) -> String {
    match node {
        Node::Leaf(i) => format!("P{i}"),
        Node::Union(x, y) => format!("({} ∪ {})", node_text(x), node_text(y)),
        Node::Intersection(x, y) => format!("({} ∩ {})", node_text(x), node_text(y)),
        Node::Difference(x, y) => format!("({} − {})", node_text(x), node_text(y)),
        Node::Transform(m, x) => format!("{}({})", affine_text(m), node_text(x)),
    }
}

/// The ray caster's frame of `scene`.
pub fn truth(scene: &Scene, camera: Camera) -> Framebuffer {
    let mut frame = Framebuffer::new(camera);
    csg::raycast::raycast(scene, &mut frame);
    frame
}

/// The surfaces a frame shows, as a set.
pub fn surfaces(frame: &Framebuffer) -> std::collections::BTreeSet<Surface> {
    frame
        .camera()
        .pixels()
        .filter_map(|p| frame.surface(p))
        .collect()
}

/// How many entry faces of the product's literals each pixel's ray
/// crosses, the largest such count: the depth complexity by definition.
pub fn depth_complexity<S: Solid>(model: &Model<S>, product: &Product, camera: &Camera) -> u8 {
    camera
        .pixels()
        .map(|p| {
            let ray = camera.ray(p);
            product
                .literals
                .iter()
                .filter(|l| model.primitives()[l.primitive].span(&ray).is_some())
                .count() as u8
        })
        .max()
        .unwrap_or(0)
}

// ---------------------------------------------------------------------------
// Cameras and scenes.

/// A small oblique camera over the cube `[-2.5, 2.5]³` for random scenes.
pub fn small_camera() -> Camera {
    Camera::new(24, 24, Vec3::ZERO, 0.55, -0.45, 4.5).expect("a valid camera")
}

/// The seed's example (its figures 1–3, 5 and 9 show a CSG of boxes,
/// spheres and cylinders; this is the classic one): a cube and a sphere
/// intersected, three cylinders along x, y and z cut out —
/// `(C ∩ S) − (X ∪ (Y ∪ Z))`, which normalizes with rule 1 twice at the
/// root, as the seed's §4.2 says of its example.
pub fn example_primitives() -> Vec<Primitive> {
    let cylinder = |axis| Primitive::Cylinder {
        centre: Vec3::ZERO,
        axis,
        radius: 0.55,
        half_length: 1.6,
    };
    vec![
        Primitive::Cuboid {
            min: Vec3::splat(-1.0),
            max: Vec3::splat(1.0),
        },
        Primitive::Sphere {
            centre: Vec3::ZERO,
            radius: 1.32,
        },
        cylinder(Axis::X),
        cylinder(Axis::Y),
        cylinder(Axis::Z),
    ]
}

/// The example's tree, `(P0 ∩ P1) − (P2 ∪ (P3 ∪ P4))`.
pub fn example_tree() -> Csg {
    Csg::difference(
        Csg::intersection(Csg::leaf(0), Csg::leaf(1)),
        Csg::union(Csg::leaf(2), Csg::union(Csg::leaf(3), Csg::leaf(4))),
    )
}

/// The example as a scene.
pub fn example_scene() -> Scene {
    Scene::new(example_primitives(), example_tree()).expect("a valid scene")
}

/// The camera of the example pictures: from above, front and right.
pub fn example_camera() -> Camera {
    Camera::new(160, 160, Vec3::ZERO, 0.6, -0.5, 52.0).expect("a valid camera")
}

/// Random primitives inside about `[-2.5, 2.5]³`.
pub fn primitive() -> impl Strategy<Value = Primitive> {
    let centre =
        (-1.5f32..1.5, -1.5f32..1.5, -1.5f32..1.5).prop_map(|(x, y, z)| Vec3::new(x, y, z));
    let size = || 0.3f32..1.2;
    let axis = prop_oneof![Just(Axis::X), Just(Axis::Y), Just(Axis::Z)];
    prop_oneof![
        (centre.clone(), size(), size(), size()).prop_map(|(c, a, b, d)| {
            let half = Vec3::new(a, b, d);
            Primitive::Cuboid {
                min: c - half,
                max: c + half,
            }
        }),
        (centre.clone(), size()).prop_map(|(centre, radius)| Primitive::Sphere { centre, radius }),
        (centre, axis, size(), size()).prop_map(|(centre, axis, radius, half_length)| {
            Primitive::Cylinder {
                centre,
                axis,
                radius,
                half_length,
            }
        }),
    ]
}

/// A random tree over the given leaves (in this order), random shape and
/// operations.
fn tree_over(leaves: Vec<usize>) -> BoxedStrategy<Csg> {
    if leaves.len() == 1 {
        return Just(Csg::leaf(leaves[0])).boxed();
    }
    let n = leaves.len();
    (1..n, 0..3u8)
        .prop_flat_map(move |(split, op)| {
            let (l, r) = leaves.split_at(split);
            (tree_over(l.to_vec()), tree_over(r.to_vec()), Just(op))
        })
        .prop_map(|(x, y, op)| match op {
            0 => Csg::union(x, y),
            1 => Csg::intersection(x, y),
            _ => Csg::difference(x, y),
        })
        .boxed()
}

/// A random tree with `1..=max_leaves` leaves naming primitives
/// `0..primitives`, repetitions allowed.
pub fn tree(primitives: usize, max_leaves: usize) -> impl Strategy<Value = Csg> {
    prop::collection::vec(0..primitives, 1..=max_leaves).prop_flat_map(tree_over)
}

/// A random scene of `1..=max` primitives, each a leaf exactly once, in
/// random order.
pub fn scene(max: usize) -> impl Strategy<Value = Scene> {
    prop::collection::vec(primitive(), 1..=max)
        .prop_flat_map(|primitives| {
            let n = primitives.len();
            (
                Just(primitives),
                Just((0..n).collect::<Vec<_>>()).prop_shuffle(),
            )
        })
        .prop_flat_map(|(primitives, order)| (Just(primitives), tree_over(order)))
        .prop_map(|(primitives, tree)| Scene::new(primitives, tree).expect("valid by construction"))
}

/// Random points in the region of the random primitives.
pub fn point() -> impl Strategy<Value = Vec3> {
    (-2.8f32..2.8, -2.8f32..2.8, -2.8f32..2.8).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

/// The model of a scene with the products by expansion.
pub fn dnf_model(scene: &Scene) -> Model {
    Model::new(scene.primitives().to_vec(), dnf(scene.tree())).expect("a valid model")
}

// ---------------------------------------------------------------------------
// The passes of a product, by definition.

/// What one pass of a product must merge, by definition: at each pixel
/// the fragment `pick` chooses (the index of a literal of `product`, whose
/// entry face the pass draws there), and of those the ones that lie inside
/// every *other* literal — with the parity test's z-less rule, a depth
/// `d` is inside a primitive whose ray interval is `(near, far)` when
/// `near < d ≤ far`. Returns (all picked fragments, the visible ones).
pub fn pass_fragments(
    model: &Model,
    product: &Product,
    camera: Camera,
    pick: impl Fn(&Ray) -> Option<usize>,
) -> (Framebuffer, Framebuffer) {
    let primitives = model.primitives();
    let mut all = Framebuffer::new(camera);
    let mut visible = Framebuffer::new(camera);
    for p in camera.pixels() {
        let ray = camera.ray(p);
        let Some(a) = pick(&ray) else { continue };
        let literal = product.literals[a];
        let Some(span) = primitives[literal.primitive].interval(&ray) else {
            continue;
        };
        let face = literal.entry_face();
        let depth = match face {
            Face::Front => span.near,
            Face::Back => span.far,
        };
        let surface = Surface {
            primitive: literal.primitive,
            face,
        };
        all.write_less(p, depth, surface);
        let inside_the_others = product.literals.iter().enumerate().all(|(b, other)| {
            let inside = primitives[other.primitive]
                .interval(&ray)
                .is_some_and(|s| s.near < depth && depth <= s.far);
            b == a || inside != other.complement
        });
        if inside_the_others {
            visible.write_less(p, depth, surface);
        }
    }
    (all, visible)
}

/// The `n`-th literal of `product` (from 0, in product order) whose
/// primitive `ray` crosses: the literal of layer `n + 1` at that pixel.
pub fn nth_literal_crossed(model: &Model, product: &Product, ray: &Ray, n: usize) -> Option<usize> {
    product
        .literals
        .iter()
        .enumerate()
        .filter(|(_, l)| model.primitives()[l.primitive].interval(ray).is_some())
        .nth(n)
        .map(|(i, _)| i)
}

/// Pictures in rows, one row above the other (the first row on top),
/// [`csg::shade::PANEL_GAP`] apart.
pub fn rows(rows: &[canvas::Canvas]) -> canvas::Canvas {
    let gap = csg::shade::PANEL_GAP;
    let width = rows.iter().map(canvas::Canvas::width).max().unwrap_or(0);
    let height = rows.iter().map(canvas::Canvas::height).sum::<u32>()
        + gap * (rows.len().saturating_sub(1) as u32);
    let mut out = canvas::Canvas::new(width, height);
    out.clear(canvas::Rgba::BLACK);
    // Canvas y points up: the first row goes at the top.
    let mut top = height as i32;
    for row in rows {
        let y0 = top - row.height() as i32;
        for (p, colour) in row.enumerate() {
            out.set(canvas::Pixel::new(p.x, p.y + y0), colour);
        }
        top = y0 - gap as i32;
    }
    out
}

// ---------------------------------------------------------------------------
// Transformed trees, for the renderers (seed §2.1): the tests' own
// flattening and moved primitives, so that a renderer is tested without
// the transforms task.

/// A primitive moved by an affine map, met by a ray where the ray taken
/// back by the inverse map meets the primitive: `M⁻¹·o + t·M⁻¹·d`, whose
/// depths along the unit direction are `|M⁻¹·d|` times the world's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Moved {
    /// The primitive in its own space.
    pub primitive: Primitive,
    /// Its space to the world's.
    pub to_world: Affine3A,
}

impl Solid for Moved {
    fn span(&self, ray: &Ray) -> Option<RayInterval> {
        let to_local = self.to_world.inverse();
        let along = to_local.transform_vector3(ray.direction);
        let stretch = along.length();
        let local = Ray {
            origin: to_local.transform_point3(ray.origin),
            direction: along / stretch,
        };
        let s = self.primitive.interval(&local)?;
        Some(RayInterval {
            near: s.near / stretch,
            far: s.far / stretch,
        })
    }
}

/// The moved primitives of `node`'s leaves, left to right, each under the
/// product of the maps above it (outermost first), and the tree over them.
pub fn moved_instances(node: &Node, primitives: &[Primitive]) -> (Vec<Moved>, Csg) {
    fn walk(node: &Node, above: Affine3A, primitives: &[Primitive], out: &mut Vec<Moved>) -> Csg {
        let mut pair = |x: &Node, y: &Node| {
            let x = walk(x, above, primitives, out);
            (x, walk(y, above, primitives, out))
        };
        match node {
            Node::Leaf(i) => {
                out.push(Moved {
                    primitive: primitives[*i],
                    to_world: above,
                });
                Csg::leaf(out.len() - 1)
            }
            Node::Union(x, y) => {
                let (x, y) = pair(x, y);
                Csg::union(x, y)
            }
            Node::Intersection(x, y) => {
                let (x, y) = pair(x, y);
                Csg::intersection(x, y)
            }
            Node::Difference(x, y) => {
                let (x, y) = pair(x, y);
                Csg::difference(x, y)
            }
            Node::Transform(m, x) => walk(x, above * *m, primitives, out),
        }
    }
    let mut out = Vec::new();
    let tree = walk(node, Affine3A::IDENTITY, primitives, &mut out);
    (out, tree)
}

/// The ray caster's frame of `tree` over any solids: at every pixel the
/// first entry point of the tree's intervals.
pub fn truth_of<S: Solid>(tree: &Csg, solids: &[S], camera: Camera) -> Framebuffer {
    let mut frame = Framebuffer::new(camera);
    for p in camera.pixels() {
        let ray = camera.ray(p);
        let span = |i: usize| solids.get(i).and_then(|s| s.span(&ray));
        if let Some(b) = csg::raycast::intervals_by(tree, &span).first()
            && b.t.is_finite()
        {
            frame.write_less(p, b.t, b.surface);
        }
    }
    frame
}

/// The model of a tree over moved primitives, products by expansion.
pub fn moved_model(instances: &[Moved], tree: &Csg) -> Model<Moved> {
    Model::with_solids(instances.to_vec(), dnf(tree)).expect("a valid model")
}

/// A random affine map: a non-uniform scale in `scale`, any rotation, a
/// translation up to `shift` along each axis.
pub fn affine(scale: std::ops::Range<f32>, shift: f32) -> impl Strategy<Value = Affine3A> {
    (
        (scale.clone(), scale.clone(), scale),
        (-1.0f32..1.0, -1.0f32..1.0, -1.0f32..1.0, -3.0f32..3.0),
        (-shift..shift, -shift..shift, -shift..shift),
    )
        .prop_map(|((sx, sy, sz), (ax, ay, az, angle), (tx, ty, tz))| {
            let axis = Vec3::new(ax, ay, az).try_normalize().unwrap_or(Vec3::Y);
            Affine3A::from_scale_rotation_translation(
                Vec3::new(sx, sy, sz),
                Quat::from_axis_angle(axis, angle),
                Vec3::new(tx, ty, tz),
            )
        })
}

/// `tree` with a transform taken from `maps` above each node whose map is
/// `Some`, in post-order (children first).
pub fn with_transforms(tree: &Csg, maps: &mut impl Iterator<Item = Option<Affine3A>>) -> Node {
    let node = match tree {
        Csg::Primitive(i) => Node::leaf(*i),
        Csg::Union(x, y) => {
            let x = with_transforms(x, maps);
            Node::union(x, with_transforms(y, maps))
        }
        Csg::Intersection(x, y) => {
            let x = with_transforms(x, maps);
            Node::intersection(x, with_transforms(y, maps))
        }
        Csg::Difference(x, y) => {
            let x = with_transforms(x, maps);
            Node::difference(x, with_transforms(y, maps))
        }
    };
    match maps.next().flatten() {
        Some(m) => Node::transform(m, node),
        None => node,
    }
}

/// A random scene of `1..=max` primitives, each a leaf once, with affine
/// maps at random nodes (mild ones, so that the solid stays in view of
/// [`small_camera`]): a transformed tree and its primitives.
pub fn transformed_scene(max: usize) -> impl Strategy<Value = (Vec<Primitive>, Node)> {
    (
        scene(max),
        prop::collection::vec(prop::option::of(affine(0.6..1.4, 0.6)), 9),
    )
        .prop_map(|(scene, maps)| {
            let node = with_transforms(scene.tree(), &mut maps.into_iter().cycle());
            (scene.primitives().to_vec(), node)
        })
}

/// A box turned about two axes, an ellipsoid (a sphere scaled by 1.5,
/// 0.7, 1.5) cut out of it, and a cylinder sheared into a slanted column
/// beside it: `turn(C − stretch(S)) ∪ shear(Y)`.
pub fn turned_scene() -> (Vec<Primitive>, Node) {
    let primitives = vec![
        Primitive::Cuboid {
            min: Vec3::splat(-1.0),
            max: Vec3::splat(1.0),
        },
        Primitive::Sphere {
            centre: Vec3::ZERO,
            radius: 1.0,
        },
        Primitive::Cylinder {
            centre: Vec3::ZERO,
            axis: Axis::Y,
            radius: 0.3,
            half_length: 1.6,
        },
    ];
    let turn = Affine3A::from_rotation_y(0.5) * Affine3A::from_rotation_x(0.4);
    let ellipsoid = Affine3A::from_scale(Vec3::new(1.5, 0.7, 1.5));
    let shear = Affine3A::from_cols(
        Vec3::X.into(),
        Vec3::new(0.4, 1.0, 0.0).into(),
        Vec3::Z.into(),
        Vec3::ZERO.into(),
    );
    let node = Node::union(
        Node::transform(
            turn,
            Node::difference(Node::leaf(0), Node::transform(ellipsoid, Node::leaf(1))),
        ),
        Node::transform(shear, Node::leaf(2)),
    );
    (primitives, node)
}

/// The camera of the turned scene's picture.
pub fn turned_camera() -> Camera {
    Camera::new(160, 160, Vec3::ZERO, 0.3, -0.35, 45.0).expect("a valid camera")
}

/// The turned scene's picture of a frame: a colour per instance (orange
/// cube, blue ellipsoid, green column), darker with depth, back faces
/// (the walls of a cut) darker still.
pub fn shade_by_depth(frame: &Framebuffer) -> canvas::Canvas {
    let palette = [
        canvas::Rgba::rgb(0.9, 0.6, 0.2),
        canvas::Rgba::rgb(0.3, 0.6, 0.9),
        canvas::Rgba::rgb(0.4, 0.8, 0.4),
    ];
    let camera = *frame.camera();
    let mut canvas = canvas::Canvas::new(camera.width(), camera.height());
    for p in camera.pixels() {
        if let (Some(depth), Some(surface)) = (frame.depth(p), frame.surface(p))
            && depth.is_finite()
        {
            let shade = (0.75 - 0.2 * depth).clamp(0.25, 1.0)
                * if surface.face == Face::Back {
                    0.55
                } else {
                    1.0
                };
            let c = palette[surface.primitive % palette.len()];
            canvas.set(p, canvas::Rgba::rgb(c.r * shade, c.g * shade, c.b * shade));
        }
    }
    canvas
}
