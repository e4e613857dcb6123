//! Task 2: normalization to a sum of products with the nine rules.

mod common;

use common::{
    assert_sum_eq, in_sum, in_tree, is_normal, point, primitive, product_tree, sum_text, tree,
};
use csg::csg::{Csg, CsgError, Literal, Product};
use csg::normalize::{normalize, products};
use proptest::prelude::*;

fn p(i: usize) -> Csg {
    Csg::leaf(i)
}
fn u(x: Csg, y: Csg) -> Csg {
    Csg::union(x, y)
}
fn i(x: Csg, y: Csg) -> Csg {
    Csg::intersection(x, y)
}
fn d(x: Csg, y: Csg) -> Csg {
    Csg::difference(x, y)
}

/// Asserts that `normalize(tree)` applied `rules` (in order) and gave
/// `expected`, showing trees as `((P0 ∩ P1) − P2)`.
#[track_caller]
fn assert_normalizes(tree: &Csg, rules: &[u8], expected: &Csg) {
    let n = normalize(tree);
    assert_eq!(
        n.rules, rules,
        "normalize({tree}): the rules applied, in order (the procedure applies the first \
         matching rule, the lowest number, then normalizes the left and the right operand); \
         yours gave {}",
        n.tree
    );
    assert!(
        n.tree == *expected,
        "normalize({tree}): rules {rules:?} give {expected}, yours {}",
        n.tree
    );
}

/// Each rule once, on primitives X = 0, Y = 1, Z = 2: the rule's number
/// and right-hand side, written down from the seed's table.
#[testkit::test]
fn each_rule_rewrites_as_the_table_says() {
    let (x, y, z) = (p(0), p(1), p(2));
    let cases = [
        (
            d(x.clone(), u(y.clone(), z.clone())),
            1,
            d(d(x.clone(), y.clone()), z.clone()),
        ),
        (
            i(x.clone(), u(y.clone(), z.clone())),
            2,
            u(i(x.clone(), y.clone()), i(x.clone(), z.clone())),
        ),
        (
            d(x.clone(), i(y.clone(), z.clone())),
            3,
            u(d(x.clone(), y.clone()), d(x.clone(), z.clone())),
        ),
        (
            i(x.clone(), i(y.clone(), z.clone())),
            4,
            i(i(x.clone(), y.clone()), z.clone()),
        ),
        (
            d(x.clone(), d(y.clone(), z.clone())),
            5,
            u(d(x.clone(), y.clone()), i(x.clone(), z.clone())),
        ),
        (
            i(x.clone(), d(y.clone(), z.clone())),
            6,
            d(i(x.clone(), y.clone()), z.clone()),
        ),
        (
            i(d(x.clone(), y.clone()), z.clone()),
            7,
            d(i(x.clone(), z.clone()), y.clone()),
        ),
        (
            d(u(x.clone(), y.clone()), z.clone()),
            8,
            u(d(x.clone(), z.clone()), d(y.clone(), z.clone())),
        ),
        (
            i(u(x.clone(), y.clone()), z.clone()),
            9,
            u(i(x.clone(), z.clone()), i(y.clone(), z.clone())),
        ),
    ];
    for (tree, rule, expected) in cases {
        let n = normalize(&tree);
        assert!(
            n.tree == expected,
            "normalize({tree}): rule {rule} of the table rewrites it to {expected}, yours {}",
            n.tree
        );
        assert_eq!(
            n.rules,
            vec![rule],
            "normalize({tree}): only rule {rule} matches, once (left: the rules yours applied)"
        );
    }
}

#[testkit::test]
fn the_seeds_example_needs_rule_one_twice_at_the_root() {
    // (C ∩ S) − (X ∪ (Y ∪ Z)) → ((C ∩ S) − X) − (Y ∪ Z) → (((C ∩ S) − X) − Y) − Z
    let tree = common::example_tree();
    assert_normalizes(&tree, &[1, 1], &d(d(d(i(p(0), p(1)), p(2)), p(3)), p(4)));
    let n = normalize(&tree);
    let expected = Product::new(vec![
        Literal::positive(0),
        Literal::positive(1),
        Literal::complement(2),
        Literal::complement(3),
        Literal::complement(4),
    ]);
    assert_products(&n.tree, &[expected]);
}

#[testkit::test]
fn the_first_matching_rule_wins() {
    // X − (Y ∪ Z) with X a union matches rules 1 and 8: rule 1 first.
    //   (A ∪ B) − (Y ∪ Z)
    //   1: ((A ∪ B) − Y) − Z                    root: no rule (left is −)
    //   left ((A ∪ B) − Y), 8: (A − Y) ∪ (B − Y)
    //   root again, 8: ((A − Y) − Z) ∪ ((B − Y) − Z)
    let tree = d(u(p(0), p(1)), u(p(2), p(3)));
    assert_normalizes(
        &tree,
        &[1, 8, 8],
        &u(d(d(p(0), p(2)), p(3)), d(d(p(1), p(2)), p(3))),
    );
}

#[testkit::test]
fn a_chain_with_a_difference_inside() {
    // A ∩ (B − (C ∩ D)):
    //   6: (A ∩ B) − (C ∩ D)
    //   3: ((A ∩ B) − C) ∪ ((A ∩ B) − D)
    let tree = i(p(0), d(p(1), i(p(2), p(3))));
    assert_normalizes(
        &tree,
        &[6, 3],
        &u(d(i(p(0), p(1)), p(2)), d(i(p(0), p(1)), p(3))),
    );
    let n = normalize(&tree);
    assert_products(
        &n.tree,
        &[
            Product::new(vec![
                Literal::positive(0),
                Literal::positive(1),
                Literal::complement(2),
            ]),
            Product::new(vec![
                Literal::positive(0),
                Literal::positive(1),
                Literal::complement(3),
            ]),
        ],
    );
}

