#version 330 core
// Tiled / clustered deferred shading (src/techniques/deferred/tiled_shading.rs):
// one full-screen pass; each pixel shades the lights with no radius and
// then the lights binned into its cluster (its screen tile, its depth
// slice) on the CPU (src/frame/clusters.rs). The sum is made here, in
// f32, and written once.
// R32UI: per cluster, two texels (offset, count) into the light numbers,
// which follow from texel u_index_base; the first u_global_count of those
// are every pixel's. With far lists (common/far_field.glsl), each cluster's
// far (offset, count) from texel u_far_table, its numbers from u_far_index_base.
uniform usamplerBuffer u_clusters;
#define TILED_SHADING 1
#include "common/lighting.glsl"
#include "common/shadow.glsl"
#include "common/gbuffer_read.glsl"
#include "common/light_buffer.glsl"
#ifdef FAR_FIELD
#include "common/far_field.glsl"
#endif
#ifdef FAR_FIELD_SH
#include "common/far_field_sh.glsl"
#endif
uniform int u_index_base;
uniform int u_global_count;
uniform ivec3 u_grid;                  // tiles across, tiles up, depth slices
uniform int u_tile_size;               // pixels
uniform vec2 u_slice_scale_bias;       // slice = floor(ln(depth) * scale + bias)
uniform mat4 u_view;                   // world to eye space (depth = -z)
#ifndef FAR_FIELD
uniform vec3 u_eye;                    // (common/far_field.glsl declares it too)
#endif
out vec4 light_out;

// Light i at the surface, as the light-volume shader shades it: nothing
// beyond the light's radius (a listed light may not reach every pixel of
// its cluster: the binning is conservative).
vec3 shade(int i, Surface s, vec3 V) {
    Light light = light_at(i);
    float radius = light.direction_radius.w;
    if (radius >= 0.0 && distance(s.P, light.position_type.xyz) > radius) return vec3(0.0);
    return surface_shade(light, s.P, s.N, V, s.kd, s.ks, s.r);
}

// A listed light's share of this pixel: all of it up to its radius, or,
// with the far field, its near part (the far part comes from far_field).
vec3 shade_listed(int i, Surface s, vec3 V) {
#ifdef FAR_FIELD
    Light light = light_at(i);
    float w = near_weight(distance(s.P, light.position_type.xyz), light.direction_radius.w);
    if (w <= 0.0) return vec3(0.0);
    return w * surface_shade(light, s.P, s.N, V, s.kd, s.ks, s.r);
#else
    return shade(i, s, V);
#endif
}

void main() {
    vec2 uv = gbuffer_uv();
    Surface s = read_gbuffer(uv);
    if (s.depth == 1.0) discard;   // background: no surface here
    vec3 V = normalize(u_eye - s.P);
    vec3 sum = vec3(0.0);
    // The lights with a shadow map (at most eight), with shadow mapping's
    // second pass (notes 01 §8.5). Only this loop calls shadow_visibility:
    // besides its cost (common/shadow.glsl), its filter loops, run for
    // every light of a long cluster list, would count towards llvmpipe's
    // 65535 loop iterations per shader invocation (nested loops share the
    // count) and cut the list short.
#if VARIANT_SHADOWS
    for (int k = 0; k < MAX_CASTERS; ++k) {
        int i = caster(k);
        if (i < 0) break;
        sum += shadow_visibility(i, s.P, s.N) * shade(i, s, V);
    }
#endif
    // The global list: the lights with no radius.
    for (int k = 0; k < u_global_count; ++k)
        sum += shade(int(texelFetch(u_clusters, u_index_base + k).r), s, V);

    // This pixel's cluster: its tile, and its slice from its eye-space depth.
    ivec2 tile = min(ivec2(gl_FragCoord.xy - u_viewport.xy) / u_tile_size, u_grid.xy - 1);
    float depth = -(u_view * vec4(s.P, 1.0)).z;
    float slice_f = floor(log(max(depth, 1e-30)) * u_slice_scale_bias.x + u_slice_scale_bias.y);
    int slice = int(clamp(slice_f, 0.0, float(u_grid.z - 1)));
    int cluster = (slice * u_grid.y + tile.y) * u_grid.x + tile.x;
    int offset = u_index_base + int(texelFetch(u_clusters, 2 * cluster).r);
    int count = int(texelFetch(u_clusters, 2 * cluster + 1).r);
    for (int k = 0; k < count; ++k)
        sum += shade_listed(int(texelFetch(u_clusters, offset + k).r), s, V);
#ifdef FAR_FIELD
    g_cluster = cluster;
#endif
#if defined(FAR_FIELD_SH)
    sum += far_field_sh(s, V, distance(u_eye, s.P));
#elif defined(FAR_FIELD)
    sum += far_field(s, V, distance(u_eye, s.P));
#endif
#if defined(FAR_FIELD_BOUND) && defined(FAR_FIELD_SH)
    // Instead of the light: the far field's error bound at this pixel.
    light_out = vec4(vec3(far_field_sh_bound(s, distance(u_eye, s.P))), 1.0);
    return;
#elif defined(FAR_FIELD_BOUND)
    light_out = vec4(vec3(far_field_bound(s, distance(u_eye, s.P))), 1.0);
    return;
#endif
    light_out = vec4(sum, 1.0);
}
