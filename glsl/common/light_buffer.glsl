// The lights as a buffer texture (tiled shading, the far field): four
// RGBA32F texels a light, the std140 `Light` of common/lighting.glsl, as
// src/frame/lights.rs packs it. A uniform block stops at 256 lights on the
// smallest GL 3.3; a buffer texture holds 16384 texels even there.
// With VARIANT_LIGHT_HALVES the same 16 values come as halves packed two to
// a uint in RGBA32UI texels (src/frame/light_halves.rs): 1, all of them in
// two texels; 2, the position as floats and the rest halves in three.
#include "common/half.glsl"

#if defined(VARIANT_LIGHT_HALVES) && VARIANT_LIGHT_HALVES != 0
uniform usamplerBuffer u_light_data;
#else
uniform samplerBuffer u_light_data;
#endif

Light light_at(int i) {
#ifdef VARIANT_LIGHT_BLOCK
#if VARIANT_LIGHT_BLOCK
    // A lighting variant whose lights all fit in the Lights block reads them
    // there: a plain load, where a texelFetch goes through the sampler
    // (src/frame/variant.rs, render.light_block).
    return u_lights[i];
#endif
#endif
    Light l;
#if defined(VARIANT_LIGHT_HALVES) && VARIANT_LIGHT_HALVES == 1
    uvec4 a = texelFetch(u_light_data, 2 * i);
    uvec4 b = texelFetch(u_light_data, 2 * i + 1);
    l.position_type = unpack_half4(a.x, a.y);
    l.direction_radius = unpack_half4(a.z, a.w);
    l.color_cos_outer = unpack_half4(b.x, b.y);
    l.atten_cos_inner = unpack_half4(b.z, b.w);
#elif defined(VARIANT_LIGHT_HALVES) && VARIANT_LIGHT_HALVES == 2
    // Words: position x, y, z (float bits); then halves in pairs: (type,
    // direction.x) (direction.y, direction.z) (radius, red) (green, blue)
    // (cos outer, kc) (kl, kq) (cos inner, -).
    uvec4 a = texelFetch(u_light_data, 3 * i);
    uvec4 b = texelFetch(u_light_data, 3 * i + 1);
    uvec2 c = texelFetch(u_light_data, 3 * i + 2).xy;
    vec2 type_dx = unpack_half2(a.w);
    vec4 d_r_red = unpack_half4(b.x, b.y);
    vec4 gb_outer_kc = unpack_half4(b.z, b.w);
    vec4 kl_kq_inner = unpack_half4(c.x, c.y);
    l.position_type = vec4(uintBitsToFloat(a.xyz), type_dx.x);
    l.direction_radius = vec4(type_dx.y, d_r_red.xyz);
    l.color_cos_outer = vec4(d_r_red.w, gb_outer_kc.xyz);
    l.atten_cos_inner = vec4(gb_outer_kc.w, kl_kq_inner.xyz);
#else
    l.position_type = texelFetch(u_light_data, 4 * i);
    l.direction_radius = texelFetch(u_light_data, 4 * i + 1);
    l.color_cos_outer = texelFetch(u_light_data, 4 * i + 2);
    l.atten_cos_inner = texelFetch(u_light_data, 4 * i + 3);
#endif
    return l;
}
