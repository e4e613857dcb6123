//! Bézier patches as the GPU reads them (seed 000 §2.4-2.5: tensor-product
//! Bézier surfaces; seed 001 §4.1: cubic Bézier triangles, equation 4.1):
//! their control points, their layout and the vertex the evaluation pass
//! writes. Evaluating them is task 3, in WGSL; the tests compare with the
//! definitions evaluated in `f64` (`testkit::oracles`).
//!
//! # Bicubic patch
//! `P(u, v) = Σᵢ Σⱼ Bᵢ,₃(u) Bⱼ,₃(v) P[4j + i]` for `(u, v) ∈ [0,1]²`, with
//! the Bernstein polynomials `Bᵢ,₃(t) = C(3,i) tⁱ (1 − t)³⁻ⁱ`. Control
//! point `P[4j + i]` is column `i` (along u) of row `j` (along v): the rows
//! are the four u-curves of the seed's Listing 5 (`gl_in[i..i+3]`).
//!
//! ```text
//!  v ^  P12 P13 P14 P15      corners: P(0,0) = P0,  P(1,0) = P3,
//!    |  P8  P9  P10 P11               P(0,1) = P12, P(1,1) = P15
//!    |  P4  P5  P6  P7
//!    |  P0  P1  P2  P3
//!    +-----------------> u
//! ```
//!
//! The normal is `∂P/∂u × ∂P/∂v`, normalised: facing the viewer when the
//! patch is seen with u to the right and v up.
//!
//! # Cubic Bézier triangle
//! `B(u, v, w) = Σ_{i+j+k=3} 3!/(i! j! k!) uⁱ vʲ wᵏ P_ijk` for barycentric
//! `u + v + w = 1`, ten control points stored in the order
//! `P300 P210 P201 P120 P111 P102 P030 P021 P012 P003`
//! ([`BezierTriangle::index`]; the type is the course library's,
//! `surface::BezierTriangle`, the same as topic 09's). Corners: `B(1,0,0) = P300`,
//! `B(0,1,0) = P030`, `B(0,0,1) = P003`. The normal is
//! `(Q010 − Q100) × (Q001 − Q100)` of the three points of the last step
//! but one, normalised: facing the viewer when `P300 → P030 → P003` runs
//! counter-clockwise.
//!
//! A normal whose cross product has a length below [`NORMAL_EPSILON`]
//! (a collapsed edge, a degenerate patch) is returned as zero.

use bytemuck::{Pod, Zeroable};
use glam::{DVec3, Vec3, Vec4};

pub use surface::BezierTriangle;

/// Cross products shorter than this give a zero normal instead of a
/// direction made of rounding noise.
pub const NORMAL_EPSILON: f64 = 1e-12;

/// A bicubic Bézier patch: 16 control points, row-major, rows along u.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BezierPatch {
    /// `points[4j + i]`: column `i` (u), row `j` (v).
    pub points: [Vec3; 16],
}

/// A point of a surface with its unit normal (zero if degenerate).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfacePoint {
    /// The position.
    pub position: DVec3,
    /// The unit normal, or zero.
    pub normal: DVec3,
}

/// A vertex as the evaluation pass writes it and the render pass reads it
/// (WGSL `struct Vertex`, 48 bytes, std430).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct GpuVertex {
    /// `(x, y, z, 1)`.
    pub position: Vec4,
    /// `(nx, ny, nz, 0)`.
    pub normal: Vec4,
    /// The domain point: `(u, v, 0, 0)` for quads, `(u, v, w, 0)` for triangles.
    pub param: Vec4,
}

impl BezierPatch {
    /// A patch from 16 points.
    #[must_use]
    pub const fn new(points: [Vec3; 16]) -> Self {
        Self { points }
    }

    /// The flat patch over `[x0, x1] × [y0, y1]` at height `z`, control
    /// points evenly spaced, so that `P(u, v) = (lerp(x0, x1, u), lerp(y0, y1, v), z)`
    /// exactly (Bernstein polynomials reproduce linear functions).
    #[must_use]
    pub fn flat(lo: glam::Vec2, hi: glam::Vec2, z: f32) -> Self {
        Self::height_field(lo, hi, [[z; 4]; 4])
    }

    /// A height field over `[x0, x1] × [y0, y1]`: control point `(i, j)` at
    /// `(lerp(x0, x1, i/3), lerp(y0, y1, j/3), heights[j][i])`, so that
    /// `x` and `y` are linear in `u` and `v`.
    #[must_use]
    pub fn height_field(lo: glam::Vec2, hi: glam::Vec2, heights: [[f32; 4]; 4]) -> Self {
        let mut points = [Vec3::ZERO; 16];
        for j in 0..4 {
            for i in 0..4 {
                let s = glam::Vec2::new(i as f32, j as f32) / 3.0;
                let xy = lo + (hi - lo) * s;
                points[4 * j + i] = xy.extend(heights[j][i]);
            }
        }
        Self { points }
    }

    /// The 16 points as the GPU reads them (`array<vec4<f32>, 16>`).
    #[must_use]
    pub fn to_gpu(&self) -> [Vec4; 16] {
        self.points.map(|p| p.extend(1.0))
    }
}

/// The 10 points of a Bézier triangle as the GPU reads them
/// (`array<vec4<f32>, 10>`, in [`BezierTriangle::index`] order).
#[must_use]
pub fn triangle_to_gpu(triangle: &BezierTriangle) -> [Vec4; 10] {
    triangle.points().map(|p| p.as_vec3().extend(1.0))
}
