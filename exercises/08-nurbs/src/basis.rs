//! The B-spline basis: Cox-de Boor's recursion, the knot span search and
//! the triangular evaluation of all non-zero basis functions and their
//! derivatives, after seed 001 (NURBS tessellation thesis), §1.2,
//! Definition 1.2.1, and The NURBS Book (Piegl & Tiller), §2.2–2.5,
//! algorithms A2.1 `FindSpan`, A2.2 `BasisFuns` and A2.3 `DersBasisFuns`.
//!
//! **Definition** (Cox-de Boor), on a knot vector `U = {u_0, …, u_m}`:
//!
//! ```text
//!   N_{i,0}(u) = 1 if u_i ≤ u < u_{i+1}, else 0
//!   N_{i,p}(u) = (u − u_i) / (u_{i+p} − u_i) · N_{i,p−1}(u)
//!              + (u_{i+p+1} − u) / (u_{i+p+1} − u_{i+1}) · N_{i+1,p−1}(u)
//! ```
//!
//! with `0/0 = 0` where knots repeat. Two departures from the seed's
//! (1.8)–(1.9), both fixed here:
//! - (1.9) has `N_{i,p}(u)` in its first term, which would define `N_{i,p}`
//!   by itself; the definition (and The NURBS Book, (2.5)) has `N_{i,p−1}`.
//! - (1.8) closes the interval, `u_i ≤ u ≤ u_{i+1}`; then at an interior
//!   knot two degree-0 functions are 1 and the basis sums to 2 there. The
//!   interval is half-open; at the domain's end `u = u_{n+1}` only the
//!   step of span `n` counts, so that the basis still sums to 1 there
//!   (A2.1 makes the same choice).
//!
//! **Span.** On `[u_s, u_{s+1})` only `N_{s−p,p} … N_{s,p}` are non-zero
//! (local support), so evaluating a B-spline means: find `s`, compute those
//! `p + 1` values, combine `p + 1` control points.
//!
//! ```text
//!   knots      u_{s−1}   u_s   u   u_{s+1}   u_{s+2}
//!   ─────────────┼────────┼────•─────┼─────────┼──────
//!   non-zero:  N_{s−p,p}, …, N_{s,p}        (p + 1 functions)
//! ```

use crate::knots::{KnotVector, NurbsError};

/// `N_{i,p}(u)` straight from the Cox-de Boor recursion (see the module
/// documentation), for any degree `p` up to the knot vector's own degree and
/// any `i` with `i + p + 1 ≤ m`; `0` for other `i` and for `u` outside
/// `[u_0, u_m]` or NaN.
///
/// The degree-0 step is `[u_i, u_{i+1})`, except at the domain's end
/// `u = u_{n+1}` (`n = m − p_U − 1` for the vector's degree `p_U`): there
/// only step `n` is 1, the limit from the left, so that the basis sums to 1
/// on the whole closed domain. Quotients with a zero denominator count as `0`.
///
/// Exponential in `p` (two calls per level): it is the definition, the
/// oracle for the fast [`basis_funs`], not for production.
#[must_use]
#[transcript::task]
pub fn cox_de_boor(knots: &KnotVector, i: usize, p: usize, u: f64) -> f64 {
    // Unused until you write the body:
    let _ = (&knots, &i, &p, &u);
    todo!("basis: the recursion with N_{{i,p−1}} (not the seed's N_{{i,p}}) and 0/0 = 0")
}

/// The knot span index `s` of `u`: `u_s ≤ u < u_{s+1}` with `p ≤ s ≤ n`, and
/// `s = n` at the domain's end `u = u_{n+1}` (The NURBS Book, A2.1
/// `FindSpan`, binary search).
///
/// The span is never empty (`u_s < u_{s+1}`) for a valid [`KnotVector`].
///
/// Errors: `u` outside the domain `[u_p, u_{n+1}]` or NaN
/// ([`NurbsError::OutOfDomain`]).
#[transcript::task]
pub fn find_span(knots: &KnotVector, u: f64) -> Result<usize, NurbsError> {
    // Unused until you write the body:
    let _ = (&knots, &u);
    todo!("basis: binary search for u_s ≤ u < u_{{s+1}}; the domain's end belongs to span n")
}

/// The `p + 1` basis functions `N_{s−p,p}(u) … N_{s,p}(u)` that are non-zero
/// in span `s` (The NURBS Book, A2.2 `BasisFuns`), with `p` the knot
/// vector's degree.
///
/// A2.2 builds the triangle of degrees `0 … p` in place, using
/// `left[j] = u − u_{s+1−j}` and `right[j] = u_{s+j} − u`; no division by
/// zero can happen because span `s` is not empty. The values are `≥ 0` and
/// sum to 1 (up to rounding).
///
/// Errors: `s` not in `p ..= n` ([`NurbsError::BadSpan`]); `u` outside
/// `[u_s, u_{s+1}]` or NaN ([`NurbsError::OutOfDomain`]).
#[transcript::task]
pub fn basis_funs(knots: &KnotVector, span: usize, u: f64) -> Result<Vec<f64>, NurbsError> {
    // Unused until you write the body:
    let _ = (&knots, &span, &u);
    todo!("basis: A2.2, the triangle of left/right differences")
}

/// The basis functions of span `s` and their derivatives up to `order`:
/// `result[k][j] = dᵏ/duᵏ N_{s−p+j,p}(u)` for `k = 0 ..= order`,
/// `j = 0 ..= p` (The NURBS Book, A2.3 `DersBasisFuns`). Derivatives of
/// order `> p` are 0.
///
/// A2.3 keeps the whole triangle `ndu` of A2.2 (basis values in the upper
/// part, knot differences in the lower) and combines it with the formula
/// `N′_{i,p} = p/(u_{i+p} − u_i) N_{i,p−1} − p/(u_{i+p+1} − u_{i+1}) N_{i+1,p−1}`
/// (NURBS Book (2.7)), differentiated `k` times.
///
/// Errors: as [`basis_funs`]. `order` is capped at `p` internally; the rows
/// above it are zeros.
#[transcript::task]
pub fn ders_basis_funs(
    knots: &KnotVector,
    span: usize,
    u: f64,
    order: usize,
) -> Result<Vec<Vec<f64>>, NurbsError> {
    // Unused until you write the body:
    let _ = (&knots, &span, &u, &order);
    todo!("basis: A2.3, the triangle ndu, then the derivative recurrences with a[2][p+1]")
}
