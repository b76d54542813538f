#version 330 core
// The far-field pass (src/techniques/deferred/far_field.rs): one fragment
// per k x k pixels. Each reads the G-buffer at its block's centre and sums
// the far part of every light there (common/far_field.glsl), diffuse and
// specular apart, so that each pixel multiplies by its own material.
#include "common/lighting.glsl"
#include "common/shadow.glsl"
#include "common/gbuffer_read.glsl"
#include "common/light_buffer.glsl"
#include "common/far_field.glsl"
layout(location = 0) out vec4 far_diffuse;
layout(location = 1) out vec4 far_specular;

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy) - ivec2(u_viewport.xy) / u_far_scale;
    Surface s = read_geometry_texel(far_sample_texel(t));
    vec3 d = vec3(0.0);
    vec3 sp = vec3(0.0);
    vec3 V = normalize(u_eye - s.P);
    if (s.depth < 1.0) far_light(s, V, d, sp);
    far_diffuse = vec4(d, 1.0);
    far_specular = vec4(sp, 1.0);
#ifdef FAR_FIELD_BOUND
    // The bound's terms instead (render.far_field_bound).
    if (s.depth < 1.0) {
        far_bound_terms(s, V, d, sp, far_support_radius(t, s), far_diffuse, far_specular);
    } else {
        far_diffuse = vec4(0.0);
        far_specular = vec4(0.0);
    }
#endif
}
