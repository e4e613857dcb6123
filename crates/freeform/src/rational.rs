//! The rational tensor-product Bézier patch (seed 001, Definition 1.1.4
//! with its weights): what a NURBS surface becomes when it is split into
//! Bézier patches (topic 08's knot insertion), and what topic 09
//! tessellates.
//!
//! ```text
//!             Σ_i Σ_j B_i,p(u) B_j,q(v) w_ij P_ij
//!   S(u, v) = ───────────────────────────────────        w_ij > 0
//!               Σ_i Σ_j B_i,p(u) B_j,q(v) w_ij
//! ```
//!
//! In homogeneous coordinates `(w·P, w)` the numerator and the denominator
//! are two polynomial patches, `A(u, v)` with the points `w_ij P_ij` and
//! `W(u, v)` with the numbers `w_ij`, and `S = A / W`: this module keeps
//! them as two [`BezierPatch`]es (`W`'s numbers in the `x` coordinate),
//! so that whatever evaluates a polynomial patch evaluates both.
//!
//! Only the data lives here: [`RationalPatch::torus`] is a NURBS torus
//! already split into its 16 biquadratic patches, written out (the
//! splitting is topic 08's task).

use glam::DVec3;

use crate::patch::{BezierPatch, PatchError};

/// A rational Bézier patch: its control points and a positive weight for
/// each (module documentation).
#[derive(Clone, Debug, PartialEq)]
pub struct RationalPatch {
    points: BezierPatch,
    weights: Vec<f64>,
    /// `A`: the points `w_ij P_ij`.
    numerator: BezierPatch,
    /// `W`: the weights, in `x`.
    denominator: BezierPatch,
}

impl RationalPatch {
    /// The patch with control points `points` and `weights`, row by row as
    /// the points (`w_ij` at `i · (q + 1) + j`).
    ///
    /// Weights must be finite and positive: the seed allows `w ≥ 0`, but a
    /// zero weight lets the denominator vanish at a corner, where `S` is
    /// not defined.
    ///
    /// # Errors
    /// [`PatchError::Shape`] for a wrong number of weights,
    /// [`PatchError::Weight`] for one that is not finite and positive.
    pub fn try_new(points: BezierPatch, weights: Vec<f64>) -> Result<Self, PatchError> {
        let (p, q) = (points.degree_u(), points.degree_v());
        if weights.len() != points.control_points().len() {
            return Err(PatchError::Shape {
                degree_u: p,
                degree_v: q,
                expected: points.control_points().len(),
                found: weights.len(),
            });
        }
        if let Some(index) = weights.iter().position(|w| !(w.is_finite() && *w > 0.0)) {
            return Err(PatchError::Weight { index });
        }
        let numerator = BezierPatch::from_fn(p, q, |i, j| {
            weights[i * (q + 1) + j] * points.control_point(i, j)
        })?;
        let denominator =
            BezierPatch::from_fn(p, q, |i, j| DVec3::new(weights[i * (q + 1) + j], 0.0, 0.0))?;
        Ok(Self {
            points,
            weights,
            numerator,
            denominator,
        })
    }

    /// A polynomial patch as a rational one: every weight 1.
    #[must_use]
    pub fn polynomial(points: BezierPatch) -> Self {
        let weights = vec![1.0; points.control_points().len()];
        Self::try_new(points, weights).expect("weights of 1 are valid")
    }

    /// The control points `P_ij` (not weighted).
    #[must_use]
    pub fn points(&self) -> &BezierPatch {
        &self.points
    }

    /// The weight `w_ij`.
    ///
    /// # Panics
    /// If `i > p` or `j > q`.
    #[must_use]
    pub fn weight(&self, i: usize, j: usize) -> f64 {
        let q = self.points.degree_v();
        assert!(i <= self.points.degree_u() && j <= q, "weight out of range");
        self.weights[i * (q + 1) + j]
    }

    /// The weights, row by row.
    #[must_use]
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// `A`, the numerator: the polynomial patch of the points `w_ij P_ij`.
    #[must_use]
    pub fn numerator(&self) -> &BezierPatch {
        &self.numerator
    }

