#version 330 core
// Forward rendering, Phong shading (per fragment): pass world-space data on.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;

uniform mat4 u_model;
uniform mat4 u_view_projection;
uniform mat3 u_normal_matrix;
// The view drawn for: a mirror's clip plane, or a curved mirror's
// reflection of each vertex (common/view.glsl).
#include "common/view.glsl"
#include "common/surface.glsl"
#include "common/tangent.glsl"

out vec3 v_position;
out vec3 v_normal;

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_position = world.xyz;
    v_normal = u_normal_matrix * a_normal;
    write_surface(a_uv);
    write_tangent();
    gl_Position = u_view_projection * view_position(world);
    write_clip_distances(world);
}
