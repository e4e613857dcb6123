//! What the tests compare with: circles, filled circles and ellipses by
//! their definitions, computed directly in exact integer arithmetic, not
//! by the incremental algorithms you write.
#![allow(dead_code, unused_imports)] // each test file uses a different part

use std::collections::BTreeSet;

use canvas::{Canvas, MAX_COORD, Pixel, Rgba};

/// The colour used for test drawings.
pub const INK: Rgba = Rgba::WHITE;

/// The midpoint circles of radius 0, 1, 2, 3 and 5, derived by hand from
/// the slides' pseudo-code (the traces are in `tests/midpoint_circle.rs`),
/// as grids of `2R + 1` rows, top row first, centred on the circle.
pub const HAND_CIRCLES: [(i32, &[&str]); 5] = [
    (0, &["#"]),
    (1, &[".#.", "#.#", ".#."]),
    (2, &[".###.", "#...#", "#...#", "#...#", ".###."]),
    (
        3,
        &[
            "..###..", ".#...#.", "#.....#", "#.....#", "#.....#", ".#...#.", "..###..",
        ],
    ),
    (
        5,
        &[
            "...#####...",
            "..#.....#..",
            ".#.......#.",
            "#.........#",
            "#.........#",
            "#.........#",
            "#.........#",
            "#.........#",
            ".#.......#.",
            "..#.....#..",
            "...#####...",
        ],
    ),
];

/// The pixels marked `#` in a grid whose rows are listed top row first
/// and whose middle character is `centre` (odd widths and heights).
pub fn grid_pixels(centre: Pixel, rows: &[&str]) -> Vec<Pixel> {
    testkit::pixels::grid_pixels(testkit::pixels::origin_of_centred(centre, rows), rows)
}

/// Whether the pixel at offset `(x, y)` from the centre belongs to the
/// filled circle of radius `R`: with `m = max(|x|, |y|)` and
/// `n = min(|x|, |y|)`, `(m − ½)² + n² < R²`, in integers
/// `m² − m + n² < R²`; for radius 0 only the centre.
pub fn in_disc(x: i64, y: i64, radius: i64) -> bool {
    let (m, n) = (x.abs().max(y.abs()), x.abs().min(y.abs()));
    (m == 0 && radius >= 0) || m * m - m + n * n < radius * radius
}

/// The pixels of the filled circle (see [`in_disc`]), each once, sorted;
/// nothing for a negative radius or a circle beyond ±`MAX_COORD`.
pub fn disc_pixels(centre: Pixel, radius: i32) -> Vec<Pixel> {
    if !within_limits(centre, radius, radius) {
        return Vec::new();
    }
    let r = i64::from(radius);
    let mut pixels = Vec::new();
    for y in -r..=r {
        for x in -r..=r {
            if in_disc(x, y, r) {
                pixels.push(offset(centre, x, y));
            }
        }
    }
    pixels.sort();
    pixels
}

/// The row nearest to the ellipse with semi-axes `a` (along x) and `b` in
/// column `x` (`0 ≤ x ≤ a`), a tie going to the inner (lower) row: the
/// smallest `y ≥ 0` with `y ≥ η − ½`, where `η = (b/a)·√(a² − x²)` is the
/// ideal height. In integers: `(2y + 1)·a ≥ √(4b²(a² − x²))`.
pub fn nearest_row(a: i64, b: i64, x: i64) -> i64 {
    let (a, b, x) = (i128::from(a), i128::from(b), i128::from(x));
    let n = (4 * b * b * (a * a - x * x)) as u128;
    // ⌈√n⌉, the smallest value of (2y + 1)·a allowed.
    let root = n.isqrt();
    let ceil_root = if root * root == n { root } else { root + 1 } as i128;
    // The smallest odd k with k·a ≥ ⌈√n⌉, then y = (k − 1) / 2.
    let k = (ceil_root + a - 1) / a;
    (k / 2).max(0) as i64
}

/// Whether column `x` belongs to region 1 of the ellipse with semi-axes
/// `a` (along x) and `b`: `x ≤ a` and the ellipse there runs above the
/// line `a²y = b²x` (where its slope is −1) lowered by half a pixel,
/// `2ab·√(a² − x²) > 2b²x − a²`.
pub fn in_region_one(a: i64, b: i64, x: i64) -> bool {
    let (a, b, x) = (i128::from(a), i128::from(b), i128::from(x));
    let lowered = 2 * b * b * x - a * a;
    x <= a && (lowered < 0 || lowered * lowered < 4 * a * a * b * b * (a * a - x * x))
}

/// Offsets `(x, y)` from a centre, in order along a curve.
pub type Offsets = Vec<(i64, i64)>;

/// The first-quadrant pixels of the midpoint ellipse by definition, as
/// offsets: region 1, the nearest row of each column `x = 0, 1, …` that
/// [`in_region_one`] admits, and region 2, the same with the axes
/// swapped (the nearest column of each row). Both regions, in order
/// along the ellipse: region 1 from `(0, b)`, region 2 from `(a, 0)`.
/// Semi-axes must be positive.
pub fn ellipse_regions(a: i32, b: i32) -> (Offsets, Offsets) {
    let (a, b) = (i64::from(a), i64::from(b));
    let one = (0..)
        .take_while(|&x| in_region_one(a, b, x))
        .map(|x| (x, nearest_row(a, b, x)))
        .collect();
    let two = (0..)
        .take_while(|&y| in_region_one(b, a, y))
        .map(|y| (nearest_row(b, a, y), y))
        .collect();
    (one, two)
}