    /// `W`, the denominator: the polynomial patch of the weights, each in
    /// the `x` coordinate of its control point (`y = z = 0`).
    #[must_use]
    pub fn denominator(&self) -> &BezierPatch {
        &self.denominator
    }

    /// The same surface with both degrees raised by one (degree
    /// elevation, exact in homogeneous coordinates): with `h_i = (w_i P_i,
    /// w_i)` along each direction of degree `n`,
    ///
    /// ```text
    ///   h'_i = i/(n+1) · h_(i−1) + (1 − i/(n+1)) · h_i,   i = 0 … n+1
    /// ```
    ///
    /// so that, say, the biquadratic torus patches become the bicubic ones
    /// a GPU buffer of 16 points holds.
    ///
    /// # Errors
    /// [`PatchError::DegreeTooHigh`] above [`crate::patch::MAX_DEGREE`].
    pub fn elevated(&self) -> Result<Self, PatchError> {
        self.raised(true, true)
    }

    /// The same surface with its degrees raised to `p × q` (each at least
    /// the patch's own), one step at a time as [`Self::elevated`] does:
    /// a patch of a NURBS surface of degree 2 × 3 becomes the bicubic
    /// patch a GPU buffer of 16 points holds.
    ///
    /// # Errors
    /// [`PatchError::DegreeTooHigh`] above [`crate::patch::MAX_DEGREE`],
    /// [`PatchError::Lower`] below the patch's own degree.
    pub fn elevated_to(&self, p: usize, q: usize) -> Result<Self, PatchError> {
        let mut patch = self.clone();
        loop {
            let (pu, qv) = (patch.points.degree_u(), patch.points.degree_v());
            if pu > p || qv > q {
                return Err(PatchError::Lower {
                    degree_u: pu,
                    degree_v: qv,
                    to_u: p,
                    to_v: q,
                });
            }
            if (pu, qv) == (p, q) {
                return Ok(patch);
            }
            patch = patch.raised(pu < p, qv < q)?;
        }
    }

    /// The degree along `u` raised by one if `in_u`, along `v` if `in_v`.
    fn raised(&self, in_u: bool, in_v: bool) -> Result<Self, PatchError> {
        let (p, q) = (self.points.degree_u(), self.points.degree_v());
        let h = |i: usize, j: usize| {
            let w = self.weight(i, j);
            (w * self.points.control_point(i, j), w)
        };
        // Raise one index of degree n: the point at i of the raised curve
        // (or the point itself, when that direction keeps its degree).
        let raise = |raised: bool, n: usize, i: usize, at: &dyn Fn(usize) -> (DVec3, f64)| {
            if !raised {
                return at(i);
            }
            let a = i as f64 / (n + 1) as f64;
            let (lo, hi) = (
                if i > 0 { at(i - 1) } else { (DVec3::ZERO, 0.0) },
                if i <= n { at(i) } else { (DVec3::ZERO, 0.0) },
            );
            (a * lo.0 + (1.0 - a) * hi.0, a * lo.1 + (1.0 - a) * hi.1)
        };
        let (p2, q2) = (p + usize::from(in_u), q + usize::from(in_v));
        let both = |i: usize, j: usize| raise(in_u, p, i, &|k| raise(in_v, q, j, &|l| h(k, l)));
        let homogeneous: Vec<(DVec3, f64)> = (0..=p2)
            .flat_map(|i| (0..=q2).map(move |j| (i, j)))
            .map(|(i, j)| both(i, j))
            .collect();
        let points =
            BezierPatch::try_new(p2, q2, homogeneous.iter().map(|&(a, w)| a / w).collect())?;
        Self::try_new(points, homogeneous.iter().map(|&(_, w)| w).collect())
    }

