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
// A geometry pass built for a scene with no specular map, or no glTF maps
// and no emission (src/techniques/deferred/gbuffer.rs `MaterialVariant`),
// defines NO_SPECULAR_MAP or NO_PBR: the flag is then a constant false and
// the compiler drops the code behind it (llvmpipe runs a uniform branch's
// code even where the uniform is false).
#ifdef NO_SPECULAR_MAP
const bool u_has_specular_map = false;
#else
uniform bool u_has_specular_map;
#endif
uniform sampler2D u_specular_map;      // unit::SPECULAR_MAP, linear data

// glTF 2.0's maps (src/scene/gltf_material.rs, docs/gltf.md): with a
// metallic-roughness map, c_d and the microfacet triple are taken per
// texel from baseColor, metallic = metallicFactor B and roughness =
// roughnessFactor G; occlusion scales the ambient term; emission is added.
#ifdef NO_PBR
const bool u_pbr = false;
#else
uniform bool u_pbr;                    // false: none of the below (one uniform per draw)
#if defined(VARIANT_FORWARD_GLTF) && !VARIANT_FORWARD_GLTF
// A lighting variant whose frame has no glTF map or emission
// (src/frame/variant.rs forward_gltf): the code below folds away.
#define u_pbr false
#endif
#endif
uniform bool u_has_metal_rough_map;
uniform sampler2D u_metal_rough_map;   // unit::METAL_ROUGH_MAP, linear
uniform vec3 u_base_color;             // baseColorFactor.rgb
uniform vec2 u_metal_rough;            // metallicFactor, roughnessFactor
uniform bool u_has_occlusion_map;
uniform sampler2D u_occlusion_map;     // unit::OCCLUSION_MAP, linear R
uniform float u_occlusion_strength;
uniform vec3 u_emissive;               // emissiveFactor, linear
uniform bool u_has_emissive_map;
uniform sampler2D u_emissive_map;      // unit::EMISSIVE_MAP, sRGB

// baseColor at uv (with a metallic-roughness map): the factor times the texture.
vec3 material_base_color(vec2 uv) {
    return u_has_diffuse_texture ? u_base_color * texture(u_diffuse_texture, uv).rgb : u_base_color;
}

// (metallic, roughness) at uv.
vec2 material_metal_rough(vec2 uv) {
    return u_metal_rough * texture(u_metal_rough_map, uv).bg;
}

vec3 material_diffuse(vec2 uv) {
    if (u_pbr && u_has_metal_rough_map) {
        return material_base_color(uv) * (1.0 - material_metal_rough(uv).x);   // c_d
    }
    return u_has_diffuse_texture ? u_diffuse * texture(u_diffuse_texture, uv).rgb : u_diffuse;
}

// The microfacet triple (alpha, eta, k_s) at uv: the material's, or with a
// metallic-roughness map glTF's mapping per texel (the CPU twin:
// scene::gltf_material::microfacet):
//   F0 = 0.04 (1 - metallic) + lum(baseColor) metallic
//   eta = (1 + sqrt F0) / (1 - sqrt F0) in 1..=10, k_s = F0 / ((eta - 1) / (eta + 1))^2
//   alpha = roughness^2
vec3 material_triple(vec2 uv) {
    if (!(u_pbr && u_has_metal_rough_map)) {
        return vec3(u_microfacet_alpha, u_microfacet_eta, u_microfacet_k_s);
    }
    vec2 mr = material_metal_rough(uv);
    float lum = dot(material_base_color(uv), vec3(0.2126, 0.7152, 0.0722));
    float f0 = 0.04 * (1.0 - mr.x) + lum * mr.x;
    float r = sqrt(clamp(f0, 0.0, 0.999));
    float eta = clamp((1.0 + r) / (1.0 - r), 1.0, 10.0);
    float f0_eta = pow((eta - 1.0) / (eta + 1.0), 2.0);
    float k_s = f0_eta > 0.0 ? f0 / f0_eta : 0.0;
    return vec3(clamp(mr.y * mr.y, 1e-3, 1e3), eta, clamp(k_s, 0.0, 10.0));
}

// A metallic-roughness map's triple at uv put into r and ks (nothing without one).
void material_metal_rough_at(vec2 uv, inout vec3 ks, inout Reflectance r) {
    if (u_pbr && u_has_metal_rough_map) {
        vec3 t = material_triple(uv);
        r.alpha = t.x;
        r.eta = t.y;
        ks = vec3(t.z);
    }
}

// What the ambient term is multiplied by: 1 + strength (R - 1), 1 without a map.
float material_occlusion(vec2 uv) {
    return u_pbr && u_has_occlusion_map ? 1.0 + u_occlusion_strength * (texture(u_occlusion_map, uv).r - 1.0) : 1.0;
}

// The light the surface emits: emissiveFactor x emissiveTexture.
vec3 material_emission(vec2 uv) {
    if (!u_pbr) return vec3(0.0);
    return u_has_emissive_map ? u_emissive * texture(u_emissive_map, uv).rgb : u_emissive;
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
