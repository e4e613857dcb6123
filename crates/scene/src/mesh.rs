//! A polygon mesh as the sheet's framework stores it (section 3.2): vertex
//! positions with colours, and faces that index them.

use canvas::Rgba;
use glam::Vec3;

/// A polygon mesh: positions and colours per vertex, faces as lists of
/// vertex indices.
///
/// Invariants, checked by [`crate::ply::parse`] for every loaded mesh:
/// `colours.len() == positions.len()` (white where the file has no
/// colours), every position is finite, every face has at least 3 corners
/// and every index is `< positions.len()`. Faces are meant to be planar
/// convex polygons in either winding; the rasterizer draws a face as a
/// triangle fan from its first corner, which is exact only for convex faces.
/// A hand-built mesh that breaks the invariants is not rejected by the
/// pipeline: faces with an index out of range are skipped
/// ([`crate::Pipeline::clip_space`]).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// Vertex positions in model space.
    pub positions: Vec<Vec3>,
    /// One colour per vertex.
    pub colours: Vec<Rgba>,
    /// Faces: indices into `positions`, in order around the polygon.
    pub faces: Vec<Vec<u32>>,
}

impl Mesh {
    /// The smallest axis-aligned box holding every position, as its minimum
    /// and maximum corner; `None` for a mesh without vertices.
    #[must_use]
    pub fn bounds(&self) -> Option<[Vec3; 2]> {
        let first = *self.positions.first()?;
        Some(
            self.positions
                .iter()
                .fold([first, first], |[lo, hi], &p| [lo.min(p), hi.max(p)]),
        )
    }
}
