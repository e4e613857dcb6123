//! Writes the course's test meshes to `crates/scene/data/`, the roles of the
//! sheet's data folder (section 3.3): a plane, a star, extruded text, a
//! torus, and `clipped_` variants that reach outside the view volume of
//! `Pipeline::for_mesh` (through the near plane, behind the eye and past the
//! sides).
//!
//! ```text
//! cargo run -p scene --example make_meshes
//! ```
//!
//! Faces are convex polygons: quads for the plane, the torus and the text,
//! a pentagon with five triangles for the star.

use std::f32::consts::TAU;

use canvas::Rgba;
use glam::{Mat4, Vec3};
use scene::Mesh;
use scene::ply::{self, Format};

/// Stars: radius of the tips and of the inner corners.
const STAR_OUTER: f32 = 1.2;
const STAR_INNER: f32 = 0.5;
/// Torus: segments around the ring and around the tube.
const TORUS_RING: usize = 24;
const TORUS_TUBE: usize = 12;
/// Text: the size of one cell of the letter grid and the extrusion depth.
const TEXT_CELL: f32 = 0.28;
const TEXT_DEPTH: f32 = 0.3;

fn main() -> std::io::Result<()> {
    let degrees = f32::to_radians;
    let meshes = [
        (
            "plane.ply",
            transformed(plane(), Mat4::from_rotation_x(degrees(-55.0))),
            Format::Ascii,
        ),
        ("star.ply", star(), Format::BinaryLittleEndian),
        (
            "text.ply",
            transformed(
                text(),
                Mat4::from_rotation_x(degrees(15.0)) * Mat4::from_rotation_y(degrees(-25.0)),
            ),
            Format::Ascii,
        ),
        (
            "torus.ply",
            transformed(
                torus(0.8, 0.3),
                Mat4::from_rotation_y(degrees(20.0)) * Mat4::from_rotation_x(degrees(-60.0)),
            ),
            Format::BinaryLittleEndian,
        ),
        // Scaled ×3 and tipped towards the eye: the upper tip crosses the
        // near plane (world z = 3), the side tips leave the view sideways.
        (
            "clipped_star.ply",
            transformed(
                star(),
                Mat4::from_rotation_x(degrees(70.0)) * Mat4::from_scale(Vec3::splat(3.0)),
            ),
            Format::Ascii,
        ),
        // A ring around the eye's position: its near side passes behind the
        // eye (world z > 4, so w < 0), its far side is visible, its sides
        // leave the view.
        (
            "clipped_torus.ply",
            transformed(torus(3.8, 0.6), Mat4::from_rotation_x(degrees(75.0))),
            Format::BinaryLittleEndian,
        ),
    ];
    for (name, mesh, format) in meshes {
        let path = scene::data::path(name);
        ply::save(&mesh, &path, format)?;
        println!(
            "{}: {} vertices, {} faces",
            path.display(),
            mesh.positions.len(),
            mesh.faces.len()
        );
    }
    Ok(())
}

/// Adds a vertex and returns its index.
fn vertex(mesh: &mut Mesh, position: Vec3, colour: Rgba) -> u32 {
    mesh.positions.push(position);
    mesh.colours.push(colour);
    (mesh.positions.len() - 1) as u32
}

fn transformed(mut mesh: Mesh, m: Mat4) -> Mesh {
    for p in &mut mesh.positions {
        *p = m.transform_point3(*p);
    }
    mesh
}

