#version 330 core
// Karis 2013, "Real Shading in Unreal Engine 4": PrefilterEnvMap, the
// environment averaged over GGX's lobe about R with N = V = R, weighted by
// N.L, for one roughness per mip level. Each sample reads the environment's
// mip level whose texel is as large as the sample's share of the lobe
// (Colbert and Krivanek 2007), so a few samples do not alias the sun. CPU
// twins: `prefilter_env_map` and `lod` in src/lighting/image_based_lighting.rs.
#include "common/cube_face.glsl"
#include "sky/importance_sample_ggx.glsl"
uniform samplerCube u_environment;
uniform int u_face;             // the output face, 0..5
uniform float u_size;           // the output level's side in texels
uniform float u_alpha;          // this level's GGX alpha
uniform int u_samples;          // GGX samples per texel
uniform float u_source_size;    // the environment's level-0 side
out vec4 frag_color;

void main() {
    vec3 R = normalize(cube_face_direction(u_face, gl_FragCoord.xy / u_size));
    vec3 N = R;
    vec3 V = R;
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    uint n = uint(u_samples);
    for (uint i = 0u; i < n; ++i) {
        vec3 H = importance_sample_ggx(hammersley(i, n), u_alpha, N);
        vec3 L = 2.0 * dot(V, H) * H - V;
        float n_dot_l = dot(N, L);
        if (n_dot_l > 0.0) {
            // pdf(L) = D (N.H) / (4 V.H) = D / 4 with N = V.
            float pdf = d_ggx(N, H, u_alpha) * 0.25;
            float omega_s = 1.0 / (float(n) * pdf);
            float omega_p = 4.0 * MICROFACET_PI / (6.0 * u_source_size * u_source_size);
            float lod = max(0.5 * log2(omega_s / omega_p), 0.0);
            sum += textureLod(u_environment, L, lod).rgb * n_dot_l;
            weight += n_dot_l;
        }
    }
    frag_color = vec4(weight > 0.0 ? sum / weight : textureLod(u_environment, R, 0.0).rgb, 1.0);
}
