//! A plane of homogeneous clip space in Hesse normal form, stored as a
//! 4-vector: TU Wien sheet "Rasterisierung" (seed 004), §5.2 "Clipping
//! planes", equations (2)–(5).
//!
//! This module is given: task 1 adds `inside` and `intersect` to
//! [`ClipPlane`] and lists the six planes of the clip volume.

use canvas::Vec4;

/// How far an intersection parameter `t` is moved towards the inside
/// endpoint of the edge, as the sheet prescribes (§5.2): "because of
/// numerical inaccuracies", a vertex computed exactly on the plane may come
/// out a rounding error *outside* it and be cut again by a later pass. The
/// nudge is in the parameter, so it moves the new vertex by
/// `1e-6 · |l_a − l_b|` in signed distance: far more than the rounding
/// error of `t` near 1 (`f32::EPSILON / 2 ≈ 6e-8`).
///
/// A limit of the sheet's method: the nudge is relative to the *edge*, so it
/// moves the new vertex by `1e-6` of the edge's length. For edges of the
/// size of the clip volume that is far below a pixel; an edge `10⁶` times
/// longer than the volume is wide has its crossing moved by a whole volume
/// width (a nudge in signed distance, `l = −1e-6 · w`, would not have this
/// limit).
pub const CLIP_NUDGE: f32 = 1e-6;

/// The largest clip-space coordinate (absolute value) clipping accepts:
/// signed distances (sums of four coordinates) and edge vectors
/// (differences of two) stay far from `f32::MAX ≈ 3.4e38`, so no
/// intermediate value overflows to infinity.
pub const MAX_CLIP_COORD: f32 = 1e18;

/// A plane `p = (n_x, n_y, n_z, −d)` of homogeneous clip space.
///
/// A point `v = (x, y, z, w)` lies
///
/// ```text
///   inside  the plane when  v · p < 0
///   on      the plane when  v · p = 0
///   outside the plane when  v · p > 0
/// ```
///
/// For a point with `w = 1` this is the sheet's equation (3),
/// `(v_x, v_y, v_z, 1) · (n_x, n_y, n_z, −d)`: the signed distance
/// `v · n − d` to the plane with normal `n` (pointing *outwards*) and
/// distance `d` from the origin. In clip space `w ≠ 1`, and the same dot
/// product with the point's own `w` tests the point *before* the division
/// by `w` (the sheet writes `1` for the last component, which holds only
/// after homogenization): `x − w ≤ 0` is `x / w ≤ 1` for `w > 0`.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipPlane {
    /// `(n_x, n_y, n_z, −d)`: the outward normal and the negative distance.
    pub vector: Vec4,
}

impl ClipPlane {
    /// The plane with the given 4-vector `(n_x, n_y, n_z, −d)`.
    #[must_use]
    pub const fn new(vector: Vec4) -> Self {
        Self { vector }
    }

    /// The signed distance `l = v · p` of a clip-space point (in units of
    /// the normal's length): negative inside, zero on, positive outside.
    #[must_use]
    #[inline]
    pub fn distance(self, v: Vec4) -> f32 {
        v.dot(self.vector)
    }
}
