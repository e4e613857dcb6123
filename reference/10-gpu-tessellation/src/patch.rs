//! Bézier patches and their CPU evaluation, the yardstick for the GPU
//! (seed 000 §2.4-2.5: tensor-product Bézier surfaces and de Casteljau;
//! seed 001 §4.1: cubic Bézier triangles, equation 4.1).
//!
//! This module is given. It evaluates in `f64`, so that the GPU's `f32`
//! results can be compared with it within a stated tolerance.
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
//! ([`BezierTriangle::index`]). Corners: `B(1,0,0) = P300`,
//! `B(0,1,0) = P030`, `B(0,0,1) = P003`. The normal is
//! `(Q010 − Q100) × (Q001 − Q100)` of the last de Casteljau step's three
//! points, normalised: facing the viewer when `P300 → P030 → P003` runs
//! counter-clockwise.
//!
//! A normal whose cross product has a length below [`NORMAL_EPSILON`]
//! (a collapsed edge, a degenerate patch) is returned as zero.

use bytemuck::{Pod, Zeroable};
use glam::{DVec2, DVec3, Vec3, Vec4};

/// Cross products shorter than this give a zero normal instead of a
/// direction made of rounding noise.
pub const NORMAL_EPSILON: f64 = 1e-12;

/// A bicubic Bézier patch: 16 control points, row-major, rows along u.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BezierPatch {
    /// `points[4j + i]`: column `i` (u), row `j` (v).
    pub points: [Vec3; 16],
}

/// A cubic Bézier triangle: 10 control points in [`BezierTriangle::index`] order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BezierTriangle {
    /// `P300 P210 P201 P120 P111 P102 P030 P021 P012 P003`.
    pub points: [Vec3; 10],
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

/// One cubic de Casteljau step: `(1 − t)·a + t·b` for each neighbouring pair.
fn lerp_step(points: &mut [DVec3], t: f64) {
    for k in 0..points.len() - 1 {
        points[k] = points[k] * (1.0 - t) + points[k + 1] * t;
    }
}

/// De Casteljau on a cubic: the point and the two points of the last step
/// but one, whose difference is `B'(t) / 3`.
fn de_casteljau_cubic(control: [DVec3; 4], t: f64) -> (DVec3, DVec3, DVec3) {
    let mut p = control;
    lerp_step(&mut p, t);
    lerp_step(&mut p[..3], t);
    let (a, b) = (p[0], p[1]);
    (a * (1.0 - t) + b * t, a, b)
}

fn unit_or_zero(n: DVec3) -> DVec3 {
    let len = n.length();
    if len > NORMAL_EPSILON && len.is_finite() {
        n / len
    } else {
        DVec3::ZERO
    }
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

    /// `P(u, v)` and its normal by de Casteljau in `f64`: first along u on
    /// each row, then along v on the four results.
    #[must_use]
    pub fn evaluate(&self, uv: DVec2) -> SurfacePoint {
        let p = |k: usize| self.points[k].as_dvec3();
        let mut on_rows = [DVec3::ZERO; 4];
        // ∂P/∂u needs the last-but-one points of every row, carried along v.
        let (mut row_a, mut row_b) = ([DVec3::ZERO; 4], [DVec3::ZERO; 4]);
        for j in 0..4 {
            let (q, a, b) =
                de_casteljau_cubic([p(4 * j), p(4 * j + 1), p(4 * j + 2), p(4 * j + 3)], uv.x);
            on_rows[j] = q;
            row_a[j] = a;
            row_b[j] = b;
        }
        let (position, va, vb) = de_casteljau_cubic(on_rows, uv.y);
        let (ua, _, _) = de_casteljau_cubic(row_a, uv.y);
        let (ub, _, _) = de_casteljau_cubic(row_b, uv.y);
        SurfacePoint {
            position,
            normal: unit_or_zero((ub - ua).cross(vb - va)),
        }
    }

    /// The 16 points as the GPU reads them (`array<vec4<f32>, 16>`).
    #[must_use]
    pub fn to_gpu(&self) -> [Vec4; 16] {
        self.points.map(|p| p.extend(1.0))
    }
}

impl BezierTriangle {
    /// The storage index of `P_ijk` (`i + j + k = 3`, so `k` is implied):
    /// rows by falling `i`, then falling `j`.
    ///
    /// # Panics
    /// If `i + j > 3`.
    #[must_use]
    pub const fn index(i: usize, j: usize) -> usize {
        assert!(i + j <= 3, "P_ijk needs i + j + k = 3");
        let row = 3 - i;
        row * (row + 1) / 2 + (row - j)
    }

    /// The flat triangle with corners `a = P300`, `b = P030`, `c = P003`
    /// and the other points at their linear positions `(i·a + j·b + k·c)/3`.
    #[must_use]
    pub fn flat(a: Vec3, b: Vec3, c: Vec3) -> Self {
        let mut points = [Vec3::ZERO; 10];
        for i in 0..=3 {
            for j in 0..=3 - i {
                let k = 3 - i - j;
                points[Self::index(i, j)] = (a * i as f32 + b * j as f32 + c * k as f32) / 3.0;
            }
        }
        Self { points }
    }

