//! The edge tests of fully adaptive tessellation (seed 001 §2.2, "Normalni
//! testovi uspoređivanja" and "Testovi glatkoće", equations (2.1)–(2.7)).
//!
//! A test looks at one edge `V1–V2` of the current mesh and the new vertex
//! `V12 = S((uv1 + uv2)/2)` that would split it, and answers whether the
//! edge must be split (the seed's "the test fails"). Normal tests compare
//! unit normals (`N1`, `N2`, `N12`, neighbours'); flatness tests look at
//! positions. Every test has its thresholds as parameters.
//!
//! ```text
//!          V6                  first-order neighbours of the edge V1–V2:
//!        ╱    ╲                every vertex joined to V1 or V2 by an edge
//!   V5 ─ V1 ─V12─ V2 ─ V7      (V1, V2 included); V6 and V10 are the
//!        ╲    ╱                vertices opposite the edge in the two
//!          V10                 triangles that share it (Figure 2.7)
//! ```

#[allow(unused_imports)]
use glam::DVec3;

use crate::bezier::SurfaceSample;
use crate::error::TessError;

/// What an edge test may look at.
#[derive(Clone, Copy, Debug)]
pub struct EdgeContext<'a> {
    /// The first end point `V1`.
    pub v1: SurfaceSample,
    /// The second end point `V2`.
    pub v2: SurfaceSample,
    /// The candidate vertex `V12`, on the surface at the parameter midpoint.
    pub mid: SurfaceSample,
    /// The vertices opposite the edge in the triangles that share it (`V6`
    /// and `V10`; one on the boundary of the mesh).
    pub opposite: &'a [SurfaceSample],
    /// The first-order neighbourhood of the edge: `V1`, `V2` and every
    /// vertex joined to either by an edge, each once.
    pub ring: &'a [SurfaceSample],
    /// The vertices joined to `V1` by an edge (`V2` among them).
    pub neighbours1: &'a [SurfaceSample],
    /// The vertices joined to `V2` by an edge (`V1` among them).
    pub neighbours2: &'a [SurfaceSample],
}

/// The seven tests, each with the seed's thresholds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum EdgeTest {
    /// (2.1) `|N1 − N12| > t1 ∨ |N2 − N12| > t1`.
    OneEdgeNormal {
        /// `t1`.
        t1: f64,
    },
    /// (2.3) (2.1) `∨ |N1 − N2| > t2`.
    OneEdgeComplementary {
        /// `t1`, for the comparisons with `N12`.
        t1: f64,
        /// `t2`, for the comparison of the end points' normals.
        t2: f64,
    },
    /// (2.4) `|N12 − N'| > t3` with `N'` the mean of `N1`, `N2` and the
    /// normals of the opposite vertices.
    TwoTriangle {
        /// `t3`.
        t3: f64,
    },
    /// (2.5) `|N12 − N''| > t3` with `N''` the mean normal of the edge's
    /// first-order neighbourhood.
    FirstOrderNeighbour {
        /// `t3`.
        t3: f64,
    },
    /// (2.6) the sub-chords `V1→V12` and `V12→V2` deviate from the chord
    /// `V1→V2`: `1 − cos` of either angle `> t1`.
    VectorDeviationFlat {
        /// `t1`.
        t1: f64,
    },
    /// `|U · N1| > t1 ∨ |U · N2| > t1` with `U` the unit edge direction.
    LocalFlat {
        /// `t1`.
        t1: f64,
    },
    /// (2.7) `|Û1 · N1| > t1 ∨ |Û2 · N2| > t1` with `Û` the unit umbrella
    /// operator at each end point.
    UmbrellaFlat {
        /// `t1`.
        t1: f64,
    },
}

impl EdgeTest {
    /// The thresholds of this test.
    #[must_use]
    pub fn thresholds(&self) -> Vec<f64> {
        match *self {
            Self::OneEdgeNormal { t1 }
            | Self::VectorDeviationFlat { t1 }
            | Self::LocalFlat { t1 }
            | Self::UmbrellaFlat { t1 } => vec![t1],
            Self::OneEdgeComplementary { t1, t2 } => vec![t1, t2],
            Self::TwoTriangle { t3 } | Self::FirstOrderNeighbour { t3 } => vec![t3],
        }
    }

    /// Checks that every threshold is a positive finite number.
    ///
    /// # Errors
    /// [`TessError::NotPositive`] naming the first bad threshold.
    pub fn validate(&self) -> Result<(), TessError> {
        match self
            .thresholds()
            .into_iter()
            .find(|t| !(t.is_finite() && *t > 0.0))
        {
            Some(value) => Err(TessError::NotPositive {
                what: "an edge test threshold",
                value,
            }),
            None => Ok(()),
        }
    }

