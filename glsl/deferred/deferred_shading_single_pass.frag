#version 330 core
// Deferred shading as notes 01 §8.6.2 writes it: for every pixel of the
// G-buffer, for every light, shade; one full-screen pass, the loop over the
// lights in the shader (the lights in the std140 Lights block). No blending:
// the sum is made here, in f32, and written once.
#include "common/lighting.glsl"
#include "common/shadow.glsl"
#include "common/gbuffer_read.glsl"
uniform int u_light_count;
uniform vec3 u_eye;
out vec4 light_out;

void main() {
    vec2 uv = gbuffer_uv();
    Surface s = read_gbuffer(uv);
    if (s.depth == 1.0) discard;   // background: no surface here
    vec3 V = normalize(u_eye - s.P);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < u_light_count; ++i) {
#if VARIANT_SHADOWS
        if (casts_shadow(i)) continue;   // in the loop below
#endif
        sum += surface_shade(u_lights[i], s.P, s.N, V, s.kd, s.ks, s.r);
    }
#if VARIANT_SHADOWS
    // The lights that cast, with shadow mapping's second pass (notes 01 §8.5).
    for (int k = 0; k < MAX_CASTERS; ++k) {
        int i = caster(k);
        if (i < 0) break;
        float lit = shadow_visibility(i, s.P, s.N);
        sum += lit * surface_shade(u_lights[i], s.P, s.N, V, s.kd, s.ks, s.r);
    }
#endif
    light_out = vec4(sum, 1.0);
}
