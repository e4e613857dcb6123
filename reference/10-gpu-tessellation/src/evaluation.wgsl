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

// BEGIN SOLUTION evaluation: write the WGSL fns evaluate_patch and evaluate_triangle (de Casteljau)
// One cubic curve by de Casteljau: returns the point in [0] and the
// last-but-one points in [1] and [2] (their difference is B'(t) / 3).
fn cubic(p0: vec4<f32>, p1: vec4<f32>, p2: vec4<f32>, p3: vec4<f32>, t: f32) -> array<vec4<f32>, 3> {
    let a = mix(p0, p1, t);
    let b = mix(p1, p2, t);
    let c = mix(p2, p3, t);
    let d = mix(a, b, t);
    let e = mix(b, c, t);
    return array(mix(d, e, t), d, e);
}

fn unit_or_zero(n: vec3<f32>) -> vec3<f32> {
    let len = length(n);
    return select(vec3(0.0), n / len, len > NORMAL_EPSILON);
}

fn evaluate_patch(patch_index: u32, uv: vec2<f32>) -> SurfacePoint {
    let p = patches[patch_index].points;
    var on_rows: array<vec4<f32>, 4>;
    var row_a: array<vec4<f32>, 4>;
    var row_b: array<vec4<f32>, 4>;
    for (var j = 0u; j < 4u; j++) {
        let r = cubic(p[4u * j], p[4u * j + 1u], p[4u * j + 2u], p[4u * j + 3u], uv.x);
        on_rows[j] = r[0];
        row_a[j] = r[1];
        row_b[j] = r[2];
    }
    let v_pass = cubic(on_rows[0], on_rows[1], on_rows[2], on_rows[3], uv.y);
    let ua = cubic(row_a[0], row_a[1], row_a[2], row_a[3], uv.y)[0];
    let ub = cubic(row_b[0], row_b[1], row_b[2], row_b[3], uv.y)[0];
    // Homogeneous: divide, and take the tangents by the quotient rule.
    let position = v_pass[0].xyz / v_pass[0].w;
    let du = ub - ua;
    let dv = v_pass[2] - v_pass[1];
    let tangent_u = du.xyz - position * du.w;
    let tangent_v = dv.xyz - position * dv.w;
    let normal = unit_or_zero(cross(tangent_u, tangent_v));
    return SurfacePoint(position, normal);
}

// Index of Q_ijk (k = degree - i - j) in a triangle array of that degree.
fn tri_index(i: u32, j: u32, degree: u32) -> u32 {
    let row = degree - i;
    return row * (row + 1u) / 2u + (row - j);
}

fn evaluate_triangle(patch_index: u32, uvw: vec3<f32>) -> SurfacePoint {
    var q: array<vec3<f32>, 10>;
    for (var k = 0u; k < 10u; k++) { q[k] = triangles[patch_index].points[k].xyz; }
    var last: array<vec3<f32>, 3>;
    for (var degree = 3u; degree > 0u; degree--) {
        let lower = degree - 1u;
        // The next level goes into its own array: no point is overwritten
        // while a later one still needs it.
        var next: array<vec3<f32>, 10>;
        for (var i = 0u; i <= lower; i++) {
            for (var j = 0u; j <= lower - i; j++) {
                next[tri_index(i, j, lower)] = uvw.x * q[tri_index(i + 1u, j, degree)]
                    + uvw.y * q[tri_index(i, j + 1u, degree)]
                    + uvw.z * q[tri_index(i, j, degree)];
            }
        }
        if lower == 1u {
            last = array(next[tri_index(1u, 0u, 1u)], next[tri_index(0u, 1u, 1u)], next[tri_index(0u, 0u, 1u)]);
        }
        q = next;
    }
    let normal = unit_or_zero(cross(last[1] - last[0], last[2] - last[0]));
    return SurfacePoint(q[0], normal);
}
// END SOLUTION
