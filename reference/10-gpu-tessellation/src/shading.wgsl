// Task 4: Phong shading in the fragment shader (seed 000 §4.2.3,
// Listing 13 lines 52-75: Phong with two lights and a texture).
//
// This file is WGSL. The crate compiles it in (`crate::wgsl::SHADING`),
// checks it with naga before a pass runs and puts it first in the shader,
// ahead of the given declarations of `crate::shaders::RENDER`,
// which you may use: an error names this file and its line.
//
// Write the function
//
//     fn shade(position: vec3<f32>, normal: vec3<f32>, uv: vec2<f32>) -> vec3<f32>
//
// returning the colour of a surface point (world position, unit normal or
// zero, texture coordinates), with the uniforms of
// `crate::shaders::RENDER`: Phong with the two lights `scene.light0`
// and `scene.light1` as in the seed,
//
//     colour = d·a + Σₗ (φₗ·d + ψₗ·s)      d = diffuse_colour(uv), a = (0.1, 0.1, 0.1), s = (1, 1, 1)
//     φₗ = max(n·Lₗ, 0)                    Lₗ = normalize(lightₗ − position)
//     ψₗ = max(Rₗ·E, 0)^150                Rₗ = reflect(−Lₗ, n), E = normalize(eye − position)
//
// The seed works in view space with the eye at the origin
// (`eye = normalize(-position)`); here positions are in world space and
// the eye is `scene.eye.xyz`. Use `pow` only on non-negative bases (WGSL
// leaves `pow` of a negative base undefined). The framebuffer clamps the
// result to `[0, 1]`.

// BEGIN SOLUTION render: write the WGSL fn shade (Phong, two lights, texture)
const AMBIENT: vec3<f32> = vec3(0.1, 0.1, 0.1);
const SPECULAR: vec3<f32> = vec3(1.0, 1.0, 1.0);
const SHININESS: f32 = 150.0;

// Diffuse weight phi and specular weight psi of one light.
fn phong_weights(light: vec3<f32>, position: vec3<f32>, normal: vec3<f32>, eye: vec3<f32>) -> vec2<f32> {
    let l = normalize(light - position);
    let r = reflect(-l, normal);
    let phi = max(dot(normal, l), 0.0);
    let psi = pow(max(dot(r, eye), 0.0), SHININESS);
    return vec2(phi, psi);
}

fn shade(position: vec3<f32>, normal: vec3<f32>, uv: vec2<f32>) -> vec3<f32> {
    let d = diffuse_colour(uv);
    let eye = normalize(scene.eye.xyz - position);
    let w0 = phong_weights(scene.light0.xyz, position, normal, eye);
    let w1 = phong_weights(scene.light1.xyz, position, normal, eye);
    return d * AMBIENT + w0.x * d + w0.y * SPECULAR + w1.x * d + w1.y * SPECULAR;
}
// END SOLUTION
