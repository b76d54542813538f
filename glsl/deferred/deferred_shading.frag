#version 330 core
// "Our current deferred shader" (notes 04): for every pixel of the G-buffer,
// for one light (u_light_id), shade. Drawn once per light with additive blending.
#include "common/lighting.glsl"
#include "common/shadow.glsl"
#include "common/gbuffer_read.glsl"
uniform int u_light_id;
uniform vec3 u_eye;
out vec4 light_out;

void main() {
    vec2 uv = gbuffer_uv();
    Surface s = read_gbuffer(uv);
    if (s.depth == 1.0) discard;   // background: no surface here
    vec3 V = normalize(u_eye - s.P);
    // Shadow mapping's second pass (notes 01 §8.5), from the G-buffer's P and N.
#if VARIANT_SHADOWS
    float lit = shadow_visibility(u_light_id, s.P, s.N);
#else
    float lit = 1.0;   // no light of the frame casts (src/frame/variant.rs)
#endif
    light_out = vec4(lit * surface_shade(u_lights[u_light_id], s.P, s.N, V, s.kd, s.ks, s.r), 1.0);
}
