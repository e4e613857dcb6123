//! Simple trimming in the parameter square: interval (rectangle, square),
//! circle and ellipse (seed 000, §3.1 and Listing 7).
//!
//! Each shape answers the fragment shader's question "discard this
//! (u, v)?". The boundaries follow the seed's comparisons exactly: the
//! interval and the ellipse include their boundary (`>=`, `<=`, `<= 1`),
//! the circle excludes it (`distance < r`).
//!
//! ```text
//!   v ↑ ┌───────────────┐      interval   u₁ ≤ u ≤ u₂  and  v₁ ≤ v ≤ v₂
//!     │ │   ┌───┐  ( c )│      circle     |(u, v) − c| < r
//!     │ │   └───┘       │      ellipse    (u − c₁)²/a² + (v − c₂)²/b² ≤ 1
//!     │ └───────────────┘
//!     └──────────────────→ u
//! ```

use glam::DVec2;

use crate::basics::{BezierError, Trim};

/// An axis-parallel rectangle `[min.x, max.x] × [min.y, max.y]` of
/// (u, v), boundary included (seed `trimValuesx`, `trimValuesy`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IntervalTrim {
    min: DVec2,
    max: DVec2,
}

impl IntervalTrim {
    /// The rectangle with corners `min` and `max`.
    ///
    /// # Errors
    /// [`BezierError::InvalidTrim`] if a corner is not finite or
    /// `min > max` in u or v. (`min == max` is a line or a point.)
    pub fn new(min: DVec2, max: DVec2) -> Result<Self, BezierError> {
        if !(min.is_finite() && max.is_finite()) {
            return Err(BezierError::InvalidTrim("interval corners must be finite"));
        }
        if min.x > max.x || min.y > max.y {
            return Err(BezierError::InvalidTrim("interval needs min ≤ max"));
        }
        Ok(Self { min, max })
    }
}

impl Trim for IntervalTrim {
    /// `min.x ≤ u ≤ max.x` and `min.y ≤ v ≤ max.y` (boundary trimmed).
    #[transcript::task]
    fn trims(&self, uv: DVec2) -> bool {
        // BEGIN SOLUTION trim: inclusive comparisons in u and in v, as the seed's shader
        uv.x >= self.min.x && uv.x <= self.max.x && uv.y >= self.min.y && uv.y <= self.max.y
        // END SOLUTION
    }
}

/// A disc of (u, v) around `centre` with `radius`, boundary kept
/// (seed `trimCenter`, `trimRadius`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CircleTrim {
    centre: DVec2,
    radius: f64,
}

impl CircleTrim {
    /// The disc around `centre`.
    ///
    /// # Errors
    /// [`BezierError::InvalidTrim`] if `centre` or `radius` is not finite
    /// or `radius < 0`.
    pub fn new(centre: DVec2, radius: f64) -> Result<Self, BezierError> {
        if !(centre.is_finite() && radius.is_finite()) || radius < 0.0 {
            return Err(BezierError::InvalidTrim(
                "circle needs a finite centre and a finite radius ≥ 0",
            ));
        }
        Ok(Self { centre, radius })
    }
}

impl Trim for CircleTrim {
    /// `|uv − centre| < radius` (GLSL `distance`; the boundary is kept).
    #[transcript::task]
    fn trims(&self, uv: DVec2) -> bool {
        // BEGIN SOLUTION trim: strict comparison of the distance with the radius, as the seed's shader
        uv.distance(self.centre) < self.radius
        // END SOLUTION
    }
}

/// An axis-parallel ellipse of (u, v) with half-axes `radii.x` (in u) and
/// `radii.y` (in v) around `centre`, boundary included (seed eq. 14).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EllipseTrim {
    centre: DVec2,
    radii: DVec2,
}

impl EllipseTrim {
    /// The ellipse around `centre` with half-axes `radii`.
    ///
    /// # Errors
    /// [`BezierError::InvalidTrim`] if a value is not finite or a half-axis
    /// is not positive (eq. 14 divides by it).
    pub fn new(centre: DVec2, radii: DVec2) -> Result<Self, BezierError> {
        if !(centre.is_finite() && radii.is_finite()) || radii.x <= 0.0 || radii.y <= 0.0 {
            return Err(BezierError::InvalidTrim(
                "ellipse needs a finite centre and finite half-axes > 0",
            ));
        }
        Ok(Self { centre, radii })
    }
}

impl Trim for EllipseTrim {
    /// `(u − c₁)²/a² + (v − c₂)²/b² ≤ 1` (seed eq. 14; boundary trimmed).
    #[transcript::task]
    fn trims(&self, uv: DVec2) -> bool {
        // BEGIN SOLUTION trim: evaluate eq. 14 and compare with ≤ 1
        let d = (uv - self.centre) / self.radii;
        d.x * d.x + d.y * d.y <= 1.0
        // END SOLUTION
    }
}
