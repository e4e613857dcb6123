//! Point in a region bounded by closed loops of Bézier curves of any degree
//! and orientation: ray-crossing parity with Bézier subdivision. This goes
//! beyond seed 000, whose Newton trimming needs both end points of its
//! curves on one horizontal line (§5.2, Fig. 28).
//!
//! Cast the ray `a + x · (1, 0)`, `x > 0`, from `a = (u, v)`; `a` is inside
//! when the boundary crosses it an odd number of times (the even-odd rule,
//! so loops inside loops make holes, whatever their orientation).
//!
//! **Half-open rule.** A boundary point counts as *above* the ray when its
//! v ≥ a.v and *below* otherwise; a crossing is a change between the two
//! along the curve at u > a.u. Tangencies, end points exactly on the ray
//! and curves running along it are then counted consistently (the rule of
//! the scanline fill, for curves).
//!
//! **Why subdivision.** Only the parity matters, and the convex hull
//! property decides it for most pieces of a curve without finding a root:
//!
//! ```text
//!   all control points above, or all below     → no change of side: 0
//!   all control points right of a (u > a.u)    → parity = [start side ≠ end side]
//!   all control points left of a (u ≤ a.u)     → not on the ray: 0
//!   otherwise                                  → split at ½ (de Casteljau), recurse
//! ```
//!
//! Only the pieces whose hull contains `a` are split again, so the work
//! grows with the depth (at most [`MAX_SUBDIVISION_DEPTH`]) only near the
//! curve — no Newton iteration, no missed double roots, no tolerance to
//! tune. A point closer to the boundary than `2⁻⁴⁸` of a curve's size may
//! be classified either way.

use glam::DVec2;

use crate::basics::{BezierError, Trim, check_control_points};

/// The deepest subdivision: a piece then spans `2⁻⁴⁸` of its curve's
/// parameter range, below `f64` resolution of most control points.
pub const MAX_SUBDIVISION_DEPTH: u32 = 48;

/// The largest gap between one curve's end and the next curve's start that
/// [`TrimLoop::new`] closes (relative to the loop's extent); the start is
/// then moved onto the end so that the sides match exactly.
pub const LOOP_CLOSURE_TOLERANCE: f64 = 1e-9;

/// A closed loop of Bézier curves in (u, v): curve k ends where curve
/// k + 1 starts, the last ends where the first starts. Any degree from 1
/// (a line segment) to `MAX_DEGREE`, any orientation.
#[derive(Clone, Debug, PartialEq)]
pub struct TrimLoop {
    curves: Vec<Vec<DVec2>>,
}

impl TrimLoop {
    /// The loop of `curves`, given in order along the loop.
    ///
    /// # Errors
    /// [`BezierError::Empty`] for no curves or a curve without points;
    /// [`BezierError::DegreeTooHigh`], [`BezierError::NonFinitePoint`];
    /// [`BezierError::LoopNotClosed`] where a curve starts farther than
    /// [`LOOP_CLOSURE_TOLERANCE`] (relative) from the previous curve's end.
    pub fn new(mut curves: Vec<Vec<DVec2>>) -> Result<Self, BezierError> {
        if curves.is_empty() {
            return Err(BezierError::Empty);
        }
        for curve in &curves {
            check_control_points(curve)?;
        }
        let extent = curves
            .iter()
            .flatten()
            .fold(0.0_f64, |m, p| m.max(p.abs().max_element()))
            .max(1.0);
        let count = curves.len();
        for k in 0..count {
            let previous = (k + count - 1) % count;
            let end = curves[previous][curves[previous].len() - 1];
            if end.distance(curves[k][0]) > LOOP_CLOSURE_TOLERANCE * extent {
                return Err(BezierError::LoopNotClosed { curve: k, previous });
            }
            curves[k][0] = end;
        }
        Ok(Self { curves })
    }

    /// The curves of the loop.
    #[must_use]
    pub fn curves(&self) -> &[Vec<DVec2>] {
        &self.curves
    }
}

/// A trimmed region: the points inside an odd number of its loops
/// (even-odd rule), so a loop inside another is a hole, a loop inside that
/// an island, and so on.
#[derive(Clone, Debug, PartialEq)]
pub struct TrimRegion {
    loops: Vec<TrimLoop>,
}

impl TrimRegion {
    /// The region bounded by `loops`.
    #[must_use]
    pub fn new(loops: Vec<TrimLoop>) -> Self {
        Self { loops }
    }

    /// Whether `uv` is inside: an odd number of crossings of the ray
    /// `uv + x · (1, 0)`, `x > 0`, with all curves of all loops. A point
    /// with a NaN or infinite coordinate is never inside.
    #[must_use]
    #[transcript::task]
    pub fn contains(&self, uv: DVec2) -> bool {
        // Unused until you write the body:
        let _ = &uv;
        todo!(
            "trim_loop: reject non-finite uv; add crossing_parity of every curve of every loop; odd is inside"
        )
    }
}

impl Trim for TrimRegion {
    /// The region is what is cut away.
    fn trims(&self, uv: DVec2) -> bool {
        self.contains(uv)
    }
}

/// Whether the curve `points` crosses the ray `a + x · (1, 0)`, `x > 0`,
/// an odd number of times, by the half-open rule above (v ≥ a.v is
/// "above"). For an open curve that is `[start side ≠ end side]` when the
/// whole curve is right of `a`.
///
/// An empty curve, or a point or `a` that is not finite (or so large
/// that `p − a` overflows), is never crossed: `false`, so that the
/// subdivision never runs on NaN.
#[must_use]
#[transcript::task]
pub fn crossing_parity(points: &[DVec2], a: DVec2) -> bool {
    // Unused until you write the body:
    let _ = (&points, &a);
    todo!(
        "trim_loop: shift so a is the origin; classify by the convex hull; split at ½ where undecided"
    )
}
