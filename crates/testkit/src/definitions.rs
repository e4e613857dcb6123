//! Rasters by their definitions, computed directly and exactly: what the
//! tests of topics 01–03 compare your pixels with, and what the viewer's
//! pixel playground draws beside yours. Never by the incremental
//! algorithms the tasks teach. And the clip volume's planes written out
//! (topic 04), which the tests and the benchmark clip against.

use std::collections::BTreeSet;

use canvas::{MAX_COORD, Pixel, Vec2, Vec4, Viewport};

// ---------------------------------------------------------------------------
// Lines (topic 01).

/// The pixels of the line from `from` to `to` by definition: in each column
/// of the major axis (x when `|Δx| ≥ |Δy|`), the pixel nearest to the ideal
/// line, a tie going to the smaller minor coordinate. Computed column by
/// column in exact integer arithmetic, in order from `from` to `to`, and
/// only for the columns inside `window` when one is given.
#[must_use]
pub fn line_pixels(from: Pixel, to: Pixel, window: Option<Viewport>) -> Vec<Pixel> {
    let (dx, dy) = (
        i128::from(to.x) - i128::from(from.x),
        i128::from(to.y) - i128::from(from.y),
    );
    let x_major = dx.abs() >= dy.abs();
    let (m0, n0, dm, dn) = if x_major {
        (from.x, from.y, dx, dy)
    } else {
        (from.y, from.x, dy, dx)
    };
    let to_pixel = |major: i128, minor: i128| {
        let (major, minor) = (major as i32, minor as i32);
        if x_major {
            Pixel::new(major, minor)
        } else {
            Pixel::new(minor, major)
        }
    };
    if dm == 0 {
        let p = from;
        return match window {
            Some(w) if !w.contains(p) => vec![],
            _ => vec![p],
        };
    }
    let step = dm.signum();
    let (first, last) = (i128::from(m0), i128::from(m0) + dm);
    // Restrict the columns to the window's major range.
    let (lo, hi) = match window {
        Some(w) if x_major => (i128::from(w.x_min), i128::from(w.x_max)),
        Some(w) => (i128::from(w.y_min), i128::from(w.y_max)),
        None => (first.min(last), first.max(last)),
    };
    let (lo, hi) = (lo.max(first.min(last)), hi.min(first.max(last)));
    let mut columns: Vec<i128> = (lo..=hi).collect();
    if step < 0 {
        columns.reverse();
    }
    columns
        .into_iter()
        .map(|m| {
            // Ideal minor = n0 + q with q = num / den, den > 0.
            let (mut num, mut den) = (dn * (m - i128::from(m0)), dm);
            if den < 0 {
                num = -num;
                den = -den;
            }
            // Nearest integer to q, ties down: ⌈q − ½⌉ = ⌈(2num − den) / 2den⌉.
            let a = 2 * num - den;
            let b = 2 * den;
            let nearest = -((-a).div_euclid(b));
            to_pixel(m, i128::from(n0) + nearest)
        })
        .filter(|&p| window.is_none_or(|w| w.contains(p)))
        .collect()
}

/// The columns (of the major axis) in which the ideal line from `from` to
/// `to` passes exactly half-way between two pixels, as those two pixels,
/// the smaller minor coordinate first: where [`line_pixels`] takes the
/// first, a rule rounding half away from zero may take the other, and a
/// floating-point sum (the DDA's) decides by its rounding errors.
#[must_use]
pub fn line_ties(from: Pixel, to: Pixel) -> Vec<[Pixel; 2]> {
    let (dx, dy) = (
        i64::from(to.x) - i64::from(from.x),
        i64::from(to.y) - i64::from(from.y),
    );
    let x_major = dx.abs() >= dy.abs();
    let (dm, dn) = if x_major { (dx, dy) } else { (dy, dx) };
    if dm == 0 {
        return Vec::new();
    }
    line_pixels(from, to, None)
        .into_iter()
        .filter_map(|p| {
            let (major, minor) = if x_major { (p.x, p.y) } else { (p.y, p.x) };
            let k = i64::from(major)
                - if x_major {
                    i64::from(from.x)
                } else {
                    i64::from(from.y)
                };
            // The ideal minor n0 + k·dn/dm has a fractional part of ½.
            if (2 * dn * k).rem_euclid(2 * dm.abs()) != dm.abs() {
                return None;
            }
            let other = minor + 1;
            Some(if x_major {
                [p, Pixel::new(p.x, other)]
            } else {
                [p, Pixel::new(other, p.y)]
            })
        })
        .collect()
}

