#version 330 core
// Area lights with linearly transformed cosines on the G-buffer paths
// (Heitz, Dupuy, Hill and Neubelt 2016; deferred/ltc_area_lights_deferred.rs):
// one full-screen triangle reads the pixel's surface from the G-buffer and
// adds the light of every area light to the lighting pass's target with
// GL_ONE, GL_ONE. The formula is forward's, lighting/ltc_area_lights.glsl.
//
// Deferred shading, light volumes and tiled shading: the shaded light,
// kd D + ks S, from the full G-buffer. The light pre-pass (LIGHT_PREPASS):
// from the thin G-buffer (normal, shininess or the microfacet triple,
// depth), the diffuse light D and the specular light S apart, without the
// material, which the combine pass applies.
#include "common/gbuffer_read.glsl"
#include "lighting/ltc_area_lights.glsl"
uniform vec3 u_eye;
#ifdef LIGHT_PREPASS
layout(location = 0) out vec4 diffuse_light;
layout(location = 1) out vec4 specular_light;
#else
out vec4 light_out;
#endif

void main() {
#ifdef LIGHT_PREPASS
    Surface s = read_geometry_texel(ivec2(gl_FragCoord.xy));
#else
    Surface s = read_gbuffer(gbuffer_uv());
#endif
    if (s.depth == 1.0) discard;   // background: no surface here
    vec3 V = normalize(u_eye - s.P);
#ifdef LIGHT_PREPASS
    vec3 D, S;
    ltc_area_light_parts(s.P, s.N, V, s.r, D, S);
    diffuse_light = vec4(D, 0.0);
    specular_light = vec4(S, 0.0);
#else
    light_out = vec4(ltc_area_lights(s.P, s.N, V, s.kd, s.ks, s.r), 0.0);
#endif
}
