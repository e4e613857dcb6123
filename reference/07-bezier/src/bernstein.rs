//! Bernstein polynomials and the Bernstein form of a Bézier curve
//! (seed 000, §2.2 eqs. 1–2 and §2.3 eqs. 3–7).
//!
//! ```text
//!   B_{i,n}(t) = C(n, i) · tⁱ · (1 − t)ⁿ⁻ⁱ,   C(n, i) = n! / (i! (n − i)!)
//!   P(t)       = Σ_{i=0}^{n} B_{i,n}(t) · P_i,   t ∈ [0, 1]
//! ```
//!
//! The basis is non-negative on `[0, 1]` and sums to 1 (a partition of
//! unity), so `P(t)` is a convex combination of the control points.

use crate::basics::{BezierError, ControlPoint, MAX_DEGREE, check_control_points, check_parameter};

/// The binomial coefficient `C(n, i) = n! / (i! (n − i)!)`, seed eq. (4).
///
/// Computed as the product `Π_{k=0}^{i−1} (n − k) / (k + 1)`, multiplying
/// before dividing so that every partial product is the integer
/// `C(n, k + 1)`: exact in `f64` for every `n ≤ MAX_DEGREE`.
///
/// # Errors
/// [`BezierError::IndexAboveDegree`] if `i > n`,
/// [`BezierError::DegreeTooHigh`] if `n > MAX_DEGREE`.
#[transcript::task]
pub fn binomial(n: usize, i: usize) -> Result<f64, BezierError> {
    // BEGIN SOLUTION bernstein: check i ≤ n ≤ MAX_DEGREE, then multiply (n − k) / (k + 1) for k < i
    check_degree(n)?;
    if i > n {
        return Err(BezierError::IndexAboveDegree { i, n });
    }
    // C(n, i) = C(n, n − i): the shorter product is the same number.
    let i = i.min(n - i);
    let mut c = 1.0;
    for k in 0..i {
        c = c * (n - k) as f64 / (k + 1) as f64;
    }
    Ok(c)
    // END SOLUTION
}

/// The Bernstein polynomial `B_{i,n}(t) = C(n, i) · tⁱ · (1 − t)ⁿ⁻ⁱ`.
///
/// The seed prints eq. (3) as `C(n, i) · tⁱ · (1 − i)ⁿ⁻ⁱ`; `(1 − i)` is a
/// typo for `(1 − t)` (with `(1 − i)` the basis would not depend on `t`
/// in its second factor and would not sum to 1). Ends: `B_{0,n}(0) = 1`,
/// `B_{n,n}(1) = 1`, all others vanish there (`0⁰ = 1`).
///
/// # Errors
/// [`BezierError::IndexAboveDegree`], [`BezierError::DegreeTooHigh`], or
/// [`BezierError::ParameterOutOfRange`] for `t` NaN or outside `[0, 1]`.
#[transcript::task]
pub fn bernstein(i: usize, n: usize, t: f64) -> Result<f64, BezierError> {
    // BEGIN SOLUTION bernstein: C(n, i) · tⁱ · (1 − t)ⁿ⁻ⁱ after checking t ∈ [0, 1]
    check_parameter("t", t)?;
    let c = binomial(n, i)?;
    // Seed eq. (3) writes (1 − i); the basis needs (1 − t).
    Ok(c * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32))
    // END SOLUTION
}

/// All `n + 1` Bernstein polynomials of degree `n` at `t`:
/// `[B_{0,n}(t), …, B_{n,n}(t)]`.
///
/// # Errors
/// As [`bernstein`].
#[transcript::task]
pub fn bernstein_basis(n: usize, t: f64) -> Result<Vec<f64>, BezierError> {
    // BEGIN SOLUTION bernstein: collect B_{i,n}(t) for i = 0..=n
    check_degree(n)?;
    (0..=n).map(|i| bernstein(i, n, t)).collect()
    // END SOLUTION
}

/// The point `P(t) = Σ B_{i,n}(t) · P_i` of the Bézier curve with control
/// points `points` (degree `n = points.len() − 1`), in Bernstein form
/// (seed eq. 6). Works for scalars, [`glam::DVec2`] and [`glam::DVec3`].
///
/// `P(0) = P_0` and `P(1) = P_n` exactly.
///
/// # Errors
/// [`BezierError::Empty`], [`BezierError::DegreeTooHigh`],
/// [`BezierError::NonFinitePoint`] or [`BezierError::ParameterOutOfRange`].
#[transcript::task]
pub fn bernstein_curve<P: ControlPoint>(points: &[P], t: f64) -> Result<P, BezierError> {
    // BEGIN SOLUTION bernstein: validate, then sum B_{i,n}(t) · P_i
    check_control_points(points)?;
    let basis = bernstein_basis(points.len() - 1, t)?;
    Ok(points
        .iter()
        .zip(basis)
        .fold(P::ZERO, |sum, (&p, b)| sum + p * b))
    // END SOLUTION
}

/// Rejects degrees above [`MAX_DEGREE`].
fn check_degree(n: usize) -> Result<(), BezierError> {
    if n > MAX_DEGREE {
        Err(BezierError::DegreeTooHigh {
            degree: n,
            max: MAX_DEGREE,
        })
    } else {
        Ok(())
    }
}
