//! The six planes of the clip volume, the inside test and the
//! intersection parameter: TU Wien sheet "Rasterisierung" (seed 004),
//! §5.2 "Clipping planes" (`ClippingPlane.m`: `getClippingPlanes`,
//! `inside`, `intersect`).
//!
//! The clip volume is the cube of side 2 around the origin *after* the
//! division by `w`, `−1 ≤ x/w, y/w, z/w ≤ 1` (OpenGL's convention, near
//! plane at `z/w = −1`). Before the division, in homogeneous clip space,
//! it is the region `−w ≤ x, y, z ≤ w`, bounded by six planes through the
//! origin of 4D space:
//!
//! ```text
//!   x ≤ w   ⇔  (x, y, z, w) · ( 1,  0,  0, −1) ≤ 0     right
//!  −x ≤ w   ⇔  (x, y, z, w) · (−1,  0,  0, −1) ≤ 0     left
//!   y ≤ w   ⇔  (x, y, z, w) · ( 0,  1,  0, −1) ≤ 0     top
//!  −y ≤ w   ⇔  (x, y, z, w) · ( 0, −1,  0, −1) ≤ 0     bottom
//!   z ≤ w   ⇔  (x, y, z, w) · ( 0,  0,  1, −1) ≤ 0     far
//!  −z ≤ w   ⇔  (x, y, z, w) · ( 0,  0, −1, −1) ≤ 0     near
//! ```
//!
//! Each 4-vector is `(n, −d)` with the outward unit normal `n` and the
//! distance `d = 1` of the cube's face from the origin. A point with
//! `w ≤ 0` (behind the eye) is outside at least one of them unless it is
//! the origin itself.

use canvas::Vec4;

use crate::plane::{CLIP_NUDGE, ClipPlane};

/// The six planes of the clip volume `−w ≤ x, y, z ≤ w`, each as
/// `(n_x, n_y, n_z, −d)` with the outward unit normal and `d = 1`, in the
/// order right, left, top, bottom, far, near (`+x`, `−x`, `+y`, `−y`,
/// `+z`, `−z`).
#[must_use]
#[transcript::task]
pub fn clip_planes() -> [ClipPlane; 6] {
    // BEGIN SOLUTION clip_planes: list the six planes (n, -d) of the cube -w <= x, y, z <= w, outward normals, in the order +x, -x, +y, -y, +z, -z
    [
        Vec4::X,
        Vec4::NEG_X,
        Vec4::Y,
        Vec4::NEG_Y,
        Vec4::Z,
        Vec4::NEG_Z,
    ]
    .map(|normal| ClipPlane::new(normal - Vec4::W))
    // END SOLUTION
}

impl ClipPlane {
    /// Whether `v` lies inside the plane or on it: `v · p ≤ 0`.
    ///
    /// The sheet's hint (§5.2): `inside` *includes* points on the plane, so
    /// a polygon lying in a face of the cube survives clipping. A point
    /// with a NaN coordinate is not inside (the comparison is false).
    #[must_use]
    #[transcript::task]
    pub fn inside(self, v: Vec4) -> bool {
        // BEGIN SOLUTION clip_planes: the inside test v · p <= 0, on the plane included
        self.distance(v) <= 0.0
        // END SOLUTION
    }

    /// The parameter `t` of the point where the edge `a → b` crosses the
    /// plane, `P(t) = (1 − t) · a + t · b`, nudged towards the inside
    /// endpoint; `None` when the edge does not cross.
    ///
    /// With the signed distances `l_a = a · p` and `l_b = b · p`, the point
    /// `P(t)` lies on the plane when `(1 − t) · l_a + t · l_b = 0`
    /// (equation (4)), so (equation (5))
    ///
    /// ```text
    ///   t = l_a / (l_a − l_b)
    /// ```
    ///
    /// The edge crosses when exactly one endpoint is [`inside`](Self::inside)
    /// (then `l_a − l_b ≠ 0`, and `t ∈ [0, 1]`). As the sheet prescribes,
    /// `t` is then moved by [`CLIP_NUDGE`] towards the inside endpoint:
    /// decreased when `a` is inside, increased when `b` is inside; the
    /// result is kept in `[0, 1]`, so that `P(t)` stays on the edge.
    ///
    /// `None` also for non-finite endpoints or distances (NaN, infinities,
    /// overflow).
    #[must_use]
    #[transcript::task]
    pub fn intersect(self, a: Vec4, b: Vec4) -> Option<f32> {
        // BEGIN SOLUTION clip_planes: t = la / (la - lb) when exactly one endpoint is inside, nudged by CLIP_NUDGE towards the inside one and kept in [0, 1]
        let (la, lb) = (self.distance(a), self.distance(b));
        if !(la.is_finite() && lb.is_finite()) {
            return None;
        }
        let (a_inside, b_inside) = (la <= 0.0, lb <= 0.0);
        if a_inside == b_inside {
            return None;
        }
        let t = la / (la - lb);
        // Departs from the sheet: the clamp. When an endpoint lies on the
        // plane (t = 0 or 1) the bare nudge would step off the edge, and the
        // new vertex's colour would no longer be a mix of the endpoints'.
        let nudged = if a_inside {
            t - CLIP_NUDGE
        } else {
            t + CLIP_NUDGE
        };
        Some(nudged.clamp(0.0, 1.0))
        // END SOLUTION
    }
}
