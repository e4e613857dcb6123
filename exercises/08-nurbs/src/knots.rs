//! Knot vectors, their parameter domain, and the errors of this crate
//! (given code: read it, do not edit it).
//!
//! Seed 001 (NURBS tessellation thesis), §1.2, Definition 1.2.1: a knot
//! vector `U = {u_0, …, u_m}` is a non-decreasing sequence of reals; with
//! degree `p` it carries `n + 1 = m − p` basis functions `N_{0,p} … N_{n,p}`,
//! one per control point. The seed (and The NURBS Book, Piegl & Tiller,
//! §2.2) mostly uses *clamped* vectors, `{a, …, a, u_{p+1}, …, u_{m−p−1},
//! b, …, b}` with `a` and `b` repeated `p + 1` times; this crate also
//! accepts *unclamped* ones (for example the seed's `{0, 1, …, 9}` in
//! listing 1.5), whose domain is `[u_p, u_{m−p}]`.
//!
//! ```text
//!   clamped, p = 2:    0 0 0  ¼  ½  ¾  1 1 1      domain [u_2, u_6] = [0, 1]
//!   unclamped, p = 2:  0 1 2  3  4  5  6 7 8      domain [u_2, u_6] = [2, 6]
//!                          ^ u_p        ^ u_{m−p}
//! ```

use thiserror::Error;

/// Everything that can be wrong with the input of this crate.
///
/// Library functions return it instead of panicking; the message names the
/// offending value.
#[transcript::evidence]
#[derive(Clone, Debug, Error, PartialEq)]
pub enum NurbsError {
    /// Degree 0 is a step function, not a curve; this crate starts at 1.
    #[error("the degree must be at least 1")]
    DegreeZero,
    /// A knot is NaN or infinite.
    #[error("knot {index} is not finite ({value})")]
    NonFiniteKnot {
        /// Its index.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// The knots decrease somewhere.
    #[error("the knots must not decrease: u[{index}] = {value} < u[{}] = {previous}", index - 1)]
    DecreasingKnots {
        /// The index of the first knot smaller than its predecessor.
        index: usize,
        /// Its value.
        value: f64,
        /// The predecessor's value.
        previous: f64,
    },
    /// Fewer knots than degree `p` needs (`2p + 2`, for `p + 1` control
    /// points), or a degree too high for the knots given.
    #[error("degree {degree} needs at least {needed} knots, got {got}")]
    TooFewKnots {
        /// The degree.
        degree: usize,
        /// The least number of knots for it.
        needed: usize,
        /// The number given.
        got: usize,
    },
    /// An empty first or last span of the domain (`u_p = u_{p+1}` or
    /// `u_{m−p−1} = u_{m−p}`): a knot repeated more than `p + 1` times at an
    /// end, or an end value also repeated inside.
    #[error("the first and the last span of the domain [{start}, {end}] must not be empty")]
    EmptyEndSpan {
        /// `u_p`.
        start: f64,
        /// `u_{m−p}`.
        end: f64,
    },
    /// A knot inside the domain repeated more than `p` times: the curve
    /// would break apart there.
    #[error("the interior knot {value} has multiplicity {multiplicity} > degree {degree}")]
    MultiplicityTooHigh {
        /// The knot value.
        value: f64,
        /// How often it occurs (or would occur).
        multiplicity: usize,
        /// The degree.
        degree: usize,
    },
    /// The number of control points does not fit the knot vector.
    #[error("expected {expected} control points, got {got}")]
    WrongCount {
        /// `m − p` for the knot vector given.
        expected: usize,
        /// The number given.
        got: usize,
    },
    /// No control points at all.
    #[error("no control points")]
    NoControlPoints,
    /// A weight that is zero, negative, NaN or infinite.
    #[error("weight {index} must be finite and > 0, got {weight}")]
    BadWeight {
        /// The control point's index (row-major for nets).
        index: usize,
        /// The weight.
        weight: f64,
    },
    /// A control point with a NaN or infinite coordinate.
    #[error("control point {index} is not finite")]
    NonFinitePoint {
        /// The control point's index (row-major for nets).
        index: usize,
    },
    /// A parameter outside the domain, or NaN.
    #[error("the parameter {value} is outside the domain [{start}, {end}]")]
    OutOfDomain {
        /// The parameter.
        value: f64,
        /// The domain's start.
        start: f64,
        /// The domain's end.
        end: f64,
    },
    /// A knot span index that is not one of `p ..= n`.
    #[error("{span} is not a knot span index of the domain ({first} ..= {last})")]
    BadSpan {
        /// The index given.
        span: usize,
        /// `p`.
        first: usize,
        /// `n = m − p − 1`.
        last: usize,
    },
    /// The tangents at a point are parallel or zero: no normal there.
    #[error("no normal at ({u}, {v}): the tangents are parallel or zero")]
    DegenerateNormal {
        /// The first parameter.
        u: f64,
        /// The second parameter.
        v: f64,
    },
    /// An operation for clamped knot vectors got an unclamped one.
    #[error("the knot vector must be clamped (both ends repeated degree + 1 times)")]
    NotClamped,
    /// A Bézier patch the course library refuses (a degree above
    /// `freeform::patch::MAX_DEGREE`): what a decomposition hands over must
    /// be a `freeform::RationalPatch`.
    #[error(transparent)]
    Patch(#[from] freeform::PatchError),
    /// A grid with fewer than 2 samples along a side, or more than
    /// [`MAX_GRID_POINTS`] in all.
    #[error("a grid of {samples_u} × {samples_v} samples is not supported")]
    BadGrid {
        /// Samples along u.
        samples_u: usize,
        /// Samples along v.
        samples_v: usize,
    },
}

/// The largest sample grid the grid evaluators accept (`2²⁶` points, 1.5 GiB
/// of `DVec3`): a guard against a size computed from garbage.
pub const MAX_GRID_POINTS: usize = 1 << 26;

/// A closed parameter interval `[start, end]` with `start < end`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Domain {
    /// The smallest parameter.
    pub start: f64,
    /// The largest parameter.
    pub end: f64,
}

impl Domain {
    /// The unit interval `[0, 1]` of Bézier curves.
    pub const UNIT: Self = Self {
        start: 0.0,
        end: 1.0,
    };

