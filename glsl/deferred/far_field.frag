#version 330 core
// The far-field pass (src/techniques/deferred/far_field.rs): one fragment
// per k x k pixels. Each reads the G-buffer at its block's centre and sums
// the far part of every light there (common/far_field.glsl), diffuse and
// specular apart, so that each pixel multiplies by its own material. With
// FAR_FIELD_SH the diffuse part is stored as spherical harmonics of the
// incoming light instead (common/far_field_sh.glsl), for any normal.
#include "common/lighting.glsl"
#include "common/shadow.glsl"
#include "common/gbuffer_read.glsl"
#include "common/light_buffer.glsl"
#include "common/far_field.glsl"
#ifdef FAR_FIELD_SH
#include "common/far_field_sh.glsl"
layout(location = 0) out vec4 far_out[SH_ATTACHMENTS];
#else
layout(location = 0) out vec4 far_diffuse;
layout(location = 1) out vec4 far_specular;
// With far lists (u_far_radius > 0): the coarse part, order-1 harmonics'
// 12 floats then its specular light and C (far_lists.rs).
layout(location = 2) out vec4 far_coarse_out[4];
#endif

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy) - ivec2(u_viewport.xy) / u_far_scale;
    Surface s = read_geometry_texel(far_sample_texel(t));
    vec3 d = vec3(0.0);
    vec3 sp = vec3(0.0);
    vec3 V = normalize(u_eye - s.P);
#ifdef FAR_FIELD_SH
    vec3 c[9];
    float total = 0.0;
    for (int j = 0; j < 9; ++j) c[j] = vec3(0.0);
    if (s.depth < 1.0) far_sh(s, V, c, sp, total);
    vec4 att[SH_ATTACHMENTS];
    sh_pack(c, sp, total, att);
#ifdef FAR_FIELD_BOUND
    // The bound's terms instead (render.far_field_bound): attachment 0 the
    // harmonics', 2 and 3 the specular interpolation's.
    for (int k = 0; k < SH_ATTACHMENTS; ++k) att[k] = vec4(0.0);
    if (s.depth < 1.0) {
        far_sh_bound_terms(s, total, c, att[0]);
        far_bound_terms(s, V, vec3(0.0), sp, far_support_radius(t, s), att[2], att[3]);
    }
#endif
    for (int k = 0; k < SH_ATTACHMENTS; ++k) far_out[k] = att[k];
#else
    for (int k = 0; k < 4; ++k) far_coarse_out[k] = vec4(0.0);
    if (u_far_radius > 0.0 && s.depth < 1.0) {
        vec3 c[4];
        vec3 cs;
        float total;
        far_coarse(s, V, d, sp, c, cs, total);
        far_coarse_out[0] = vec4(c[0], c[1].r);
        far_coarse_out[1] = vec4(c[1].gb, c[2].rg);
        far_coarse_out[2] = vec4(c[2].b, c[3]);
        far_coarse_out[3] = vec4(cs, total);
    } else if (s.depth < 1.0) {
        far_light(s, V, d, sp);
    }
    far_diffuse = vec4(d, 1.0);
    far_specular = vec4(sp, 1.0);
#ifdef FAR_FIELD_BOUND
    // The bound's terms instead (render.far_field_bound).
    if (s.depth < 1.0) {
        far_bound_terms(s, V, d, sp, far_support_radius(t, s), far_diffuse, far_specular);
        if (u_far_radius > 0.0) far_coarse_out[0] = far_coarse_bound_terms(s);
    } else {
        far_diffuse = vec4(0.0);
        far_specular = vec4(0.0);
    }
#endif
#endif
}
