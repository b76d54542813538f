// The lights as a buffer texture (tiled shading, the far field): four
// RGBA32F texels a light, the std140 `Light` of common/lighting.glsl, as
// src/frame/lights.rs packs it. A uniform block stops at 256 lights on the
// smallest GL 3.3; a buffer texture holds 16384 texels even there.
uniform samplerBuffer u_light_data;

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
    l.position_type = texelFetch(u_light_data, 4 * i);
    l.direction_radius = texelFetch(u_light_data, 4 * i + 1);
    l.color_cos_outer = texelFetch(u_light_data, 4 * i + 2);
    l.atten_cos_inner = texelFetch(u_light_data, 4 * i + 3);
    return l;
}
