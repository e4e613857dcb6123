//! Affine transformations at the nodes of a CSG tree (seed 003, §2.1 "Der
//! CSG-Baum": "jeder Knoten stellt eine CSG-Operation dar, die
//! gegebenenfalls um eine affine Transformation ergänzt werden kann").
//!
//! A [`Node::Transform`] moves the solid below it: `M(X)` is the set of
//! points `M·p` for `p ∈ X`. Nothing else changes, so the other tasks keep
//! working on plain trees: [`flatten`] pushes the transforms down to the
//! leaves, each leaf becoming an [`Instance`] (a primitive and the product
//! of the transforms above it), and a plain [`Csg`] over the instances
//! remains. Two questions are then answered in the primitive's own space:
//!
//! ```text
//!   point:  P ∈ M(X)  ⟺  M⁻¹·P ∈ X
//!   ray:    o + t·d meets M(X) at t  ⟺  M⁻¹o + t·(M⁻¹d) meets X at t
//! ```
//!
//! An affine map keeps the ray's parameter, so depths need no
//! transforming back, but `M⁻¹d` is not a unit vector where `M` scales,
//! while [`Primitive::interval`] takes a unit direction: along
//! `d' = M⁻¹d / |M⁻¹d|` the depth `t'` is `t · |M⁻¹d|`.
//!
//! The image-based renderers draw the instances too: a [`Placed`]
//! primitive is a [`Solid`] whose span is [`instance_interval`]'s, so
//! `Model::with_solids` over them is drawn by Goldfeather as it is (the
//! seed's model matrix at each node, pushed down to the primitives).
//!
//! Convention: glam's `Affine3A` maps column vectors, `(A · B)·p =
//! A·(B·p)`: in `Transform(A, Transform(B, X))` the inner `B` moves `X`
//! first, then `A` moves the result.

use glam::{Affine3A, Vec3};

use crate::csg::Csg;
use crate::primitive::{Primitive, Ray, RayInterval};
use crate::raster::Solid;

/// A CSG tree whose nodes may carry an affine transformation.
#[derive(Clone, Debug, PartialEq)]
pub enum Node {
    /// Primitive number `i` of the scene.
    Leaf(usize),
    /// `X ∪ Y`.
    Union(Box<Node>, Box<Node>),
    /// `X ∩ Y`.
    Intersection(Box<Node>, Box<Node>),
    /// `X − Y`.
    Difference(Box<Node>, Box<Node>),
    /// `M(X)`: the solid `X` moved by the affine map `M` (into the space
    /// of the node above).
    Transform(Affine3A, Box<Node>),
}

impl Node {
    /// Primitive number `index`.
    #[must_use]
    pub fn leaf(index: usize) -> Self {
        Self::Leaf(index)
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

    /// `m(x)`.
    #[must_use]
    pub fn transform(m: Affine3A, x: Self) -> Self {
        Self::Transform(m, Box::new(x))
    }

    /// Whether every leaf names one of `primitives` primitives and every
    /// transform is finite and invertible (`|det| > 1e-6` of its linear
    /// part): what [`flatten`], [`instance_interval`] and [`contains`]
    /// assume.
    pub fn check(&self, primitives: usize) -> Result<(), TransformError> {
        match self {
            Self::Leaf(i) if *i < primitives => Ok(()),
            Self::Leaf(i) => Err(TransformError::UnknownPrimitive(*i)),
            Self::Union(x, y) | Self::Intersection(x, y) | Self::Difference(x, y) => {
                x.check(primitives)?;
                y.check(primitives)
            }
            Self::Transform(m, x) => {
                if !m.is_finite() {
                    return Err(TransformError::NotFinite);
                }
                if m.matrix3.determinant().abs() <= 1e-6 {
                    return Err(TransformError::Singular);
                }
                x.check(primitives)
            }
        }
    }
}

/// Why a tree with transforms cannot be used.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum TransformError {
    /// A leaf names a primitive the scene does not have.
    #[error("the tree names primitive {0}, which the scene does not have")]
    UnknownPrimitive(usize),
    /// A transform has a NaN or infinite entry.
    #[error("a transform has a NaN or infinite entry")]
    NotFinite,
    /// A transform flattens space (its determinant is about 0): it has no
    /// inverse.
    #[error("a transform is singular: it has no inverse")]
    Singular,
}

