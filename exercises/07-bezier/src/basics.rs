//! Given code: the error type, the degree limit, the point trait shared by
//! curves in 1, 2 and 3 dimensions, and the trimming trait.
//!
//! Nothing here is an exercise; every task builds on it.

use std::ops::{Add, Mul, Sub};

use glam::{DVec2, DVec3};

/// The highest degree any curve or surface direction may have.
///
/// The binomial coefficients of degree 32 are below 2³¹, so every
/// `C(n, i)` is an exact `f64`, and no figure of the course needs more.
/// Higher degrees are rejected with [`BezierError::DegreeTooHigh`] rather
/// than evaluated with a growing rounding error. (The course library's
/// [`freeform::patch::MAX_DEGREE`], which patches keep.)
pub const MAX_DEGREE: usize = freeform::patch::MAX_DEGREE;

/// Why a curve, surface or trim could not be built or evaluated.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum BezierError {
    /// A curve or net without control points.
    #[error("there are no control points")]
    Empty,
    /// More control points than [`MAX_DEGREE`] + 1 in one direction.
    #[error("degree {degree} is above the limit of {max}")]
    DegreeTooHigh {
        /// The degree asked for.
        degree: usize,
        /// [`MAX_DEGREE`].
        max: usize,
    },
    /// A Bernstein index `i` above the degree `n`.
    #[error("index i = {i} is above the degree n = {n}")]
    IndexAboveDegree {
        /// The index.
        i: usize,
        /// The degree.
        n: usize,
    },
    /// A curve or surface parameter that is NaN or outside `[0, 1]`.
    #[error("parameter {name} = {value} is not in [0, 1]")]
    ParameterOutOfRange {
        /// `"t"`, `"u"` or `"v"`.
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// A control point with a NaN or infinite coordinate.
    #[error("control point {index} is not finite")]
    NonFinitePoint {
        /// Its index in the input.
        index: usize,
    },
    /// The partial derivatives are zero or parallel at and next to (u, v).
    #[error("the normal at ({u}, {v}) is undefined: the partial derivatives are parallel")]
    DegenerateNormal {
        /// u.
        u: f64,
        /// v.
        v: f64,
    },
    /// A trim shape with invalid parameters (the message says which).
    #[error("invalid trim shape: {0}")]
    InvalidTrim(&'static str),
    /// A render or Newton setting out of its range (the message says which).
    #[error("invalid setting: {0}")]
    InvalidSetting(&'static str),
    /// The curves of a trim loop do not join end to start.
    #[error("trim loop: curve {curve} does not start where curve {previous} ends")]
    LoopNotClosed {
        /// The curve that starts elsewhere.
        curve: usize,
        /// The curve before it.
        previous: usize,
    },
}

// The grader records the errors your functions return and replays them
// (the `transcript` crate); written by hand for the `&'static str` names
// and messages, which a replay gets back as text kept for the process.
impl transcript::Record for BezierError {
    fn record(&self, out: &mut Vec<u8>) {
        match *self {
            Self::Empty => 0_u8.record(out),
            Self::DegreeTooHigh { degree, max } => (1_u8, degree, max).record(out),
            Self::IndexAboveDegree { i, n } => (2_u8, i, n).record(out),
            Self::ParameterOutOfRange { name, value } => (3_u8, name, value).record(out),
            Self::NonFinitePoint { index } => (4_u8, index).record(out),
            Self::DegenerateNormal { u, v } => (5_u8, u, v).record(out),
            Self::InvalidTrim(message) => (6_u8, message).record(out),
            Self::InvalidSetting(message) => (7_u8, message).record(out),
            Self::LoopNotClosed { curve, previous } => (8_u8, curve, previous).record(out),
        }
    }
}

impl transcript::Replay for BezierError {
    fn replay(input: &mut &[u8]) -> Result<Self, String> {
        let text = |input: &mut &[u8]| -> Result<&'static str, String> {
            Ok(String::leak(String::replay(input)?))
        };
        Ok(match u8::replay(input)? {
            0 => Self::Empty,
            1 => Self::DegreeTooHigh {
                degree: usize::replay(input)?,
                max: usize::replay(input)?,
            },
            2 => Self::IndexAboveDegree {
                i: usize::replay(input)?,
                n: usize::replay(input)?,
            },
            3 => Self::ParameterOutOfRange {
                name: text(input)?,
                value: f64::replay(input)?,
            },
            4 => Self::NonFinitePoint {
                index: usize::replay(input)?,
            },
            5 => Self::DegenerateNormal {
                u: f64::replay(input)?,
                v: f64::replay(input)?,
            },
            6 => Self::InvalidTrim(text(input)?),
            7 => Self::InvalidSetting(text(input)?),
            8 => Self::LoopNotClosed {
                curve: usize::replay(input)?,
                previous: usize::replay(input)?,
            },
            tag => return Err(format!("a BezierError tagged {tag}")),
        })
    }
}

/// A point (or scalar) that curves interpolate: `f64`, [`DVec2`], [`DVec3`].
///
/// De Casteljau and the Bernstein form need only affine combinations, so
/// one generic implementation serves scalar, planar and spatial curves.
/// A point is also `transcript::Record` and `transcript::Replay`: the
/// grader records the points your functions return (`f64` and glam's
/// vectors are both already).
pub trait ControlPoint:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<f64, Output = Self>
    + transcript::Record
    + transcript::Replay
{
    /// The origin (or 0), the start of a sum.
    const ZERO: Self;
    /// Whether every coordinate is finite (neither NaN nor infinite).
    fn is_finite_point(self) -> bool;
}

impl ControlPoint for f64 {
    const ZERO: Self = 0.0;
    fn is_finite_point(self) -> bool {
        self.is_finite()
    }
}

impl ControlPoint for DVec2 {
    const ZERO: Self = DVec2::ZERO;
    fn is_finite_point(self) -> bool {
        self.is_finite()
    }
}

impl ControlPoint for DVec3 {
    const ZERO: Self = DVec3::ZERO;
    fn is_finite_point(self) -> bool {
        self.is_finite()
    }
}

/// Checks a curve's control points: not empty, degree at most
/// [`MAX_DEGREE`], every point finite.
///
/// # Errors
/// [`BezierError::Empty`], [`BezierError::DegreeTooHigh`] or
/// [`BezierError::NonFinitePoint`] (the first bad point).
pub fn check_control_points<P: ControlPoint>(points: &[P]) -> Result<(), BezierError> {
    if points.is_empty() {
        return Err(BezierError::Empty);
    }
    let degree = points.len() - 1;
    if degree > MAX_DEGREE {
        return Err(BezierError::DegreeTooHigh {
            degree,
            max: MAX_DEGREE,
        });
    }
    match points.iter().position(|p| !p.is_finite_point()) {
        Some(index) => Err(BezierError::NonFinitePoint { index }),
        None => Ok(()),
    }
}

/// Checks a curve or surface parameter: `0 ≤ value ≤ 1` (NaN fails).
///
/// # Errors
/// [`BezierError::ParameterOutOfRange`] naming the parameter.
pub fn check_parameter(name: &'static str, value: f64) -> Result<(), BezierError> {
    if (0.0..=1.0).contains(&value) {
        Ok(())
    } else {
        Err(BezierError::ParameterOutOfRange { name, value })
    }
}

/// A region cut out of a surface's parameter square `[0, 1]²`.
///
/// `trims(uv)` is the fragment shader's `discard` condition (seed 000,
/// Listing 7): `true` means the surface point `P(u, v)` is not drawn.
/// A NaN `uv` is never trimmed.
pub trait Trim {
    /// Whether the point `uv` of the parameter square is cut away.
    fn trims(&self, uv: DVec2) -> bool;
}
