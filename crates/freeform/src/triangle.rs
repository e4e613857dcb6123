//! The cubic Bézier triangle (seed 001 §4.1, equation (4.1)): ten control
//! points named by their exponents, and the one order in which they are
//! stored where a list is needed (the GPU's buffer in topic 10).
//!
//! ```text
//!                 b030                  B(u, v, w) = Σ_{i+j+k=3} 3!/(i! j! k!) uⁱ vʲ wᵏ b_ijk,
//!               ╱      ╲                u + v + w = 1
//!           b021        b120
//!          ╱     b111      ╲            corners: B(1,0,0) = b300,
//!      b012                b210                  B(0,1,0) = b030,
//!      ╱                      ╲                  B(0,0,1) = b003
//!  b003 ─── b102 ──── b201 ─── b300
//! ```
//!
//! Evaluating one is a task (topic 09 by the sum, topic 10 by de Casteljau
//! in WGSL): this module holds only the points.

use glam::DVec3;

/// A cubic Bézier triangle: `b_ijk` goes with `uⁱ vʲ wᵏ`.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq)]
#[allow(missing_docs)] // the names are the documentation: b_ijk goes with uⁱ vʲ wᵏ
pub struct BezierTriangle {
    pub b300: DVec3,
    pub b030: DVec3,
    pub b003: DVec3,
    pub b210: DVec3,
    pub b201: DVec3,
    pub b120: DVec3,
    pub b021: DVec3,
    pub b102: DVec3,
    pub b012: DVec3,
    pub b111: DVec3,
}

impl BezierTriangle {
    /// The storage index of `b_ijk` (`k = 3 − i − j`): rows by falling `i`,
    /// then falling `j`, so the order is
    /// `b300 b210 b201 b120 b111 b102 b030 b021 b012 b003`.
    ///
    /// # Panics
    /// If `i + j > 3`.
    #[must_use]
    pub const fn index(i: usize, j: usize) -> usize {
        assert!(i + j <= 3, "b_ijk needs i + j + k = 3");
        let row = 3 - i;
        row * (row + 1) / 2 + (row - j)
    }

    /// The triangle whose `b_ijk` is `point(i, j, k)`.
    #[must_use]
    pub fn from_fn(point: impl Fn(usize, usize, usize) -> DVec3) -> Self {
        Self {
            b300: point(3, 0, 0),
            b030: point(0, 3, 0),
            b003: point(0, 0, 3),
            b210: point(2, 1, 0),
            b201: point(2, 0, 1),
            b120: point(1, 2, 0),
            b021: point(0, 2, 1),
            b102: point(1, 0, 2),
            b012: point(0, 1, 2),
            b111: point(1, 1, 1),
        }
    }

    /// The triangle of ten points in [`index`](Self::index) order.
    #[must_use]
    pub fn from_points(points: [DVec3; 10]) -> Self {
        Self::from_fn(|i, j, _| points[Self::index(i, j)])
    }

    /// `b_ijk`.
    ///
    /// # Panics
    /// If `i + j + k ≠ 3`.
    #[must_use]
    pub fn point(&self, i: usize, j: usize, k: usize) -> DVec3 {
        match (i, j, k) {
            (3, 0, 0) => self.b300,
            (0, 3, 0) => self.b030,
            (0, 0, 3) => self.b003,
            (2, 1, 0) => self.b210,
            (2, 0, 1) => self.b201,
            (1, 2, 0) => self.b120,
            (0, 2, 1) => self.b021,
            (1, 0, 2) => self.b102,
            (0, 1, 2) => self.b012,
            (1, 1, 1) => self.b111,
            _ => panic!("b_{i}{j}{k} is no point of a cubic triangle (i + j + k = 3)"),
        }
    }

    /// The ten points in [`index`](Self::index) order.
    #[must_use]
    pub fn points(&self) -> [DVec3; 10] {
        let mut points = [DVec3::ZERO; 10];
        for i in 0..=3 {
            for j in 0..=3 - i {
                points[Self::index(i, j)] = self.point(i, j, 3 - i - j);
            }
        }
        points
    }

    /// The flat triangle with corners `a = b300`, `b = b030`, `c = b003`
    /// and every other point at its linear position `(i·a + j·b + k·c)/3`,
    /// so that `B(u, v, w) = u·a + v·b + w·c` exactly.
    #[must_use]
    pub fn flat(a: DVec3, b: DVec3, c: DVec3) -> Self {
        Self::from_fn(|i, j, k| (a * i as f64 + b * j as f64 + c * k as f64) / 3.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn storage_order_is_the_documented_one() {
        let names = [
            (3, 0),
            (2, 1),
            (2, 0),
            (1, 2),
            (1, 1),
            (1, 0),
            (0, 3),
            (0, 2),
            (0, 1),
            (0, 0),
        ];
        for (k, (i, j)) in names.into_iter().enumerate() {
            assert_eq!(BezierTriangle::index(i, j), k, "b{i}{j}{}", 3 - i - j);
        }
    }

    #[test]
    fn points_and_from_points_round_trip() {
        let t = BezierTriangle::from_fn(|i, j, k| DVec3::new(i as f64, j as f64, 10.0 * k as f64));
        assert_eq!(BezierTriangle::from_points(t.points()), t);
        assert_eq!(t.b210, DVec3::new(2.0, 1.0, 0.0));
        assert_eq!(t.points()[4], t.b111);
    }

    #[test]
    fn flat_corners_are_the_given_points() {
        let (a, b, c) = (DVec3::X, DVec3::Y, DVec3::Z);
        let t = BezierTriangle::flat(a, b, c);
        assert_eq!((t.b300, t.b030, t.b003), (a, b, c));
        assert_eq!(t.b111, DVec3::splat(1.0 / 3.0));
    }
}
