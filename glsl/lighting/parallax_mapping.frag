#version 330 core
// Parallax mapping (LearnOpenGL, 5.advanced_lighting, "Parallax Mapping":
// parallax mapping, steep parallax mapping, parallax occlusion mapping) with
// self-shadowing (Tatarchuk 2006, "Dynamic parallax occlusion mapping with
// approximate soft shadows": a second ray, from the point the view ray hit
// toward the light). The forward pass's Phong shading (lighting/forward.frag)
// at the texture coordinates where the view ray meets the height field; each
// light's term times whether the relief lets it through.
#include "common/lighting.glsl"
#include "common/shadow.glsl"
#include "common/normals.glsl"
#include "common/material.glsl"
#include "common/alpha_test.glsl"
#include "common/lighting_output.glsl"
#include "common/environment.glsl"

in vec3 v_position;
in vec3 v_normal;
#include "common/surface_in.glsl"
#include "common/bump_mapping.glsl"

uniform int u_light_count;
uniform vec3 u_eye;
uniform vec3 u_ambient;
uniform sampler2D u_height_map;  // unit::HEIGHT_MAP: linear greyscale, white high
uniform float u_height_scale;    // the relief's depth, in texture uv units
uniform int u_parallax;          // 1 plain, 2 steep, 3 occlusion
uniform int u_layers;            // steep and occlusion: the layers a ray crosses
uniform bool u_self_shadow;
uniform bool u_show_uv;          // debug: fract(uv) in red and green, light 0 let through in blue

out vec4 frag_color;

#define PARALLAX_PLAIN 1
#define PARALLAX_STEEP 2

// LearnOpenGL samples a depth map (0 at the top); gloss stores heights (1
// at the top). Every sample reads with g, the gradients of the uv before any
// offset (dFdx, dFdy): texture() inside a loop with a data-dependent exit has
// undefined derivatives, and the offset uv's own would jump at every layer.
float depth_at(vec2 uv, vec4 g) {
    return 1.0 - textureGrad(u_height_map, uv, g.xy, g.zw).r;
}

// The view ray from the top of the relief at uv, direction -V (V in tangent
// space, z out of the surface): the uv where it meets the height field, and
// in hit_depth how deep (0 top, 1 bottom).
vec2 parallax_uv(vec2 uv, vec3 V, vec4 g, out float hit_depth) {
    vec2 P = V.xy / V.z * u_height_scale;   // the uv shift over the whole depth
    // 1. Parallax mapping: one shift, by the depth at the fragment.
    if (u_parallax == PARALLAX_PLAIN) {
        hit_depth = depth_at(uv, g);
        return uv - P * hit_depth;
    }
    // 2. Steep parallax mapping: step the ray down layer by layer until it
    // is below the surface.
    float layer_depth = 1.0 / float(u_layers);
    vec2 delta_uv = P * layer_depth;
    vec2 current_uv = uv;
    float current_layer = 0.0;
    float current_depth = depth_at(current_uv, g);
    for (int i = 0; i < u_layers && current_layer < current_depth; ++i) {
        current_uv -= delta_uv;
        current_depth = depth_at(current_uv, g);
        current_layer += layer_depth;
    }
    hit_depth = current_layer;
    if (u_parallax == PARALLAX_STEEP) return current_uv;
    // 3. Parallax occlusion mapping: the surface taken as a straight line
    // between the samples before and after the hit; where the ray crosses it.
    vec2 prev_uv = current_uv + delta_uv;
    float after = current_depth - current_layer;                // <= 0
    float before = depth_at(prev_uv, g) - current_layer + layer_depth; // > 0
    float weight = after - before < 0.0 ? after / (after - before) : 0.0;
    hit_depth = current_layer - weight * layer_depth;
    return prev_uv * weight + current_uv * (1.0 - weight);
}

// Self-shadowing: from the hit (uv, depth) toward the light L (tangent
// space), up through the layers to the top; 0 where the relief rises above
// the ray, 1 where the ray leaves the top unblocked. The ray starts one
// layer up: steep parallax's hit lies up to a layer below the surface.
float relief_light(vec2 uv, float depth, vec3 L, vec4 g) {
    if (L.z <= 0.0) return 0.0;   // below the surface's horizon
    float layer_depth = 1.0 / float(u_layers);
    vec2 delta_uv = L.xy / L.z * u_height_scale * layer_depth;
    float ray = depth - layer_depth;
    vec2 p = uv + delta_uv;
    for (int i = 0; i < u_layers && ray > 0.0; ++i) {
        if (depth_at(p, g) < ray) return 0.0;
        p += delta_uv;
        ray -= layer_depth;
    }
    return 1.0;
}

void main() {
    vec2 uv = surface_uv();
    vec4 g = vec4(dFdx(uv), dFdy(uv));
    vec3 N0 = safe_normal(v_normal, v_position);
    // The tangent frame (common/bump_mapping.glsl's, the axes flipped with
    // the uv transform): T along the texture's u, B along its v.
    vec3 T = v_tangent.xyz - N0 * dot(N0, v_tangent.xyz);
    bool framed = length(T) > 1e-12;
    T = framed ? normalize(T) : vec3(1.0, 0.0, 0.0);
    vec3 B = cross(N0, T) * v_tangent.w;
    T *= u_uv_transform.x < 0.0 ? -1.0 : 1.0;
    B *= u_uv_transform.y < 0.0 ? -1.0 : 1.0;
    mat3 to_tangent = transpose(mat3(T, B, N0));
    vec3 V = normalize(u_eye - v_position);
    vec3 V_t = to_tangent * V;
    float hit_depth = 0.0;
    if (framed && V_t.z > 1e-4) uv = parallax_uv(uv, V_t, g, hit_depth);

    alpha_test(material_alpha(uv));
    vec3 N = bumped_normal(N0, uv);
    vec3 kd = material_diffuse(uv) * surface_color();
    vec3 ks = material_specular() * material_specular_map(uv);
    Reflectance r = material_reflectance();
    vec3 c = u_ambient * kd;
    float shown = 1.0;   // light 0, for u_show_uv
    for (int i = 0; i < u_light_count; ++i) {
        vec3 L;
        float sin_sigma;
        light_factor(u_lights[i], v_position, L, sin_sigma);
        float lit = u_self_shadow && framed ? relief_light(uv, hit_depth, to_tangent * L, g) : 1.0;
        if (i == 0) shown = lit;
#if VARIANT_SHADOWS
        // Shadow mapping's second pass (notes 01 §8.5) for the lights that cast.
        if (casts_shadow(i)) lit *= shadow_visibility(i, v_position, N);
#endif
        c += lit * surface_shade(u_lights[i], v_position, N, V, kd, ks, r);
    }
    c += environment_reflection(u_reflectivity, N, V);   // notes 03, Implementation
    frag_color = u_show_uv ? vec4(fract(uv), shown, 1.0) : output_color(c);
}
