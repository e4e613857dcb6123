//! Point classification: is a point inside a primitive, on its surface or
//! outside it, and is it in the solid a CSG tree describes? Seed 003,
//! §2.2 "Klassifikation".

use glam::Vec3;

use crate::csg::{Csg, Scene};
use crate::primitive::Primitive;

/// Where a point lies relative to a closed solid.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Class {
    /// In the interior.
    Inside,
    /// On the surface (it still belongs to the solid: seed §2.2).
    On,
    /// Not in the solid.
    Outside,
}

/// Classifies `p` against `primitive`, comparing exactly (no tolerance).
///
/// ```text
///   cuboid    min ≤ p ≤ max componentwise; On when some coordinate
///             equals its bound
///   sphere    |p − c|² compared with r²
///   cylinder  along = (p − c)·e, across² = |p − c|² − along² … computed
///             as |(p − c) − along·e|²; Inside when |along| < h and
///             across² < r², On when both are ≤ and one is =
/// ```
///
/// A point with a NaN coordinate is `Outside` everything.
#[must_use]
#[transcript::task]
pub fn classify_point(primitive: &Primitive, p: Vec3) -> Class {
    // BEGIN SOLUTION classify: compare p with the box bounds, |p − c|² with r², or the cylinder's two tests
    if p.is_nan() {
        return Class::Outside;
    }
    // Two conditions "a ≤ b", each strict (Inside) or tight (On).
    let combine = |conditions: &[(f32, f32)]| {
        // `a <= b` is false for NaN, so a NaN anywhere gives Outside.
        if !conditions.iter().all(|&(a, b)| a <= b) {
            Class::Outside
        } else if conditions.iter().all(|&(a, b)| a < b) {
            Class::Inside
        } else {
            Class::On
        }
    };
    match *primitive {
        Primitive::Cuboid { min, max } => combine(&[
            (min.x, p.x),
            (p.x, max.x),
            (min.y, p.y),
            (p.y, max.y),
            (min.z, p.z),
            (p.z, max.z),
        ]),
        Primitive::Sphere { centre, radius } => {
            combine(&[((p - centre).length_squared(), radius * radius)])
        }
        Primitive::Cylinder {
            centre,
            axis,
            radius,
            half_length,
        } => {
            let e = axis.unit();
            let along = (p - centre).dot(e);
            let across = (p - centre) - along * e;
            combine(&[
                (along.abs(), half_length),
                (across.length_squared(), radius * radius),
            ])
        }
    }
    // END SOLUTION
}

/// Whether `p` belongs to the solid of `scene`'s tree, by the seed's three
/// rules applied recursively (a point `On` a primitive counts as in it):
///
/// ```text
///   P ∈ X ∩ Y  ⟺  P ∈ X ∧ P ∈ Y
///   P ∈ X ∪ Y  ⟺  P ∈ X ∨ P ∈ Y
///   P ∈ X − Y  ⟺  P ∈ X ∧ P ∉ Y
/// ```
///
/// These rules do not regularize: a point on the surface of `Y` is not in
/// `X − Y`. A point with a NaN coordinate is in nothing.
#[must_use]
#[transcript::task]
pub fn contains(scene: &Scene, p: Vec3) -> bool {
    // BEGIN SOLUTION classify: evaluate the tree recursively with the three rules, On counts as inside
    fn member(tree: &Csg, primitives: &[Primitive], p: Vec3) -> bool {
        match tree {
            Csg::Primitive(i) => primitives
                .get(*i)
                .is_some_and(|prim| classify_point(prim, p) != Class::Outside),
            Csg::Union(x, y) => member(x, primitives, p) || member(y, primitives, p),
            Csg::Intersection(x, y) => member(x, primitives, p) && member(y, primitives, p),
            Csg::Difference(x, y) => member(x, primitives, p) && !member(y, primitives, p),
        }
    }
    member(scene.tree(), scene.primitives(), p)
    // END SOLUTION
}
