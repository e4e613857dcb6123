//! Lines as bands: the pixels whose centre lies within half a pixel of
//! the segment, a one-pixel-wide rectangle around it.
//!
//! Deliberately not a line algorithm: topic 01 teaches those (the DDA,
//! the midpoint line, Wu), and the pipeline's wireframes need none. A band
//! is as thin as a line where the segment is axis-parallel or diagonal,
//! and two pixels thick in the columns where a sloped segment passes
//! between two pixel centres.
//!
//! Convention: the canvas's; the band runs from half a pixel before `a`
//! to half a pixel after `b` (square caps), so both endpoints are drawn,
//! and its border counts as inside (as the fill's edges do).

use canvas::{Canvas, Fragment, Pixel, Vertex, Viewport, round_half_away};
use glam::DVec2;

use super::{depth_test, drawable};

/// Draws the segment from `a` to `b` as a band one pixel wide, with colour
/// and depth interpolated along it (linear from `a` to `b`), depth-tested
/// (see [`band`]).
pub fn draw_line(canvas: &mut Canvas, a: Vertex, b: Vertex) {
    let viewport = canvas.viewport();
    band(a, b, viewport, |fragment| depth_test(canvas, fragment));
}

/// Emits the fragments of the band one pixel wide around the segment from
/// `a` to `b` that lie in `viewport` (inclusive bounds), row by row from
/// the bottom, with colour and depth interpolated along it (linear from
/// `a` to `b`, continued half a pixel beyond the ends).
///
/// A zero-length segment emits the one pixel at `round(a)`. Nothing is
/// emitted if an endpoint is not finite or lies beyond ±[`canvas::MAX_COORD`];
/// the work is bounded by the viewport's size, however long the segment.
pub fn band(a: Vertex, b: Vertex, viewport: Viewport, mut emit: impl FnMut(Fragment)) {
    if !drawable(&a) || !drawable(&b) || viewport.is_empty() {
        return;
    }
    let (pa, pb) = (a.position.as_dvec2(), b.position.as_dvec2());
    let length = pa.distance(pb);
    if length == 0.0 {
        let pixel = Pixel::new(round_half_away(a.position.x), round_half_away(a.position.y));
        if viewport.contains(pixel) {
            emit(Fragment {
                pixel,
                depth: a.depth,
                colour: a.colour,
            });
        }
        return;
    }
    // A centre p is in the band when, with d the unit direction,
    //   along(p)  = (p − a)·d  ∈ [−½, length + ½]   (square caps)
    //   across(p) = d × (p − a) ∈ [−½, ½]
    // Both are linear in x along a row: each row's run of pixels follows
    // from the two intervals, so the work is the band's pixels and rows.
    let d = (pb - pa) / length;
    let lo = pa.min(pb) - 1.0;
    let hi = pa.max(pb) + 1.0;
    let first_row = lo.y.ceil().max(f64::from(viewport.y_min));
    let last_row = hi.y.floor().min(f64::from(viewport.y_max));
    if first_row > last_row {
        return;
    }
    for y in first_row as i32..=last_row as i32 {
        let dy = f64::from(y) - pa.y;
        // along = d.x · x + (dy · d.y − a.x · d.x), across = −d.y · x + (d.x · dy + d.y · a.x).
        let runs = [
            (d.x, dy * d.y - pa.x * d.x, -0.5, length + 0.5),
            (-d.y, d.x * dy + d.y * pa.x, -0.5, 0.5),
        ];
        let (mut from, mut to) = (f64::from(viewport.x_min), f64::from(viewport.x_max));
        for (slope, offset, min, max) in runs {
            if slope == 0.0 {
                if !(min..=max).contains(&offset) {
                    from = f64::INFINITY;
                }
                continue;
            }
            let (x0, x1) = ((min - offset) / slope, (max - offset) / slope);
            from = from.max(x0.min(x1).ceil());
            to = to.min(x0.max(x1).floor());
        }
        if from > to {
            continue;
        }
        for x in from as i32..=to as i32 {
            let p = DVec2::new(f64::from(x), f64::from(y));
            // Linear from a to b, continued half a pixel beyond the ends.
            let t = (p - pa).dot(d) / length;
            let v = a.mix(&b, t as f32);
            emit(Fragment {
                pixel: Pixel::new(x, y),
                depth: v.depth,
                colour: v.colour,
            });
        }
    }
}