/// A primitive placed by the transforms above its leaf.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Instance {
    /// The primitive's index in the scene.
    pub primitive: usize,
    /// Its space to the root's: the product of the transforms on the path
    /// from the root to the leaf, the root's leftmost.
    pub to_world: Affine3A,
}

/// A primitive moved into the root's space by an instance's map: what the
/// image-based renderers draw for an [`Instance`] (`Model::with_solids`).
/// Its span along a viewing ray is [`instance_interval`]'s.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placed {
    /// The primitive, in its own space.
    pub primitive: Primitive,
    /// Its space to the root's.
    pub to_world: Affine3A,
}

impl Placed {
    /// The instances of [`flatten`] as solids, in order: literal `i` of a
    /// product of the flattened tree names `placed[i]`. `None` if an
    /// instance names a primitive `primitives` does not have.
    #[must_use]
    pub fn instances(primitives: &[Primitive], instances: &[Instance]) -> Option<Vec<Self>> {
        instances
            .iter()
            .map(|instance| {
                Some(Self {
                    primitive: *primitives.get(instance.primitive)?,
                    to_world: instance.to_world,
                })
            })
            .collect()
    }
}

impl Solid for Placed {
    /// [`instance_interval`] of the primitive and its map.
    fn span(&self, ray: &Ray) -> Option<RayInterval> {
        instance_interval(&self.primitive, self.to_world, ray)
    }
}

/// Pushes the transforms down to the leaves: every leaf becomes an
/// [`Instance`] with the product of the transforms on its path (outermost
/// leftmost: `Transform(A, Transform(B, leaf))` gives `A · B`, the
/// identity for a leaf without any), numbered left to right as the leaves
/// appear in the tree; the returned tree is `node` without its transforms,
/// its leaves naming the instances. A primitive under two transforms
/// becomes two instances.
#[must_use]
#[transcript::task]
pub fn flatten(node: &Node) -> (Vec<Instance>, Csg) {
    // Unused until you write the body:
    let _ = &node;
    todo!(
        "transforms: walk the tree carrying the product of the transforms so far (parent · node), each leaf becoming the next instance"
    )
}

/// Where `ray` runs through `primitive` moved by `to_world`, in the ray's
/// own depths: the ray taken into the primitive's space by the inverse
/// (`o' = M⁻¹·o` as a point, `M⁻¹·d` as a direction), made a unit
/// direction `d'` for [`Primitive::interval`], and that interval's depths
/// `t'` divided by `|M⁻¹·d|`. `None` where the ray misses (or `to_world`
/// has no inverse).
#[must_use]
#[transcript::task]
pub fn instance_interval(
    primitive: &Primitive,
    to_world: Affine3A,
    ray: &Ray,
) -> Option<RayInterval> {
    // Unused until you write the body:
    let _ = (&primitive, &to_world, &ray);
    todo!(
        "transforms: the ray into the primitive's space by the inverse, its direction made unit, the interval's depths divided by that length"
    )
}

/// Whether `p` belongs to the solid of `node`, by the seed's three rules
/// (as `classify::contains`) and `P ∈ M(X) ⟺ M⁻¹·P ∈ X` at a transform;
/// `inside(i, q)` says whether `q` belongs to primitive `i` in its own
/// space.
#[transcript::task]
pub fn contains(node: &Node, p: Vec3, inside: &impl Fn(usize, Vec3) -> bool) -> bool {
    // Unused until you write the body:
    let _ = (&node, &p, &inside);
    todo!("transforms: recurse with the three rules; at a transform, ask the child about M⁻¹·p")
}
