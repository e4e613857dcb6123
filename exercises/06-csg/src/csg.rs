//! CSG trees, their normal form (a sum of products) and the two validated
//! inputs of the renderers: a [`Scene`] (primitives and a tree) and a
//! [`Model`] (primitives and a sum of products). Seed 003, §2.1 "Der
//! CSG-Baum" and §4.2.
//!
//! ```text
//!          −                the tree of (A ∩ B) − C:
//!        /   \              leaves are primitives (by index),
//!       ∩     C             inner nodes are the operations
//!      / \                  ∪ (sum), ∩ (product), − (difference)
//!     A   B
//! ```
//!
//! This module is given: you use it, you do not edit it.

use std::fmt;

use crate::primitive::Primitive;
use crate::raster::{Face, Solid};

/// The most literals a product may have: the layer count of layered
/// Goldfeather must fit the 8-bit stencil buffer without saturating.
pub const MAX_LITERALS: usize = 254;

/// What can be wrong with the input of this crate.
#[transcript::evidence]
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum CsgError {
    /// A primitive has a non-finite number or an empty extent.
    #[error("primitive {index} is invalid: {reason}")]
    InvalidPrimitive {
        /// Its index.
        index: usize,
        /// What is wrong.
        reason: String,
    },
    /// A tree leaf or a literal names a primitive that does not exist.
    #[error("primitive {index} does not exist (there are {count})")]
    UnknownPrimitive {
        /// The index named.
        index: usize,
        /// How many primitives there are.
        count: usize,
    },
    /// A product is empty, starts with a complement, repeats a primitive
    /// or is longer than [`MAX_LITERALS`].
    #[error("product {index} cannot be rendered: {reason}")]
    BadProduct {
        /// Its index in the sum.
        index: usize,
        /// What is wrong.
        reason: &'static str,
    },
    /// A tree is not in normal form where a normal tree is required.
    #[error("the tree is not in normal form: {0}")]
    NotNormal(String),
    /// A framebuffer would be empty or too large.
    #[error("a {width}x{height} framebuffer is empty or too large")]
    BadSize {
        /// The width asked for.
        width: u32,
        /// The height asked for.
        height: u32,
    },
    /// A camera parameter is not finite or not positive.
    #[error("the camera is invalid: {0}")]
    BadCamera(&'static str),
}

/// A CSG tree over primitives named by their index in a list.
#[transcript::evidence]
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Csg {
    /// A leaf: the primitive with this index.
    Primitive(usize),
    /// `X ∪ Y`, the sum.
    Union(Box<Csg>, Box<Csg>),
    /// `X ∩ Y`, the product.
    Intersection(Box<Csg>, Box<Csg>),
    /// `X − Y = X ∩ Ȳ`, the difference.
    Difference(Box<Csg>, Box<Csg>),
}

impl Csg {
    /// The leaf naming primitive `index`.
    #[must_use]
    pub fn leaf(index: usize) -> Self {
        Self::Primitive(index)
    }

    /// `x ∪ y`.
    #[must_use]
    pub fn union(x: Self, y: Self) -> Self {
        Self::Union(Box::new(x), Box::new(y))
    }

    /// `x ∩ y`.
    #[must_use]
    pub fn intersection(x: Self, y: Self) -> Self {
        Self::Intersection(Box::new(x), Box::new(y))
    }

    /// `x − y`.
    #[must_use]
    pub fn difference(x: Self, y: Self) -> Self {
        Self::Difference(Box::new(x), Box::new(y))
    }

    /// Whether this node is a leaf.
    #[must_use]
    pub fn is_primitive(&self) -> bool {
        matches!(self, Self::Primitive(_))
    }

    /// Whether this node is a union.
    #[must_use]
    pub fn is_union(&self) -> bool {
        matches!(self, Self::Union(..))
    }

    /// The primitive indices of the leaves, left to right.
    #[must_use]
    pub fn leaves(&self) -> Vec<usize> {
        let mut out = Vec::new();
        self.collect_leaves(&mut out);
        out
    }

    fn collect_leaves(&self, out: &mut Vec<usize>) {
        match self {
            Self::Primitive(i) => out.push(*i),
            Self::Union(x, y) | Self::Intersection(x, y) | Self::Difference(x, y) => {
                x.collect_leaves(out);
                y.collect_leaves(out);
            }
        }
    }

    /// The number of nodes, leaves included.
    #[must_use]
    pub fn size(&self) -> usize {
        match self {
            Self::Primitive(_) => 1,
            Self::Union(x, y) | Self::Intersection(x, y) | Self::Difference(x, y) => {
                1 + x.size() + y.size()
            }
        }
    }
}

impl fmt::Display for Csg {
    /// Fully parenthesized, primitives as `P0`, `P1`, …: `((P0 ∩ P1) − P2)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Primitive(i) => write!(f, "P{i}"),
            Self::Union(x, y) => write!(f, "({x} ∪ {y})"),
            Self::Intersection(x, y) => write!(f, "({x} ∩ {y})"),
            Self::Difference(x, y) => write!(f, "({x} − {y})"),
        }
    }
}

/// A primitive or its complement, one factor of a product.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Literal {
    /// The primitive's index.
    pub primitive: usize,
    /// `true` for the complement `P̄` (the product subtracts `P`).
    pub complement: bool,
}

impl Literal {
    /// The primitive itself.
    #[must_use]
    pub const fn positive(primitive: usize) -> Self {
        Self {
            primitive,
            complement: false,
        }
    }

