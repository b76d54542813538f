#version 330 core
// Flat shading: one colour per triangle, lit at its centroid with the face
// normal N = (v1 - v0) x (v2 - v0) (notes 01 §8.3, counter-clockwise front faces).
#include "common/lighting.glsl"
#include "common/material.glsl"
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in vec3 g_position[];
in vec2 g_uv[];
in vec3 g_color[];
uniform mat4 u_view_projection;
uniform int u_light_count;
uniform vec3 u_eye;
uniform vec3 u_ambient;
// The view drawn for: a mirror's clip plane, or a curved mirror's
// reflection of each vertex (common/view.glsl).
#include "common/view.glsl"
uniform float u_mirror;   // -1 when the model matrix flips handedness
flat out vec3 f_color;

void main() {
    vec3 P = (g_position[0] + g_position[1] + g_position[2]) / 3.0;
    vec3 n = u_mirror * cross(g_position[1] - g_position[0], g_position[2] - g_position[0]);
    float len = length(n);
    if (len < 1e-30) return;   // a degenerate triangle covers no pixel
    vec3 N = n / len;
    vec3 V = normalize(u_eye - P);
    vec2 uv = (g_uv[0] + g_uv[1] + g_uv[2]) / 3.0;
    vec3 kd = u_has_diffuse_texture ? u_diffuse * textureLod(u_diffuse_texture, uv, 0.0).rgb : u_diffuse;
    kd *= (g_color[0] + g_color[1] + g_color[2]) / 3.0;   // the vertex colours' mean
    vec3 c = u_ambient * kd;
    for (int i = 0; i < u_light_count; ++i) {
        c += surface_shade(u_lights[i], P, N, V, kd, material_specular(), material_reflectance());
    }
    for (int k = 0; k < 3; ++k) {
        f_color = c;
        gl_Position = u_view_projection * view_position(vec4(g_position[k], 1.0));
        write_clip_distances(vec4(g_position[k], 1.0));
        EmitVertex();
    }
    EndPrimitive();
}
