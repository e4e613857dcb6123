//! Antialiasing by unweighted area sampling: lecture slides
//! "Anti-Aliasing: ungewichtete Abtastung" (seed 002).
//!
//! Convention (see `canvas`): pixel `(x, y)` is the unit square around its
//! centre `(x, y)`, y up; the line is a rectangle one pixel wide whose
//! middle line runs from `from` to `to` (no caps beyond the endpoints).

use canvas::{Pixel, Vec2, within_limits};
use glam::DVec2;

/// Draws the line from `from` to `to` as a rectangle one pixel wide and
/// calls `plot(pixel, intensity)` for every pixel it overlaps, with the
/// intensity equal to the overlapped area of the pixel's square (in
/// `(0, 1]`).
///
/// ```text
///   ┌───┬───┬───┐      the pixel's intensity is the area of its
///   │  ╱│▒▒▒│▒▒▒│      square inside the 1-wide rectangle; where in
///   │╱▒▒│▒▒▒│▒▒╱│      the square that area lies does not matter
///   │▒▒▒│▒▒▒│╱  │      ("ungewichtet": unweighted)
///   └───┴───┴───┘
/// ```
///
/// The intensities add up to the rectangle's area, the line's length.
/// A zero-length line covers no area and draws nothing; endpoints that are
/// not finite or lie beyond ±`MAX_COORD` draw nothing.
#[transcript::task]
pub fn area_sampling_line(from: Vec2, to: Vec2, mut plot: impl FnMut(Pixel, f32)) {
    // BEGIN SOLUTION area_sampling: intersect each nearby pixel square with the 1-pixel-wide rectangle around the line and plot the overlapped area
    if ![from.x, from.y, to.x, to.y].into_iter().all(within_limits) {
        return;
    }
    let (a, b) = (from.as_dvec2(), to.as_dvec2());
    let length = (b - a).length();
    if length == 0.0 {
        return;
    }
    // Work with x as the major axis; areas do not change when x and y swap.
    let x_major = (b.x - a.x).abs() >= (b.y - a.y).abs();
    let swap = |p: DVec2| if x_major { p } else { DVec2::new(p.y, p.x) };
    let (a, b) = (swap(a), swap(b));
    let dir = (b - a) / length;
    let normal = dir.perp();
    // The rectangle as four half-planes n·p ≤ c.
    let rectangle = [
        (normal, normal.dot(a) + 0.5),
        (-normal, -normal.dot(a) + 0.5),
        (dir, dir.dot(b)),
        (-dir, -dir.dot(a)),
    ];
    let half_width = 0.5 * normal.abs();
    let (x_first, x_last) = (
        (a.x.min(b.x) - half_width.x).floor() as i32,
        (a.x.max(b.x) + half_width.x).ceil() as i32,
    );
    let slope = (b.y - a.y) / (b.x - a.x);
    for x in x_first..=x_last {
        // Near the middle line the rectangle is less than 1.5 pixels thick
        // within one column, so two rows either side are enough.
        let cx = f64::from(x).clamp(a.x.min(b.x), a.x.max(b.x));
        let centre = (a.y + slope * (cx - a.x)).round() as i32;
        for y in centre - 2..=centre + 2 {
            let area = square_area_inside(f64::from(x), f64::from(y), &rectangle);
            if area > 0.0 {
                let p = if x_major {
                    Pixel::new(x, y)
                } else {
                    Pixel::new(y, x)
                };
                plot(p, area.min(1.0) as f32);
            }
        }
    }
    // END SOLUTION
}

// BEGIN SOLUTION
/// The area of the unit square centred at `(x, y)` inside all the
/// half-planes `n·p ≤ c`: the square clipped by each in turn
/// (Sutherland-Hodgman), then measured with the shoelace formula.
fn square_area_inside(x: f64, y: f64, half_planes: &[(DVec2, f64)]) -> f64 {
    let mut polygon = vec![
        DVec2::new(x - 0.5, y - 0.5),
        DVec2::new(x + 0.5, y - 0.5),
        DVec2::new(x + 0.5, y + 0.5),
        DVec2::new(x - 0.5, y + 0.5),
    ];
    for &(n, c) in half_planes {
        let mut clipped = Vec::with_capacity(polygon.len() + 1);
        for (k, &p) in polygon.iter().enumerate() {
            let q = polygon[(k + 1) % polygon.len()];
            let (fp, fq) = (n.dot(p) - c, n.dot(q) - c);
            if fp <= 0.0 {
                clipped.push(p);
            }
            if (fp < 0.0 && fq > 0.0) || (fp > 0.0 && fq < 0.0) {
                clipped.push(p + (q - p) * (fp / (fp - fq)));
            }
        }
        polygon = clipped;
        if polygon.len() < 3 {
            return 0.0;
        }
    }
    let twice_area: f64 = (0..polygon.len())
        .map(|k| polygon[k].perp_dot(polygon[(k + 1) % polygon.len()]))
        .sum();
    twice_area.abs() / 2.0
}
// END SOLUTION
