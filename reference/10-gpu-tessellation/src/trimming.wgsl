// Task 5: trimming in the fragment shader (seed 000 §3 and §4.2: interval,
// circle and ellipse trimming; Newton trimming with quadratic and cubic
// Bézier curves, single and nested).
//
// The render pass (`crate::render::render`) asks `is_trimmed(uv)` for
// every fragment and discards it when true; the given `is_trimmed` loops
// over the trim shapes and calls your predicates.
//
// This file is WGSL. The crate compiles it in (`crate::wgsl::TRIMMING`),
// checks it with naga before a pass runs and puts it first in the shader,
// ahead of the given declarations of `crate::shaders::RENDER` and `crate::shaders::TRIMMING`,
// which you may use: an error names this file and its line.
//
// Write the functions
//
//     fn trimmed_by_rectangle(uv: vec2<f32>, u_range: vec2<f32>, v_range: vec2<f32>) -> bool
//     fn trimmed_by_circle(uv: vec2<f32>, centre: vec2<f32>, radius: f32) -> bool
//     fn trimmed_by_ellipse(uv: vec2<f32>, centre: vec2<f32>, radii: vec2<f32>) -> bool
//     fn trim_curve_derivative(c: TrimCurve, t: f32) -> vec2<f32>
//     fn newton_root(c: TrimCurve, v: f32, t0: f32) -> f32
//     fn inside_bezier_region(uv: vec2<f32>, upper: TrimCurve, lower: TrimCurve) -> bool
//
// with the declarations of `crate::shaders::TRIMMING` (`TrimCurve`,
// `trim_curve_point`, the uniforms `trim.iterations` and `trim.epsilon`).
//
// - Rectangle (seed Listing 7): `u1 ≤ u ≤ u2 ∧ v1 ≤ v ≤ v2`, edges included.
// - Circle: `distance(uv, centre) < radius`.
// - Ellipse (seed equation 14): `(u − c₁)²/a² + (v − c₂)²/b² ≤ 1`.
// - `trim_curve_derivative`: `B'(t)` of the quadratic or cubic curve
//   (`c.degree` is 2 or 3; `c.points[0 ..= degree].xy`).
// - `newton_root` (seed Listing 10): Newton's iteration on
//   `f(t) = B_v(t) − v` from `t0`, `t ← t − h` with `h = f(t)/f'(t)`, at
//   most `trim.iterations` steps, stopping after the first step with
//   `|h| < trim.epsilon`; returns the last `t`. If `f'(t) = 0` it stops
//   and returns `t` (Newton cannot go on). The seed's loop has no return
//   after its last iteration; returning the last `t` is the fix.
// - `inside_bezier_region` (seed §3.2.1 and Listing 11): for each of the
//   two curves, `t₁ = newton_root(c, v, 1)`, `t₂ = newton_root(c, v, 0)`,
//   `xₖ = B_u(tₖ) − u`. The point is inside the half bounded by that curve
//   when both roots are real roots in `[0, 1]` (`|B_v(tₖ) − v| ≤
//   ROOT_TOLERANCE`, a named constant of `1e-3` you declare) and `x₁`, `x₂`
//   have opposite signs (strictly: one `> 0`, the other `< 0`, the seed's
//   cases 3 and 4). Inside the region = inside either half.
//
// Limits, as in the seed: the two curves share their end points, and these
// lie on one horizontal line; a horizontal line meets each curve at most
// twice. The residual check is not in the seed: without it a line that
// misses a curve can still end Newton at some `t` in `[0, 1]` and trim.

// BEGIN SOLUTION trimming: write the WGSL trim predicates and Newton trimming
// A Newton result counts as a root only if the curve is this close to the line.
const ROOT_TOLERANCE: f32 = 1e-3;

fn trimmed_by_rectangle(uv: vec2<f32>, u_range: vec2<f32>, v_range: vec2<f32>) -> bool {
    return uv.x >= u_range.x && uv.x <= u_range.y && uv.y >= v_range.x && uv.y <= v_range.y;
}

fn trimmed_by_circle(uv: vec2<f32>, centre: vec2<f32>, radius: f32) -> bool {
    return distance(uv, centre) < radius;
}

fn trimmed_by_ellipse(uv: vec2<f32>, centre: vec2<f32>, radii: vec2<f32>) -> bool {
    let d = (uv - centre) / radii;
    return dot(d, d) <= 1.0;
}

// B'(t) = degree * (the curve of the differences of neighbouring points).
fn trim_curve_derivative(c: TrimCurve, t: f32) -> vec2<f32> {
    var q = array(c.points[1].xy - c.points[0].xy, c.points[2].xy - c.points[1].xy, c.points[3].xy - c.points[2].xy);
    for (var d = c.degree - 1u; d > 0u; d--) {
        for (var k = 0u; k < d; k++) { q[k] = mix(q[k], q[k + 1u], t); }
    }
    return f32(c.degree) * q[0];
}

fn newton_root(c: TrimCurve, v: f32, t0: f32) -> f32 {
    var t = t0;
    for (var i = 0u; i < trim.iterations; i++) {
        let slope = trim_curve_derivative(c, t).y;
        if slope == 0.0 { return t; }
        let h = (trim_curve_point(c, t).y - v) / slope;
        t = t - h;
        if abs(h) < trim.epsilon { return t; }
    }
    return t;
}

// Whether the horizontal line through uv crosses the curve on both sides of uv.
fn between_crossings(uv: vec2<f32>, c: TrimCurve) -> bool {
    let t1 = newton_root(c, uv.y, 1.0);
    let t2 = newton_root(c, uv.y, 0.0);
    let p1 = trim_curve_point(c, t1);
    let p2 = trim_curve_point(c, t2);
    let real = t1 >= 0.0 && t1 <= 1.0 && t2 >= 0.0 && t2 <= 1.0
        && abs(p1.y - uv.y) <= ROOT_TOLERANCE && abs(p2.y - uv.y) <= ROOT_TOLERANCE;
    let x1 = p1.x - uv.x;
    let x2 = p2.x - uv.x;
    return real && ((x1 > 0.0 && x2 < 0.0) || (x1 < 0.0 && x2 > 0.0));
}

fn inside_bezier_region(uv: vec2<f32>, upper: TrimCurve, lower: TrimCurve) -> bool {
    return between_crossings(uv, upper) || between_crossings(uv, lower);
}
// END SOLUTION