/// The pixels of Wu's antialiased line from `from` to `to` by definition
/// (task 5c of `01-lines`), each with its intensity: the first and
/// last pixels full; in each column of the major axis between them, the
/// ideal line crosses the minor axis at `j + f` (counted from `from`
/// towards `to`), and pixel `j` gets `1 − f`, pixel `j + 1` gets `f`.
/// Axis-parallel and diagonal lines are one pixel per column, full.
#[must_use]
pub fn wu_pixels(from: Pixel, to: Pixel) -> Vec<(Pixel, f32)> {
    let (dx, dy) = (i64::from(to.x - from.x), i64::from(to.y - from.y));
    let (sx, sy) = (if dx < 0 { -1 } else { 1 }, if dy < 0 { -1 } else { 1 });
    let x_major = dx.abs() >= dy.abs();
    let (long, short) = if x_major {
        (dx.abs(), dy.abs())
    } else {
        (dy.abs(), dx.abs())
    };
    #[allow(clippy::cast_possible_truncation)] // within the grid
    let pixel = |i: i64, j: i64| {
        if x_major {
            Pixel::new(from.x + (sx * i) as i32, from.y + (sy * j) as i32)
        } else {
            Pixel::new(from.x + (sx * j) as i32, from.y + (sy * i) as i32)
        }
    };
    let mut pixels = vec![(from, 1.0)];
    if long == 0 {
        return pixels;
    }
    for i in 1..long {
        if short == 0 || short == long {
            pixels.push((pixel(i, if short == 0 { 0 } else { i }), 1.0));
        } else {
            let (j, rest) = ((i * short) / long, (i * short) % long);
            #[allow(clippy::cast_precision_loss)] // small
            let f = rest as f32 / long as f32;
            pixels.push((pixel(i, j), 1.0 - f));
            pixels.push((pixel(i, j + 1), f));
        }
    }
    pixels.push((to, 1.0));
    pixels
}

// ---------------------------------------------------------------------------
// Circles (topic 02).

/// Whether a shape reaching `rx` pixels left and right and `ry` up and
/// down of `centre` stays within ±`MAX_COORD` (and the reaches are not
/// negative): the limit every function of this topic draws within.
#[must_use]
pub fn within_limits(centre: Pixel, rx: i32, ry: i32) -> bool {
    let fits = |c: i32, r: i32| r >= 0 && i64::from(c).abs() + i64::from(r) <= i64::from(MAX_COORD);
    fits(centre.x, rx) && fits(centre.y, ry)
}

/// `centre + (x, y)`, for offsets the caller knows to be in range.
#[must_use]
pub fn offset(centre: Pixel, x: i64, y: i64) -> Pixel {
    Pixel::new(
        (i64::from(centre.x) + x) as i32,
        (i64::from(centre.y) + y) as i32,
    )
}

/// The second octant of the midpoint circle of radius `R` by definition:
/// for each column `x = 0, 1, …` the row nearest to the circle,
/// `y = round(√(R² − x²))`, as long as `x ≤ y`.
///
/// There are no ties: `√(R² − x²)` is never an integer plus ½, since
/// `(y + ½)² = y² + y + ¼` is never an integer. So `y` is the midpoint
/// rule's choice, `F(x, y − ½) < 0 < F(x, y + ½)` with `F = x² + y² − R²`,
/// and `2y + 1` is the first odd number above `√(4(R² − x²))`:
/// `y = (⌊√(4(R² − x²))⌋ + 1) div 2`, in exact integer arithmetic.
#[must_use]
pub fn second_octant(radius: i32) -> Vec<(i64, i64)> {
    let r = i64::from(radius);
    let mut octant = Vec::new();
    for x in 0..=r {
        let y = circle_row(r, x);
        if x > y {
            break;
        }
        octant.push((x, y));
    }
    octant
}

/// The row nearest to the circle of radius `r` in column `x` (`|x| ≤ r`):
/// `(⌊√(4(r² − x²))⌋ + 1) div 2` (see [`second_octant`]).
#[must_use]
pub fn circle_row(r: i64, x: i64) -> i64 {
    (((4 * (r * r - x * x)) as u64).isqrt() as i64 + 1) / 2
}

/// The pixels of the midpoint circle: the second octant and its seven
/// mirror images, each pixel once, sorted; nothing for a negative radius
/// or a circle beyond ±`MAX_COORD`.
#[must_use]
pub fn circle_pixels(centre: Pixel, radius: i32) -> Vec<Pixel> {
    if !within_limits(centre, radius, radius) {
        return Vec::new();
    }
    let mut set = BTreeSet::new();
    for (x, y) in second_octant(radius) {
        for (a, b) in [(x, y), (y, x)] {
            for (sa, sb) in [(1, 1), (-1, 1), (1, -1), (-1, -1)] {
                set.insert(offset(centre, sa * a, sb * b));
            }
        }
    }
    set.into_iter().collect()
}

// ---------------------------------------------------------------------------
// Triangles (topic 03).

/// Every pixel of a (small) viewport.
pub fn viewport_pixels(viewport: Viewport) -> impl Iterator<Item = Pixel> {
    (viewport.y_min..=viewport.y_max)
        .flat_map(move |y| (viewport.x_min..=viewport.x_max).map(move |x| Pixel::new(x, y)))
}

