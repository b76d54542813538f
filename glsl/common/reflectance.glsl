// How a surface reflects light (src/scene/material.rs, `model`): notes 01
// §8.3's Phong lobe with its shininess, or notes 03's microfacet triple
// (alpha, eta, k_s), whose k_s is the specular colour's weight. Included by
// common/lighting.glsl and common/gbuffer_read.glsl; the guard lets a shader
// include both.
#ifndef REFLECTANCE_GLSL
#define REFLECTANCE_GLSL
struct Reflectance {
    bool microfacet;
    float shininess;   // Phong
    float alpha;       // microfacet: GGX width
    float eta;         // microfacet: index of refraction
};
#endif