#[testkit::test]
fn the_procedure_stops_once_the_right_operand_is_a_primitive() {
    // (X ∩ (Y − Z)) ∩ W: at the root no rule matches (W is a primitive, the
    // left operand an ∩); in the left subtree rule 6 gives (X ∩ Y) − Z.
    // Back at the root the `until` condition holds, so the procedure
    // stops — although rule 7 would now match ((X ∩ Y) − Z) ∩ W. The
    // result is in normal form all the same: normal form is not a fixed
    // point of the nine rules.
    let tree = i(i(p(0), d(p(1), p(2))), p(3));
    assert_normalizes(&tree, &[6], &i(d(i(p(0), p(1)), p(2)), p(3)));
}

#[testkit::test]
fn primitives_and_normal_trees_are_left_alone() {
    for tree in [
        p(3),
        i(p(0), p(1)),
        u(d(p(0), p(1)), i(p(2), p(0))),
        d(d(d(p(0), p(1)), p(2)), p(3)),
    ] {
        assert_normalizes(&tree, &[], &tree);
    }
}

#[testkit::test]
fn products_of_trees_not_in_normal_form_are_refused() {
    for tree in [
        d(p(0), u(p(1), p(2))),
        i(u(p(0), p(1)), p(2)),
        i(p(0), i(p(1), p(2))),
    ] {
        assert!(
            matches!(products(&tree), Err(CsgError::NotNormal(_))),
            "products({tree}): a tree that is not a union of left-deep ∩/− chains with \
             primitives on the right is CsgError::NotNormal; yours {}",
            match products(&tree) {
                Ok(sum) => format!("Ok({})", sum_text(&sum)),
                Err(e) => format!("{e:?}"),
            }
        );
    }
    assert_products(&p(7), &[Product::new(vec![Literal::positive(7)])]);
}

/// Asserts that `products(normal)` is `Ok(expected)`, showing sums as
/// `P0 ∩ P1 − P2 ∪ …`.
#[track_caller]
fn assert_products(normal: &Csg, expected: &[Product]) {
    let what = format!(
        "products({normal}): split at the unions, left to right, each chain read from its \
         leftmost primitive (∩ P gives P, − P gives ¬P)"
    );
    match products(normal) {
        Ok(sum) => assert_sum_eq(&sum, expected, &what),
        Err(e) => panic!("{what}: expected {}, yours {e:?}", sum_text(expected)),
    }
}

/// The terms of a (nested) union, left to right.
fn union_terms(tree: &Csg) -> Vec<Csg> {
    match tree {
        Csg::Union(x, y) => {
            let mut terms = union_terms(x);
            terms.extend(union_terms(y));
            terms
        }
        t => vec![t.clone()],
    }
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[testkit::test]
    fn normalized_trees_are_sums_of_products_with_primitives_on_the_right(tree in tree(5, 8)) {
        let n = normalize(&tree);
        prop_assert!(is_normal(&n.tree), "normalize({}) = {}: not in normal form, a union of products, each a left-deep chain of ∩/− with primitives as right operands", tree, n.tree);
        prop_assert!(n.rules.iter().all(|r| (1..=9).contains(r)), "normalize({}): the rules applied are numbered 1 to 9, yours {:?}", tree, n.rules);
        let sum = products(&n.tree).map_err(|e| TestCaseError::fail(format!("products({}) of a normal tree (normalized from {}) is Ok, yours {:?}", n.tree, tree, e)))?;
        prop_assert!(sum.iter().all(|p| !p.literals.is_empty() && !p.literals[0].complement), "products({}) = {}: each product has literals and starts with a positive one (its leftmost primitive)", n.tree, sum_text(&sum));
        // The products, read back as trees, are the union's terms in order.
        let rebuilt: Vec<Csg> = sum.iter().map(product_tree).collect();
        let terms = union_terms(&n.tree);
        prop_assert!(rebuilt == terms, "products({}) = {}: read back as trees, the products are the union's terms, left to right", n.tree, sum_text(&sum));
    }

    #[testkit::test]
    fn normalization_preserves_membership(
        primitives in prop::collection::vec(primitive(), 5),
        tree in tree(5, 8),
        points in prop::collection::vec(point(), 24),
    ) {
        let n = normalize(&tree);
        let sum = products(&n.tree).map_err(|e| TestCaseError::fail(format!("products({}) of a normal tree (normalized from {}) is Ok, yours {:?}", n.tree, tree, e)))?;
        for q in points {
            let before = in_tree(&tree, &primitives, q);
            prop_assert_eq!(in_tree(&n.tree, &primitives, q), before, "normalize({}) = {}: the rules keep the solid, but at {} the normal tree says {} (left), the tree {} (right)", tree, n.tree, q, in_tree(&n.tree, &primitives, q), before);
            prop_assert_eq!(in_sum(&sum, &primitives, q), before, "products({}) = {}: the sum of products is the same solid, but at {} it says {} (left), the tree {} (right)", n.tree, sum_text(&sum), q, in_sum(&sum, &primitives, q), before);
        }
    }

    #[testkit::test]
    fn normalization_keeps_the_leaves(tree in tree(6, 8)) {
        // Rules only copy and move subtrees: every leaf survives, no new one
        // appears.
        let mut before = tree.leaves();
        let mut after = normalize(&tree).tree.leaves();
        before.sort_unstable();
        before.dedup();
        after.sort_unstable();
        after.dedup();
        prop_assert_eq!(after, before, "normalize({}): the rules only copy and move subtrees, so the primitives named (left: yours, right: the tree's) stay the same", tree);
    }
}
