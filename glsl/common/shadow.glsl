// Shadow mapping, the second pass (notes 01 §8.5): "the shadow matrix is
// passed to shaders ... in the fragment shader compare the z component of
// the fragment to the value from the shadow buffer. If z <= light depth the
// fragment is lit." The comparison is the "specialised sampler":
// sampler2DShadow / samplerCubeShadow on a texture whose
// GL_TEXTURE_COMPARE_MODE is GL_COMPARE_REF_TO_TEXTURE (src/frame/shadows.rs
// sets it, with GL_LEQUAL). texture() returns 1.0 (lit) or 0.0 (shadowed),
// or with GL_LINEAR the blend of four such results.
//
// Needs common/lighting.glsl (the Lights block) included first.

#define SHADOW_ORTHOGRAPHIC 0
#define SHADOW_PERSPECTIVE 1
#define SHADOW_CUBE 2

#define PCF_NONE 0
#define PCF_HARDWARE 1
#define PCF_3X3 2
#define PCF_5X5 3
#define PCF_POISSON 4

// std140, 96 bytes a map (src/frame/shadows.rs writes this layout).
struct ShadowMap {
    mat4 matrix;                 // bias * light projection * light view
    vec4 kind_texel_near_far;    // kind, texel size, near, far
    vec4 bias_offset_pcf_size;   // bias (world), normal offset (texels), kernel, resolution
};

layout(std140) uniform Shadows {
    ShadowMap u_shadows[8];          // 0-3: 2D maps, 4-7: cube maps
    ivec4 u_shadow_of[MAX_LIGHTS / 4 + 1];  // light i's map: [i / 4][i % 4], -1: none
    ivec4 u_casters[2];          // the lights with a map this frame, -1 after the last
};

#define MAX_CASTERS 8

// Whether light i has a shadow map this frame.
bool casts_shadow(int i) {
    return u_shadow_of[i / 4][i % 4] >= 0;
}

// The k-th light with a shadow map this frame (-1: no more). A shader that
// loops over many lights shades these in a loop of their own: the shadow
// lookup below, with its filter loops and its eight samplers, costs far
// more than a light's Phong term even where it returns at once (a
// software rasteriser runs it for every light), so the lights without a
// map skip it.
int caster(int k) {
    return u_casters[k / 4][k % 4];
}

// GLSL 3.30 indexes sampler arrays only with constants: shadow_2d and
// shadow_cube pick the sampler with an if per slot.
uniform sampler2DShadow u_shadow_map[4];
uniform samplerCubeShadow u_shadow_cube[4];

// Sixteen points of a Poisson disc in the unit circle.
const vec2 POISSON[16] = vec2[](
    vec2(-0.94201624, -0.39906216), vec2(0.94558609, -0.76890725),
    vec2(-0.09418410, -0.92938870), vec2(0.34495938, 0.29387760),
    vec2(-0.91588581, 0.45771432), vec2(-0.81544232, -0.87912464),
    vec2(-0.38277543, 0.27676845), vec2(0.97484398, 0.75648379),
    vec2(0.44323325, -0.97511554), vec2(0.53742981, -0.47373420),
    vec2(-0.26496911, -0.41893023), vec2(0.79197514, 0.19090188),
    vec2(-0.24188840, 0.99706507), vec2(-0.81409955, 0.91437590),
    vec2(0.19984126, 0.78641367), vec2(0.14383161, -0.14100790));

// Percentage-closer filtering (notes 01 §8.5.1, aliasing): average the
// comparisons at texel offsets around c.xy; `texel` is one texel in uv.
float pcf_2d(sampler2DShadow map, vec3 c, int kernel, float texel) {
    if (kernel == PCF_NONE || kernel == PCF_HARDWARE) return texture(map, c);
    float sum = 0.0;
#if VARIANT_PCF_POISSON
    if (kernel == PCF_POISSON) {
        for (int i = 0; i < 16; ++i)
            sum += texture(map, vec3(c.xy + POISSON[i] * 2.5 * texel, c.z));
        return sum / 16.0;
    }
#endif
#if VARIANT_PCF_BOX
    int r = kernel == PCF_3X3 ? 1 : 2;
    for (int y = -r; y <= r; ++y)
        for (int x = -r; x <= r; ++x)
            sum += texture(map, vec3(c.xy + vec2(x, y) * texel, c.z));
    return sum / float((2 * r + 1) * (2 * r + 1));
#else
    return texture(map, c);   // not reached: the frame has no box filter
#endif
}