/// Fixed-point fractional bits, as the sheet prescribes for `edge_function`.
pub const SUBPIXEL_BITS: u32 = 8;

/// `round(v · 2^SUBPIXEL_BITS)`, ties away from zero; `None` for NaN,
/// infinities and `|v| > MAX_COORD`.
#[must_use]
pub fn snap(v: f32) -> Option<i64> {
    if !v.is_finite() || v.abs() > MAX_COORD as f32 {
        return None;
    }
    Some((f64::from(v) * f64::from(1_u32 << SUBPIXEL_BITS)).round() as i64)
}

/// Whether the triangle covers the centre of `p`, by a definition written
/// differently from the sheet's: the centre is moved by an infinitesimal
/// `(δ, −δ²)` (right, and a hair down), which never lies on an edge, and is
/// then inside when it lies strictly on the inner side of all three edges.
/// Moving right takes centres on left edges in and on right edges out;
/// moving down does the same for top and bottom edges: the top-left rule.
#[must_use]
pub fn triangle_covers(positions: [Vec2; 3], p: Pixel) -> bool {
    let mut q = [[0_i64; 2]; 3];
    for (k, v) in positions.iter().enumerate() {
        match (snap(v.x), snap(v.y)) {
            (Some(x), Some(y)) => q[k] = [x, y],
            _ => return false,
        }
    }
    let one = 1_i64 << SUBPIXEL_BITS;
    let c = [i64::from(p.x) * one, i64::from(p.y) * one];
    let cross = |a: [i64; 2], b: [i64; 2], d: [i64; 2]| {
        i128::from(b[0] - a[0]) * i128::from(d[1] - a[1])
            - i128::from(b[1] - a[1]) * i128::from(d[0] - a[0])
    };
    let area = cross(q[0], q[1], q[2]);
    if area == 0 {
        return false;
    }
    (0..3).all(|i| {
        let (a, b) = (q[i], q[(i + 1) % 3]);
        let (ex, ey) = (b[0] - a[0], b[1] - a[1]);
        // cross(e, c + (δ, −δ²) − a) = O + δ·(−e.y) + δ²·(−e.x)
        let side = [cross(a, b, c), i128::from(-ey), i128::from(-ex)]
            .into_iter()
            .find(|&t| t != 0)
            .unwrap_or(0);
        side.signum() == area.signum()
    })
}

/// The pixels of `viewport` a triangle covers, by [`triangle_covers`].
#[must_use]
pub fn triangle_pixels(positions: [Vec2; 3], viewport: Viewport) -> Vec<Pixel> {
    viewport_pixels(viewport)
        .filter(|&p| triangle_covers(positions, p))
        .collect()
}

// ---------------------------------------------------------------------------
// The clip volume (topic 04).

/// The six planes of the clip volume `−w ≤ x, y, z ≤ w` (OpenGL's, the
/// sheet's cube of side 2 after the divide), each as the 4-vector
/// `(n_x, n_y, n_z, −d)` of its unit outward normal and distance `d = 1`
/// (sheet §5.2, equation (3)), in the order right, left, top, bottom, far,
/// near. A clip-space point `v` is inside a plane `p` when `v · p ≤ 0`:
/// `x − w ≤ 0` is `x / w ≤ 1` for `w > 0`.
pub const CLIP_VOLUME_PLANES: [Vec4; 6] = [
    Vec4::new(1.0, 0.0, 0.0, -1.0),
    Vec4::new(-1.0, 0.0, 0.0, -1.0),
    Vec4::new(0.0, 1.0, 0.0, -1.0),
    Vec4::new(0.0, -1.0, 0.0, -1.0),
    Vec4::new(0.0, 0.0, 1.0, -1.0),
    Vec4::new(0.0, 0.0, -1.0, -1.0),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ties_are_the_columns_half_way_between_two_pixels() {
        // y = x / 2: half-way at every odd x.
        let ties = line_ties(Pixel::new(0, 0), Pixel::new(4, 2));
        assert_eq!(
            ties,
            [
                [Pixel::new(1, 0), Pixel::new(1, 1)],
                [Pixel::new(3, 1), Pixel::new(3, 2)]
            ]
        );
        // Steep, going down and left: x = 3 − (y − 3)/4 at y = 5, 9, 13.
        let ties = line_ties(Pixel::new(3, 3), Pixel::new(0, 15));
        assert_eq!(ties.len(), 3);
        assert_eq!(ties[0], [Pixel::new(2, 5), Pixel::new(3, 5)]);
        assert!(line_ties(Pixel::new(0, 0), Pixel::new(3, 1)).is_empty());
        assert!(line_ties(Pixel::new(2, 2), Pixel::new(2, 2)).is_empty());
    }
}
