// Task 1: the tessellation control stage as a compute shader (seed 000
// §4.1.1, Listing 1; seed 001 §2.1 per-patch adaptive tessellation).
//
// OpenGL's TCS runs once per patch and writes `gl_TessLevelOuter[0..4]`
// and `gl_TessLevelInner[0..2]`. wgpu has no such stage, so a compute pass
// (`crate::passes::run_control`) runs one invocation per patch and calls
// your WGSL function `tessellation_levels`.
//
// This file is WGSL. The crate compiles it in (`crate::wgsl::CONTROL`),
// checks it with naga before a pass runs and puts it first in the shader,
// ahead of the given declarations of `crate::shaders::COMMON` and `crate::shaders::CONTROL`,
// which you may use: an error names this file and its line.
//
// Write the function
//
//     fn tessellation_levels(patch_index: u32) -> TessLevels
//
// (and any helpers you like), computing the levels of `patches[patch_index]`
// (declarations in `crate::shaders::COMMON` and
// `crate::shaders::CONTROL`).
//
// - `control.mode == MODE_UNIFORM`: all six levels are
//   `control.uniform_level`, clamped to `[1, MAX_TESS_LEVEL]` (the seed's
//   Listing 1, which sets all levels to `tessLevel`).
// - `control.mode == MODE_ADAPTIVE`: each outer level is the projected
//   length `L` in pixels of its boundary's **control polygon** (three
//   segments: an upper bound of the curve's length), divided by
//   `control.pixels_per_segment`, clamped to `[1, MAX_TESS_LEVEL]`.
//   Project a point `p` with `c = control.view_proj * vec4(p, 1)` to the
//   pixel position `(c.xy / c.w) · ½ · control.viewport`; if any of the
//   boundary's four points has `c.w ≤ W_EPSILON` (at or behind the eye)
//   the level is `MAX_TESS_LEVEL`.
//
// Which boundary is which (GL's quad layout, see `crate::domain`):
// `outer[0]`: `u = 0` (points 0, 4, 8, 12), `outer[1]`: `v = 0` (0, 1,
// 2, 3), `outer[2]`: `u = 1` (3, 7, 11, 15), `outer[3]`: `v = 1` (12, 13,
// 14, 15). `inner[0]` cuts along u: `max(outer[1], outer[3])`; `inner[1]`
// cuts along v: `max(outer[0], outer[2])`. Set `_pad` to zero.
//
// Limits: two patches sharing a boundary must get bit-identical levels for
// it, or cracks open between them, even when one patch runs along the
// boundary in the opposite direction. Sum the three segment lengths in an
// order that does not depend on the direction: `(|s₀| + |s₂|) + |s₁|`.

// TODO control: write the WGSL fn tessellation_levels (uniform and adaptive levels)
