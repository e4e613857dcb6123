//! NURBS surfaces as data: degrees, knot vectors, control points and
//! weights (seed 001, Definition 1.2.4), and nothing that evaluates them
//! (evaluation and knot insertion are topic 08's tasks). These are the
//! surfaces the course's chain starts from: topic 08 splits one into
//! rational Bézier patches ([`crate::RationalPatch`]), topic 09
//! tessellates those on the CPU and topic 10 on the GPU.
//!
//! ```text
//!             Σ_i Σ_j N_i,p(u) N_j,q(v) w_ij P_ij
//!   S(u, v) = ───────────────────────────────────
//!               Σ_i Σ_j N_i,p(u) N_j,q(v) w_ij
//! ```
//!
//! The net is stored as the course stores every net: row `i` along `u`,
//! column `j` along `v`, `P_ij` at `i · columns + j`.
//!
//! - [`NurbsSurfaceData::torus`]: the torus as one NURBS surface, each
//!   direction a circle of four rational quadratic arcs whose interior
//!   knots are already double (its decomposition needs no insertion:
//!   [`crate::RationalPatch::torus`] are its 16 pieces, written out).
//! - [`NurbsSurfaceData::vase`]: a surface of revolution whose profile is a
//!   cubic B-spline with *single* interior knots, so that its
//!   decomposition must insert each of them twice.

use glam::DVec3;

/// `√2 / 2`, the weight of a quarter circle's middle control point.
const HALF_SQRT_2: f64 = std::f64::consts::FRAC_1_SQRT_2;

/// The unit circle as four rational quadratic arcs: nine points `(x, y)`
/// with their weights (the last point is the first), and its knots.
pub(crate) const CIRCLE: [(f64, f64, f64); 9] = [
    (1.0, 0.0, 1.0),
    (1.0, 1.0, HALF_SQRT_2),
    (0.0, 1.0, 1.0),
    (-1.0, 1.0, HALF_SQRT_2),
    (-1.0, 0.0, 1.0),
    (-1.0, -1.0, HALF_SQRT_2),
    (0.0, -1.0, 1.0),
    (1.0, -1.0, HALF_SQRT_2),
    (1.0, 0.0, 1.0),
];
const CIRCLE_KNOTS: [f64; 12] = [
    0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0,
];

/// The vase's profile: radius and height of six control points of a cubic
/// B-spline, from the foot to the lip.
const VASE_PROFILE: [(f64, f64); 6] = [
    (0.45, -0.6),
    (0.85, -0.45),
    (0.25, -0.05),
    (0.3, 0.25),
    (0.75, 0.45),
    (0.6, 0.65),
];
/// Its knots: clamped, with the single interior knots `⅓` and `⅔`.
const VASE_KNOTS: [f64; 10] = [0.0, 0.0, 0.0, 0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0, 1.0, 1.0, 1.0];

/// A NURBS surface's data (module documentation).
#[derive(Clone, Debug, PartialEq)]
pub struct NurbsSurfaceData {
    /// The degree `p` along `u`.
    pub degree_u: usize,
    /// The degree `q` along `v`.
    pub degree_v: usize,
    /// The knot vector along `u`: `rows + p + 1` knots.
    pub knots_u: Vec<f64>,
    /// The knot vector along `v`: `columns + q + 1` knots.
    pub knots_v: Vec<f64>,
    /// The number of rows of the net (points along `u`).
    pub rows: usize,
    /// The number of columns (points along `v`).
    pub columns: usize,
    /// The control points `P_ij`, row by row.
    pub points: Vec<DVec3>,
    /// Their weights `w_ij > 0`, in the same order.
    pub weights: Vec<f64>,
}

impl NurbsSurfaceData {
    /// The torus around the `z` axis, `major` from the axis to the tube's
    /// centre and `minor` the tube's radius (`0 < minor < major`): `u` goes
    /// around the axis from the `x` axis (counter-clockwise seen from
    /// `+z`), `v` around the tube from its outermost circle upwards; a 9 × 9
    /// net of degree 2 × 2 with the knots `0 0 0 ¼ ¼ ½ ½ ¾ ¾ 1 1 1` both
    /// ways (The NURBS Book, §8.5, Example 8.4's construction).
    ///
    /// # Panics
    /// Unless `0 < minor < major`, both finite.
    #[must_use]
    pub fn torus(major: f64, minor: f64) -> Self {
        assert!(
            minor > 0.0 && minor < major && major.is_finite(),
            "a torus needs 0 < minor < major"
        );
        let profile: Vec<(f64, f64, f64)> = CIRCLE
            .iter()
            .map(|&(x, z, w)| (major + minor * x, minor * z, w))
            .collect();
        Self::revolved(&profile, 2, CIRCLE_KNOTS.to_vec())
    }

