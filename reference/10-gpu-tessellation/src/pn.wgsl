// Task 6: the PN triangle built in the control stage (seed 001 §4.1,
// "Zakrivljeni PN trokuti", Slika 4.2; Vlachos et al. 2001).
//
// In OpenGL the tessellation control shader of a PN pass receives the
// three corners and vertex normals of a flat triangle and writes the ten
// control points of a cubic Bézier triangle, which the evaluation stage
// (task 3) then evaluates over the primitive generator's domain. Here a
// compute pass (`crate::passes::run_pn_control`) runs one invocation per
// flat triangle and calls your WGSL function `pn_triangle`.
//
// This file is WGSL. The crate compiles it in (`crate::wgsl::PN`), checks it
// with naga and puts it first in the shader, ahead of the given
// declarations of `crate::shaders::COMMON` and `crate::shaders::PN`, which
// you may use (`FlatTriangle`, `TrianglePatch`).
//
// Write the function
//
//     fn pn_triangle(t: FlatTriangle) -> TrianglePatch
//
// with `P1, P2, P3` = `t.corners[0..3].xyz` and `N1, N2, N3` =
// `normalize(t.normals[0..3].xyz)`:
//
// - the corners: `b300 = P1`, `b030 = P2`, `b003 = P3`;
// - the edge points: the third of edge i→j next to `Pi`, moved along `Ni`
//   onto the tangent plane at `Pi`,
//       `b_ij = (2 Pi + Pj − ((Pj − Pi) · Ni) Ni) / 3`,
//   so `b210 = b_12`, `b120 = b_21`, `b021 = b_23`, `b012 = b_32`,
//   `b102 = b_31`, `b201 = b_13`;
// - the centre: with `E` the mean of the six edge points and `V` the mean
//   of the three corners, `b111 = E + (E − V) / 2`.
//
// Store the points in `TrianglePatch`'s order (`crate::shaders::COMMON`:
// P300 P210 P201 P120 P111 P102 P030 P021 P012 P003), each with w = 1.
// The pass refuses non-finite input and zero normals before it runs.

// BEGIN SOLUTION pn_control: write the WGSL fn pn_triangle (corners, edge thirds on the tangent planes, the centre)
// The third of edge i -> j next to pi, moved onto the tangent plane at pi.
fn edge_third(pi: vec3<f32>, pj: vec3<f32>, ni: vec3<f32>) -> vec3<f32> {
    return (2.0 * pi + pj - dot(pj - pi, ni) * ni) / 3.0;
}

fn pn_triangle(t: FlatTriangle) -> TrianglePatch {
    let p1 = t.corners[0].xyz;
    let p2 = t.corners[1].xyz;
    let p3 = t.corners[2].xyz;
    let n1 = normalize(t.normals[0].xyz);
    let n2 = normalize(t.normals[1].xyz);
    let n3 = normalize(t.normals[2].xyz);
    let b210 = edge_third(p1, p2, n1);
    let b120 = edge_third(p2, p1, n2);
    let b021 = edge_third(p2, p3, n2);
    let b012 = edge_third(p3, p2, n3);
    let b102 = edge_third(p3, p1, n3);
    let b201 = edge_third(p1, p3, n1);
    let e = (b210 + b120 + b021 + b012 + b102 + b201) / 6.0;
    let v = (p1 + p2 + p3) / 3.0;
    let b111 = e + (e - v) / 2.0;
    return TrianglePatch(array<vec4<f32>, 10>(
        vec4(p1, 1.0), vec4(b210, 1.0), vec4(b201, 1.0), vec4(b120, 1.0), vec4(b111, 1.0),
        vec4(b102, 1.0), vec4(p2, 1.0), vec4(b021, 1.0), vec4(b012, 1.0), vec4(p3, 1.0),
    ));
}
// END SOLUTION
