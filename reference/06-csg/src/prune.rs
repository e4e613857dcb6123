//! Bounding-box pruning of a sum of products (seed 003, §4.2, Tabelle 2
//! "Ausdünnung des normalisierten CSG-Baums").
//!
//! Normalization multiplies products; many of them are empty because
//! their primitives do not even overlap. Axis-aligned bounding boxes find
//! many such cases cheaply:
//!
//! ```text
//!   A ∩ B = ∅   if bound(A) ∩ bound(B) = ∅
//!   A − B = A   if bound(A) ∩ bound(B) = ∅
//! ```
//!
//! The seed's table gives `A − B = ∅` for the second rule; that is wrong:
//! cutting away something that lies elsewhere leaves `A` whole.

use crate::csg::{Model, Product};
// BEGIN SOLUTION
use crate::primitive::Aabb;
// END SOLUTION

/// Prunes every product of `model` with the two rules, applied to the
/// whole product:
///
/// 1. The product lies inside the *product bound*, the intersection of the
///    bounds of its positive literals. If that intersection is empty, the
///    product is empty: drop it.
/// 2. A complement `P̄` whose primitive's bound misses the product bound
///    changes no point of the product: drop the literal.
///
/// Products keep their order, literals their order. Bounds are closed
/// boxes: touching boxes count as overlapping (nothing is dropped that
/// might share a point). The result defines the same solid as `model`.
#[must_use]
#[transcript::task]
pub fn prune(model: &Model) -> Vec<Product> {
    // BEGIN SOLUTION prune: intersect the positive literals' bounds, drop empty products and complements outside that bound
    let primitives = model.primitives();
    let bound = |index: usize| primitives[index].bounds();
    let mut out = Vec::new();
    'products: for product in model.products() {
        let mut positives = product.literals.iter().filter(|l| !l.complement);
        let Some(first) = positives.next() else {
            continue;
        };
        let mut product_bound: Aabb = bound(first.primitive);
        for l in positives {
            match product_bound.intersection(&bound(l.primitive)) {
                Some(b) => product_bound = b,
                None => continue 'products,
            }
        }
        let literals = product
            .literals
            .iter()
            .copied()
            .filter(|l| !l.complement || bound(l.primitive).intersects(&product_bound))
            .collect();
        out.push(Product::new(literals));
    }
    out
    // END SOLUTION
}