    /// The PN triangle of seed 001 §4.1 (Vlachos et al., "Curved PN
    /// Triangles"): a Bézier triangle through three vertices whose edge
    /// points are the third points of the edges projected into the tangent
    /// plane of the nearest vertex, and whose centre point is
    /// `E + (E − V)/2` with `E` the mean of the six edge points and `V` the
    /// mean of the vertices. Normals need not be unit: they are normalised
    /// here (zero normals leave the edge points unmoved).
    #[must_use]
    pub fn pn_triangle(vertices: [Vec3; 3], normals: [Vec3; 3]) -> Self {
        let n = normals.map(Vec3::normalize_or_zero);
        // The point one third from `from` to `to`, moved into `from`'s plane.
        let edge = |from: usize, to: usize| {
            let (p, q) = (vertices[from], vertices[to]);
            let third = (2.0 * p + q) / 3.0;
            third - (third - p).dot(n[from]) * n[from]
        };
        let mut points = [Vec3::ZERO; 10];
        points[Self::index(3, 0)] = vertices[0];
        points[Self::index(0, 3)] = vertices[1];
        points[Self::index(0, 0)] = vertices[2];
        points[Self::index(2, 1)] = edge(0, 1);
        points[Self::index(1, 2)] = edge(1, 0);
        points[Self::index(0, 2)] = edge(1, 2);
        points[Self::index(0, 1)] = edge(2, 1);
        points[Self::index(1, 0)] = edge(2, 0);
        points[Self::index(2, 0)] = edge(0, 2);
        let e: Vec3 = [(2, 1), (1, 2), (0, 2), (0, 1), (1, 0), (2, 0)]
            .iter()
            .map(|&(i, j)| points[Self::index(i, j)])
            .sum::<Vec3>()
            / 6.0;
        let v = (vertices[0] + vertices[1] + vertices[2]) / 3.0;
        points[Self::index(1, 1)] = e + (e - v) / 2.0;
        Self { points }
    }

    /// `B(u, v, w)` and its normal by de Casteljau in `f64`: three steps of
    /// `Q_ijk ← u·Q_(i+1)jk + v·Q_i(j+1)k + w·Q_ij(k+1)`, 10 → 6 → 3 → 1 points.
    #[must_use]
    pub fn evaluate(&self, uvw: DVec3) -> SurfacePoint {
        let mut q: Vec<DVec3> = self.points.iter().map(|p| p.as_dvec3()).collect();
        let mut degree = 3;
        let mut last = [DVec3::ZERO; 3];
        while degree > 0 {
            let lower = degree - 1;
            let at = |i: usize, j: usize, d: usize| {
                let row = d - i;
                row * (row + 1) / 2 + (row - j)
            };
            let mut next = vec![DVec3::ZERO; (lower + 1) * (lower + 2) / 2];
            for i in 0..=lower {
                for j in 0..=lower - i {
                    next[at(i, j, lower)] = q[at(i + 1, j, degree)] * uvw.x
                        + q[at(i, j + 1, degree)] * uvw.y
                        + q[at(i, j, degree)] * uvw.z;
                }
            }
            if lower == 1 {
                last = [next[at(1, 0, 1)], next[at(0, 1, 1)], next[at(0, 0, 1)]];
            }
            q = next;
            degree = lower;
        }
        SurfacePoint {
            position: q[0],
            normal: unit_or_zero((last[1] - last[0]).cross(last[2] - last[0])),
        }
    }

    /// The 10 points as the GPU reads them (`array<vec4<f32>, 10>`).
    #[must_use]
    pub fn to_gpu(&self) -> [Vec4; 10] {
        self.points.map(|p| p.extend(1.0))
    }
}

/// Evaluates a patch at every domain point on the CPU (`f64`, stored as
/// `f32`): the mesh the render and trimming tasks draw, independent of the
/// GPU evaluation task.
#[must_use]
pub fn tessellate_patch(patch: &BezierPatch, points: &[Vec3]) -> Vec<GpuVertex> {
    points
        .iter()
        .map(|d| {
            let s = patch.evaluate(DVec2::new(f64::from(d.x), f64::from(d.y)));
            GpuVertex {
                position: s.position.as_vec3().extend(1.0),
                normal: s.normal.as_vec3().extend(0.0),
                param: d.extend(0.0),
            }
        })
        .collect()
}

/// Evaluates a Bézier triangle at every barycentric domain point on the CPU.
#[must_use]
pub fn tessellate_triangle(triangle: &BezierTriangle, points: &[Vec3]) -> Vec<GpuVertex> {
    points
        .iter()
        .map(|d| {
            let s = triangle.evaluate(d.as_dvec3());
            GpuVertex {
                position: s.position.as_vec3().extend(1.0),
                normal: s.normal.as_vec3().extend(0.0),
                param: d.extend(0.0),
            }
        })
        .collect()
}
