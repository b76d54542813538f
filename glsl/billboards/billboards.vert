#version 330 core
// Billboards (notes 05, "Billboards"): the quad is built here from the
// billboard's centre and size; the CPU sends one instance per billboard
// (glVertexAttribDivisor 1) and four vertices, a triangle strip, per instance.
layout(location = 0) in vec3 a_center;
layout(location = 1) in vec2 a_size;       // width, height
layout(location = 2) in float a_sprite;    // which sprite of the sheet
layout(location = 3) in float a_cylindrical;

uniform mat4 u_view;
uniform mat4 u_view_projection;
uniform float u_sprite_count;
// The view drawn for: a mirror's clip plane, or a curved mirror's
// reflection of each vertex (common/view.glsl).
#include "common/view.glsl"

out vec2 v_uv;

// Strip order: bottom left, bottom right, top left, top right.
const vec2 CORNERS[4] = vec2[4](vec2(-0.5, -0.5), vec2(0.5, -0.5),
                                vec2(-0.5, 0.5), vec2(0.5, 0.5));

void main() {
    vec2 corner = CORNERS[gl_VertexID];
    // Spherical: the camera's right and up axes in world space (the first two
    // rows of the view matrix), so the quad lies in the image plane.
    vec3 right = vec3(u_view[0][0], u_view[1][0], u_view[2][0]);
    vec3 up = vec3(u_view[0][1], u_view[1][1], u_view[2][1]);
    if (a_cylindrical > 0.5) {
        // Cylindrical: turn only about world up; right made horizontal.
        vec3 flat_right = vec3(right.x, 0.0, right.z);
        right = length(flat_right) > 1e-6 ? normalize(flat_right) : vec3(1.0, 0.0, 0.0);
        up = vec3(0.0, 1.0, 0.0);
    }
    vec3 world = a_center + right * (corner.x * a_size.x) + up * (corner.y * a_size.y);
    v_uv = vec2((a_sprite + corner.x + 0.5) / u_sprite_count, corner.y + 0.5);
    gl_Position = u_view_projection * view_position(vec4(world, 1.0));
    write_clip_distances(vec4(world, 1.0));
}
