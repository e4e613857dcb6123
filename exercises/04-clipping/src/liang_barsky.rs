//! Liang-Barsky line clipping against an axis-parallel window, in the
//! segment's parameter: Y.-D. Liang and B. A. Barsky, "A new concept and
//! method for line clipping", ACM Transactions on Graphics 3(1), 1984;
//! also Foley et al., *Computer Graphics: Principles and Practice*, 2nd
//! ed., §3.12.4 (Cyrus-Beck). The window is the viewport without rounding,
//! as in the lecture slides ("Schnittpunkt mit Viewport", seed 002).
//!
//! Convention (see `canvas`): pixel coordinates, y up; the window is
//! closed, so a point on its border is inside and is kept.

#[allow(unused_imports)]
use canvas::MAX_COORD;

use crate::error::ClipError;
use crate::window::{ClipWindow, Segment};

/// The part of `segment` inside the closed `window`, same direction
/// (`from` towards `to`), or `None` when the segment misses the window.
/// A segment that only touches the window comes back as that point.
///
/// Liang-Barsky: the segment's points are `P(t) = P₀ + t · Δ`,
/// `t ∈ [0, 1]`. Each border `k` of the window is one inequality
/// `p_k · t ≤ q_k`:
///
/// ```text
///   k   border   p_k     q_k
///   0   left     −Δx     x₀ − min.x        (x₀ + t·Δx ≥ min.x)
///   1   right     Δx     max.x − x₀        (x₀ + t·Δx ≤ max.x)
///   2   bottom   −Δy     y₀ − min.y
///   3   top       Δy     max.y − y₀
/// ```
///
/// Start with `[t_in, t_out] = [0, 1]`. For `p_k < 0` the line *enters*
/// the half-plane at `r = q_k / p_k`: raise `t_in` to `r`; for `p_k > 0` it
/// *leaves* there: lower `t_out` to `r`. For `p_k = 0` the segment is
/// parallel to the border: inside it for every `t` when `q_k ≥ 0`, and
/// for none (reject) when `q_k < 0`. Reject as soon as `t_in > t_out`;
/// otherwise the result is `P(t_in)` to `P(t_out)` (take `P₀` and `P₁`
/// themselves for `t = 0` and `t = 1`, see [`Segment::at`]).
///
/// # Errors
///
/// [`ClipError::NonFinite`] for an endpoint with a NaN or infinite
/// coordinate, [`ClipError::OutOfRange`] for one beyond ±[`MAX_COORD`]
/// (`index` 0 for `from`, 1 for `to`).
#[transcript::task]
pub fn liang_barsky(segment: Segment, window: ClipWindow) -> Result<Option<Segment>, ClipError> {
    // Unused until you write the body:
    let _ = (&segment, &window);
    todo!(
        "liang_barsky: check the endpoints, then narrow [t_in, t_out] = [0, 1] with p_k t <= q_k for the four borders"
    )
}
