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
#define MAX_CASCADES 8

// std140, src/frame/shadows/cascades.rs writes this layout.
layout(std140) uniform Cascades {
    mat4 u_cascade_matrix[MAX_CASCADES];  // bias * projection * view of each cascade
    vec4 u_cascade_range[MAX_CASCADES];   // near, far (view depth), texel (world), 0
    vec4 u_cascade_eye;                   // the camera's eye, w: the cascade count
    vec4 u_cascade_forward;               // its unit forward axis, w: the blend band
    vec4 u_cascade_flags;                 // x: tint each cascade (debugging)
};

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

// The cascade colours (shadow.cascade_colors): the last lookup's cascade
// tint, which output_color (common/lighting_output.glsl) multiplies into
// the pixel when the shader includes this file before that one (the forward
// and transparent passes; the deferred paths add light in passes of their
// own, and their composite shows no tint).
#define CASCADE_TINT 1
vec3 g_cascade_tint = vec3(1.0);

// The tint of cascade k when u_cascade_flags.x is set (else white).
vec3 cascade_tint(int k) {
    const vec3 TINTS[MAX_CASCADES] = vec3[](
        vec3(1.0, 0.45, 0.45), vec3(0.45, 1.0, 0.45), vec3(0.5, 0.6, 1.0), vec3(1.0, 1.0, 0.4),
        vec3(1.0, 0.5, 1.0), vec3(0.4, 1.0, 1.0), vec3(1.0, 0.7, 0.35), vec3(0.75, 0.75, 0.75));
    return u_cascade_flags.x > 0.5 ? TINTS[k] : vec3(1.0);
}

// The cascade whose slice holds view depth z (the last past the far split).
int cascade_of(float z) {
    int count = int(u_cascade_eye.w);
    int k = 0;
    while (k < count - 1 && z > u_cascade_range[k].y) ++k;
    return k;
}

// How much of the directional light (towards L) reaches P, normal N.
float cascaded_shadow(vec3 P, vec3 N, vec3 L, vec4 b) {
    int count = int(u_cascade_eye.w);
    if (count < 1) return 1.0;
    float z = dot(P - u_cascade_eye.xyz, u_cascade_forward.xyz);
    int k = cascade_of(z);
    float lit = cascade_visibility(k, P, N, L, b);
    // The blend band: the last `blend` of cascade k's range fades into k + 1,
    // reaching it exactly at the split.
    float band = u_cascade_forward.w * (u_cascade_range[k].y - u_cascade_range[k].x);
    float to_split = u_cascade_range[k].y - z;
    if (k + 1 < count && band > 0.0 && to_split < band) {
        float t = clamp(to_split / band, 0.0, 1.0);
        lit = mix(cascade_visibility(k + 1, P, N, L, b), lit, t);
        g_cascade_tint = mix(cascade_tint(k + 1), cascade_tint(k), t);
    } else {
        g_cascade_tint = cascade_tint(k);
    }
    return lit;
}
#endif
