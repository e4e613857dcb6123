//! Normalization of a CSG tree to a sum of products with Goldfeather's
//! nine rewrite rules and the seed's recursive procedure (seed 003, §4.2
//! "Normalisierung", Tabelle 1; Goldfeather et al. 1989).
//!
//! A tree is in *normal form* when it is a union of products, and every
//! product is a left-deep chain of `∩`/`−` whose right operands are all
//! primitives:
//!
//! ```text
//!              ∪                 (A ∩ B − C) ∪ (D − E)
//!            /   \
//!           −     −              no union below a ∩ or −,
//!          / \   / \             every right child a primitive
//!         ∩   C D   E
//!        / \
//!       A   B
//! ```

#[allow(unused_imports)]
use crate::csg::{Csg, CsgError, Literal, Product};

/// The result of [`normalize`]: the normal tree and the rules applied.
#[transcript::evidence]
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Normalization {
    /// The tree in normal form.
    pub tree: Csg,
    /// The numbers (1–9, as in the seed's table) of the rules applied, in
    /// the order the procedure applied them.
    pub rules: Vec<u8>,
}

/// Rewrites `tree` into normal form with the nine rules, following the
/// seed's procedure exactly:
///
/// ```text
///   1. X − (Y ∪ Z) = (X − Y) − Z          6. X ∩ (Y − Z) = (X ∩ Y) − Z
///   2. X ∩ (Y ∪ Z) = (X ∩ Y) ∪ (X ∩ Z)    7. (X − Y) ∩ Z = (X ∩ Z) − Y
///   3. X − (Y ∩ Z) = (X − Y) ∪ (X − Z)    8. (X ∪ Y) − Z = (X − Z) ∪ (Y − Z)
///   4. X ∩ (Y ∩ Z) = (X ∩ Y) ∩ Z          9. (X ∪ Y) ∩ Z = (X ∩ Z) ∪ (Y ∩ Z)
///   5. X − (Y − Z) = (X − Y) ∪ (X ∩ Z)
///
///   proc normalize(T)
///     if T is a primitive: return
///     repeat
///       while T matches a rule from 1–9: apply the first matching rule
///       normalize(T.left)
///     until T.op is a union
///        or (T.right is a primitive and T.left is not a union)
///     normalize(T.right)
/// ```
///
/// "First matching" means the lowest rule number: rules 1–6 look at the
/// right operand, 7–9 at the left one. Rules 2, 3, 5, 8 and 9 copy a
/// subtree, so the result can be exponentially larger than the input
/// (the seed says so); trees of a few dozen leaves are fine.
#[must_use]
#[transcript::task]
pub fn normalize(tree: &Csg) -> Normalization {
    // Unused until you write the body:
    let _ = &tree;
    todo!(
        "normalize: apply the first matching rule while one matches, recurse as the seed's procedure"
    )
}

/// Reads the products off a tree in normal form, left to right: each
/// maximal subtree without a union is one product, its literals in tree
/// order (`∩ P` gives `P`, `− P` gives `P̄`; the leftmost leaf is positive).
///
/// # Errors
/// [`CsgError::NotNormal`] naming the offending subtree when a `∩` or `−`
/// has a right operand that is not a primitive or a union below it.
#[transcript::task]
pub fn products(normal: &Csg) -> Result<Vec<Product>, CsgError> {
    // Unused until you write the body:
    let _ = &normal;
    todo!(
        "normalize: split at the unions, then walk each left-deep chain down to its first primitive"
    )
}
