//! The de Casteljau algorithm: evaluation, subdivision and the tangent of
//! a Bézier curve of any degree (seed 000, §2.5 and Listing 4).
//!
//! Repeated linear interpolation of neighbouring points in the ratio t:
//!
//! ```text
//!   b_i⁰ = P_i,   b_iʳ = (1 − t) · b_iʳ⁻¹ + t · b_{i+1}ʳ⁻¹,   r = 1 … n
//!
//!   P0 ──── P1 ──── P2 ──── P3        r = 0   (the control points)
//!      b0¹     b1¹     b2¹            r = 1
//!          b0²     b1²                r = 2   (the penultimate step)
//!              b0³ = P(t)             r = n
//! ```
//!
//! The last point is `P(t)`; the two points of the penultimate step span
//! the tangent, `P'(t) = n · (b1ⁿ⁻¹ − b0ⁿ⁻¹)`. The left edge of the
//! triangle (`b0⁰, b0¹, …, b0ⁿ`) is the control polygon of the curve on
//! `[0, t]`, the right edge read upwards (`b0ⁿ, b1ⁿ⁻¹, …, bn⁰`) that of
//! `[t, 1]`. Only convex combinations happen for `t ∈ [0, 1]`, which is why
//! the algorithm is numerically stable.

use crate::basics::{BezierError, ControlPoint, check_control_points, check_parameter};

/// A point of a curve together with its derivative there (the course
/// library's record, `freeform::CurvePoint`). [`point_and_derivative`]
/// fills it with `P'(t) = n · (b1ⁿ⁻¹ − b0ⁿ⁻¹)`, not normalised: the seed
/// normalises it (Listing 4); normalise it yourself where only the
/// direction matters — it is zero where the curve has a cusp.
pub use freeform::CurvePoint;

/// The two halves of a curve split at `t`, each with as many control
/// points as the original.
#[transcript::evidence]
#[derive(Clone, Debug, PartialEq)]
pub struct Split<P> {
    /// The control points of the curve on `[0, t]`, starting at `P_0`.
    pub left: Vec<P>,
    /// The control points of the curve on `[t, 1]`, ending at `P_n`.
    pub right: Vec<P>,
}

/// `P(t)` by the de Casteljau algorithm, for any degree.
///
/// Ends: `P(0) = P_0`, `P(1) = P_n` exactly (one of the two weights is 0).
///
/// # Errors
/// [`BezierError::Empty`], [`BezierError::DegreeTooHigh`],
/// [`BezierError::NonFinitePoint`], or [`BezierError::ParameterOutOfRange`]
/// for `t` NaN or outside `[0, 1]`.
#[transcript::task]
pub fn de_casteljau<P: ControlPoint>(points: &[P], t: f64) -> Result<P, BezierError> {
    // BEGIN SOLUTION de_casteljau: validate; interpolate neighbours (1 − t)·b_i + t·b_{i+1} until one point is left
    check_control_points(points)?;
    check_parameter("t", t)?;
    let mut b = points.to_vec();
    for r in (1..b.len()).rev() {
        for i in 0..r {
            b[i] = b[i] * (1.0 - t) + b[i + 1] * t;
        }
    }
    Ok(b[0])
    // END SOLUTION
}

/// `P(t)` and `P'(t)`, the derivative taken from the penultimate step:
/// `P'(t) = n · (b1ⁿ⁻¹ − b0ⁿ⁻¹)` (seed Listing 4, lines 12–15, which keeps
/// only its direction).
///
/// # Errors
/// As [`de_casteljau`].
#[transcript::task]
pub fn point_and_derivative<P: ControlPoint>(
    points: &[P],
    t: f64,
) -> Result<CurvePoint<P>, BezierError> {
    // BEGIN SOLUTION de_casteljau: run de Casteljau; keep n · (b1 − b0) of the step that leaves two points
    check_control_points(points)?;
    check_parameter("t", t)?;
    let n = points.len() - 1;
    let mut b = points.to_vec();
    let mut derivative = P::ZERO;
    for r in (1..=n).rev() {
        if r == 1 {
            // The penultimate step: b[0] and b[1] span the tangent.
            derivative = (b[1] - b[0]) * n as f64;
        }
        for i in 0..r {
            b[i] = b[i] * (1.0 - t) + b[i + 1] * t;
        }
    }
    Ok(CurvePoint {
        point: b[0],
        derivative,
    })
    // END SOLUTION
}

/// Splits the curve at `t` into the curves on `[0, t]` and `[t, 1]`:
/// the edges of the de Casteljau triangle.
///
/// `left[0] = P_0`, `left[n] = right[0] = P(t)`, `right[n] = P_n`.
/// Splitting at 0 or 1 gives a degenerate half (all points equal).
///
/// # Errors
/// As [`de_casteljau`].
#[transcript::task]
pub fn split<P: ControlPoint>(points: &[P], t: f64) -> Result<Split<P>, BezierError> {
    // BEGIN SOLUTION de_casteljau: keep the first point of every level (left) and the last one (right, reversed)
    check_control_points(points)?;
    check_parameter("t", t)?;
    let n = points.len() - 1;
    let mut b = points.to_vec();
    let mut left = Vec::with_capacity(n + 1);
    let mut right = Vec::with_capacity(n + 1);
    left.push(b[0]);
    right.push(b[n]);
    for r in (1..=n).rev() {
        for i in 0..r {
            b[i] = b[i] * (1.0 - t) + b[i + 1] * t;
        }
        left.push(b[0]);
        right.push(b[r - 1]);
    }
    right.reverse();
    Ok(Split { left, right })
    // END SOLUTION
}
