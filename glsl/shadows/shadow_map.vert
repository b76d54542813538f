#version 330 core
// Shadow pass, 2D map (notes 01 §8.5, first pass): the scene "rendered from
// the position of the light in the relevant direction"; only depth is kept.
// u_light_view_projection is orthographic for a directional light and
// perspective for a spot light (notes 02). The texture coordinates go on
// for an alpha-tested caster (shadows/shadow_alpha.glsl); DEPTH_ONLY (the
// opaque casters' program, src/techniques/shadows/casters.rs) leaves them out.
layout(location = 0) in vec3 a_position;
#ifndef DEPTH_ONLY
layout(location = 2) in vec2 a_uv;
uniform vec4 u_uv_transform;   // the material's uv scale.xy, offset.zw
out vec2 v_uv;
#endif

uniform mat4 u_model;
uniform mat4 u_light_view_projection;

void main() {
#ifndef DEPTH_ONLY
    v_uv = a_uv * u_uv_transform.xy + u_uv_transform.zw;
#endif
    gl_Position = u_light_view_projection * u_model * vec4(a_position, 1.0);
}
