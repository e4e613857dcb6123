//! Given code, not an exercise: triangles and lines turned into fragments
//! with depth, so that the buffer tasks have something to test and write.
//! The pixels are those of the course's given rasterizer (`scene::raster`);
//! this module adds the top-left rule for triangles. (Topic 03 teaches how
//! to write one; nothing here needs its solution.)
//!
//! Convention (see `canvas`): pixel centres at integers, y up. Triangles
//! cover the pixels whose centre lies inside, with the top-left rule on
//! edges; lines are one-pixel bands that include both endpoints.

use canvas::{Fragment, Vertex, Viewport};

/// Emits one fragment per pixel whose centre lies inside the triangle,
/// with depth and colour interpolated by barycentric weights (the plane
/// through the three vertices, evaluated at the pixel centre).
///
/// - **Pixels:** those of the course's given rasterizer,
///   `scene::raster::cover` (the centres inside or on an edge, each with
///   its barycentric weights), less the centres on an edge that is
///   neither a left nor a top edge (the top-left rule), so triangles
///   sharing an edge never both emit a pixel.
/// - **Skipped:** zero-area triangles and vertices with a NaN, infinite or
///   out-of-range (beyond ±[`MAX_COORD`](canvas::MAX_COORD)) position emit
///   nothing.
/// - Only pixels inside `viewport` (inclusive bounds) are emitted, row by
///   row from the bottom, left to right.
///
/// Evaluated in `f64`; exact for vertices on a grid of 1/256 pixel and
/// coordinates below 2¹⁶.
pub fn fill_triangle(vertices: [Vertex; 3], viewport: Viewport, mut emit: impl FnMut(Fragment)) {
    let p = vertices.map(|v| v.position.as_dvec2());
    // Twice the signed area: its sign is the winding (positive when
    // counter-clockwise, y up).
    let sign = (p[1] - p[0]).perp_dot(p[2] - p[0]).signum();
    // Weight k belongs to vertex k; it is zero on the edge opposite it,
    // which runs from vertex k+1 to vertex k+2. Oriented counter-clockwise
    // (y up), a left edge runs downwards and a top edge runs to the left.
    let top_left = [(1, 2), (2, 0), (0, 1)].map(|(i, j)| {
        let e = (p[j] - p[i]) * sign;
        e.y < 0.0 || (e.y == 0.0 && e.x < 0.0)
    });
    scene::raster::cover(p, viewport, |pixel, l| {
        if (0..3).any(|k| l[k] == 0.0 && !top_left[k]) {
            return;
        }
        let depth = l[0] * f64::from(vertices[0].depth)
            + l[1] * f64::from(vertices[1].depth)
            + l[2] * f64::from(vertices[2].depth);
        let colour = vertices[0].colour * l[0] as f32
            + vertices[1].colour * l[1] as f32
            + vertices[2].colour * l[2] as f32;
        emit(Fragment {
            pixel,
            depth: depth as f32,
            colour,
        });
    });
}

/// Emits the fragments of the line from `a` to `b`: the course's
/// one-pixel band around the segment (`scene::raster::band`: the centres
/// within half a pixel of it, both ends included, depth and colour
/// interpolated along it), those inside `viewport`. Not a line algorithm
/// of topic 01: the outlines need one pixel of width, not a DDA.
/// Non-finite or out-of-range endpoints emit nothing.
pub fn draw_line(a: Vertex, b: Vertex, viewport: Viewport, emit: impl FnMut(Fragment)) {
    scene::raster::band(a, b, viewport, emit);
}

#[cfg(test)]
mod tests {
    use super::*;
    use canvas::{Pixel, Rgba, Vec2};

    fn at(x: f32, y: f32, depth: f32) -> Vertex {
        Vertex::new(Vec2::new(x, y), depth, Rgba::WHITE)
    }

    #[test]
    fn right_triangle_keeps_left_and_bottom_edge_pixels_by_the_top_left_rule() {
        // (0,0)-(4,0)-(0,4): centres on the left edge x = 0 are in, on the
        // bottom edge y = 0 out (a bottom edge), on the hypotenuse out.
        let mut pixels = Vec::new();
        let vp = Viewport::new(-5, -5, 5, 5);
        fill_triangle(
            [at(0.0, 0.0, 0.0), at(4.0, 0.0, 0.0), at(0.0, 4.0, 0.0)],
            vp,
            |f| {
                pixels.push(f.pixel);
            },
        );
        let expected: Vec<Pixel> = [(0, 1), (1, 1), (2, 1), (0, 2), (1, 2), (0, 3)]
            .map(|(x, y)| Pixel::new(x, y))
            .to_vec();
        assert_eq!(pixels, expected);
    }

    #[test]
    fn depth_is_the_plane_through_the_vertices() {
        // z = 0.01·x + 0.02·y + 0.1
        let z = |x: f32, y: f32| 0.01 * x + 0.02 * y + 0.1;
        let tri = [
            at(0.0, 0.0, z(0.0, 0.0)),
            at(8.0, 1.0, z(8.0, 1.0)),
            at(2.0, 7.0, z(2.0, 7.0)),
        ];
        fill_triangle(tri, Viewport::new(0, 0, 9, 9), |f| {
            let expect = z(f.pixel.x as f32, f.pixel.y as f32);
            assert!((f.depth - expect).abs() < 1e-6, "{f:?}");
        });
    }

    #[test]
    fn a_line_includes_both_endpoints_and_interpolates_depth() {
        let mut frags = Vec::new();
        draw_line(
            at(0.0, 0.0, 0.0),
            at(4.0, 0.0, 1.0),
            Viewport::new(0, 0, 9, 9),
            |f| {
                frags.push(f);
            },
        );
        let pixels: Vec<Pixel> = frags.iter().map(|f| f.pixel).collect();
        let expected = [(0, 0), (1, 0), (2, 0), (3, 0), (4, 0)].map(|(x, y)| Pixel::new(x, y));
        assert_eq!(pixels, expected);
        assert!((frags[2].depth - 0.5).abs() < 1e-6, "{:?}", frags[2]);
    }

    #[test]
    fn hostile_input_emits_nothing() {
        let vp = Viewport::new(0, 0, 9, 9);
        let mut count = 0;
        fill_triangle(
            [at(f32::NAN, 0.0, 0.0), at(4.0, 0.0, 0.0), at(0.0, 4.0, 0.0)],
            vp,
            |_| {
                count += 1;
            },
        );
        fill_triangle(
            [at(1.0, 1.0, 0.0), at(2.0, 2.0, 0.0), at(3.0, 3.0, 0.0)],
            vp,
            |_| count += 1,
        );
        draw_line(at(0.0, 0.0, 0.0), at(f32::INFINITY, 0.0, 0.0), vp, |_| {
            count += 1
        });
        assert_eq!(count, 0);
    }
}
