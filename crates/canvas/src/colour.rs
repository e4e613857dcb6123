//! Colours: linear RGBA with `f32` channels in `[0, 1]`.

use std::ops::{Add, Mul};

/// A colour with red, green, blue and alpha channels in `[0, 1]`.
///
/// Channels are plain (not premultiplied) and linear: interpolating two
/// colours interpolates each channel. Values outside `[0, 1]` are kept as
/// they are and only clamped when a canvas is written to a PNG.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Rgba {
    /// Red.
    pub r: f32,
    /// Green.
    pub g: f32,
    /// Blue.
    pub b: f32,
    /// Alpha (opacity; 1 is opaque).
    pub a: f32,
}

impl Rgba {
    /// Opaque black, the canvas clear colour.
    pub const BLACK: Self = Self::rgb(0.0, 0.0, 0.0);
    /// Opaque white, the colour tests draw with.
    pub const WHITE: Self = Self::rgb(1.0, 1.0, 1.0);
    /// Opaque red.
    pub const RED: Self = Self::rgb(1.0, 0.0, 0.0);
    /// Opaque green.
    pub const GREEN: Self = Self::rgb(0.0, 1.0, 0.0);
    /// Opaque blue.
    pub const BLUE: Self = Self::rgb(0.0, 0.0, 1.0);
    /// Fully transparent black.
    pub const TRANSPARENT: Self = Self::new(0.0, 0.0, 0.0, 0.0);

    /// A colour from all four channels.
    #[must_use]
    pub const fn new(r: f32, g: f32, b: f32, a: f32) -> Self {
        Self { r, g, b, a }
    }

    /// An opaque colour.
    #[must_use]
    pub const fn rgb(r: f32, g: f32, b: f32) -> Self {
        Self::new(r, g, b, 1.0)
    }

    /// An opaque grey of the given intensity (`0` black, `1` white).
    #[must_use]
    pub const fn grey(v: f32) -> Self {
        Self::rgb(v, v, v)
    }

    /// Linear interpolation `self · (1 − t) + other · t`, channel by channel
    /// (the sheet's equation (1)).
    ///
    /// `t = 0` gives `self`, `t = 1` gives `other` exactly; `t` outside
    /// `[0, 1]` extrapolates, so callers clamp it when they mean a point on
    /// the segment.
    #[must_use]
    #[inline]
    pub fn lerp(self, other: Self, t: f32) -> Self {
        self * (1.0 - t) + other * t
    }

    /// The brightest of the three colour channels: how much "ink" the pixel
    /// shows on the black clear colour. ASCII art draws this value.
    #[must_use]
    #[inline]
    pub fn ink(self) -> f32 {
        self.r.max(self.g).max(self.b)
    }

    /// The colour as 8-bit channels, each rounded from `[0, 1]` to the
    /// nearest of 256 levels; values outside are clamped and NaN becomes 0.
    #[must_use]
    #[inline]
    pub fn to_rgba8(self) -> [u8; 4] {
        // `+ 0.5` then truncation rounds half up, which for the non-negative
        // values that matter is half away from zero; the saturating `as`
        // clamps to 0..=255 and maps NaN to 0. (`f32::round` would be a
        // library call on baseline x86-64, in every pixel write.)
        let q = |v: f32| (v * 255.0 + 0.5) as u8;
        [q(self.r), q(self.g), q(self.b), q(self.a)]
    }

    /// The colour of 8-bit channels.
    #[must_use]
    pub fn from_rgba8([r, g, b, a]: [u8; 4]) -> Self {
        let f = |v: u8| f32::from(v) / 255.0;
        Self::new(f(r), f(g), f(b), f(a))
    }

    /// Whether every channel differs from `other`'s by at most `tolerance`.
    #[must_use]
    pub fn approx_eq(self, other: Self, tolerance: f32) -> bool {
        (self.r - other.r).abs() <= tolerance
            && (self.g - other.g).abs() <= tolerance
            && (self.b - other.b).abs() <= tolerance
            && (self.a - other.a).abs() <= tolerance
    }
}

impl Add for Rgba {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Self::new(self.r + o.r, self.g + o.g, self.b + o.b, self.a + o.a)
    }
}

impl Mul<f32> for Rgba {
    type Output = Self;
    #[inline]
    fn mul(self, s: f32) -> Self {
        Self::new(self.r * s, self.g * s, self.b * s, self.a * s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lerp_hits_both_ends_exactly() {
        let a = Rgba::new(0.1, 0.2, 0.3, 1.0);
        let b = Rgba::new(0.9, 0.5, 0.0, 0.5);
        assert_eq!(a.lerp(b, 0.0), a);
        assert_eq!(a.lerp(b, 1.0), b);
        assert!(
            a.lerp(b, 0.5)
                .approx_eq(Rgba::new(0.5, 0.35, 0.15, 0.75), 1e-6)
        );
    }

    #[test]
    fn eight_bit_round_trip() {
        assert_eq!(Rgba::WHITE.to_rgba8(), [255, 255, 255, 255]);
        assert_eq!(
            Rgba::new(f32::NAN, 2.0, -1.0, 0.5).to_rgba8(),
            [0, 255, 0, 128]
        );
        assert_eq!(
            Rgba::from_rgba8([255, 0, 51, 255]),
            Rgba::new(1.0, 0.0, 0.2, 1.0)
        );
    }
}
