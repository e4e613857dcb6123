//! What the tests compare with: lines by their definition, computed
//! directly and exactly, not by the incremental algorithms you write.
#![allow(dead_code, unused_imports)] // each test file uses a different part

use canvas::{Canvas, Pixel, Rgba};

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

pub use testkit::definitions::line_pixels as nearest_pixels;
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

/// Side of the fan pictures.
pub const FAN_SIDE: u32 = 64;

/// The seed's comparison of antialiasing (slides 002, "Antialiasing"): 24
/// spokes around the centre of a 64 × 64 canvas, from radius 5 to 29,
/// their ends rounded to pixel centres.
pub fn fan() -> Vec<(Pixel, Pixel)> {
    (0..24)
        .map(|k| {
            let angle = f64::from(k) * std::f64::consts::TAU / 24.0;
            let at = |r: f64| {
                Pixel::new(
                    (31.5 + r * angle.cos()).round() as i32,
                    (31.5 + r * angle.sin()).round() as i32,
                )
            };
            (at(5.0), at(29.0))
        })
        .collect()
}

/// The fan drawn with an antialiasing line, white over black: each
/// `plot(pixel, intensity)` blends white with that coverage.
pub fn fan_picture(draw: impl Fn(Pixel, Pixel, &mut dyn FnMut(Pixel, f32))) -> Canvas {
    let mut canvas = Canvas::new(FAN_SIDE, FAN_SIDE);
    for (from, to) in fan() {
        draw(from, to, &mut |p, coverage| {
            canvas.blend(p, Rgba::WHITE, coverage)
        });
    }
    canvas
}

/// Pictures of lines may differ in a few pixels where an intensity rounds
/// the other way (f32 against f64), never in the lines' shape.
pub const FAN_TOLERANCE: testkit::image::Tolerance = testkit::image::Tolerance {
    channel: 3.0 / 255.0,
    mismatched_fraction: 0.01,
};

/// Compares a fan picture with `tests/images/<name>.png`.
#[track_caller]
pub fn assert_fan(name: &str, canvas: &Canvas) {
    testkit::image::assert_image_matches(
        name,
        canvas,
        format!("{}/tests/images/{name}.png", env!("CARGO_MANIFEST_DIR")),
        FAN_TOLERANCE,
    );
}
