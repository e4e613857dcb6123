//! Why a tessellation could not be made: one error type for the crate.
//!
//! Library functions never panic or hang on bad input (NaN, infinities,
//! empty or mis-sized control grids, zero or huge resolutions); they return
//! one of these instead.

/// What went wrong, with the offending value.
#[transcript::evidence]
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum TessError {
    /// A control point, parameter or tolerance is NaN or infinite.
    #[error("{what} is not finite")]
    NonFinite {
        /// Which input.
        what: &'static str,
    },
    /// The control grid does not have `(degree_u + 1) · (degree_v + 1)` points.
    #[error("a control grid of degree {degree_u}×{degree_v} needs {expected} points, got {found}")]
    ControlGrid {
        /// Degree in u.
        degree_u: usize,
        /// Degree in v.
        degree_v: usize,
        /// `(degree_u + 1) · (degree_v + 1)`.
        expected: usize,
        /// What was given.
        found: usize,
    },
    /// A resolution (number of cells or segments) that is zero or too large.
    #[error("resolution {0} is outside 1..={max}", max = crate::bezier::MAX_RESOLUTION)]
    Resolution(usize),
    /// A tolerance or threshold that is not positive.
    #[error("{what} must be positive, got {value}")]
    NotPositive {
        /// Which parameter.
        what: &'static str,
        /// Its value.
        value: f64,
    },
    /// A patch grid whose neighbours do not share their boundary curve.
    #[error("patches ({row}, {col}) and their {side} neighbour do not share a boundary curve")]
    NotContinuous {
        /// Row of the first patch.
        row: usize,
        /// Column of the first patch.
        col: usize,
        /// `"right"` or `"upper"`.
        side: &'static str,
    },
    /// A mesh whose triangles name vertices it does not have, or whose
    /// attribute lists differ in length.
    #[error("invalid mesh: {0}")]
    Mesh(&'static str),
}
