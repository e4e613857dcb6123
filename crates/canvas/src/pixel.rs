//! Pixel coordinates, viewports and the rounding rule.

use std::fmt;

/// The largest coordinate magnitude (in pixels) that rasterizers accept.
///
/// `2^24` is where `f32` stops representing every integer, so a continuous
/// position beyond it no longer names a unique pixel. Rasterizers document
/// what they do with endpoints beyond it (usually: nothing is drawn).
pub const MAX_COORD: i32 = 1 << 24;

/// The integer coordinates of one pixel; its centre is at `(x, y)` exactly.
///
/// A different type from a continuous point (`Vec2`): adding two pixels
/// means nothing, and a pixel is never "between" two others.
#[transcript::evidence]
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub struct Pixel {
    /// Column, growing to the right.
    pub x: i32,
    /// Row, growing upwards (row 0 is the bottom of the canvas).
    pub y: i32,
}

impl Pixel {
    /// The pixel at column `x`, row `y`.
    #[must_use]
    pub const fn new(x: i32, y: i32) -> Self {
        Self { x, y }
    }

    /// The pixel whose square contains the continuous point `p`, rounding
    /// half away from zero; `None` for non-finite points or points beyond
    /// ±[`MAX_COORD`].
    #[must_use]
    pub fn nearest(p: glam::Vec2) -> Option<Self> {
        if !within_limits(p.x) || !within_limits(p.y) {
            return None;
        }
        Some(Self::new(round_half_away(p.x), round_half_away(p.y)))
    }

    /// The pixel centre as a continuous point.
    #[must_use]
    pub fn centre(self) -> glam::Vec2 {
        glam::Vec2::new(self.x as f32, self.y as f32)
    }

    /// Whether `self` and `other` touch: equal, or neighbours in one of the
    /// eight directions (8-connectivity).
    #[must_use]
    pub fn touches(self, other: Self) -> bool {
        (i64::from(self.x) - i64::from(other.x)).abs() <= 1
            && (i64::from(self.y) - i64::from(other.y)).abs() <= 1
    }
}

impl fmt::Debug for Pixel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}, {})", self.x, self.y)
    }
}

impl fmt::Display for Pixel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self, f)
    }
}

/// Rounds half away from zero, as the TU Wien sheet's `round`:
/// `0.5 → 1`, `1.5 → 2`, `−0.5 → −1`.
///
/// Values beyond the `i32` range saturate and NaN becomes 0 (Rust's `as`);
/// callers reject such input before rounding.
#[must_use]
#[inline]
pub fn round_half_away(v: f32) -> i32 {
    // `f32::round` is specified as "half-way cases away from 0.0".
    v.round() as i32
}

/// Whether a continuous coordinate is finite and within ±[`MAX_COORD`].
#[must_use]
#[inline]
pub fn within_limits(v: f32) -> bool {
    v.is_finite() && v.abs() <= MAX_COORD as f32
}

/// An axis-aligned rectangle of pixels, bounds inclusive.
///
/// ```text
///   y_max +-----------+
///         |  visible  |
///   y_min +-----------+
///       x_min       x_max
/// ```
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Viewport {
    /// Leftmost visible column.
    pub x_min: i32,
    /// Bottom visible row.
    pub y_min: i32,
    /// Rightmost visible column (inclusive).
    pub x_max: i32,
    /// Top visible row (inclusive).
    pub y_max: i32,
}

impl Viewport {
    /// The viewport spanning the given inclusive bounds. An empty viewport
    /// (`x_min > x_max` or `y_min > y_max`) contains nothing.
    #[must_use]
    pub const fn new(x_min: i32, y_min: i32, x_max: i32, y_max: i32) -> Self {
        Self {
            x_min,
            y_min,
            x_max,
            y_max,
        }
    }

