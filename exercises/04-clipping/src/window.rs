//! The 2D clip window and line segments for Cohen-Sutherland and
//! Liang-Barsky (tasks 3 and 4).
//!
//! This module is given.

use canvas::{MAX_COORD, Vec2, Viewport};

/// A line segment from `from` to `to`, in pixel coordinates (pixel centres
/// at integers, y up; see `canvas`). Its points are
/// `P(t) = from + t · (to − from)` for `t ∈ [0, 1]`.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    /// Start point, `P(0)`.
    pub from: Vec2,
    /// End point, `P(1)`.
    pub to: Vec2,
}

impl Segment {
    /// The segment from `from` to `to`.
    #[must_use]
    pub const fn new(from: Vec2, to: Vec2) -> Self {
        Self { from, to }
    }

    /// The point `P(t) = from + t · (to − from)`; `t = 0` and `t = 1` give
    /// the endpoints exactly.
    #[must_use]
    #[inline]
    pub fn at(self, t: f32) -> Vec2 {
        if t == 1.0 {
            self.to
        } else {
            self.from + t * (self.to - self.from)
        }
    }
}

/// An axis-parallel rectangle `[min.x, max.x] × [min.y, max.y]`, closed: a
/// point on the border is inside.
///
/// ```text
///   max.y +-----------+
///         |  window   |
///   min.y +-----------+
///       min.x       max.x
/// ```
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipWindow {
    min: Vec2,
    max: Vec2,
}

impl ClipWindow {
    /// The window spanning `min` to `max`; `None` unless both corners are
    /// finite, within ±[`MAX_COORD`], and `min ≤ max` in both axes (a window
    /// of zero width or height is allowed: a segment or a point).
    #[must_use]
    pub fn try_new(min: Vec2, max: Vec2) -> Option<Self> {
        let limit = MAX_COORD as f32;
        let ok = |v: Vec2| v.is_finite() && v.abs().max_element() <= limit;
        (ok(min) && ok(max) && min.x <= max.x && min.y <= max.y).then_some(Self { min, max })
    }

    /// The window of a pixel viewport *without rounding*, as the lecture
    /// slides intersect a line with the viewport ("Schnittpunkt mit
    /// Viewport", seed 002): the pixels `x_min..=x_max` cover
    /// `[x_min − ½, x_max + ½]`, likewise in y. `None` for an empty
    /// viewport or one beyond ±[`MAX_COORD`].
    #[must_use]
    pub fn from_viewport(viewport: Viewport) -> Option<Self> {
        if viewport.is_empty() {
            return None;
        }
        // f64 first: `i32 as f32` would round large bounds before the ½.
        let half = |v: i32, s: f64| (f64::from(v) + s) as f32;
        Self::try_new(
            Vec2::new(half(viewport.x_min, -0.5), half(viewport.y_min, -0.5)),
            Vec2::new(half(viewport.x_max, 0.5), half(viewport.y_max, 0.5)),
        )
    }

    /// The lower-left corner.
    #[must_use]
    pub fn min(self) -> Vec2 {
        self.min
    }

    /// The upper-right corner.
    #[must_use]
    pub fn max(self) -> Vec2 {
        self.max
    }

    /// Whether `p` lies in the closed window (NaN never does).
    #[must_use]
    pub fn contains(self, p: Vec2) -> bool {
        self.min.x <= p.x && p.x <= self.max.x && self.min.y <= p.y && p.y <= self.max.y
    }
}