    /// A vase: the profile curve `(r(v), z(v))`, a cubic B-spline of six
    /// points with the single interior knots `⅓` and `⅔`, revolved about
    /// the `z` axis by the circle of [`Self::torus`] (`u`, degree 2). A 9 ×
    /// 6 net; split into Bézier patches it gives 4 × 3 of degree 2 × 3,
    /// after each interior knot of `v` is inserted twice.
    #[must_use]
    pub fn vase() -> Self {
        let profile: Vec<(f64, f64, f64)> =
            VASE_PROFILE.iter().map(|&(r, z)| (r, z, 1.0)).collect();
        Self::revolved(&profile, 3, VASE_KNOTS.to_vec())
    }

    /// The surface swept by a profile `(radius, height, weight)` of
    /// degree `degree_v` with `knots_v` around the `z` axis: `P_ij` is the
    /// profile's point `j` turned to the circle's point `i`, `w_ij` the
    /// product of their weights (The NURBS Book, §8.5).
    fn revolved(profile: &[(f64, f64, f64)], degree_v: usize, knots_v: Vec<f64>) -> Self {
        let mut points = Vec::with_capacity(CIRCLE.len() * profile.len());
        let mut weights = Vec::with_capacity(points.capacity());
        for &(cx, cy, cw) in &CIRCLE {
            for &(radius, height, w) in profile {
                points.push(DVec3::new(radius * cx, radius * cy, height));
                weights.push(cw * w);
            }
        }
        Self {
            degree_u: 2,
            degree_v,
            knots_u: CIRCLE_KNOTS.to_vec(),
            knots_v,
            rows: CIRCLE.len(),
            columns: profile.len(),
            points,
            weights,
        }
    }

    /// The number of Bézier pieces along `u` and along `v`: the non-empty
    /// spans of each knot vector.
    #[must_use]
    pub fn pieces(&self) -> (usize, usize) {
        let spans = |knots: &[f64]| knots.windows(2).filter(|w| w[0] < w[1]).count();
        (spans(&self.knots_u), spans(&self.knots_v))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_nets_fit_their_knots() {
        for data in [NurbsSurfaceData::torus(2.0, 0.5), NurbsSurfaceData::vase()] {
            assert_eq!(data.knots_u.len(), data.rows + data.degree_u + 1);
            assert_eq!(data.knots_v.len(), data.columns + data.degree_v + 1);
            assert_eq!(data.points.len(), data.rows * data.columns);
            assert_eq!(data.weights.len(), data.points.len());
            assert!(data.weights.iter().all(|&w| w > 0.0));
        }
        assert_eq!(NurbsSurfaceData::torus(2.0, 0.5).pieces(), (4, 4));
        assert_eq!(NurbsSurfaceData::vase().pieces(), (4, 3));
    }

    #[test]
    fn the_vases_interior_knots_are_single_and_the_torus_double() {
        let interior = |knots: &[f64], value: f64| knots.iter().filter(|&&k| k == value).count();
        let vase = NurbsSurfaceData::vase();
        assert_eq!(interior(&vase.knots_v, 1.0 / 3.0), 1);
        assert_eq!(interior(&vase.knots_v, 2.0 / 3.0), 1);
        let torus = NurbsSurfaceData::torus(2.0, 0.5);
        assert_eq!(interior(&torus.knots_u, 0.5), 2);
        assert_eq!(interior(&torus.knots_v, 0.25), 2);
    }

    #[test]
    fn the_torus_nets_corner_points_lie_on_the_torus() {
        // The net's points with weight 1 are points of the surface (the
        // ends of the arcs); every one of them is on the torus.
        let (major, minor) = (2.0, 0.5);
        let torus = NurbsSurfaceData::torus(major, minor);
        for (p, &w) in torus.points.iter().zip(&torus.weights) {
            if w == 1.0 {
                let off = ((p.x.hypot(p.y) - major).hypot(p.z) - minor).abs();
                assert!(off < 1e-12, "{p} is {off} off the torus");
            }
        }
    }
}
