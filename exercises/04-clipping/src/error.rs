//! Why a clipping function refused its input.

/// Why a clipping function refused its input.
///
/// Clipping never panics: input it cannot give a meaningful answer for is
/// reported with the index of the first offending vertex or endpoint.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ClipError {
    /// A coordinate is NaN or infinite.
    #[error("vertex {index} has a NaN or infinite coordinate")]
    NonFinite {
        /// Index of the vertex (polygon) or endpoint (`0` from, `1` to).
        index: usize,
    },
    /// A coordinate is finite but beyond the limit the function states
    /// ([`MAX_CLIP_COORD`](crate::plane::MAX_CLIP_COORD) in clip space,
    /// [`canvas::MAX_COORD`] for 2D lines).
    #[error("vertex {index} lies beyond the coordinate limit")]
    OutOfRange {
        /// Index of the vertex (polygon) or endpoint (`0` from, `1` to).
        index: usize,
    },
    /// A clip plane has a NaN or infinite component.
    #[error("clip plane {index} has a NaN or infinite component")]
    InvalidPlane {
        /// Index of the plane in the list given.
        index: usize,
    },
}
