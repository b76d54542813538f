#version 330 core
// Gouraud shading (notes 01 §8.2): light each vertex, interpolate the light.
// Diffuse and specular light are kept apart so a texture can still modulate
// the diffuse part per fragment.
#include "common/lighting.glsl"
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
uniform int u_light_count;
uniform vec3 u_eye;
uniform float u_shininess;
// The material's model (common/material.glsl, which the fragment stage reads).
uniform bool u_microfacet;
uniform float u_microfacet_alpha;
uniform float u_microfacet_eta;

out vec3 v_diffuse_light;
out vec3 v_specular_light;

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    vec3 n = u_normal_matrix * a_normal;
    vec3 N = length(n) > 1e-12 ? normalize(n) : vec3(0.0, 1.0, 0.0);
    vec3 V = normalize(u_eye - world.xyz);
    v_diffuse_light = vec3(0.0);
    v_specular_light = vec3(0.0);
    Reflectance r = Reflectance(u_microfacet, u_shininess, u_microfacet_alpha, u_microfacet_eta);
    for (int i = 0; i < u_light_count; ++i) {
        vec3 d, s;
        surface_light(u_lights[i], world.xyz, N, V, r, d, s);
        v_diffuse_light += d;
        v_specular_light += s;
    }
    write_surface(a_uv);
    gl_Position = u_view_projection * view_position(world);
    write_clip_distances(world);
}