// The same on a cube face: offsets across the face that d points into;
// `texel` is one texel at unit distance along the face's axis.
float pcf_cube(samplerCubeShadow map, vec3 d, float ref, int kernel, float texel) {
    if (kernel == PCF_NONE || kernel == PCF_HARDWARE) return texture(map, vec4(d, ref));
    vec3 a = abs(d);
    float major = max(a.x, max(a.y, a.z));
    vec3 u = a.x == major ? vec3(0, 1, 0) : vec3(1, 0, 0);
    vec3 v = a.z == major ? vec3(0, 1, 0) : vec3(0, 0, 1);
    float step = texel * major;
    float sum = 0.0;
#if VARIANT_PCF_POISSON
    if (kernel == PCF_POISSON) {
        for (int i = 0; i < 16; ++i) {
            vec2 o = POISSON[i] * 2.5 * step;
            sum += texture(map, vec4(d + o.x * u + o.y * v, ref));
        }
        return sum / 16.0;
    }
#endif
#if VARIANT_PCF_BOX
    int r = kernel == PCF_3X3 ? 1 : 2;
    for (int y = -r; y <= r; ++y)
        for (int x = -r; x <= r; ++x)
            sum += texture(map, vec4(d + (float(x) * u + float(y) * v) * step, ref));
    return sum / float((2 * r + 1) * (2 * r + 1));
#else
    return texture(map, vec4(d, ref));   // not reached: the frame has no box filter
#endif
}

// A lighting variant (src/frame/variant.rs) keeps only the slots its frame
// fills: VARIANT_SHADOW_2D and VARIANT_SHADOW_CUBE maps, from slot 0 on.
float shadow_2d(int i, vec3 c, int kernel, float texel) {
#if VARIANT_SHADOW_2D == 0
    return 1.0;
#else
#if VARIANT_SHADOW_2D > 1
    if (i == 0) return pcf_2d(u_shadow_map[0], c, kernel, texel);
#endif
#if VARIANT_SHADOW_2D > 2
    if (i == 1) return pcf_2d(u_shadow_map[1], c, kernel, texel);
#endif
#if VARIANT_SHADOW_2D > 3
    if (i == 2) return pcf_2d(u_shadow_map[2], c, kernel, texel);
#endif
    return pcf_2d(u_shadow_map[VARIANT_SHADOW_2D - 1], c, kernel, texel);
#endif
}

float shadow_cube(int i, vec3 d, float ref, int kernel, float texel) {
#if VARIANT_SHADOW_CUBE == 0
    return 1.0;
#else
#if VARIANT_SHADOW_CUBE > 1
    if (i == 0) return pcf_cube(u_shadow_cube[0], d, ref, kernel, texel);
#endif
#if VARIANT_SHADOW_CUBE > 2
    if (i == 1) return pcf_cube(u_shadow_cube[1], d, ref, kernel, texel);
#endif
#if VARIANT_SHADOW_CUBE > 3
    if (i == 2) return pcf_cube(u_shadow_cube[2], d, ref, kernel, texel);
#endif
    return pcf_cube(u_shadow_cube[VARIANT_SHADOW_CUBE - 1], d, ref, kernel, texel);
#endif
}

// A directional light's cascades (cascaded_shadow).
#include "shadows/cascaded_shadow_maps.glsl"

// How much of light `light_index` reaches P (normal N): 1 lit, 0 shadowed.
float shadow_visibility(int light_index, vec3 P, vec3 N) {
    int slot = u_shadow_of[light_index / 4][light_index % 4];
    if (slot < 0) return 1.0;
    ShadowMap m = u_shadows[slot];
    Light light = u_lights[light_index];
    int kind = int(m.kind_texel_near_far.x);
    float texel = m.kind_texel_near_far.y;
#if VARIANT_CASCADES
    if (kind == SHADOW_CASCADED)
        return cascaded_shadow(P, N, -light.direction_radius.xyz, m.bias_offset_pcf_size);
#endif
    vec3 from_light = P - light.position_type.xyz;
    vec3 L = kind == SHADOW_ORTHOGRAPHIC ? -light.direction_radius.xyz : -normalize(from_light);
    // A texel's size in world units at P: constant for an orthographic map,
    // growing with the distance from the light for a perspective or cube map.
    vec3 a = abs(from_light);
    float world_texel = kind == SHADOW_ORTHOGRAPHIC ? texel
        : kind == SHADOW_PERSPECTIVE ? texel * dot(from_light, light.direction_radius.xyz)
        : texel * max(a.x, max(a.y, a.z));
    // Acne (notes 01 §8.5.1): "offset the vertices used in the shadow map
    // depth comparison, either towards the camera or along their normal":
    // here towards the light by `bias` world units, and along the normal by
    // `normal offset` texels.
    vec4 b = m.bias_offset_pcf_size;
    vec3 Q = P + N * (b.y * world_texel) + L * b.x;
    int kernel = int(b.z);
    if (kind == SHADOW_CUBE) {
        // The cube stores the distance to the light / far, on every face.
        vec3 d = Q - light.position_type.xyz;
        float ref = min(length(d) / m.kind_texel_near_far.w, 1.0);
        return shadow_cube(slot - 4, d, ref, kernel, texel);
    }
    // The shadow matrix takes P to the map's texture space (the bias matrix
    // after the light's projection); then the perspective divide.
    vec4 s = m.matrix * vec4(Q, 1.0);
    if (s.w <= 0.0) return 1.0;   // behind a spot light: its cone is dark there anyway
    vec3 c = s.xyz / s.w;
    c.z = min(c.z, 1.0);          // beyond the far plane: only a stored 1.0 (nothing) is lit
    return shadow_2d(slot, c, kernel, 1.0 / b.w);
}
