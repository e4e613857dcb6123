//! The DDA line ("digital differential analyzer") with colour and depth
//! interpolation: sheet, sections 4.2 and 4.3.
//!
//! Convention: pixel centres at integers, rounding half away from zero;
//! both endpoints are drawn.

use canvas::{Canvas, Fragment, Pixel, Vertex, round_half_away};

use super::{depth_test, drawable};

/// Draws the line from `a` to `b` with interpolated colour and depth,
/// depth-tested.
///
/// With `n = ⌈max(|Δx|, |Δy|)⌉` steps, step `i = 0 ..= n` samples
/// `v(t) = a · (1 − t) + b · t` at `t = i / n ∈ [0, 1]` (the sheet's
/// equation (1)) and rounds its position to a pixel; so every step moves at
/// most one pixel along each axis. A zero-length line draws the one pixel
/// at `round(a)`.
///
/// Steps whose coordinate along the longer axis rounds off the canvas are
/// skipped without being computed, so a line of any length costs at most
/// the canvas's width or height in steps. Nothing is drawn if an endpoint is
/// not finite or lies beyond ±[`canvas::MAX_COORD`].
pub fn draw_line(canvas: &mut Canvas, a: Vertex, b: Vertex) {
    if !drawable(&a) || !drawable(&b) {
        return;
    }
    let delta = (b.position - a.position).as_dvec2();
    let steps = delta.x.abs().max(delta.y.abs()).ceil();
    let (start, along, size) = if delta.x.abs() >= delta.y.abs() {
        (a.position.x, delta.x, canvas.width())
    } else {
        (a.position.y, delta.y, canvas.height())
    };
    let (first, last) = if steps == 0.0 {
        (0, 0)
    } else {
        // Step i lies at start + i · per_step along the longer axis; it can
        // only hit the canvas if that is within [−½, size − ½]. One step of
        // margin on each side absorbs rounding in this estimate.
        let per_step = along / steps;
        let enter = (-0.5 - f64::from(start)) / per_step;
        let leave = (f64::from(size) - 0.5 - f64::from(start)) / per_step;
        let lo = (enter.min(leave).floor() - 1.0).clamp(0.0, steps);
        let hi = (enter.max(leave).ceil() + 1.0).clamp(0.0, steps);
        (lo as i64, hi as i64)
    };
    let origin = a.position.as_dvec2();
    for i in first..=last {
        let t = if steps == 0.0 { 0.0 } else { i as f64 / steps };
        // The position in f64: in f32, a line 10⁷ pixels long would lose
        // the fraction that decides the rounding.
        let position = origin + delta * t;
        let v = a.mix(&b, t as f32);
        let pixel = Pixel::new(
            round_half_away(position.x as f32),
            round_half_away(position.y as f32),
        );
        depth_test(
            canvas,
            Fragment {
                pixel,
                depth: v.depth,
                colour: v.colour,
            },
        );
    }
}
