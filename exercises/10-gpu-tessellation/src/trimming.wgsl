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

// TODO trimming: write the WGSL trim predicates and Newton trimming