    /// Whether `u` lies in `[start, end]` (false for NaN).
    #[must_use]
    pub fn contains(self, u: f64) -> bool {
        self.start <= u && u <= self.end
    }

    /// `Ok(u)` if `u` lies in the domain, else [`NurbsError::OutOfDomain`].
    pub fn check(self, u: f64) -> Result<f64, NurbsError> {
        if self.contains(u) {
            Ok(u)
        } else {
            Err(NurbsError::OutOfDomain {
                value: u,
                start: self.start,
                end: self.end,
            })
        }
    }

    /// The parameter a fraction `t` of the way from `start` to `end`:
    /// `start + t·(end − start)`, exactly `end` at `t = 1`.
    #[must_use]
    pub fn lerp(self, t: f64) -> f64 {
        if t == 1.0 {
            self.end
        } else {
            self.start + t * (self.end - self.start)
        }
    }
}

/// A validated knot vector `U = {u_0, …, u_m}` together with its degree `p`.
///
/// Guarantees (checked by [`KnotVector::try_new`]):
/// - `p ≥ 1` and `m + 1 ≥ 2p + 2` (at least `p + 1` control points);
/// - all knots finite and non-decreasing;
/// - the first and the last span of the domain are not empty
///   (`u_p < u_{p+1}`, `u_{m−p−1} < u_{m−p}`), so the span search always
///   lands on a non-empty span;
/// - a knot strictly inside the domain occurs at most `p` times (the
///   curve stays continuous).
#[transcript::evidence]
#[derive(Clone, Debug, PartialEq)]
pub struct KnotVector {
    degree: usize,
    knots: Vec<f64>,
}

impl KnotVector {
    /// Validates `knots` for degree `degree`; see the type's guarantees.
    pub fn try_new(degree: usize, knots: Vec<f64>) -> Result<Self, NurbsError> {
        if degree == 0 {
            return Err(NurbsError::DegreeZero);
        }
        let needed = degree.saturating_mul(2).saturating_add(2);
        if knots.len() < needed {
            return Err(NurbsError::TooFewKnots {
                degree,
                needed,
                got: knots.len(),
            });
        }
        if let Some(index) = knots.iter().position(|k| !k.is_finite()) {
            return Err(NurbsError::NonFiniteKnot {
                index,
                value: knots[index],
            });
        }
        if let Some(index) = (1..knots.len()).find(|&i| knots[i] < knots[i - 1]) {
            return Err(NurbsError::DecreasingKnots {
                index,
                value: knots[index],
                previous: knots[index - 1],
            });
        }
        let m = knots.len() - 1;
        let (start, end) = (knots[degree], knots[m - degree]);
        if knots[degree] >= knots[degree + 1] || knots[m - degree - 1] >= knots[m - degree] {
            return Err(NurbsError::EmptyEndSpan { start, end });
        }
        let mut i = degree + 1;
        while i < m - degree {
            let value = knots[i];
            let multiplicity = knots[i..].iter().take_while(|&&k| k == value).count();
            if multiplicity > degree {
                return Err(NurbsError::MultiplicityTooHigh {
                    value,
                    multiplicity,
                    degree,
                });
            }
            i += multiplicity;
        }
        Ok(Self { degree, knots })
    }

