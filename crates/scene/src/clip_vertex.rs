//! A vertex in homogeneous clip space, the input and output of clipping.

use canvas::Rgba;
use glam::Vec4;

/// A vertex after the projection and before the perspective divide: its
/// homogeneous clip-space position `(x, y, z, w)` and its colour.
///
/// Depth travels in `position.z` (divided by `w` later), so interpolating
/// the position interpolates depth too.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipVertex {
    /// Homogeneous clip-space position.
    pub position: Vec4,
    /// Colour.
    pub colour: Rgba,
}

impl ClipVertex {
    /// A clip-space vertex.
    #[must_use]
    pub const fn new(position: Vec4, colour: Rgba) -> Self {
        Self { position, colour }
    }

    /// Linear interpolation of position and colour,
    /// `self · (1 − t) + other · t` (the sheet's equation (1), applied to
    /// the intersection point of section 5.2).
    ///
    /// `t = 0` gives `self` and `t = 1` gives `other` exactly; `t` outside
    /// `[0, 1]` extrapolates.
    #[must_use]
    pub fn lerp(self, other: Self, t: f32) -> Self {
        Self {
            // `a·(1 − t) + b·t` rather than glam's `a + (b − a)·t`: exact at
            // both ends.
            position: self.position * (1.0 - t) + other.position * t,
            colour: self.colour.lerp(other.colour, t),
        }
    }
}
