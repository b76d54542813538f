// The material of the object being drawn: Phong (notes 01 §8.3) or, with
// u_microfacet, notes 03's microfacet triple (alpha, eta, k_s).
#include "common/reflectance.glsl"
uniform vec3 u_diffuse;
uniform vec3 u_specular;
uniform float u_shininess;
uniform float u_reflectivity;   // the environment it mirrors, 0..=1 (common/environment.glsl)
uniform bool u_microfacet;
uniform float u_microfacet_alpha;
uniform float u_microfacet_eta;
uniform float u_microfacet_k_s;
uniform bool u_has_diffuse_texture;
uniform sampler2D u_diffuse_texture;   // sRGB texture: sampling returns linear
uniform bool u_has_specular_map;
uniform sampler2D u_specular_map;      // unit::SPECULAR_MAP, linear data

vec3 material_diffuse(vec2 uv) {
    return u_has_diffuse_texture ? u_diffuse * texture(u_diffuse_texture, uv).rgb : u_diffuse;
}

// The texture's alpha, what the alpha test reads (1 without a texture).
float material_alpha(vec2 uv) {
    return u_has_diffuse_texture ? texture(u_diffuse_texture, uv).a : 1.0;
}

// What the specular light is multiplied by: the Phong specular colour, or
// the microfacet k_s (a dielectric's highlight is white).
vec3 material_specular() {
    return u_microfacet ? vec3(u_microfacet_k_s) : u_specular;
}

// The specular map's weight at uv (an MTL's map_Ks, LearnOpenGL's
// "lighting maps"): it multiplies a Phong material's specular colour; 1
// without a map, and for a microfacet material (whose k_s the G-buffer
// stores apart).
vec3 material_specular_map(vec2 uv) {
    return u_has_specular_map && !u_microfacet ? texture(u_specular_map, uv).rgb : vec3(1.0);
}

Reflectance material_reflectance() {
    return Reflectance(u_microfacet, u_shininess, u_microfacet_alpha, u_microfacet_eta);
}