/// The square `[−1, 1]²` at z = 0 as a grid of 4 × 4 quads, coloured by
/// position (red to the right, green upwards, blue at the lower left).
fn plane() -> Mesh {
    const N: usize = 4;
    let mut mesh = Mesh::default();
    for j in 0..=N {
        for i in 0..=N {
            let (u, v) = (i as f32 / N as f32, j as f32 / N as f32);
            let colour = Rgba::rgb(u, v, 1.0 - 0.5 * (u + v));
            vertex(
                &mut mesh,
                Vec3::new(2.0 * u - 1.0, 2.0 * v - 1.0, 0.0),
                colour,
            );
        }
    }
    let at = |i: usize, j: usize| (j * (N + 1) + i) as u32;
    for j in 0..N {
        for i in 0..N {
            mesh.faces
                .push(vec![at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    mesh
}

/// A five-pointed star at z = 0: a pentagon of the inner corners (white)
/// and five tip triangles with coloured tips, the top tip pointing up (+y).
fn star() -> Mesh {
    const TIPS: [Rgba; 5] = [
        Rgba::rgb(1.0, 0.2, 0.2),
        Rgba::rgb(1.0, 0.9, 0.1),
        Rgba::rgb(0.2, 0.9, 0.2),
        Rgba::rgb(0.2, 0.5, 1.0),
        Rgba::rgb(0.9, 0.3, 1.0),
    ];
    let mut mesh = Mesh::default();
    let around = |k: f32, r: f32| {
        let a = TAU / 4.0 + k * TAU / 5.0;
        Vec3::new(r * a.cos(), r * a.sin(), 0.0)
    };
    // Inner corner k lies between tip k and tip k + 1.
    let inner: Vec<u32> = (0..5)
        .map(|k| vertex(&mut mesh, around(k as f32 + 0.5, STAR_INNER), Rgba::WHITE))
        .collect();
    mesh.faces.push(inner.clone());
    for (k, colour) in TIPS.into_iter().enumerate() {
        let tip = vertex(&mut mesh, around(k as f32, STAR_OUTER), colour);
        mesh.faces.push(vec![inner[(k + 4) % 5], tip, inner[k]]);
    }
    mesh
}

/// A torus around the z axis (ring radius `ring`, tube radius `tube`) as
/// quads, hue changing around the ring and brightness around the tube.
fn torus(ring: f32, tube: f32) -> Mesh {
    let mut mesh = Mesh::default();
    for i in 0..TORUS_RING {
        let u = i as f32 / TORUS_RING as f32;
        for j in 0..TORUS_TUBE {
            let v = j as f32 / TORUS_TUBE as f32;
            let (a, b) = (u * TAU, v * TAU);
            let r = ring + tube * b.cos();
            let p = Vec3::new(r * a.cos(), r * a.sin(), tube * b.sin());
            let shade = 0.6 + 0.4 * b.cos();
            vertex(
                &mut mesh,
                p,
                Rgba {
                    a: 1.0,
                    ..hue(u) * shade
                },
            );
        }
    }
    let at = |i: usize, j: usize| ((i % TORUS_RING) * TORUS_TUBE + j % TORUS_TUBE) as u32;
    for i in 0..TORUS_RING {
        for j in 0..TORUS_TUBE {
            mesh.faces
                .push(vec![at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    mesh
}

/// The fully saturated colour of hue `h ∈ [0, 1]` (red at 0, green at ⅓,
/// blue at ⅔), as in the HSV model with `S = V = 1`.
fn hue(h: f32) -> Rgba {
    let x = h * 6.0;
    Rgba::rgb(
        ((x - 3.0).abs() - 1.0).clamp(0.0, 1.0),
        (2.0 - (x - 2.0).abs()).clamp(0.0, 1.0),
        (2.0 - (x - 4.0).abs()).clamp(0.0, 1.0),
    )
}

/// The letters "CG", extruded along z: each stroke is a box of six quads.
/// Front corners carry the letter's colour, back corners a darker one.
fn text() -> Mesh {
    // Strokes as rectangles [x0, y0, x1, y1] on a grid of cells; each
    // letter is 3 cells wide and 5 high.
    const C: &[[f32; 4]] = &[
        [0.0, 0.0, 1.0, 5.0],
        [1.0, 4.0, 3.0, 5.0],
        [1.0, 0.0, 3.0, 1.0],
    ];
    const G: &[[f32; 4]] = &[
        [0.0, 0.0, 1.0, 5.0],
        [1.0, 4.0, 3.0, 5.0],
        [1.0, 0.0, 3.0, 1.0],
        [2.0, 1.0, 3.0, 2.5],
        [1.5, 2.0, 2.0, 2.5],
    ];
    let letters = [
        (C, 0.0, Rgba::rgb(1.0, 0.6, 0.1), Rgba::rgb(1.0, 1.0, 0.3)),
        (G, 4.0, Rgba::rgb(0.1, 0.6, 1.0), Rgba::rgb(0.3, 1.0, 0.9)),
    ];
    // The text is 7 × 5 cells; centre it on the origin.
    let centre = Vec3::new(3.5, 2.5, 0.0);
    let mut mesh = Mesh::default();
    for (strokes, x_offset, bottom, top) in letters {
        for &[x0, y0, x1, y1] in strokes {
            let mut corner = |x: f32, y: f32, front: bool| {
                let z = if front { 0.5 } else { -0.5 };
                let p = (Vec3::new(x + x_offset, y, 0.0) - centre) * TEXT_CELL
                    + Vec3::new(0.0, 0.0, z * TEXT_DEPTH);
                let colour = bottom.lerp(top, y / 5.0);
                let colour = if front { colour } else { colour * 0.4 };
                vertex(&mut mesh, p, Rgba { a: 1.0, ..colour })
            };
            // f: front, b: back; corners counter-clockwise from the lower left.
            let f = [
                corner(x0, y0, true),
                corner(x1, y0, true),
                corner(x1, y1, true),
                corner(x0, y1, true),
            ];
            let b = [
                corner(x0, y0, false),
                corner(x1, y0, false),
                corner(x1, y1, false),
                corner(x0, y1, false),
            ];
            mesh.faces.push(f.to_vec());
            mesh.faces.push(vec![b[3], b[2], b[1], b[0]]);
            for k in 0..4 {
                let n = (k + 1) % 4;
                mesh.faces.push(vec![f[k], b[k], b[n], f[n]]);
            }
        }
    }
    mesh
}
