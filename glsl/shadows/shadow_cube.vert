#version 330 core
// Shadow pass, cube map (notes 01 §8.5, "6 maps for omnidirectional
// lights"): world position on, for the fragment shader's distance. Six
// passes: u_light_view_projection is one face's. One pass: the geometry
// shader (shadow_cube.geom) projects to every face itself. DEPTH_ONLY (opaque
// casters, src/techniques/shadows/casters.rs): no texture coordinates.
layout(location = 0) in vec3 a_position;
#ifndef DEPTH_ONLY
layout(location = 2) in vec2 a_uv;
uniform vec4 u_uv_transform;   // the material's uv scale.xy, offset.zw
out vec2 v_uv;   // for an alpha-tested caster (shadows/shadow_alpha.glsl)
#endif

uniform mat4 u_model;
uniform mat4 u_light_view_projection;

out vec3 v_world;

void main() {
#ifndef DEPTH_ONLY
    v_uv = a_uv * u_uv_transform.xy + u_uv_transform.zw;
#endif
    vec4 world = u_model * vec4(a_position, 1.0);
    v_world = world.xyz;
    gl_Position = u_light_view_projection * world;
}
