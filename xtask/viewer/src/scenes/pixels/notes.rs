//! What decided each pixel you plotted, in one line: where the ideal
//! primitive lies from it, or what your own numbers there were.

use canvas::Pixel;

/// What decides a pixel of Wu's line: the intensity you gave it, and the
/// definition's.
pub(super) fn wu_note(
    from: Pixel,
    to: Pixel,
    p: Pixel,
    yours: f32,
    expected: Option<&f32>,
) -> String {
    let definition = expected.map_or_else(
        || "not a pixel of the definition".to_owned(),
        |e| format!("the definition's {e:.3}"),
    );
    format!(
        "intensity {yours:.3}, {definition}; {}",
        line_note(from, to, p)
    )
}

/// What decides a line's pixel: where the ideal line crosses its column
/// (or row, for a steep line), and how far from the pixel's centre.
pub(super) fn line_note(from: Pixel, to: Pixel, p: Pixel) -> String {
    let (dx, dy) = (f64::from(to.x - from.x), f64::from(to.y - from.y));
    if dx == 0.0 && dy == 0.0 {
        return format!("({}, {}): a line of one pixel", p.x, p.y);
    }
    if dx.abs() >= dy.abs() {
        let ideal = f64::from(from.y) + (f64::from(p.x - from.x)) * dy / dx;
        format!(
            "({}, {}): the ideal line crosses column x = {} at y = {ideal:.3}, {:.3} from this centre",
            p.x,
            p.y,
            p.x,
            (f64::from(p.y) - ideal).abs()
        )
    } else {
        let ideal = f64::from(from.x) + (f64::from(p.y - from.y)) * dx / dy;
        format!(
            "({}, {}): the ideal line crosses row y = {} at x = {ideal:.3}, {:.3} from this centre",
            p.x,
            p.y,
            p.y,
            (f64::from(p.x) - ideal).abs()
        )
    }
}

/// What decides a circle's pixel: the implicit function at its centre.
pub(super) fn circle_note(centre: Pixel, radius: i32, p: Pixel) -> String {
    let (x, y) = (i64::from(p.x - centre.x), i64::from(p.y - centre.y));
    let f = x * x + y * y - i64::from(radius) * i64::from(radius);
    #[allow(clippy::cast_precision_loss)] // small offsets
    let off = ((x * x + y * y) as f64).sqrt() - f64::from(radius);
    format!(
        "({}, {}): offset ({x}, {y}) from the centre, x² + y² − R² = {f}, {off:+.3} pixels from the circle",
        p.x, p.y
    )
}

/// What decides a triangle's pixel: your exact edge functions there, and
/// the barycentric weights they give.
pub(super) fn triangle_note(p: Pixel, w: [i128; 3]) -> String {
    let sum: i128 = w.iter().sum();
    #[allow(clippy::cast_precision_loss)] // shown to three decimals
    let weights = if sum == 0 {
        "no area".to_owned()
    } else {
        let l = w.map(|wi| wi as f64 / sum as f64);
        format!("barycentric ({:.3}, {:.3}, {:.3})", l[0], l[1], l[2])
    };
    format!(
        "({}, {}): your edge functions ({}, {}, {}) in 1/65536 px², {weights}",
        p.x, p.y, w[0], w[1], w[2]
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn notes_say_where_the_ideal_primitive_is() {
        let note = line_note(Pixel::new(0, 0), Pixel::new(3, 1), Pixel::new(1, 0));
        assert!(note.contains("y = 0.333, 0.333 from this centre"), "{note}");
        let note = circle_note(Pixel::new(5, 5), 3, Pixel::new(7, 7));
        assert!(note.contains("x² + y² − R² = -1"), "{note}");
        let note = triangle_note(Pixel::new(1, 1), [1, 1, 2]);
        assert!(note.contains("(0.250, 0.250, 0.500)"), "{note}");
    }
}
