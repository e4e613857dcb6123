// Task 3: the tessellation evaluation stage as a compute shader (seed 000
// §2.5 and §4.1.2, Listings 4-6; seed 001 §4.1, Bézier triangles).
//
// OpenGL's TES runs once per domain point the primitive generator makes
// and places it on the surface. Here a compute pass
// (`crate::passes::run_evaluation`) runs one invocation per (patch,
// domain point) and calls your WGSL functions.
//
// This file is WGSL. The crate compiles it in (`crate::wgsl::EVALUATION`),
// checks it with naga before a pass runs and puts it first in the shader,
// ahead of the given declarations of `crate::shaders::COMMON` and `crate::shaders::EVALUATION`,
// which you may use: an error names this file and its line.
//
// Write the two functions
//
//     fn evaluate_patch(patch_index: u32, uv: vec2<f32>) -> SurfacePoint
//     fn evaluate_triangle(patch_index: u32, uvw: vec3<f32>) -> SurfacePoint
//
// (and any helpers), reading `patches[patch_index].points` and
// `triangles[patch_index].points` (declarations in `crate::shaders::COMMON`
// and `crate::shaders::EVALUATION`; the point order is documented in
// `crate::patch`).
//
// - `evaluate_patch`: de Casteljau along u on each of the four rows, then
//   along v on the four results (the seed's `doubleDeCasteljau`). The
//   normal is `normalize(∂P/∂u × ∂P/∂v)`. `∂P/∂v` is `3·(b − a)` of the
//   v-pass's last-but-one points `a`, `b`; for `∂P/∂u`, carry the u-pass's
//   last-but-one points of all four rows through the v-pass as well (two
//   more cubic evaluations). The seed takes the u tangent from the last
//   row only (Listing 4, `index == 0`), which is the tangent of the
//   boundary curve `v = 1`, not of the surface at `v`: do not copy that.
//   The points are homogeneous, `(w·P, w)` (`w = 1` for a polynomial
//   patch, other weights for a piece of a NURBS surface): run the scheme
//   on all four coordinates, then `P = A.xyz / A.w`, and a tangent `T` of
//   `A` becomes `T.xyz − P·T.w` (the quotient rule without its positive
//   factor `1/A.w`, which the normal does not need).
// - `evaluate_triangle`: three barycentric de Casteljau steps, 10 → 6 → 3
//   → 1 points, `Q_ijk ← u·Q_(i+1)jk + v·Q_i(j+1)k + w·Q_ij(k+1)`; with
//   the last-but-one step's points `Q100, Q010, Q001` the normal is
//   `normalize((Q010 − Q100) × (Q001 − Q100))`.
//
// Limits: where the cross product is shorter than `NORMAL_EPSILON` (a
// collapsed edge), return a zero normal instead of dividing by ~0.
// Results must match the CPU evaluation (`crate::patch`) within `1e-5`
// for positions and `1e-3` for normals, for control points in `[-1, 1]³`.

// TODO evaluation: write the WGSL fns evaluate_patch and evaluate_triangle (de Casteljau)