    /// A torus around the `z` axis, `major` from the axis to the tube's
    /// centre and `minor` the tube's radius (`0 < minor < major`), as the
    /// 16 biquadratic rational patches a NURBS torus splits into: patch
    /// `4·row + col` sweeps the quarter `col` of the circle around the axis
    /// (`u`, from the `x` axis counter-clockwise seen from `+z`) and the
    /// quarter `row` of the tube (`v`, from its outermost circle upwards).
    /// Neighbours share their boundary control points and weights, so the
    /// 16 patches meet without a gap; every point of every patch lies on
    /// the torus `(√(x² + y²) − major)² + z² = minor²`.
    ///
    /// # Panics
    /// Unless `0 < minor < major`, both finite.
    #[must_use]
    pub fn torus(major: f64, minor: f64) -> Vec<Self> {
        assert!(
            minor > 0.0 && minor < major && major.is_finite(),
            "a torus needs 0 < minor < major"
        );
        // The unit circle's 9 points and weights ([`crate::nurbs::CIRCLE`]):
        // quarter k on points 2k, 2k+1, 2k+2.
        let circle = crate::nurbs::CIRCLE;
        let mut patches = Vec::with_capacity(16);
        for row in 0..4 {
            for col in 0..4 {
                // P_ij: the tube's point j of quarter `row`, swept to the
                // axis circle's point i of quarter `col`.
                let point = |i: usize, j: usize| {
                    let (cx, cy, _) = circle[2 * col + i];
                    let (tx, tz, _) = circle[2 * row + j];
                    let radius = major + minor * tx;
                    DVec3::new(radius * cx, radius * cy, minor * tz)
                };
                let points = BezierPatch::from_fn(2, 2, point).expect("a 2 × 2 net");
                let weights = (0..3)
                    .flat_map(|i| (0..3).map(move |j| (i, j)))
                    .map(|(i, j)| circle[2 * col + i].2 * circle[2 * row + j].2)
                    .collect();
                patches.push(Self::try_new(points, weights).expect("positive weights"));
            }
        }
        patches
    }
}

// A patch crosses between a task and its test (topic 08's decomposition):
// its degrees, points and weights are recorded, and the replay builds it
// again through `try_new`, so that a replayed patch is as valid as any.
impl transcript::Record for RationalPatch {
    fn record(&self, out: &mut Vec<u8>) {
        self.points.degree_u().record(out);
        self.points.degree_v().record(out);
        self.points.control_points().record(out);
        self.weights.record(out);
    }
}

