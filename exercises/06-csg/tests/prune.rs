//! Task 3: bounding-box pruning of a sum of products.

mod common;

use common::{assert_sum_eq, in_sum, point, primitive, sum_text};
use csg::Vec3;
use csg::csg::{Literal, Model, Product};
use csg::primitive::Primitive;
use csg::prune::prune;
use proptest::prelude::*;

fn sphere(x: f32, radius: f32) -> Primitive {
    Primitive::Sphere {
        centre: Vec3::new(x, 0.0, 0.0),
        radius,
    }
}

fn product(literals: &[Literal]) -> Product {
    Product::new(literals.to_vec())
}

const A: Literal = Literal::positive(0);
const B: Literal = Literal::positive(1);
const NOT_B: Literal = Literal::complement(1);
const C: Literal = Literal::positive(2);
const NOT_C: Literal = Literal::complement(2);

/// A at x = 0, B at x = 5 (far apart), C at x = 1 (overlapping A), all of
/// radius 1.5: bound(A) = [−1.5, 1.5] in x, bound(B) = [3.5, 6.5].
fn three_spheres(products: Vec<Product>) -> Model {
    Model::new(
        vec![sphere(0.0, 1.5), sphere(5.0, 1.5), sphere(1.0, 1.5)],
        products,
    )
    .expect("valid")
}

#[testkit::test]
fn disjoint_bounds_empty_a_product() {
    let model = three_spheres(vec![product(&[A, B]), product(&[A, C])]);
    assert_sum_eq(
        &prune(&model),
        &[product(&[A, C])],
        "prune(P0 ∩ P1 ∪ P0 ∩ P2), spheres P0 at x = 0, P1 at x = 5, P2 at x = 1, radius 1.5: \
         bound(P0) ∩ bound(P1) = ∅ drops the product P0 ∩ P1, P0 ∩ P2 overlaps and stays",
    );
}

#[testkit::test]
fn subtracting_something_elsewhere_leaves_the_product_whole() {
    // The seed's table says A − B = ∅ here; it is A.
    let model = three_spheres(vec![product(&[A, NOT_B]), product(&[A, NOT_C])]);
    assert_sum_eq(
        &prune(&model),
        &[product(&[A]), product(&[A, NOT_C])],
        "prune(P0 − P1 ∪ P0 − P2), spheres P0 at x = 0, P1 at x = 5, P2 at x = 1, radius 1.5: \
         A − B = A when the bounds miss (not ∅, as the seed's table says), so P0 − P1 becomes \
         P0; P0 − P2 overlaps and stays",
    );
}

#[testkit::test]
fn the_product_bound_is_the_intersection_of_all_positive_bounds() {
    // D at x = 3 overlaps both A (bound up to 1.5) and B (from 3.5) — its
    // bound is [1.5, 4.5] — but A ∩ D's bound is the single plane x = 1.5,
    // which B's bound misses: A ∩ D ∩ B = ∅, and in A ∩ D − B the B goes —
    // also when D comes first, although B's bound meets D's.
    let d = Literal::positive(3);
    let model = Model::new(
        vec![
            sphere(0.0, 1.5),
            sphere(5.0, 1.5),
            sphere(1.0, 1.5),
            sphere(3.0, 1.5),
        ],
        vec![
            product(&[A, d, B]),
            product(&[A, d, NOT_B]),
            product(&[d, NOT_B]),
            product(&[d, A, NOT_B]),
        ],
    )
    .expect("valid");
    assert_sum_eq(
        &prune(&model),
        &[product(&[A, d]), product(&[d, NOT_B]), product(&[d, A])],
        "prune(P0 ∩ P3 ∩ P1 ∪ P0 ∩ P3 − P1 ∪ P3 − P1 ∪ P3 ∩ P0 − P1): the product bound is the \
         intersection of all positive bounds (P0 ∩ P3: the plane x = 1.5, touching counts as \
         overlapping), a product whose product bound is empty goes, and so does each complement \
         whose bound misses the product bound",
    );
}

