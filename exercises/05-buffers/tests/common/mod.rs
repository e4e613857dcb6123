//! What the tests compare with: answers from the definitions, brute force
//! over the given rasterizer, never the algorithms you write.
#![allow(dead_code)] // each test file uses a different part

use buffers::raster::fill_triangle;
use canvas::{Canvas, Fragment, Pixel, Rgba, Vec2, Vertex};

/// A vertex at `(x, y)` with the given depth and colour.
pub fn vertex(x: f32, y: f32, depth: f32, colour: Rgba) -> Vertex {
    Vertex::new(Vec2::new(x, y), depth, colour)
}

/// A fragment at `(x, y)`.
pub fn fragment(x: i32, y: i32, depth: f32, colour: Rgba) -> Fragment {
    Fragment {
        pixel: Pixel::new(x, y),
        depth,
        colour,
    }
}

/// The fragments the given rasterizer emits for a triangle on `canvas`.
pub fn fragments_of(canvas: &Canvas, triangle: [Vertex; 3]) -> Vec<Fragment> {
    let mut out = Vec::new();
    fill_triangle(triangle, canvas.viewport(), |f| out.push(f));
    out
}

/// The correct picture of opaque triangles: for every pixel, the colour of
/// the nearest fragment of all triangles (the first one drawn on a tie),
/// found by brute force over all fragments — no buffer, no order.
pub fn nearest_fragment_picture(width: u32, height: u32, triangles: &[[Vertex; 3]]) -> Canvas {
    let mut best: Vec<Option<Fragment>> = vec![None; (width * height) as usize];
    let canvas = Canvas::new(width, height);
    for &t in triangles {
        for f in fragments_of(&canvas, t) {
            let slot = &mut best[(f.pixel.y as u32 * width + f.pixel.x as u32) as usize];
            if slot.is_none_or(|b| f.depth < b.depth) {
                *slot = Some(f);
            }
        }
    }
    let mut picture = Canvas::new(width, height);
    for (i, f) in best.into_iter().enumerate() {
        if let Some(f) = f {
            picture.set(
                Pixel::new((i as u32 % width) as i32, (i as u32 / width) as i32),
                f.colour,
            );
        }
    }
    picture
}

/// The pixels whose colour differs between two canvases of equal size.
pub fn differing_pixels(a: &Canvas, b: &Canvas) -> Vec<Pixel> {
    a.enumerate()
        .filter(|&(p, c)| b.get(p) != Some(c))
        .map(|(p, _)| p)
        .collect()
}

/// Two triangles that pass through each other: red is nearer on the left,
/// blue on the right; their depths are equal on the line `x = 32`.
///
/// ```text
///   depth ↑  red  ──────╲  ╱────  blue is behind on the left,
///            blue ──────╱  ╲────  in front on the right
///                  x = 32
/// ```
pub fn interpenetrating_triangles() -> [[Vertex; 3]; 2] {
    // Red: depth 0.2 at x = 4 rising to 0.8 at x = 60 (z = 0.2 + 0.6·(x − 4)/56).
    // Blue: depth 0.8 at x = 4 falling to 0.2 at x = 60. Equal at x = 32.
    let red = Rgba::rgb(0.8, 0.2, 0.2);
    let blue = Rgba::rgb(0.2, 0.4, 0.8);
    [
        [
            vertex(4.0, 10.0, 0.2, red),
            vertex(60.0, 4.0, 0.8, red),
            vertex(60.0, 40.0, 0.8, red),
        ],
        [
            vertex(4.0, 20.0, 0.8, blue),
            vertex(60.0, 14.0, 0.2, blue),
            vertex(4.0, 58.0, 0.8, blue),
        ],
    ]
}

/// Asserts that two canvases of equal size hold the same colour (8-bit),
/// depth and stencil value at every pixel. On failure it names `what`,
/// counts the pixels that differ and shows the first three with both
/// values, rather than dumping two canvases.
#[track_caller]
pub fn assert_same_canvas(expected: &Canvas, yours: &Canvas, what: &str) {
    let (size, your_size) = (
        (expected.width(), expected.height()),
        (yours.width(), yours.height()),
    );
    assert_eq!(size, your_size, "{what}: the canvas size");
    let held = |c: &Canvas, p: Pixel| (c.get(p).map(Rgba::to_rgba8), c.depth(p), c.stencil(p));
    let differing: Vec<String> = expected
        .enumerate()
        .map(|(p, _)| (p, held(expected, p), held(yours, p)))
        .filter(|(_, e, y)| e != y)
        .map(|(p, e, y)| {
            let show = |(c, d, s): (Option<[u8; 4]>, Option<f32>, Option<u8>)| {
                format!(
                    "colour {:?}, depth {}, stencil {}",
                    c.unwrap_or_default(),
                    d.unwrap_or(f32::NAN),
                    s.unwrap_or_default()
                )
            };
            format!("{p}: expected {}; yours {}", show(e), show(y))
        })
        .collect();
    assert!(
        differing.is_empty(),
        "{what}: {} of {} pixels differ, first:\n  {}",
        differing.len(),
        size.0 * size.1,
        differing[..differing.len().min(3)].join("\n  ")
    );
}
