// Karis 2013, "Real Shading in Unreal Engine 4", Image-Based Lighting:
// Hammersley points and ImportanceSampleGGX, with gloss's alpha (GGX's
// alpha_g itself, where Karis squares his roughness). The CPU twins are
// `hammersley` and `importance_sample_ggx` in src/lighting/image_based_lighting.rs.
#include "common/microfacet.glsl"

vec2 hammersley(uint i, uint n) {
    uint b = i;
    b = (b << 16u) | (b >> 16u);
    b = ((b & 0x55555555u) << 1u) | ((b & 0xAAAAAAAAu) >> 1u);
    b = ((b & 0x33333333u) << 2u) | ((b & 0xCCCCCCCCu) >> 2u);
    b = ((b & 0x0F0F0F0Fu) << 4u) | ((b & 0xF0F0F0F0u) >> 4u);
    b = ((b & 0x00FF00FFu) << 8u) | ((b & 0xFF00FF00u) >> 8u);
    return vec2(float(i) / float(n), float(b) * 2.3283064365386963e-10);
}

// A half vector about N distributed as D(H) (N.H).
vec3 importance_sample_ggx(vec2 xi, float alpha, vec3 N) {
    float a = clamp(alpha, MICROFACET_ALPHA_MIN, MICROFACET_ALPHA_MAX);
    float phi = 2.0 * MICROFACET_PI * xi.x;
    float cos_theta = sqrt((1.0 - xi.y) / (1.0 + (a * a - 1.0) * xi.y));
    float sin_theta = sqrt(max(1.0 - cos_theta * cos_theta, 0.0));
    vec3 H = vec3(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
    vec3 up = abs(N.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    vec3 tx = normalize(cross(up, N));
    vec3 ty = cross(N, tx);
    return tx * H.x + ty * H.y + N * H.z;
}