    /// Whether the pixel lies inside (bounds inclusive).
    #[must_use]
    #[inline]
    pub fn contains(&self, p: Pixel) -> bool {
        (self.x_min..=self.x_max).contains(&p.x) && (self.y_min..=self.y_max).contains(&p.y)
    }

    /// Whether the viewport contains no pixel at all.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.x_min > self.x_max || self.y_min > self.y_max
    }
}

/// A horizontal run of pixels: row `y`, columns `x_start ..= x_end` (both
/// ends included). Scanline rasterizers produce spans, because a span is
/// what a framebuffer writes fastest (one slice fill instead of a bounds
/// check per pixel); `x_start > x_end` is an empty span.
///
/// ```text
///   y  ·  ·  ■  ■  ■  ■  ·      Span { y, x_start: 2, x_end: 5 }
///      0  1  2  3  4  5  6
/// ```
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Span {
    /// The row.
    pub y: i32,
    /// The first column of the run.
    pub x_start: i32,
    /// The last column of the run (inclusive).
    pub x_end: i32,
}

impl Span {
    /// The span of row `y` from `x_start` to `x_end`, both included.
    #[must_use]
    pub const fn new(y: i32, x_start: i32, x_end: i32) -> Self {
        Self { y, x_start, x_end }
    }

    /// The number of pixels (0 for an empty span).
    #[must_use]
    pub fn len(self) -> u64 {
        u64::try_from(i64::from(self.x_end) - i64::from(self.x_start) + 1).unwrap_or(0)
    }

    /// Whether the span holds no pixel (`x_start > x_end`).
    #[must_use]
    pub fn is_empty(self) -> bool {
        self.x_start > self.x_end
    }

    /// The pixels of the span, left to right.
    pub fn pixels(self) -> impl Iterator<Item = Pixel> {
        (self.x_start..=self.x_end).map(move |x| Pixel::new(x, self.y))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn span_counts_and_lists_its_pixels_left_to_right() {
        let span = Span::new(3, -1, 2);
        assert_eq!(span.len(), 4);
        assert!(!span.is_empty());
        let xs: Vec<i32> = span.pixels().map(|p| p.x).collect();
        assert_eq!(xs, [-1, 0, 1, 2]);
        assert!(span.pixels().all(|p| p.y == 3));
        let empty = Span::new(0, 5, 4);
        assert!(empty.is_empty());
        assert_eq!(empty.len(), 0);
        assert_eq!(empty.pixels().count(), 0);
        assert_eq!(Span::new(0, i32::MIN, i32::MAX).len(), 1 << 32);
    }

    #[test]
    fn rounding_is_half_away_from_zero() {
        assert_eq!(round_half_away(0.5), 1);
        assert_eq!(round_half_away(1.5), 2);
        assert_eq!(round_half_away(2.5), 3);
        assert_eq!(round_half_away(-0.5), -1);
        assert_eq!(round_half_away(-2.5), -3);
        assert_eq!(round_half_away(0.49), 0);
    }

    #[test]
    fn nearest_rejects_non_finite_and_huge_points() {
        assert_eq!(Pixel::nearest(glam::Vec2::new(f32::NAN, 0.0)), None);
        assert_eq!(Pixel::nearest(glam::Vec2::new(0.0, f32::INFINITY)), None);
        assert_eq!(Pixel::nearest(glam::Vec2::new(1e30, 0.0)), None);
        assert_eq!(
            Pixel::nearest(glam::Vec2::new(2.5, -0.5)),
            Some(Pixel::new(3, -1))
        );
    }

    #[test]
    fn viewport_bounds_are_inclusive() {
        let v = Viewport::new(0, 0, 3, 2);
        assert!(v.contains(Pixel::new(0, 0)));
        assert!(v.contains(Pixel::new(3, 2)));
        assert!(!v.contains(Pixel::new(4, 2)));
        assert!(!v.contains(Pixel::new(0, -1)));
        assert!(Viewport::new(1, 0, 0, 0).is_empty());
    }
}
