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
    // The thin G-buffer: normal, shininess (or the microfacet triple), depth.
    Surface g = read_geometry_texel(ivec2(gl_FragCoord.xy));
    if (g.depth == 1.0) discard;
    Light light = u_lights[u_light_id];
    float radius = light.direction_radius.w;
    if (radius >= 0.0 && distance(g.P, light.position_type.xyz) > radius) discard;
    vec3 d, s;
    surface_light(light, g.P, g.N, normalize(u_eye - g.P), g.r, d, s);
    // Shadow mapping's second pass (notes 01 §8.5) scales both lights.
#if VARIANT_SHADOWS
    float lit = shadow_visibility(u_light_id, g.P, g.N);
#else
    float lit = 1.0;   // no light casts in this frame (src/frame/variant.rs)
#endif
    diffuse_light = vec4(lit * d, 1.0);
    specular_light = vec4(lit * s, 1.0);
}