#[testkit::test]
fn order_is_kept_and_nothing_else_changes() {
    let products = vec![product(&[C, A, NOT_B]), product(&[A, NOT_C]), product(&[B])];
    let model = three_spheres(products);
    assert_sum_eq(
        &prune(&model),
        &[product(&[C, A]), product(&[A, NOT_C]), product(&[B])],
        "prune(P2 ∩ P0 − P1 ∪ P0 − P2 ∪ P1): the order of the products and of their literals is \
         kept; only − P1, whose bound misses P2 ∩ P0's, goes",
    );
    assert_sum_eq(
        &prune(&three_spheres(vec![])),
        &[],
        "prune of the empty sum is the empty sum",
    );
}

fn random_model() -> impl Strategy<Value = Model> {
    (
        prop::collection::vec(primitive(), 6),
        prop::collection::vec(
            (
                Just((0..6).collect::<Vec<usize>>()).prop_shuffle(),
                1usize..=6,
                prop::collection::vec(any::<bool>(), 6),
            ),
            0..5,
        ),
    )
        .prop_map(|(primitives, products)| {
            let products = products
                .into_iter()
                .map(|(order, len, complements)| {
                    Product::new(
                        order[..len]
                            .iter()
                            .enumerate()
                            .map(|(k, &primitive)| Literal {
                                primitive,
                                complement: k > 0 && complements[k],
                            })
                            .collect(),
                    )
                })
                .collect();
            Model::new(primitives, products).expect("valid by construction")
        })
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn pruning_never_changes_membership(model in random_model(), points in prop::collection::vec(point(), 32)) {
        let pruned = prune(&model);
        prop_assert!(Model::new(model.primitives().to_vec(), pruned.clone()).is_ok(), "prune({}) = {}: not a valid sum (Model::new refuses it: an empty product, one starting with a complement, or a primitive named twice)", sum_text(model.products()), sum_text(&pruned));
        for q in points {
            prop_assert_eq!(
                in_sum(&pruned, model.primitives(), q),
                in_sum(model.products(), model.primitives(), q),
                "prune({}) = {}: pruning never changes the solid, but at {} yours (left) and the original sum (right) differ", sum_text(model.products()), sum_text(&pruned), q
            );
        }
    }

    #[testkit::test]
    fn pruning_only_removes(model in random_model()) {
        // Every pruned product is one of the original products with some
        // complements left out, in the original order.
        let pruned = prune(&model);
        let mut originals = model.products().iter();
        for p in &pruned {
            let found = originals.by_ref().any(|o| {
                let mut lits = o.literals.iter();
                p.literals.iter().all(|l| lits.by_ref().any(|m| m == l))
                    && o.literals.iter().filter(|l| !l.complement).eq(p.literals.iter().filter(|l| !l.complement))
            });
            prop_assert!(found, "prune({}) = {}: the product {} is not one of the originals, in order, with some complements left out (pruning only removes)", sum_text(model.products()), sum_text(&pruned), p);
        }
        // Rule 1 drops exactly the products whose positive bounds miss.
        let bounds: Vec<_> = model.primitives().iter().map(Primitive::bounds).collect();
        let non_empty = model.products().iter().filter(|o| {
            o.literals.iter().filter(|l| !l.complement).try_fold(None, |acc: Option<csg::primitive::Aabb>, l| {
                let b = bounds[l.primitive];
                match acc {
                    None => Some(Some(b)),
                    Some(a) => a.intersection(&b).map(Some),
                }
            }).is_some()
        }).count();
        prop_assert_eq!(pruned.len(), non_empty, "prune({}) = {}: the products kept (left: yours), rule 1 drops exactly those whose positive bounds do not overlap (right: how many remain)", sum_text(model.products()), sum_text(&pruned));
    }
}
