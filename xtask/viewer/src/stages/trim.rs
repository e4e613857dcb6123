//! The trims of the surface and GPU scenes: the shapes of seed 000 §3, a
//! trim's set-up, and the trim your topic 07 builds from it.

#[cfg(feature = "bezier")]
use std::sync::Arc;

use glam::DVec2;

#[cfg(feature = "bezier")]
use super::TrimFn;

/// The trim shapes of seed 000 §3 (and §5's nested regions).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TrimShape {
    /// Nothing is cut away.
    None,
    /// `u` and `v` both in an interval (§3.1).
    Rectangle,
    /// Within a radius of a centre (§3.2).
    Circle,
    /// Inside an axis-aligned ellipse (§3.3, eq. 14).
    Ellipse,
    /// Between two quadratic Bézier curves, found by Newton's method
    /// (§3.4, Abbildung 11).
    NewtonQuadratic,
    /// Between two cubic Bézier curves (Abbildung 24).
    NewtonCubic,
    /// A quadratic region with another one inside it kept (Abbildung 12).
    Nested,
}

impl TrimShape {
    /// Every shape, in the order of the controls.
    pub const ALL: [Self; 7] = [
        Self::None,
        Self::Rectangle,
        Self::Circle,
        Self::Ellipse,
        Self::NewtonQuadratic,
        Self::NewtonCubic,
        Self::Nested,
    ];

    /// Its name on screen.
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Self::None => "No trim",
            Self::Rectangle => "Rectangle",
            Self::Circle => "Circle",
            Self::Ellipse => "Ellipse",
            Self::NewtonQuadratic => "Newton, quadratic curves",
            Self::NewtonCubic => "Newton, cubic curves",
            Self::Nested => "Newton, nested",
        }
    }

    /// Your code that decides it: topic 07's type and method.
    #[must_use]
    pub fn source(self) -> &'static str {
        match self {
            Self::None => "nothing to trim",
            Self::Rectangle => "07-bezier · simple_trim::IntervalTrim::trims",
            Self::Circle => "07-bezier · simple_trim::CircleTrim::trims",
            Self::Ellipse => "07-bezier · simple_trim::EllipseTrim::trims",
            Self::NewtonQuadratic | Self::NewtonCubic => {
                "07-bezier · newton_trim::NewtonTrim::trims (newton, between_crossings)"
            }
            Self::Nested => "07-bezier · newton_trim::NestedNewtonTrim::trims",
        }
    }

    /// Whether Newton's method decides it.
    #[must_use]
    pub fn newton(self) -> bool {
        matches!(
            self,
            Self::NewtonQuadratic | Self::NewtonCubic | Self::Nested
        )
    }
}

/// The seed's regions between two quadratic curves (Abbildung 11) and
/// two cubic curves (Abbildung 24), as topic 07's tests draw them.
pub use freeform::trim::{CUBIC_REGION as CUBIC, QUADRATIC_REGION as QUADRATIC};

/// The region kept inside [`QUADRATIC`] in the nested trim (Abbildung 12).
pub use freeform::trim::INNER_REGION as INNER;

/// A trim and its parameters, in the parameter square `[0, 1]²`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrimSetup {
    /// Which shape.
    pub shape: TrimShape,
    /// The shape's centre (Newton regions: where the middle of their
    /// curves' square goes).
    pub centre: DVec2,
    /// Half the rectangle's sides; the circle's radius in `x`; the
    /// ellipse's radii.
    pub size: DVec2,
    /// How much the Newton regions are scaled about their centre.
    pub scale: f64,
    /// Newton's most steps (seed §5.2: 6 and 7 differ).
    pub iterations: u32,
    /// Newton stops after a step shorter than this (seed §5.2: ε from 0.1
    /// to 0.0001).
    pub epsilon: f64,
}

impl Default for TrimSetup {
    /// The circle of the seed's Abbildung 15 with Newton's default
    /// settings (10 steps, ε = 0.001).
    fn default() -> Self {
        Self {
            shape: TrimShape::Circle,
            centre: DVec2::splat(0.5),
            size: DVec2::new(0.2, 0.15),
            scale: 1.0,
            iterations: 10,
            epsilon: 0.001,
        }
    }
}

impl TrimSetup {
    /// The control points of a Newton shape's curves, moved and scaled
    /// (the curves of the seed's figures at the defaults).
    #[must_use]
    pub fn curve_points<const N: usize>(&self, points: [DVec2; N]) -> [DVec2; N] {
        points.map(|p| self.centre + (p - DVec2::splat(0.5)) * self.scale)
    }

    /// Keeps the trim drawable: its parameters in range and finite.
    pub fn tidy(&mut self) {
        let finite_or = |v: f64, fallback: f64| if v.is_finite() { v } else { fallback };
        let fallback = Self::default();
        if !self.centre.is_finite() {
            self.centre = fallback.centre;
        }
        self.centre = self.centre.clamp(DVec2::ZERO, DVec2::ONE);
        if !self.size.is_finite() {
            self.size = fallback.size;
        }
        self.size = self.size.clamp(DVec2::splat(0.01), DVec2::splat(1.0));
        self.scale = finite_or(self.scale, 1.0).clamp(0.1, 2.0);
        self.iterations = self.iterations.clamp(1, 30);
        self.epsilon = finite_or(self.epsilon, fallback.epsilon).clamp(1e-6, 0.5);
    }
}

/// The trim a set-up describes, built from your types.
#[cfg(feature = "bezier")]
pub(super) fn build_trim(setup: &TrimSetup) -> Result<TrimFn, String> {
    use bezier::Trim;
    use bezier::newton_trim::{NestedNewtonTrim, NewtonSettings, NewtonTrim};
    use bezier::simple_trim::{CircleTrim, EllipseTrim, IntervalTrim};
    fn shared(trim: impl Trim + Send + Sync + 'static) -> TrimFn {
        Arc::new(move |uv| trim.trims(uv))
    }
    let error = |e: bezier::BezierError| e.to_string();
    let settings = NewtonSettings {
        max_iterations: setup.iterations,
        epsilon: setup.epsilon,
    };
    let quadratic = |points| {
        NewtonTrim::quadratic(setup.curve_points(points))
            .map(|t| t.with_settings(settings))
            .map_err(error)
    };
    Ok(match setup.shape {
        TrimShape::None => Arc::new(|_| false),
        TrimShape::Rectangle => shared(
            IntervalTrim::new(setup.centre - setup.size, setup.centre + setup.size)
                .map_err(error)?,
        ),
        TrimShape::Circle => shared(CircleTrim::new(setup.centre, setup.size.x).map_err(error)?),
        TrimShape::Ellipse => shared(EllipseTrim::new(setup.centre, setup.size).map_err(error)?),
        TrimShape::NewtonQuadratic => shared(quadratic(QUADRATIC)?),
        TrimShape::NewtonCubic => shared(
            NewtonTrim::cubic(setup.curve_points(CUBIC))
                .map(|t| t.with_settings(settings))
                .map_err(error)?,
        ),
        TrimShape::Nested => shared(NestedNewtonTrim::new(
            quadratic(QUADRATIC)?,
            quadratic(INNER)?,
        )),
    })
}