impl transcript::Replay for RationalPatch {
    fn replay(input: &mut &[u8]) -> Result<Self, String> {
        let degree_u = usize::replay(input)?;
        let degree_v = usize::replay(input)?;
        let points = Vec::<DVec3>::replay(input)?;
        let weights = Vec::<f64>::replay(input)?;
        BezierPatch::try_new(degree_u, degree_v, points)
            .and_then(|points| Self::try_new(points, weights))
            .map_err(|error| format!("a rational patch that is none: {error}"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `S(u, v)` by the definition (Bernstein sums), for the tests.
    fn evaluate(patch: &RationalPatch, u: f64, v: f64) -> DVec3 {
        let b = |i: usize, n: usize, t: f64| {
            let binomial = (0..i).fold(1.0, |c, k| c * (n - k) as f64 / (k + 1) as f64);
            binomial * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32)
        };
        let (p, q) = (patch.points().degree_u(), patch.points().degree_v());
        let (mut a, mut w) = (DVec3::ZERO, 0.0);
        for i in 0..=p {
            for j in 0..=q {
                let basis = b(i, p, u) * b(j, q, v) * patch.weight(i, j);
                a += basis * patch.points().control_point(i, j);
                w += basis;
            }
        }
        a / w
    }

    #[test]
    fn every_point_of_the_torus_patches_lies_on_the_torus() {
        let (major, minor) = (2.0, 0.6);
        for patch in RationalPatch::torus(major, minor) {
            for k in 0..=10 {
                for l in 0..=10 {
                    let p = evaluate(&patch, f64::from(k) / 10.0, f64::from(l) / 10.0);
                    let off = ((p.x.hypot(p.y) - major).hypot(p.z) - minor).abs();
                    assert!(off < 1e-12, "{p} is {off} off the torus");
                }
            }
        }
    }

    #[test]
    fn neighbouring_torus_patches_share_their_boundaries() {
        let patches = RationalPatch::torus(2.0, 0.6);
        for row in 0..4 {
            for col in 0..4 {
                let here = &patches[4 * row + col];
                let right = &patches[4 * row + (col + 1) % 4];
                let up = &patches[4 * ((row + 1) % 4) + col];
                for k in 0..3 {
                    // u = 1 here is u = 0 to the right; v = 1 here is v = 0 above.
                    for (a, b, wa, wb) in [
                        (
                            here.points().control_point(2, k),
                            right.points().control_point(0, k),
                            here.weight(2, k),
                            right.weight(0, k),
                        ),
                        (
                            here.points().control_point(k, 2),
                            up.points().control_point(k, 0),
                            here.weight(k, 2),
                            up.weight(k, 0),
                        ),
                    ] {
                        assert!(a.distance(b) < 1e-12 && wa == wb, "patch ({row}, {col})");
                    }
                }
            }
        }
    }

    #[test]
    fn an_elevated_patch_is_the_same_surface() {
        for patch in RationalPatch::torus(2.0, 0.6).iter().step_by(5) {
            let raised = patch.elevated().unwrap();
            assert_eq!(
                (raised.points().degree_u(), raised.points().degree_v()),
                (3, 3)
            );
            for k in 0..=6 {
                for l in 0..=6 {
                    let (u, v) = (f64::from(k) / 6.0, f64::from(l) / 6.0);
                    let (a, b) = (evaluate(patch, u, v), evaluate(&raised, u, v));
                    assert!(a.distance(b) < 1e-12, "at ({u}, {v}): {a} against {b}");
                }
            }
        }
    }

    #[test]
    fn a_patch_elevated_in_one_direction_is_the_same_surface() {
        // A 2 × 3 patch with uneven weights, raised to 3 × 3 and to 4 × 5.
        let points = BezierPatch::from_fn(2, 3, |i, j| {
            DVec3::new(i as f64, j as f64, ((i * 7 + j * 3) % 5) as f64 * 0.3)
        })
        .unwrap();
        let weights = (0..12).map(|k| 0.5 + f64::from(k % 4) * 0.4).collect();
        let patch = RationalPatch::try_new(points, weights).unwrap();
        for (p, q) in [(3, 3), (4, 5), (2, 3)] {
            let raised = patch.elevated_to(p, q).unwrap();
            assert_eq!(
                (raised.points().degree_u(), raised.points().degree_v()),
                (p, q)
            );
            for k in 0..=6 {
                for l in 0..=6 {
                    let (u, v) = (f64::from(k) / 6.0, f64::from(l) / 6.0);
                    let (a, b) = (evaluate(&patch, u, v), evaluate(&raised, u, v));
                    assert!(
                        a.distance(b) < 1e-12,
                        "{p} × {q} at ({u}, {v}): {a} against {b}"
                    );
                }
            }
        }
        assert!(patch.elevated_to(1, 3).is_err(), "lowering is no elevation");
    }

    #[test]
    fn bad_weights_are_refused_and_weights_of_one_are_polynomial() {
        let flat = BezierPatch::from_fn(1, 1, |i, j| DVec3::new(i as f64, j as f64, 0.0)).unwrap();
        assert_eq!(
            RationalPatch::try_new(flat.clone(), vec![1.0, 0.0, 1.0, 1.0]),
            Err(PatchError::Weight { index: 1 })
        );
        assert_eq!(
            RationalPatch::try_new(flat.clone(), vec![1.0, 1.0, f64::NAN, 1.0]),
            Err(PatchError::Weight { index: 2 })
        );
        assert!(matches!(
            RationalPatch::try_new(flat.clone(), vec![1.0; 3]),
            Err(PatchError::Shape { found: 3, .. })
        ));
        let polynomial = RationalPatch::polynomial(flat.clone());
        assert_eq!(polynomial.numerator(), &flat);
        assert!(
            polynomial
                .denominator()
                .control_points()
                .iter()
                .all(|w| *w == DVec3::X)
        );
    }
}
