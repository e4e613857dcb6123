//! Trimming with Bézier curves by the Newton method (seed 000, §3.2,
//! §3.2.1 and Listings 8–12): a region bounded by an upper and a lower
//! quadratic or cubic Bézier curve that share their end points, and a
//! region nested in another.
//!
//! ```text
//!                upper curve                 v ↑
//!            .-~~~~~~~~~~~-.                   │   a ───x₂───●═══════●──x₁──→ d = (1, 0)
//!      P_0 ●                 ● P_n             │        t₂ (from 0)   t₁ (from 1)
//!            '-~~~~~~~~~~~-'                   └──────────────────────→ u
//!                lower curve
//! ```
//!
//! For the point `a = (u, v)` and one curve `C(t) = (C_u(t), C_v(t))`:
//!
//! 1. solve the v-equation `C_v(t) − v = 0` (seed eq. 17) by Newton's
//!    method twice, from `t = 1` and from `t = 0`, for `t₁` and `t₂`;
//! 2. `x_k = C_u(t_k) − u` (eqs. 18–19): how far along `d = (1, 0)` from
//!    `a` the curve is crossed;
//! 3. `a` lies between the two crossings — inside this half of the region
//!    — when `x₁` and `x₂` have opposite signs and both `t` are in `[0, 1]`.
//!
//! A point is trimmed when it is inside the upper or the lower half.
//!
//! **Limit (seed §5.2).** The method assumes each curve is an arch over
//! the line through its end points, crossed at most twice per v, and that
//! both end points lie on one horizontal line (equal v). Otherwise the
//! region near the end points comes out wrong (the seed's Fig. 28);
//! [`crate::ray_parity`] lifts that limit.
//!
//! The file is in two parts: what is given first, then your part of the
//! `trim` task: [`newton`], [`between_crossings`] and the two trims'
//! `contains`.

use glam::DVec2;

use crate::basics::{BezierError, Trim};

// ─── Given ───────────────────────────────────────────────────────────────
// The seed's settings, what Newton's method returns, and the two trims
// with their constructors: you use them, you do not edit them.

/// The seed's iteration limit (Listing 10: `for (i = 0; i < 10; i++)`).
pub const NEWTON_MAX_ITERATIONS: u32 = 10;

/// The seed's step tolerance (Listing 10: `epsilon = 0.001`): the iteration
/// stops once a Newton step `|h|` is smaller.
pub const NEWTON_EPSILON: f64 = 0.001;

/// How long Newton's method runs (seed §5.2 compares 6 with 7 iterations
/// and ε from 0.1 to 0.0001).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NewtonSettings {
    /// The most Newton steps taken.
    pub max_iterations: u32,
    /// Stop after the first step with `|h| < epsilon`.
    pub epsilon: f64,
}

impl Default for NewtonSettings {
    /// The seed's values: 10 iterations, ε = 0.001.
    fn default() -> Self {
        Self {
            max_iterations: NEWTON_MAX_ITERATIONS,
            epsilon: NEWTON_EPSILON,
        }
    }
}

/// What Newton's method ended with.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NewtonRoot {
    /// The last approximation `t`.
    pub t: f64,
    /// The Newton steps taken.
    pub iterations: u32,
    /// Whether a step `|h| < epsilon` was reached.
    pub converged: bool,
}

/// A region bounded by an upper and a lower Bézier curve (quadratic or
/// cubic), both running from the shared left end point to the shared
/// right end point (seed Fig. 11, Listings 11 and 17).
#[derive(Clone, Debug, PartialEq)]
pub struct NewtonTrim {
    upper: Vec<DVec2>,
    lower: Vec<DVec2>,
    settings: NewtonSettings,
}

impl NewtonTrim {
    /// The region between `upper` and `lower`, trimmed with the seed's
    /// default [`NewtonSettings`].
    ///
    /// # Errors
    /// [`BezierError::InvalidTrim`] if a curve does not have 3 or 4 points,
    /// a point is not finite, or the curves do not share both end points.
    /// End points at different heights are accepted (to reproduce the
    /// seed's Fig. 28) though the region is then wrong near them.
    pub fn new(upper: Vec<DVec2>, lower: Vec<DVec2>) -> Result<Self, BezierError> {
        for curve in [&upper, &lower] {
            if !(3..=4).contains(&curve.len()) {
                return Err(BezierError::InvalidTrim(
                    "Newton trim curves must be quadratic or cubic (3 or 4 points)",
                ));
            }
            if !curve.iter().all(|p| p.is_finite()) {
                return Err(BezierError::InvalidTrim("trim curve points must be finite"));
            }
        }
        if upper[0] != lower[0] || upper[upper.len() - 1] != lower[lower.len() - 1] {
            return Err(BezierError::InvalidTrim(
                "the upper and lower curve must share both end points",
            ));
        }
        Ok(Self {
            upper,
            lower,
            settings: NewtonSettings::default(),
        })
    }

