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
    // BEGIN SOLUTION normalize: apply the first matching rule while one matches, recurse as the seed's procedure
    let mut tree = tree.clone();
    let mut rules = Vec::new();
    normalize_node(&mut tree, &mut rules);
    Normalization { tree, rules }
    // END SOLUTION
}

// BEGIN SOLUTION
fn normalize_node(t: &mut Csg, rules: &mut Vec<u8>) {
    if t.is_primitive() {
        return;
    }
    loop {
        loop {
            let old = std::mem::replace(t, Csg::Primitive(0));
            match rewrite(old) {
                Ok((new, rule)) => {
                    *t = new;
                    rules.push(rule);
                }
                Err(old) => {
                    *t = old;
                    break;
                }
            }
        }
        // `until T.op is a union or (T.right is a primitive and T.left is
        // not a union)`.
        let is_union = t.is_union();
        let (left, right) = children(t);
        normalize_node(left, rules);
        if is_union || (right.is_primitive() && !left.is_union()) {
            break;
        }
    }
    let (_, right) = children(t);
    normalize_node(right, rules);
}

/// Both operands of an inner node.
fn children(t: &mut Csg) -> (&mut Csg, &mut Csg) {
    match t {
        Csg::Union(x, y) | Csg::Intersection(x, y) | Csg::Difference(x, y) => (x, y),
        Csg::Primitive(_) => unreachable!("normalize_node returns early on primitives"),
    }
}

/// Applies the first matching rule at the root, returning the new tree and
/// the rule's number, or the unchanged tree when no rule matches.
fn rewrite(t: Csg) -> Result<(Csg, u8), Csg> {
    use Csg::{Difference as D, Intersection as I, Union as U};
    let (u, i, d) = (Csg::union, Csg::intersection, Csg::difference);
    match t {
        D(x, right) => match *right {
            U(y, z) => Ok((d(d(*x, *y), *z), 1)),
            I(y, z) => Ok((u(d((*x).clone(), *y), d(*x, *z)), 3)),
            D(y, z) => Ok((u(d((*x).clone(), *y), i(*x, *z)), 5)),
            z => match *x {
                U(x, y) => Ok((u(d(*x, z.clone()), d(*y, z)), 8)),
                x => Err(d(x, z)),
            },
        },
        I(x, right) => match *right {
            U(y, z) => Ok((u(i((*x).clone(), *y), i(*x, *z)), 2)),
            I(y, z) => Ok((i(i(*x, *y), *z), 4)),
            D(y, z) => Ok((d(i(*x, *y), *z), 6)),
            z => match *x {
                D(x, y) => Ok((d(i(*x, z), *y), 7)),
                U(x, y) => Ok((u(i(*x, z.clone()), i(*y, z)), 9)),
                x => Err(i(x, z)),
            },
        },
        t @ (U(..) | Csg::Primitive(_)) => Err(t),
    }
}
// END SOLUTION

/// Reads the products off a tree in normal form, left to right: each
/// maximal subtree without a union is one product, its literals in tree
/// order (`∩ P` gives `P`, `− P` gives `P̄`; the leftmost leaf is positive).
///
/// # Errors
/// [`CsgError::NotNormal`] naming the offending subtree when a `∩` or `−`
/// has a right operand that is not a primitive or a union below it.
#[transcript::task]
pub fn products(normal: &Csg) -> Result<Vec<Product>, CsgError> {
    // BEGIN SOLUTION normalize: split at the unions, then walk each left-deep chain down to its first primitive
    fn sum(t: &Csg, out: &mut Vec<Product>) -> Result<(), CsgError> {
        if let Csg::Union(x, y) = t {
            sum(x, out)?;
            sum(y, out)
        } else {
            let mut literals = Vec::new();
            chain(t, &mut literals)?;
            out.push(Product::new(literals));
            Ok(())
        }
    }
    fn chain(t: &Csg, literals: &mut Vec<Literal>) -> Result<(), CsgError> {
        let (x, y, complement) = match t {
            Csg::Primitive(i) => {
                literals.push(Literal::positive(*i));
                return Ok(());
            }
            Csg::Union(..) => {
                return Err(CsgError::NotNormal(format!("a union below a product: {t}")));
            }
            Csg::Intersection(x, y) => (x, y, false),
            Csg::Difference(x, y) => (x, y, true),
        };
        let Csg::Primitive(j) = **y else {
            return Err(CsgError::NotNormal(format!(
                "a right operand that is not a primitive: {t}"
            )));
        };
        chain(x, literals)?;
        literals.push(Literal {
            primitive: j,
            complement,
        });
        Ok(())
    }
    let mut out = Vec::new();
    sum(normal, &mut out)?;
    Ok(out)
    // END SOLUTION
}
