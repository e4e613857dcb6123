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
    // BEGIN SOLUTION basis: the recursion with N_{i,p−1} (not the seed's N_{i,p}) and 0/0 = 0
    let k = knots.knots();
    if i + p + 1 >= k.len() || !u.is_finite() {
        return 0.0;
    }
    if p == 0 {
        // Departure from seed (1.8), which closes every step: half-open,
        // and at the domain's end u_{n+1} only step n counts (the limit
        // from the left), not a step beyond the domain that starts there.
        let on = if u == knots.domain().end {
            i == knots.last_index()
        } else {
            k[i] <= u && u < k[i + 1]
        };
        return if on { 1.0 } else { 0.0 };
    }
    // Departure from seed (1.9): N_{i,p−1} here, the seed has N_{i,p}.
    let ratio = |num: f64, den: f64| if den == 0.0 { 0.0 } else { num / den };
    ratio(u - k[i], k[i + p] - k[i]) * cox_de_boor(knots, i, p - 1, u)
        + ratio(k[i + p + 1] - u, k[i + p + 1] - k[i + 1]) * cox_de_boor(knots, i + 1, p - 1, u)
    // END SOLUTION
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
    // BEGIN SOLUTION basis: binary search for u_s ≤ u < u_{s+1}; the domain's end belongs to span n
    let u = knots.domain().check(u)?;
    let (k, n) = (knots.knots(), knots.last_index());
    if u >= k[n + 1] {
        return Ok(n); // the special case of A2.1: the domain's end
    }
    let (mut low, mut high) = (knots.degree(), n + 1);
    // Invariant: k[low] ≤ u < k[high].
    while high - low > 1 {
        let mid = low + (high - low) / 2;
        if u < k[mid] {
            high = mid;
        } else {
            low = mid;
        }
    }
    Ok(low)
    // END SOLUTION
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
    // BEGIN SOLUTION basis: A2.2, the triangle of left/right differences
    check_span(knots, span, u)?;
    let (p, k) = (knots.degree(), knots.knots());
    let mut n = vec![0.0; p + 1];
    let mut left = vec![0.0; p + 1];
    let mut right = vec![0.0; p + 1];
    n[0] = 1.0;
    for j in 1..=p {
        left[j] = u - k[span + 1 - j];
        right[j] = k[span + j] - u;
        // Degree j from degree j − 1: each N_{·,j−1} feeds two neighbours.
        let mut saved = 0.0;
        for r in 0..j {
            let temp = n[r] / (right[r + 1] + left[j - r]);
            n[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        n[j] = saved;
    }
    Ok(n)
    // END SOLUTION
}

// BEGIN SOLUTION
/// The span must be one of the domain's, `u` must lie in it.
fn check_span(knots: &KnotVector, span: usize, u: f64) -> Result<(), NurbsError> {
    let (p, k, last) = (knots.degree(), knots.knots(), knots.last_index());
    if span < p || span > last {
        return Err(NurbsError::BadSpan {
            span,
            first: p,
            last,
        });
    }
    if !(k[span] <= u && u <= k[span + 1]) {
        return Err(NurbsError::OutOfDomain {
            value: u,
            start: k[span],
            end: k[span + 1],
        });
    }
    Ok(())
}
// END SOLUTION

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
    // BEGIN SOLUTION basis: A2.3, the triangle ndu, then the derivative recurrences with a[2][p+1]
    check_span(knots, span, u)?;
    let (p, k) = (knots.degree(), knots.knots());
    // ndu[j][r]: basis values (j ≥ r) and knot differences (j < r).
    let mut ndu = vec![vec![0.0; p + 1]; p + 1];
    let mut left = vec![0.0; p + 1];
    let mut right = vec![0.0; p + 1];
    ndu[0][0] = 1.0;
    for j in 1..=p {
        left[j] = u - k[span + 1 - j];
        right[j] = k[span + j] - u;
        let mut saved = 0.0;
        for r in 0..j {
            ndu[j][r] = right[r + 1] + left[j - r];
            let temp = ndu[r][j - 1] / ndu[j][r];
            ndu[r][j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
    let mut ders = vec![vec![0.0; p + 1]; order + 1];
    for j in 0..=p {
        ders[0][j] = ndu[j][p];
    }
    let top = order.min(p);
    let mut a = [vec![0.0; p + 1], vec![0.0; p + 1]];
    for r in 0..=p {
        let (mut s1, mut s2) = (0, 1);
        a[0][0] = 1.0;
        for kk in 1..=top {
            let mut d = 0.0;
            let rk = r as isize - kk as isize;
            let pk = p - kk;
            if r >= kk {
                a[s2][0] = a[s1][0] / ndu[pk + 1][rk as usize];
                d = a[s2][0] * ndu[rk as usize][pk];
            }
            let j1 = if rk >= -1 { 1 } else { (-rk) as usize };
            let j2 = if r as isize - 1 <= pk as isize {
                kk - 1
            } else {
                p - r
            };
            for j in j1..=j2 {
                let index = (rk + j as isize) as usize;
                a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][index];
                d += a[s2][j] * ndu[index][pk];
            }
            if r <= pk {
                a[s2][kk] = -a[s1][kk - 1] / ndu[pk + 1][r];
                d += a[s2][kk] * ndu[r][pk];
            }
            ders[kk][r] = d;
            std::mem::swap(&mut s1, &mut s2);
        }
    }
    // Multiply by p! / (p − k)!.
    let mut factor = p as f64;
    for (kk, row) in ders.iter_mut().enumerate().take(top + 1).skip(1) {
        for value in row.iter_mut() {
            *value *= factor;
        }
        factor *= (p - kk) as f64;
    }
    Ok(ders)
    // END SOLUTION
}