    /// The seed's quadratic region from 4 points given "from the left,
    /// clockwise" (§4.3): `p[0]` left end, `p[1]` upper control point,
    /// `p[2]` right end, `p[3]` lower control point (Listing 8: the curves
    /// are `p0 p1 p2` and `p0 p3 p2`).
    ///
    /// # Errors
    /// As [`NewtonTrim::new`].
    pub fn quadratic(p: [DVec2; 4]) -> Result<Self, BezierError> {
        Self::new(vec![p[0], p[1], p[2]], vec![p[0], p[3], p[2]])
    }

    /// The seed's cubic region from 6 points: `p[0]` left end, `p[1]`,
    /// `p[2]` upper control points, `p[3]` right end, `p[4]`, `p[5]` lower
    /// control points from left to right (Listing 9: the curves are
    /// `p0 p1 p2 p3` and `p0 p4 p5 p3` — so the lower ones are not in
    /// clockwise order, despite §4.3).
    ///
    /// # Errors
    /// As [`NewtonTrim::new`].
    pub fn cubic(p: [DVec2; 6]) -> Result<Self, BezierError> {
        Self::new(vec![p[0], p[1], p[2], p[3]], vec![p[0], p[4], p[5], p[3]])
    }

    /// The same region with other Newton settings.
    #[must_use]
    pub fn with_settings(mut self, settings: NewtonSettings) -> Self {
        self.settings = settings;
        self
    }

    /// The upper curve.
    #[must_use]
    pub fn upper(&self) -> &[DVec2] {
        &self.upper
    }

    /// The lower curve.
    #[must_use]
    pub fn lower(&self) -> &[DVec2] {
        &self.lower
    }

    /// The Newton settings in use.
    #[must_use]
    pub fn settings(&self) -> NewtonSettings {
        self.settings
    }
}

/// A ring: the region of `outer` without the region of `inner` (seed
/// Fig. 12, Listing 12). What lies inside `inner` is drawn again.
///
/// The inner curves' end points should lie on the outer curves' horizontal
/// line: upper halves are compared with upper halves.
#[derive(Clone, Debug, PartialEq)]
pub struct NestedNewtonTrim {
    outer: NewtonTrim,
    inner: NewtonTrim,
}

impl NestedNewtonTrim {
    /// `outer` without `inner`; both use the settings of `outer`.
    #[must_use]
    pub fn new(outer: NewtonTrim, inner: NewtonTrim) -> Self {
        Self { outer, inner }
    }
}

// ─── Your tasks (the `trim` task) ─────────────────────────────────────────

/// Newton's method `x_{k+1} = x_k − f(x_k) / f'(x_k)` (seed eq. 15,
/// Listing 10) from `start`. (The seed's legend calls `x_{n+1}` "the
/// previous approximation"; it is the next one.)
///
/// Each step computes `h = f(x)/f'(x)` and `x ← x − h`; the method returns
/// right after the first step with `|h| < epsilon` (`converged`), or after
/// `max_iterations` steps with the last `x` and `converged = false`. (The
/// seed's GLSL function falls off its end without a `return` in that case,
/// which is undefined behaviour; here the caller learns that no root was
/// found.) Where `f'(x) = 0` or `h` is not finite (the seed's "Newton is
/// not applicable", §3.2) it stops at `x` without converging. Never panics.
#[must_use]
#[transcript::task]
pub fn newton(
    f: impl Fn(f64) -> f64,
    df: impl Fn(f64) -> f64,
    start: f64,
    settings: NewtonSettings,
) -> NewtonRoot {
    // BEGIN SOLUTION trim: up to max_iterations steps h = f/f', x −= h; return once |h| < epsilon; stop if h is not finite
    let mut x = start;
    for k in 0..settings.max_iterations {
        let h = f(x) / df(x);
        if !h.is_finite() {
            return NewtonRoot {
                t: x,
                iterations: k,
                converged: false,
            };
        }
        x -= h;
        if h.abs() < settings.epsilon {
            return NewtonRoot {
                t: x,
                iterations: k + 1,
                converged: true,
            };
        }
    }
    NewtonRoot {
        t: x,
        iterations: settings.max_iterations,
        converged: false,
    }
    // END SOLUTION
}

