#version 330 core
// Light volume shading (notes 04): the volume is a window into the G-buffer.
// Same lighting code as before, for ONE light: u_lights[u_light_id].
#include "common/lighting.glsl"
#include "common/shadow.glsl"
#include "common/gbuffer_read.glsl"
uniform int u_light_id;
uniform vec3 u_eye;
out vec4 light_out;

void main() {
    vec2 uv = gbuffer_uv();
    Surface s = read_gbuffer(uv);
    if (s.depth == 1.0) discard;
    Light light = u_lights[u_light_id];
    // The shader check: the rasterised volume may cover surfaces in front of
    // the light's sphere; only shade those within its radius.
    float radius = light.direction_radius.w;
    if (radius >= 0.0 && distance(s.P, light.position_type.xyz) > radius) discard;
    vec3 V = normalize(u_eye - s.P);
    // The volume shader samples the light's shadow map (notes 01 §8.5).
#if VARIANT_SHADOWS
    float lit = shadow_visibility(u_light_id, s.P, s.N);
#else
    float lit = 1.0;   // no light casts in this frame (src/frame/variant.rs)
#endif
    light_out = vec4(lit * surface_shade(light, s.P, s.N, V, s.kd, s.ks, s.r), 1.0);
}
