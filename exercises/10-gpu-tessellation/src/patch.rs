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
//! are the four u-curves of the seed's Listing 5 (`gl_in[i..i+3]`). The
//! patch itself is the course library's `freeform::BezierPatch`, the one
//! topics 07 and 09 use, which stores its points the other way round (row
//! `i` along v, `P_ij` at `4i + j`): [`patch_to_gpu`] transposes.
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
//! # Rational patches
//! A rational patch (`freeform::RationalPatch`, a piece of a NURBS
//! surface) is uploaded homogeneous, each control point `(w·P, w)`
//! ([`rational_patch_to_gpu`]); a polynomial patch is the case `w = 1`
//! ([`patch_to_gpu`]). Its surface is `A(u, v) / W(u, v)`, the bicubic
//! formula above applied to the four coordinates, then divided:
//! `P = A.xyz / A.w`, and `∂P/∂u = (∂A.xyz/∂u − P·∂A.w/∂u) / A.w`
//! (likewise for v), whose direction is all the normal needs.
//!
//! # Cubic Bézier triangle
//! `B(u, v, w) = Σ_{i+j+k=3} 3!/(i! j! k!) uⁱ vʲ wᵏ P_ijk` for barycentric
//! `u + v + w = 1`, ten control points stored in the order
//! `P300 P210 P201 P120 P111 P102 P030 P021 P012 P003`
//! ([`BezierTriangle::index`]; the type is the course library's,
//! `freeform::BezierTriangle`, the same as topic 09's). Corners: `B(1,0,0) = P300`,
//! `B(0,1,0) = P030`, `B(0,0,1) = P003`. The normal is
//! `(Q010 − Q100) × (Q001 − Q100)` of the three points of the last step
//! but one, normalised: facing the viewer when `P300 → P030 → P003` runs
//! counter-clockwise.
//!
//! A normal whose cross product has a length below [`NORMAL_EPSILON`]
//! (a collapsed edge, a degenerate patch) is returned as zero.

use bytemuck::{Pod, Zeroable};
use glam::Vec4;

pub use freeform::{BezierPatch, BezierTriangle, RationalPatch};

/// Cross products shorter than this give a zero normal instead of a
/// direction made of rounding noise.
pub const NORMAL_EPSILON: f64 = 1e-12;

/// A point of a surface with its parameters and unit normal (zero if
/// degenerate): the course library's record, `freeform::SurfaceSample`,
/// what the WGSL `struct SurfacePoint` holds on the GPU besides the domain
/// point the entry points pass on.
pub use freeform::SurfaceSample;

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

/// The 16 control points of a bicubic patch as the GPU reads them
/// (`array<vec4<f32>, 16>`): `P_ij` at `4j + i`, the transpose of the
/// patch's own row-by-row order, each homogeneous with weight 1:
/// `(x, y, z, 1)`. `None` unless the patch is bicubic.
#[must_use]
pub fn patch_to_gpu(patch: &BezierPatch) -> Option<[Vec4; 16]> {
    if (patch.degree_u(), patch.degree_v()) != (3, 3) {
        return None;
    }
    Some(std::array::from_fn(|k| {
        patch.control_point(k % 4, k / 4).as_vec3().extend(1.0)
    }))
}

/// The 16 control points of a rational patch as the GPU reads them:
/// homogeneous, `(w·x, w·y, w·z, w)`, in the order of [`patch_to_gpu`]. A
/// patch of degree `n × n` below 3 (the torus's biquadratic pieces) is
/// raised to bicubic first (degree elevation, `RationalPatch::elevated`,
/// the same surface); `None` for any other degree than bicubic.
#[must_use]
pub fn rational_patch_to_gpu(patch: &RationalPatch) -> Option<[Vec4; 16]> {
    let mut patch = patch.clone();
    while patch.points().degree_u().max(patch.points().degree_v()) < 3 {
        patch = patch.elevated().ok()?;
    }
    if (patch.points().degree_u(), patch.points().degree_v()) != (3, 3) {
        return None;
    }
    Some(std::array::from_fn(|k| {
        let (i, j) = (k % 4, k / 4);
        let w = patch.weight(i, j);
        (w * patch.points().control_point(i, j))
            .as_vec3()
            .extend(w as f32)
    }))
}

/// The 10 points of a Bézier triangle as the GPU reads them
/// (`array<vec4<f32>, 10>`, in [`BezierTriangle::index`] order).
#[must_use]
pub fn triangle_to_gpu(triangle: &BezierTriangle) -> [Vec4; 10] {
    triangle.points().map(|p| p.as_vec3().extend(1.0))
}
