//! Task 4: shading and the wireframe (seed 000 §4.2.3, Listing 13 lines
//! 52-75: Phong with two lights and a texture; the wireframe of a
//! tessellation as in the seed's figures).

/// Your WGSL: the function
///
/// ```wgsl
/// fn shade(position: vec3<f32>, normal: vec3<f32>, uv: vec2<f32>) -> vec3<f32>
/// ```
///
/// returning the colour of a surface point (world position, unit normal or
/// zero, texture coordinates), with the uniforms of
/// [`crate::shaders::RENDER`]: Phong with the two lights `scene.light0`
/// and `scene.light1` as in the seed,
///
/// ```text
/// colour = d·a + Σₗ (φₗ·d + ψₗ·s)      d = diffuse_colour(uv), a = (0.1, 0.1, 0.1), s = (1, 1, 1)
/// φₗ = max(n·Lₗ, 0)                    Lₗ = normalize(lightₗ − position)
/// ψₗ = max(Rₗ·E, 0)^150                Rₗ = reflect(−Lₗ, n), E = normalize(eye − position)
/// ```
///
/// The seed works in view space with the eye at the origin
/// (`eye = normalize(-position)`); here positions are in world space and
/// the eye is `scene.eye.xyz`. Use `pow` only on non-negative bases (WGSL
/// leaves `pow` of a negative base undefined). The framebuffer clamps the
/// result to `[0, 1]`.
#[must_use]
pub fn shading_wgsl() -> &'static str {
    todo!("render: write the WGSL fn shade (Phong, two lights, texture)")
}

/// The edges of a triangle mesh for a wireframe drawn as a line list: every
/// edge once, as `[a, b]` with `a < b`, sorted, whichever triangles share
/// it.
///
/// A triangle with a repeated index contributes only its real edges (none
/// of the form `[a, a]`). Empty input gives no edges.
#[must_use]
pub fn wireframe_edges(triangles: &[[u32; 3]]) -> Vec<[u32; 2]> {
    // Unused until you write the body:
    let _ = &triangles;
    todo!("render: collect each triangle edge once as [min, max], sorted")
}
