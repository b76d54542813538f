// Image-based lighting as the ambient term (Karis 2013, "Real Shading in
// Unreal Engine 4", Image-Based Lighting; src/techniques/sky/image_based_lighting.rs
// makes the three textures, src/frame/image_based_lighting.rs binds them).
// With render.ibl on, a surface's ambient light is
//
//   k_d E(N) / pi                                  the irradiance cube map
//   + k_s prefiltered(R, alpha) (F0 A + B)         ApproximateSpecularIBL
//
// R = reflect(-V, N); the prefiltered level is sqrt(alpha) (levels - 1),
// (A, B) = table(N.V, sqrt(alpha)), F0 = ((eta - 1) / (eta + 1))^2. A Phong
// material takes the diffuse term only. alpha above 1 reads as 1.
// src/lighting/image_based_lighting.rs is the CPU twin.
#ifndef IMAGE_BASED_LIGHTING_GLSL
#define IMAGE_BASED_LIGHTING_GLSL
#include "common/reflectance.glsl"
uniform bool u_has_ibl;              // false: the constant ambient
uniform samplerCube u_ibl_irradiance;
uniform samplerCube u_ibl_prefiltered;
uniform sampler2D u_ibl_brdf;
uniform float u_ibl_levels;          // the prefiltered map's levels

// The diffuse light, E(N) / pi: k_d times it is the diffuse term.
vec3 ibl_diffuse(vec3 N) {
    return texture(u_ibl_irradiance, N).rgb;
}

// ApproximateSpecularIBL: the specular light for k_s = 1.
vec3 ibl_specular(vec3 N, vec3 V, Reflectance r) {
    if (!r.microfacet) return vec3(0.0);
    float roughness = sqrt(clamp(r.alpha, 0.0, 1.0));
    float n_dot_v = clamp(dot(N, V), 0.0, 1.0);
    vec3 R = 2.0 * dot(V, N) * N - V;
    vec3 prefiltered = textureLod(u_ibl_prefiltered, R, roughness * (u_ibl_levels - 1.0)).rgb;
    vec2 ab = texture(u_ibl_brdf, vec2(n_dot_v, roughness)).rg;
    float f = (r.eta - 1.0) / (r.eta + 1.0);
    return prefiltered * (f * f * ab.x + ab.y);
}

// The ambient light of a surface: u_ambient k_d without IBL.
vec3 ibl_ambient(vec3 ambient, vec3 N, vec3 V, vec3 kd, vec3 ks, Reflectance r) {
    if (!u_has_ibl) return ambient * kd;
    return kd * ibl_diffuse(N) + ks * ibl_specular(N, V, r);
}
#endif
