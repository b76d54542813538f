#version 330 core
// Deferred lighting / light pre-pass (notes 02): per light, accumulate the
// diffuse and the specular light apart, without the material.
#include "common/lighting.glsl"
#include "common/shadow.glsl"
#include "common/gbuffer_read.glsl"
uniform int u_light_id;
uniform vec3 u_eye;
layout(location = 0) out vec4 diffuse_light;
layout(location = 1) out vec4 specular_light;

void main() {
    vec2 uv = gbuffer_uv();
    float depth = texture(u_gbuffer_depth, uv).r;
    if (depth == 1.0) discard;
    vec4 ns = texture(u_gbuffer_normal, uv);
    vec3 P = world_position(uv, depth);
    Light light = u_lights[u_light_id];
    float radius = light.direction_radius.w;
    if (radius >= 0.0 && distance(P, light.position_type.xyz) > radius) discard;
    vec3 d, s;
    phong_light(light, P, ns.xyz, normalize(u_eye - P), ns.w, d, s);
    // Shadow mapping's second pass (notes 01 §8.5) scales both lights.
    float lit = shadow_visibility(u_light_id, P, ns.xyz);
    diffuse_light = vec4(lit * d, 1.0);
    specular_light = vec4(lit * s, 1.0);
}
