#version 330 core
// Forward rendering (notes 04): for every fragment, for every light, shade.
#include "common/lighting.glsl"
#include "common/shadow.glsl"
#include "common/normals.glsl"
#include "common/material.glsl"
#include "common/alpha_test.glsl"
#include "common/lighting_output.glsl"
#include "common/environment.glsl"
#include "common/image_based_lighting.glsl"
#include "lighting/ltc_area_lights.glsl"
#include "lighting/area_light_reference.glsl"

in vec3 v_position;
in vec3 v_normal;
#include "common/surface_in.glsl"
#include "common/bump_mapping.glsl"

uniform int u_light_count;
uniform vec3 u_eye;
uniform vec3 u_ambient;
uniform bool u_has_light_map;
uniform sampler2D u_light_map;   // unit::LIGHT_MAP: linear RGB, RGBA16F

out vec4 frag_color;

void main() {
    vec2 uv = surface_uv();
    alpha_test(material_alpha(uv));
    vec3 N = bumped_normal(safe_normal(v_normal, v_position), uv);
    vec3 V = normalize(u_eye - v_position);
    vec3 kd = material_diffuse(uv) * surface_color();
    vec3 ks = material_specular() * material_specular_map(uv);
    Reflectance r = material_reflectance();
    material_metal_rough_at(uv, ks, r);
    // Static lighting (notes 01 §8.2): the diffuse light baked when the
    // scene loaded, read over the mesh's own uvs; no light loop.
    if (u_has_light_map) {
        vec2 mesh_uv = (uv - u_uv_transform.zw) / u_uv_transform.xy;
        frag_color = output_color(kd * (u_ambient + texture(u_light_map, mesh_uv).rgb) + material_emission(uv));
        return;
    }
    // u_ambient kd without render.ibl; the material's occlusion map scales it.
    vec3 c = ibl_ambient(u_ambient, N, V, kd, ks, r) * material_occlusion(uv) + material_emission(uv);
    for (int i = 0; i < u_light_count; ++i) {
#if VARIANT_SHADOWS
        if (casts_shadow(i)) continue;   // in the loop below
#endif
        c += surface_shade(u_lights[i], v_position, N, V, kd, ks, r);
    }
#if VARIANT_SHADOWS
    // The lights that cast, with shadow mapping's second pass (notes 01
    // §8.5): how much of light i reaches here.
    for (int k = 0; k < MAX_CASTERS; ++k) {
        int i = caster(k);
        if (i < 0) break;
        float lit = shadow_visibility(i, v_position, N);
        c += lit * surface_shade(u_lights[i], v_position, N, V, kd, ks, r);
    }
#endif
    // Area lights by linearly transformed cosines (lighting/ltc_area_lights.rs),
    // or by the quadrature they are measured against (render.area_light_reference).
    if (u_area_light_reference == 0) {
        c += ltc_area_lights(v_position, N, V, kd, ks, r);
    } else {
        c += area_light_reference(v_position, N, V, kd, ks, r);
    }
    c += environment_reflection(u_reflectivity, N, V);   // notes 03, Implementation
    frag_color = output_color(c);
}