/// The pixels of the midpoint ellipse: both regions and their mirror
/// images `(±x, ±y)`, each pixel once, sorted; a semi-axis 0 gives the
/// segment along the other axis; nothing for a negative semi-axis, one
/// beyond `max_semi_axis`, or an ellipse beyond ±`MAX_COORD`.
pub fn ellipse_pixels(centre: Pixel, a: i32, b: i32, max_semi_axis: i32) -> Vec<Pixel> {
    if !within_limits(centre, a, b) || a > max_semi_axis || b > max_semi_axis {
        return Vec::new();
    }
    let quadrant: Vec<(i64, i64)> = if a == 0 {
        (0..=i64::from(b)).map(|y| (0, y)).collect()
    } else if b == 0 {
        (0..=i64::from(a)).map(|x| (x, 0)).collect()
    } else {
        let (one, two) = ellipse_regions(a, b);
        one.into_iter().chain(two).collect()
    };
    let mut set = BTreeSet::new();
    for (x, y) in quadrant {
        for (sx, sy) in [(1, 1), (-1, 1), (1, -1), (-1, -1)] {
            set.insert(offset(centre, sx * x, sy * y));
        }
    }
    set.into_iter().collect()
}

pub use testkit::definitions::{circle_pixels, circle_row, offset, second_octant, within_limits};
pub use testkit::pixels::{collect, count, first_duplicate};

/// The first pixel whose mirror image about `centre` is missing: mirrored
/// at both axes, and with `diagonals` also at both diagonals.
pub fn missing_mirror_image(
    pixels: &[Pixel],
    centre: Pixel,
    diagonals: bool,
) -> Option<(Pixel, Pixel)> {
    let set: BTreeSet<Pixel> = pixels.iter().copied().collect();
    let (cx, cy) = (i64::from(centre.x), i64::from(centre.y));
    for &p in pixels {
        let (x, y) = (i64::from(p.x) - cx, i64::from(p.y) - cy);
        let mut images = vec![(-x, y), (x, -y), (-x, -y)];
        if diagonals {
            images.extend([(y, x), (-y, x), (y, -x), (-y, -x)]);
        }
        for (ix, iy) in images {
            let image = offset(centre, ix, iy);
            if !set.contains(&image) {
                return Some((p, image));
            }
        }
    }
    None
}

/// Whether the pixels, taken in order of their angle around `centre`,
/// form a closed 8-connected loop: each touches the next, the last the
/// first, and no two are equal.
pub fn closed_loop(pixels: &[Pixel], centre: Pixel) -> Result<(), String> {
    let angle = |p: &Pixel| f64::from(p.y - centre.y).atan2(f64::from(p.x - centre.x));
    let mut sorted = pixels.to_vec();
    sorted.sort_by(|p, q| angle(p).total_cmp(&angle(q)));
    for (k, &p) in sorted.iter().enumerate() {
        let q = sorted[(k + 1) % sorted.len()];
        if sorted.len() > 1 && (p == q || !p.touches(q)) {
            return Err(format!(
                "going round the centre, {p} is followed by {q}: not neighbours"
            ));
        }
    }
    Ok(())
}

/// Whether the pixels form one 8-connected piece.
pub fn connected(pixels: &[Pixel]) -> bool {
    let set: BTreeSet<Pixel> = pixels.iter().copied().collect();
    let Some(&start) = set.first() else {
        return true;
    };
    let mut seen = BTreeSet::from([start]);
    let mut stack = vec![start];
    while let Some(p) = stack.pop() {
        for dx in -1..=1 {
            for dy in -1..=1 {
                let q = Pixel::new(p.x + dx, p.y + dy);
                if set.contains(&q) && seen.insert(q) {
                    stack.push(q);
                }
            }
        }
    }
    seen.len() == set.len()
}

/// One ASCII picture per radius, the circle centred on a canvas of
/// `2R + 3` pixels square, as a single snapshot text.
pub fn radius_sheet(radii: &[i32], draw: impl Fn(Pixel, i32, &mut Canvas)) -> String {
    let mut sheet = String::new();
    for &r in radii {
        let side = 2 * r as u32 + 3;
        let centre = Pixel::new(r + 1, r + 1);
        let mut canvas = Canvas::new(side, side);
        draw(centre, r, &mut canvas);
        sheet += &format!("radius {r} around {centre}\n{}\n", canvas.to_ascii());
    }
    sheet
}

/// One ASCII picture per pair of semi-axes, the ellipse centred on a
/// canvas of `(2a + 3) × (2b + 3)` pixels, as a single snapshot text.
pub fn ellipse_sheet(axes: &[(i32, i32)], draw: impl Fn(Pixel, i32, i32, &mut Canvas)) -> String {
    let mut sheet = String::new();
    for &(a, b) in axes {
        let centre = Pixel::new(a + 1, b + 1);
        let mut canvas = Canvas::new(2 * a as u32 + 3, 2 * b as u32 + 3);
        draw(centre, a, b, &mut canvas);
        sheet += &format!(
            "semi-axes a = {a}, b = {b} around {centre}\n{}\n",
            canvas.to_ascii()
        );
    }
    sheet
}
