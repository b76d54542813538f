#version 330 core
// An area light's rectangle (lighting/ltc_area_lights.rs): a unit square's
// (s, t) in a_position.xy spread over the light's corners,
// c0 + s (c1 - c0) + t (c3 - c0).
layout(location = 0) in vec3 a_position;

uniform mat4 u_view_projection;
uniform vec3 u_corners[4];
#include "common/view.glsl"

void main() {
    vec3 c0 = u_corners[0];
    vec4 world = vec4(c0 + a_position.x * (u_corners[1] - c0) + a_position.y * (u_corners[3] - c0), 1.0);
    gl_Position = u_view_projection * view_position(world);
    write_clip_distances(world);
}
