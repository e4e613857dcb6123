//! Point classification: is a point inside a primitive, on its surface or
//! outside it, and is it in the solid a CSG tree describes? Seed 003,
//! §2.2 "Klassifikation".

use glam::Vec3;

#[allow(unused_imports)]
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
    // Unused until you write the body:
    let _ = (&primitive, &p);
    todo!("classify: compare p with the box bounds, |p − c|² with r², or the cylinder's two tests")
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
    // Unused until you write the body:
    let _ = (&scene, &p);
    todo!("classify: evaluate the tree recursively with the three rules, On counts as inside")
}