    /// The complement of the primitive.
    #[must_use]
    pub const fn complement(primitive: usize) -> Self {
        Self {
            primitive,
            complement: true,
        }
    }

    /// The face through which the literal bounds a product, seen by a
    /// viewer outside: the front face of a primitive, the back face of a
    /// complement (the wall of the hole it cuts).
    #[must_use]
    pub const fn entry_face(self) -> Face {
        if self.complement {
            Face::Back
        } else {
            Face::Front
        }
    }
}

/// A product `L₁ ∩ L₂ ∩ … ∩ Lₘ` of literals: the normal-form tree
/// `((L₁ op L₂) op L₃) …` read left to right, `op` being `∩` for a
/// positive literal and `−` for a complement. `L₁` is always positive.
#[transcript::evidence]
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct Product {
    /// The literals in tree order.
    pub literals: Vec<Literal>,
}

impl Product {
    /// The product of the given literals.
    #[must_use]
    pub fn new(literals: Vec<Literal>) -> Self {
        Self { literals }
    }
}

impl fmt::Display for Product {
    /// `P0 ∩ P1 − P2`, read left to right.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (k, l) in self.literals.iter().enumerate() {
            match (k, l.complement) {
                (0, false) => write!(f, "P{}", l.primitive)?,
                (0, true) => write!(f, "¬P{}", l.primitive)?,
                (_, false) => write!(f, " ∩ P{}", l.primitive)?,
                (_, true) => write!(f, " − P{}", l.primitive)?,
            }
        }
        Ok(())
    }
}

fn validate_primitives(primitives: &[Primitive]) -> Result<(), CsgError> {
    primitives
        .iter()
        .enumerate()
        .try_for_each(|(index, p)| p.validate(index))
}

fn known(index: usize, count: usize) -> Result<(), CsgError> {
    if index < count {
        Ok(())
    } else {
        Err(CsgError::UnknownPrimitive { index, count })
    }
}

/// Valid primitives and a tree whose leaves all name one of them.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    primitives: Vec<Primitive>,
    tree: Csg,
}

impl Scene {
    /// Checks the primitives and the leaves.
    ///
    /// # Errors
    /// [`CsgError::InvalidPrimitive`] or [`CsgError::UnknownPrimitive`].
    pub fn new(primitives: Vec<Primitive>, tree: Csg) -> Result<Self, CsgError> {
        validate_primitives(&primitives)?;
        for index in tree.leaves() {
            known(index, primitives.len())?;
        }
        Ok(Self { primitives, tree })
    }

    /// The primitives.
    #[must_use]
    pub fn primitives(&self) -> &[Primitive] {
        &self.primitives
    }

    /// The tree.
    #[must_use]
    pub fn tree(&self) -> &Csg {
        &self.tree
    }
}

/// Valid primitives and a sum of products ready for rendering: every
/// product is non-empty, starts with a positive literal, names each
/// primitive at most once and has at most [`MAX_LITERALS`] literals.
/// The empty sum is the empty solid.
///
/// The "primitives" are whatever the renderers can draw, any
/// [`Solid`]: [`Primitive`]s ([`Model::new`]), or primitives placed by
/// the transformations of a tree ([`Model::with_solids`] over
/// `transforms::Placed`); a literal names one by its index.
#[derive(Clone, Debug, PartialEq)]
pub struct Model<S = Primitive> {
    primitives: Vec<S>,
    products: Vec<Product>,
}

impl Model {
    /// Checks the primitives and the products.
    ///
    /// # Errors
    /// [`CsgError::InvalidPrimitive`], [`CsgError::UnknownPrimitive`] or
    /// [`CsgError::BadProduct`].
    pub fn new(primitives: Vec<Primitive>, products: Vec<Product>) -> Result<Self, CsgError> {
        validate_primitives(&primitives)?;
        Self::with_solids(primitives, products)
    }
}

impl<S: Solid> Model<S> {
    /// Checks the products over `solids`, which the caller vouches for
    /// (each convex, closed and bounded; a [`Primitive`] checked by
    /// [`Primitive::validate`] and moved by an invertible map is).
    ///
    /// # Errors
    /// [`CsgError::UnknownPrimitive`] or [`CsgError::BadProduct`].
    pub fn with_solids(solids: Vec<S>, products: Vec<Product>) -> Result<Self, CsgError> {
        for (index, product) in products.iter().enumerate() {
            let bad = |reason| Err(CsgError::BadProduct { index, reason });
            let Some(first) = product.literals.first() else {
                return bad("it is empty");
            };
            if first.complement {
                return bad("its first literal is a complement (an unbounded solid)");
            }
            if product.literals.len() > MAX_LITERALS {
                return bad("it has more literals than MAX_LITERALS");
            }
            let mut seen = std::collections::BTreeSet::new();
            for l in &product.literals {
                known(l.primitive, solids.len())?;
                if !seen.insert(l.primitive) {
                    return bad("it names a primitive twice");
                }
            }
        }
        Ok(Self {
            primitives: solids,
            products,
        })
    }
}

impl<S> Model<S> {
    /// The primitives (the solids the literals name).
    #[must_use]
    pub fn primitives(&self) -> &[S] {
        &self.primitives
    }

    /// The products.
    #[must_use]
    pub fn products(&self) -> &[Product] {
        &self.products
    }
}
