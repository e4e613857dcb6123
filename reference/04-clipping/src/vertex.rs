//! SCRATCH: a local copy of `scene::ClipVertex` until the course library has it.

use canvas::{Rgba, Vec4};

/// A vertex in homogeneous clip space with its colour.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipVertex {
    /// Position in clip space.
    pub position: Vec4,
    /// Colour.
    pub colour: Rgba,
}

impl ClipVertex {
    /// Linear interpolation of position and colour.
    #[must_use]
    pub fn lerp(self, other: Self, t: f32) -> Self {
        Self {
            position: self.position.lerp(other.position, t),
            colour: self.colour.lerp(other.colour, t),
        }
    }
}