    /// The clamped knot vector with uniformly spaced interior knots on
    /// `[0, 1]` for `control_points` control points:
    /// `{0 (p+1 times), 1/k, 2/k, …, (k−1)/k, 1 (p+1 times)}` with
    /// `k = control_points − p`.
    pub fn clamped_uniform(degree: usize, control_points: usize) -> Result<Self, NurbsError> {
        if degree == 0 {
            return Err(NurbsError::DegreeZero);
        }
        if control_points <= degree {
            return Err(NurbsError::TooFewKnots {
                degree,
                needed: degree.saturating_mul(2).saturating_add(2),
                got: control_points.saturating_add(degree).saturating_add(1),
            });
        }
        let spans = control_points - degree;
        let mut knots = vec![0.0; degree + 1];
        knots.extend((1..spans).map(|i| i as f64 / spans as f64));
        knots.extend(std::iter::repeat_n(1.0, degree + 1));
        Self::try_new(degree, knots)
    }

    /// The clamped vector `{0, …, 0, 1, …, 1}` (each `p + 1` times) of a
    /// Bézier curve of degree `p`: with it the B-spline basis *is* the
    /// Bernstein basis.
    pub fn bezier(degree: usize) -> Result<Self, NurbsError> {
        Self::clamped_uniform(degree, degree.saturating_add(1))
    }

    /// The unclamped uniform vector `{0, 1, 2, …, m}` for `control_points`
    /// control points (`m = control_points + p`); its domain is `[p, m − p]`.
    pub fn uniform(degree: usize, control_points: usize) -> Result<Self, NurbsError> {
        let count = control_points.saturating_add(degree).saturating_add(1);
        if degree == 0 {
            return Err(NurbsError::DegreeZero);
        }
        if control_points <= degree {
            return Self::clamped_uniform(degree, control_points);
        }
        Self::try_new(degree, (0..count).map(|i| i as f64).collect())
    }

    /// The degree `p`.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The knots `u_0 ..= u_m`.
    #[must_use]
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// The number of basis functions, and so of control points: `n + 1 = m − p`.
    #[must_use]
    pub fn control_points(&self) -> usize {
        self.knots.len() - self.degree - 1
    }

    /// The index of the last basis function, `n = m − p − 1`; also the last
    /// knot span index of the domain.
    #[must_use]
    pub fn last_index(&self) -> usize {
        self.control_points() - 1
    }

    /// The parameter domain `[u_p, u_{m−p}]` (`[u_p, u_{n+1}]`).
    #[must_use]
    pub fn domain(&self) -> Domain {
        Domain {
            start: self.knots[self.degree],
            end: self.knots[self.control_points()],
        }
    }

    /// How often the value `u` occurs among the knots.
    #[must_use]
    pub fn multiplicity(&self, u: f64) -> usize {
        self.knots.iter().filter(|&&k| k == u).count()
    }

    /// Whether both ends are repeated `p + 1` times (`u_0 = u_p` and
    /// `u_{m−p} = u_m`): the curve then starts and ends at its first and
    /// last control points.
    #[must_use]
    pub fn is_clamped(&self) -> bool {
        let m = self.knots.len() - 1;
        self.knots[0] == self.knots[self.degree] && self.knots[m - self.degree] == self.knots[m]
    }

    /// The distinct knot values strictly inside the domain, with their
    /// multiplicities, in increasing order.
    #[must_use]
    pub fn interior_breakpoints(&self) -> Vec<Breakpoint> {
        let domain = self.domain();
        let mut result: Vec<Breakpoint> = Vec::new();
        for &k in &self.knots {
            if k <= domain.start || k >= domain.end {
                continue;
            }
            match result.last_mut() {
                Some(last) if last.value == k => last.multiplicity += 1,
                _ => result.push(Breakpoint {
                    value: k,
                    multiplicity: 1,
                }),
            }
        }
        result
    }
}

/// A distinct knot value and how often it occurs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Breakpoint {
    /// The knot value.
    pub value: f64,
    /// Its multiplicity.
    pub multiplicity: usize,
}
