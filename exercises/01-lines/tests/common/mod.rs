//! What the tests compare with: lines by their definition, computed
//! directly and exactly, not by the incremental algorithms you write.
#![allow(dead_code, unused_imports)] // each test file uses a different part

use canvas::{Canvas, Pixel, Rgba, Viewport};

/// The pixels of the line from `from` to `to` by definition: in each column
/// of the major axis (x when `|Δx| ≥ |Δy|`), the pixel nearest to the ideal
/// line, a tie going to the smaller minor coordinate. Computed column by
/// column in exact integer arithmetic, in order from `from` to `to`, and
/// only for the columns inside `window` when one is given.
pub fn nearest_pixels(from: Pixel, to: Pixel, window: Option<Viewport>) -> Vec<Pixel> {
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

/// Whether the ideal line passes exactly half-way between two pixels in
/// some column (where rounding rules differ).
pub fn has_tie(from: Pixel, to: Pixel) -> bool {
    let (dx, dy) = (i64::from(to.x - from.x), i64::from(to.y - from.y));
    let (dm, dn) = if dx.abs() >= dy.abs() {
        (dx, dy)
    } else {
        (dy, dx)
    };
    dm != 0 && (0..=dm.abs()).any(|k| (2 * dn * k).rem_euclid(2 * dm.abs()) == dm.abs())
}

pub use testkit::pixels::{collect, collect_weighted};

/// The eight octants' characteristic lines from the origin of a 17 × 17
/// canvas centred on `(8, 8)`, plus the axis directions, as
/// `(name, from, to)`.
pub fn octant_lines() -> Vec<(&'static str, Pixel, Pixel)> {
    let c = Pixel::new(8, 8);
    let at = |dx: i32, dy: i32| Pixel::new(8 + dx, 8 + dy);
    vec![
        ("octant 1 (ENE)", c, at(7, 3)),
        ("octant 2 (NNE)", c, at(3, 7)),
        ("octant 3 (NNW)", c, at(-3, 7)),
        ("octant 4 (WNW)", c, at(-7, 3)),
        ("octant 5 (WSW)", c, at(-7, -3)),
        ("octant 6 (SSW)", c, at(-3, -7)),
        ("octant 7 (SSE)", c, at(3, -7)),
        ("octant 8 (ESE)", c, at(7, -3)),
        ("ties: slope 1/2 east", c, at(8, 4)),
        ("ties: slope 1/2 west", c, at(-8, -4)),
        ("horizontal", c, at(-8, 0)),
        ("vertical", c, at(0, 8)),
        ("diagonal", c, at(-8, 8)),
        ("zero length", c, c),
    ]
}

/// One ASCII picture per characteristic line, as a single snapshot text.
pub fn octant_sheet(draw: impl Fn(Pixel, Pixel, &mut Canvas)) -> String {
    let mut sheet = String::new();
    for (name, from, to) in octant_lines() {
        let mut canvas = Canvas::new(17, 17);
        draw(from, to, &mut canvas);
        sheet += &format!("{name}: {from} -> {to}\n{}\n", canvas.to_ascii());
    }
    sheet
}

/// Whether consecutive pixels touch (8-connectivity) and each step moves
/// exactly one pixel along the major axis.
pub fn one_step_per_column(pixels: &[Pixel], x_major: bool) -> Result<(), String> {
    for w in pixels.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (dmaj, dmin) = if x_major {
            ((b.x - a.x).abs(), (b.y - a.y).abs())
        } else {
            ((b.y - a.y).abs(), (b.x - a.x).abs())
        };
        if dmaj != 1 || dmin > 1 {
            return Err(format!(
                "step {a} -> {b} is not one column and at most one row"
            ));
        }
    }
    Ok(())
}

/// The colour used for aliased test lines.
pub const INK: Rgba = Rgba::WHITE;