/// Whether `uv` lies between the two crossings of the ray `uv + x · (1, 0)`
/// with the quadratic or cubic curve `curve` that Newton finds from `t = 1`
/// and from `t = 0` (steps 1–3 above).
///
/// Inside means: both Newton runs converged, both roots in `[0, 1]`, and
/// `x₁ = C_u(t₁) − u`, `x₂ = C_u(t₂) − u` of opposite signs. A run that
/// does not converge finds no crossing: in the seed's shader it returns
/// nothing (undefined in GLSL); above the apex of an arch, where the
/// v-equation has no real root, its wandering `t` would otherwise often
/// land in `[0, 1]` and trim points far outside the region. Too few
/// iterations therefore leave points near the apex untrimmed — the
/// notches of the seed's Fig. 30. The seed's §3.2.1 lists both sign
/// cases (3 and 4); its shader (Listing 11) tests only `x₁ > 0 ∧ x₂ < 0`.
/// The seed uses quadratic and cubic curves (3 or 4 points, as the trims
/// below check); any other length is evaluated the same way. An empty
/// curve, a non-finite point or a non-finite `uv` is never inside.
#[must_use]
#[transcript::task]
pub fn between_crossings(curve: &[DVec2], uv: DVec2, settings: NewtonSettings) -> bool {
    // BEGIN SOLUTION trim: Newton on C_v(t) − v from 1 and from 0; both converged, both t in [0, 1], x₁ and x₂ of opposite signs
    if curve.is_empty() || !uv.is_finite() || !curve.iter().all(|p| p.is_finite()) {
        return false;
    }
    let v = |t: f64| bernstein_sum(curve, t).y - uv.y;
    let dv = |t: f64| derivative_sum(curve, t).y;
    let r1 = newton(v, dv, 1.0, settings);
    let r2 = newton(v, dv, 0.0, settings);
    if !(r1.converged && r2.converged) {
        return false;
    }
    let (t1, t2) = (r1.t, r2.t);
    let in_range = (0.0..=1.0).contains(&t1) && (0.0..=1.0).contains(&t2);
    let x1 = bernstein_sum(curve, t1).x - uv.x;
    let x2 = bernstein_sum(curve, t2).x - uv.x;
    // Seed cases 3 and 4: x₁ > 0 > x₂ or x₁ < 0 < x₂.
    in_range && ((x1 > 0.0 && x2 < 0.0) || (x1 < 0.0 && x2 > 0.0))
    // END SOLUTION
}

impl Trim for NewtonTrim {
    /// Inside the upper half or inside the lower half (Listing 11).
    #[transcript::task]
    fn trims(&self, uv: DVec2) -> bool {
        // BEGIN SOLUTION trim: between the crossings of the upper curve, or of the lower curve
        between_crossings(&self.upper, uv, self.settings)
            || between_crossings(&self.lower, uv, self.settings)
        // END SOLUTION
    }
}

impl Trim for NestedNewtonTrim {
    /// Per half: between the outer curve's crossings and not between the
    /// inner curve's, each "between" as [`between_crossings`] decides it —
    /// both sign cases, with the `t ∈ [0, 1]` test. Listing 12 writes
    /// `x₁ > 0 ∧ x₂ < 0 ∧ ¬(x₃ > 0 ∧ x₄ < 0)`: one sign case only (curves
    /// running left to right), and no `t` test for the inner curves, so
    /// that where Newton finds no inner root the ring came out wrong.
    #[transcript::task]
    fn trims(&self, uv: DVec2) -> bool {
        // BEGIN SOLUTION trim: per half, between the outer curve's crossings and not between the inner curve's
        let s = self.outer.settings;
        (between_crossings(&self.outer.upper, uv, s)
            && !between_crossings(&self.inner.upper, uv, s))
            || (between_crossings(&self.outer.lower, uv, s)
                && !between_crossings(&self.inner.lower, uv, s))
        // END SOLUTION
    }
}

// BEGIN SOLUTION
/// `C(t) = Σ B_{i,n}(t) P_i` for any real `t` (Newton may step outside
/// `[0, 1]`); `points` is not empty.
fn bernstein_sum(points: &[DVec2], t: f64) -> DVec2 {
    let n = points.len() - 1;
    let mut sum = DVec2::ZERO;
    let mut binomial = 1.0;
    for (i, &p) in points.iter().enumerate() {
        sum += p * binomial * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32);
        binomial = binomial * (n - i) as f64 / (i + 1) as f64;
    }
    sum
}

/// `C'(t) = n Σ B_{i,n−1}(t) (P_{i+1} − P_i)`.
fn derivative_sum(points: &[DVec2], t: f64) -> DVec2 {
    let n = points.len() - 1;
    if n == 0 {
        return DVec2::ZERO;
    }
    let differences: Vec<DVec2> = points
        .windows(2)
        .map(|w| (w[1] - w[0]) * n as f64)
        .collect();
    bernstein_sum(&differences, t)
}
// END SOLUTION
