//! Cohen-Sutherland line clipping against an axis-parallel window, with
//! outcodes: J. D. Foley, A. van Dam, S. K. Feiner, J. F. Hughes,
//! *Computer Graphics: Principles and Practice*, 2nd ed., §3.12.3. The
//! window is the viewport without rounding, as the lecture slides
//! intersect lines with it ("Schnittpunkt mit Viewport", seed 002).
//!
//! Convention (see `canvas`): pixel coordinates, y up; the window is
//! closed, so a point on its border is inside and is kept.

use std::ops::{BitAnd, BitOr};

use canvas::{MAX_COORD, Vec2};

use crate::error::ClipError;
use crate::window::{ClipWindow, Segment};

/// Which of the four half-planes around the window a point lies in: one
/// bit per border it lies strictly beyond.
///
/// ```text
///          │          │
///    1001  │   1000   │  1010        bit 3 (8)  TOP     y > max.y
///   ───────┼──────────┼───────       bit 2 (4)  BOTTOM  y < min.y
///    0001  │   0000   │  0010        bit 1 (2)  RIGHT   x > max.x
///   ───────┼──────────┼───────       bit 0 (1)  LEFT    x < min.x
///    0101  │   0100   │  0110
///          │          │
/// ```
///
/// Two endpoints whose codes share a bit lie beyond the same border: the
/// segment misses the window (trivial reject). Two zero codes: it lies
/// inside (trivial accept).
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Outcode(pub u8);

impl Outcode {
    /// Inside the (closed) window: no bit set.
    pub const INSIDE: Self = Self(0);
    /// `x < min.x`.
    pub const LEFT: Self = Self(1);
    /// `x > max.x`.
    pub const RIGHT: Self = Self(2);
    /// `y < min.y`.
    pub const BOTTOM: Self = Self(4);
    /// `y > max.y`.
    pub const TOP: Self = Self(8);

    /// Whether every bit of `other` is set in `self`.
    #[must_use]
    pub const fn contains(self, other: Self) -> bool {
        self.0 & other.0 == other.0
    }

    /// Whether no bit is set.
    #[must_use]
    pub const fn is_inside(self) -> bool {
        self.0 == 0
    }
}

impl BitOr for Outcode {
    type Output = Self;
    fn bitor(self, rhs: Self) -> Self {
        Self(self.0 | rhs.0)
    }
}

impl BitAnd for Outcode {
    type Output = Self;
    fn bitand(self, rhs: Self) -> Self {
        Self(self.0 & rhs.0)
    }
}

/// Rounds of "move one endpoint onto one border" before giving up. In exact
/// arithmetic four suffice: each endpoint moves at most once per axis. The
/// rest absorbs rounding, which can leave a moved point an ulp outside
/// another border of a window corner it passes.
pub const MAX_ROUNDS: usize = 8;

/// The outcode of `p` relative to the closed `window`: `LEFT` when
/// `p.x < min.x`, `RIGHT` when `p.x > max.x`, `BOTTOM` when `p.y < min.y`,
/// `TOP` when `p.y > max.y`, combined with `|`. A point on the border gets
/// no bit for it. NaN compares false everywhere and gets `INSIDE`: check
/// finiteness before.
#[must_use]
#[transcript::task]
pub fn outcode(p: Vec2, window: ClipWindow) -> Outcode {
    // BEGIN SOLUTION cohen_sutherland: one bit per border that p lies strictly beyond
    let (min, max) = (window.min(), window.max());
    let mut code = Outcode::INSIDE;
    if p.x < min.x {
        code = code | Outcode::LEFT;
    } else if p.x > max.x {
        code = code | Outcode::RIGHT;
    }
    if p.y < min.y {
        code = code | Outcode::BOTTOM;
    } else if p.y > max.y {
        code = code | Outcode::TOP;
    }
    code
    // END SOLUTION
}

/// The part of `segment` inside the closed `window`, same direction
/// (`from` towards `to`), or `None` when the segment misses the window.
/// A segment that only touches the window comes back as that point
/// (a segment of length zero).
///
/// Cohen-Sutherland: compute both outcodes. Both zero: accept the segment
/// as it is. Sharing a bit: reject. Otherwise take an endpoint outside
/// (`from` first), pick a border it lies beyond (`TOP`, `BOTTOM`, `RIGHT`,
/// `LEFT`, in this order), move the endpoint to where the line crosses that
/// border and repeat:
///
/// ```text
///   crossing with y = y_b:  x = x₀ + (x₁ − x₀) · (y_b − y₀) / (y₁ − y₀)
///   crossing with x = x_b:  y = y₀ + (y₁ − y₀) · (x_b − x₀) / (x₁ − x₀)
/// ```
///
/// (the denominator is never 0: an endpoint beyond `y = y_b` whose partner
/// is not beyond it has a different y). Set the border coordinate exactly
/// (`y = y_b`), so the moved endpoint lies on it. Give up with `None`
/// after [`MAX_ROUNDS`] moves.
///
/// # Errors
///
/// [`ClipError::NonFinite`] for an endpoint with a NaN or infinite
/// coordinate, [`ClipError::OutOfRange`] for one beyond ±[`MAX_COORD`]
/// (`index` 0 for `from`, 1 for `to`).
#[transcript::task]
pub fn cohen_sutherland(
    segment: Segment,
    window: ClipWindow,
) -> Result<Option<Segment>, ClipError> {
    // BEGIN SOLUTION cohen_sutherland: check the endpoints, then accept, reject, or move an outside endpoint onto a border and repeat
    check_endpoints(segment)?;
    let (min, max) = (window.min(), window.max());
    let (mut p0, mut p1) = (segment.from, segment.to);
    for _ in 0..MAX_ROUNDS {
        let (c0, c1) = (outcode(p0, window), outcode(p1, window));
        if (c0 | c1).is_inside() {
            return Ok(Some(Segment::new(p0, p1)));
        }
        if !(c0 & c1).is_inside() {
            return Ok(None);
        }
        let (moving, code) = if c0.is_inside() { (1, c1) } else { (0, c0) };
        let d = p1 - p0;
        let crossing = if code.contains(Outcode::TOP) {
            Vec2::new(p0.x + d.x * (max.y - p0.y) / d.y, max.y)
        } else if code.contains(Outcode::BOTTOM) {
            Vec2::new(p0.x + d.x * (min.y - p0.y) / d.y, min.y)
        } else if code.contains(Outcode::RIGHT) {
            Vec2::new(max.x, p0.y + d.y * (max.x - p0.x) / d.x)
        } else {
            Vec2::new(min.x, p0.y + d.y * (min.x - p0.x) / d.x)
        };
        if moving == 0 {
            p0 = crossing;
        } else {
            p1 = crossing;
        }
    }
    Ok(None)
    // END SOLUTION
}

// BEGIN SOLUTION
/// Both endpoints finite and within ±`MAX_COORD`.
fn check_endpoints(segment: Segment) -> Result<(), ClipError> {
    for (index, p) in [segment.from, segment.to].into_iter().enumerate() {
        if !p.is_finite() {
            return Err(ClipError::NonFinite { index });
        }
        if p.abs().max_element() > MAX_COORD as f32 {
            return Err(ClipError::OutOfRange { index });
        }
    }
    Ok(())
}
// END SOLUTION
