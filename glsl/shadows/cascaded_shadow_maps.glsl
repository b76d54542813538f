// Cascaded shadow maps, the lookup (Engel 2006, "Cascaded Shadow Maps",
// ShaderX5; Dimitrov 2007, NVIDIA; src/techniques/shadows/cascaded_shadow_maps.rs):
// pick the cascade whose slice of the camera's depth range holds the point,
// compare against that layer of the sampler2DArrayShadow (the "specialised
// sampler" of notes 01 §8.5 on a GL_TEXTURE_2D_ARRAY), and across the last
// `blend` of a cascade's range mix into the next one, so that the change of
// resolution at a split leaves no seam.
//
// Included by common/shadow.glsl; only a program whose variant has
// cascades compiles it (src/frame/variant.rs), and the general one.

#ifndef VARIANT_CASCADES
#define VARIANT_CASCADES 1
#endif
#define SHADOW_CASCADED 3

#if VARIANT_CASCADES
#include "shadows/cascade_block.glsl"

uniform sampler2DArrayShadow u_shadow_cascades;   // UNIT_CASCADES

// PCF on one layer (the kernels of pcf_2d): c = (u, v, layer, reference depth).
float pcf_cascade(vec4 c, int kernel, float texel) {
    if (kernel == PCF_NONE || kernel == PCF_HARDWARE) return texture(u_shadow_cascades, c);
    float sum = 0.0;
    if (kernel == PCF_POISSON) {
        for (int i = 0; i < 16; ++i)
            sum += texture(u_shadow_cascades, vec4(c.xy + POISSON[i] * 2.5 * texel, c.zw));
        return sum / 16.0;
    }
    int r = kernel == PCF_3X3 ? 1 : 2;
    for (int y = -r; y <= r; ++y)
        for (int x = -r; x <= r; ++x)
            sum += texture(u_shadow_cascades, vec4(c.xy + vec2(x, y) * texel, c.zw));
    return sum / float((2 * r + 1) * (2 * r + 1));
}

// Cascade k's answer at P: the biases of shadow_visibility, the normal
// offset in this cascade's texels.
float cascade_visibility(int k, vec3 P, vec3 N, vec3 L, vec4 b) {
    vec3 Q = P + N * (b.y * u_cascade_range[k].z) + L * b.x;
    vec3 c = (u_cascade_matrix[k] * vec4(Q, 1.0)).xyz;   // orthographic: w = 1
    c.z = min(c.z, 1.0);
    return pcf_cascade(vec4(c.xy, float(k), c.z), int(b.z), 1.0 / b.w);
}

// How much of the directional light (towards L) reaches P, normal N.
float cascaded_shadow(vec3 P, vec3 N, vec3 L, vec4 b) {
    int count = int(u_cascade_eye.w);
    if (count < 1) return 1.0;
    float z = cascade_depth(P);
    int k = cascade_of(z);
    float lit = cascade_visibility(k, P, N, L, b);
    // The blend band: the last `blend` of cascade k's range fades into k + 1,
    // reaching it exactly at the split.
    float t = cascade_band(k, z);
    if (t < 1.0) {
        lit = mix(cascade_visibility(k + 1, P, N, L, b), lit, t);
    }
    g_cascade_tint = cascade_tint_at(P);
    return lit;
}
#endif
