// The colour of a transparent fragment: lit like a forward fragment (the
// same Phong code, glsl/common/lighting.glsl), in the output's encoding, with
// alpha = the material's opacity. The sorted pass (transparency.frag) and the
// order-independent ones (weighted_blended.frag, depth_peeling.frag) share it.
#include "common/lighting.glsl"
#include "common/shadow.glsl"
#include "common/normals.glsl"
#include "common/material.glsl"
#include "common/lighting_output.glsl"
#include "common/alpha_test.glsl"

in vec3 v_position;
in vec3 v_normal;
#include "common/surface_in.glsl"
#include "common/bump_mapping.glsl"

uniform int u_light_count;
uniform vec3 u_eye;
uniform vec3 u_ambient;
uniform float u_opacity;

vec4 transparent_color() {
    vec2 uv = surface_uv();
    // A cut-out that is also see-through (an MTL's map_d with d < 1).
    alpha_test(material_alpha(uv));
    vec3 N = bumped_normal(safe_normal(v_normal, v_position), uv);
    // A back face (the far wall of a glass sphere) faces the eye from inside.
    if (!gl_FrontFacing) N = -N;
    vec3 V = normalize(u_eye - v_position);
    vec3 kd = material_diffuse(uv) * surface_color();
    vec3 ks = material_specular() * material_specular_map(uv);
    Reflectance r = material_reflectance();
    material_metal_rough_at(uv, ks, r);
    vec3 c = u_ambient * kd * material_occlusion(uv) + material_emission(uv);
    for (int i = 0; i < u_light_count; ++i) {
        if (casts_shadow(i)) continue;   // in the loop below
        c += surface_shade(u_lights[i], v_position, N, V, kd, ks, r);
    }
    // The lights that cast, with shadow mapping's second pass (notes 01
    // §8.5): how much of light i reaches here.
    for (int k = 0; k < MAX_CASTERS; ++k) {
        int i = caster(k);
        if (i < 0) break;
        float lit = shadow_visibility(i, v_position, N);
        c += lit * surface_shade(u_lights[i], v_position, N, V, kd, ks, r);
    }
    return vec4(output_color(c).rgb, u_opacity);
}
