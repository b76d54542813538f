#version 330 core
// Karis 2013, "Real Shading in Unreal Engine 4": IntegrateBRDF, the split
// sum's second factor for gloss's microfacet BRDF (common/microfacet.glsl's
// GGX and height-correlated Smith G): the specular directional albedo with
// Schlick's Fresnel F0 + (1 - F0)(1 - V.H)^5 is F0 A + B; red holds A,
// green B. Across: N.V at texel centres; up: sqrt(alpha). CPU twin:
// `integrate_brdf` in src/lighting/image_based_lighting.rs.
#include "sky/importance_sample_ggx.glsl"
uniform float u_size;           // the table's side in texels
uniform int u_samples;
out vec4 frag_color;

void main() {
    vec2 uv = gl_FragCoord.xy / u_size;
    float n_dot_v = uv.x;
    float alpha = uv.y * uv.y;
    vec3 V = vec3(sqrt(1.0 - n_dot_v * n_dot_v), 0.0, n_dot_v);
    vec3 N = vec3(0.0, 0.0, 1.0);
    float A = 0.0;
    float B = 0.0;
    uint n = uint(u_samples);
    for (uint i = 0u; i < n; ++i) {
        vec3 H = importance_sample_ggx(hammersley(i, n), alpha, N);
        float v_dot_h = dot(V, H);
        vec3 L = 2.0 * v_dot_h * H - V;
        if (L.z > 0.0 && v_dot_h > 0.0) {
            float G = g_smith(L, V, N, alpha);
            float G_vis = G * v_dot_h / (H.z * n_dot_v);
            float Fc = pow(1.0 - v_dot_h, 5.0);
            A += (1.0 - Fc) * G_vis;
            B += Fc * G_vis;
        }
    }
    frag_color = vec4(A / float(n), B / float(n), 0.0, 1.0);
}
