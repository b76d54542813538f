#version 330 core
// The mirror's own polygon (notes 05): drawn to mark its region in the
// stencil buffer, and to tint and roughen the reflection inside it.
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;

uniform mat4 u_model;
uniform mat4 u_view_projection;
// The view drawn for: a mirror's clip plane, or a curved mirror's
// reflection of each vertex (common/view.glsl).
#include "common/view.glsl"

out vec2 v_uv;

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_uv = a_uv;
    gl_Position = u_view_projection * view_position(world);
    write_clip_distances(world);
}