    /// Whether this test splits the edge: dispatches to the functions below.
    #[must_use]
    pub fn must_split(&self, edge: &EdgeContext) -> bool {
        match *self {
            Self::OneEdgeNormal { t1 } => one_edge_normal(edge, t1),
            Self::OneEdgeComplementary { t1, t2 } => one_edge_complementary(edge, t1, t2),
            Self::TwoTriangle { t3 } => two_triangle(edge, t3),
            Self::FirstOrderNeighbour { t3 } => first_order_neighbour(edge, t3),
            Self::VectorDeviationFlat { t1 } => vector_deviation_flat(edge, t1),
            Self::LocalFlat { t1 } => local_flat(edge, t1),
            Self::UmbrellaFlat { t1 } => umbrella_flat(edge, t1),
        }
    }
}

/// One-edge normal test (2.1): split when `|N1 − N12| > t1` or
/// `|N2 − N12| > t1` (distances of unit normals).
#[must_use]
#[transcript::task]
pub fn one_edge_normal(edge: &EdgeContext, t1: f64) -> bool {
    // Unused until you write the body:
    let _ = (&edge, &t1);
    todo!("fully_adaptive: compare both end normals with the midpoint normal")
}

/// Complementary one-edge test (2.3): the one-edge test with `t1`, or
/// `|N1 − N2| > t2`. (The seed's listing 2.3 returns early when (2.1)
/// fails, which is the same "or".)
#[must_use]
#[transcript::task]
pub fn one_edge_complementary(edge: &EdgeContext, t1: f64, t2: f64) -> bool {
    // Unused until you write the body:
    let _ = (&edge, &t1, &t2);
    todo!("fully_adaptive: (2.1), or the end normals differ by more than t2")
}

/// Two-triangle test (2.4): split when `|N12 − N'| > t3` with
/// `N' = (N1 + N2 + N6 + N10) / 4`, the mean over the end points and the
/// opposite vertices (`(N1 + N2 + N6) / 3` on the boundary). Like the seed,
/// `N'` is not normalised.
#[must_use]
#[transcript::task]
pub fn two_triangle(edge: &EdgeContext, t3: f64) -> bool {
    // Unused until you write the body:
    let _ = (&edge, &t3);
    todo!("fully_adaptive: mean of the end and opposite normals against N12")
}

/// First-order neighbour test (2.5): split when `|N12 − N''| > t3` with
/// `N'' = Σ N_i / n` over the `n` vertices of the edge's first-order
/// neighbourhood ([`EdgeContext::ring`]); an empty ring never splits.
#[must_use]
#[transcript::task]
pub fn first_order_neighbour(edge: &EdgeContext, t3: f64) -> bool {
    // Unused until you write the body:
    let _ = (&edge, &t3);
    todo!("fully_adaptive: mean normal of the ring against N12")
}

/// Vector-deviation flatness test (2.6): with the unit chord
/// `e = (V2 − V1)/|V2 − V1|`, split when `1 − ê·(V12 − V1)/|V12 − V1| > t1`
/// or `1 − ê·(V2 − V12)/|V2 − V12| > t1`: the new vertex pulls either
/// sub-chord away from the chord. A zero-length vector never splits.
///
/// Departure from the seed: (2.6) and listing 2.4 split when a dot product
/// of *unnormalised* vectors is *below* `t1`, and the listing takes the
/// average of the end points (a point on the chord) as `V12`, so it splits
/// short edges rather than curved ones; here `V12` lies on the surface and
/// the vectors are normalised, as the text describes.
#[must_use]
#[transcript::task]
pub fn vector_deviation_flat(edge: &EdgeContext, t1: f64) -> bool {
    // Unused until you write the body:
    let _ = (&edge, &t1);
    todo!("fully_adaptive: angle of each sub-chord against the chord")
}

/// Local flatness test: with the unit edge direction
/// `U = (V1 − V2)/|V1 − V2|`, split when `|U · N1| > t1` or `|U · N2| > t1`
/// (on a flat piece the edge is perpendicular to both normals). A
/// zero-length edge never splits.
///
/// Departure from the seed: listing 2.5 compares the product of the
/// *lengths* `|N1|·|V1 − V2|` with `t1` instead of the dot product the text
/// describes.
#[must_use]
#[transcript::task]
pub fn local_flat(edge: &EdgeContext, t1: f64) -> bool {
    // Unused until you write the body:
    let _ = (&edge, &t1);
    todo!("fully_adaptive: the unit edge against both end normals")
}

/// Umbrella-operator flatness test (Definition 2.2.1): with
/// `U(V) = (1/n) Σ V_i − V` over the `n` neighbours of `V`, normalised,
/// split when `|Û(V1) · N1| > t1` or `|Û(V2) · N2| > t1` (on a flat piece
/// the umbrella lies in the tangent plane). A vertex without neighbours or
/// with a zero umbrella does not split.
#[must_use]
#[transcript::task]
pub fn umbrella_flat(edge: &EdgeContext, t1: f64) -> bool {
    // Unused until you write the body:
    let _ = (&edge, &t1);
    todo!("fully_adaptive: unit umbrella vector at each end against its normal")
}
