// The Cook-Torrance microfacet specular BRDF (Cook and Torrance 1982) for
// notes 03's material triple (alpha, eta, k_s) (notes 03, Geometry Pass).
// common/lighting.glsl's surface_light uses it. Its Rust twin is src/lighting/microfacet.rs:
// `brdf` there is the f64 reference, and `brdf_f32` takes the steps of
// `microfacet_brdf` below in f32, for a GPU test to compare with.
//
//   f_s(L, V, N) = k_s D(H) F(V.H) G(L, V) / (4 (N.L)(N.V)),  H = (L + V) / |L + V|
//   D = alpha^2 / (pi ((N.H)^2 alpha^2 + |N x H|^2)^2)      GGX (Walter et al. 2007)
//   F = 1/2 ((g - c) / (g + c))^2 (1 + ((c g - s^2) / (c g + s^2))^2),
//       c = V.H, s^2 = 1 - c^2, g^2 = eta^2 - s^2        exact unpolarised
//       dielectric Fresnel (Walter et al. 2007, eq. 22); g^2 <= 0: F = 1
//   G = 1 / (1 + Lambda(L) + Lambda(V)),                 Smith height-correlated
//       Lambda(W) = (sqrt(1 + alpha^2 tan^2 theta_W) - 1) / 2     (Heitz 2014)
//
// alpha is GGX's alpha_g as it is (not squared), clamped to [1e-3, 1e3]; eta
// is clamped to [1e-3, 1e3] and eta = 1 gives F = 0. 0 below the horizon
// (N.L <= 0 or N.V <= 0) and for L = -V; above it N.L and N.V are floored at
// 1e-8. Sines come from cross products (1 - cos^2 cancels near the normal).
// L, V, N are unit vectors in one space, L and V pointing away from the
// surface. The names are prefixed: lighting.glsl already has PI.

const float MICROFACET_PI = 3.14159265358979;
const float MICROFACET_ALPHA_MIN = 1e-3;
const float MICROFACET_ALPHA_MAX = 1e3;
const float MICROFACET_ETA_MIN = 1e-3;
const float MICROFACET_ETA_MAX = 1e3;
const float MICROFACET_COS_MIN = 1e-8;

// GGX from cos theta_H and sin^2 theta_H, alpha already clamped.
float microfacet_d_ggx_cs(float cos_h, float sin2_h, float alpha) {
    if (cos_h <= 0.0) {
        return 0.0;
    }
    float a2 = alpha * alpha;
    float d = a2 * cos_h * cos_h + sin2_h;
    return a2 / (MICROFACET_PI * d * d);
}

// The GGX normal distribution D(H) about N: integral of D (N.H) dH = 1.
float d_ggx(vec3 N, vec3 H, float alpha) {
    vec3 c = cross(N, H);
    return microfacet_d_ggx_cs(dot(N, H), dot(c, c),
                               clamp(alpha, MICROFACET_ALPHA_MIN, MICROFACET_ALPHA_MAX));
}

// Exact unpolarised dielectric Fresnel reflectance at cos_i (sign ignored).
float fresnel_dielectric(float cos_i, float eta) {
    eta = clamp(eta, MICROFACET_ETA_MIN, MICROFACET_ETA_MAX);
    if (eta == 1.0) {
        return 0.0;
    }
    float c = min(abs(cos_i), 1.0);
    float s2 = 1.0 - c * c;
    float g2 = eta * eta - s2;
    if (g2 <= 0.0) {
        return 1.0; // total internal reflection
    }
    float g = sqrt(g2);
    float a = (g - c) / (g + c);
    float b = (c * g - s2) / (c * g + s2);
    return 0.5 * a * a * (1.0 + b * b);
}

// Smith's Lambda for GGX as alpha^2 tan^2 / (2 (1 + sqrt(1 + alpha^2 tan^2))).
float microfacet_lambda(float cos_w, float sin2_w, float alpha) {
    float c = max(cos_w, MICROFACET_COS_MIN);
    float a2t2 = alpha * alpha * sin2_w / (c * c);
    return a2t2 / (2.0 * (1.0 + sqrt(1.0 + a2t2)));
}

// Smith's height-correlated masking-shadowing G(L, V); 0 below the horizon.
float g_smith(vec3 L, vec3 V, vec3 N, float alpha) {
    float n_dot_l = dot(N, L);
    float n_dot_v = dot(N, V);
    if (n_dot_l <= 0.0 || n_dot_v <= 0.0) {
        return 0.0;
    }
    alpha = clamp(alpha, MICROFACET_ALPHA_MIN, MICROFACET_ALPHA_MAX);
    vec3 cl = cross(N, L);
    vec3 cv = cross(N, V);
    return 1.0 / (1.0 + (microfacet_lambda(n_dot_l, dot(cl, cl), alpha) +
                         microfacet_lambda(n_dot_v, dot(cv, cv), alpha)));
}

// f_s(L, V, N). G / (4 N.L N.V) is taken in one piece,
// 1 / (2 (N.V q(L) + N.L q(V))), q(W) = sqrt((N.W)^2 + alpha^2 |N x W|^2),
// which divides by no cosine; V.H = |L + V| / 2 keeps it reciprocal.
float microfacet_brdf(vec3 L, vec3 V, vec3 N, float alpha, float eta, float k_s) {
    float n_dot_l = dot(N, L);
    float n_dot_v = dot(N, V);
    if (n_dot_l <= 0.0 || n_dot_v <= 0.0) {
        return 0.0;
    }
    vec3 s = L + V;
    float len = length(s);
    if (len <= 0.0) {
        return 0.0; // L = -V: no half vector
    }
    vec3 H = s / len;
    alpha = clamp(alpha, MICROFACET_ALPHA_MIN, MICROFACET_ALPHA_MAX);
    float a2 = alpha * alpha;
    vec3 ch = cross(N, H);
    float D = microfacet_d_ggx_cs(dot(N, H), dot(ch, ch), alpha);
    float F = fresnel_dielectric(0.5 * len, eta);
    n_dot_l = max(n_dot_l, MICROFACET_COS_MIN);
    n_dot_v = max(n_dot_v, MICROFACET_COS_MIN);
    vec3 cl = cross(N, L);
    vec3 cv = cross(N, V);
    float q_l = sqrt(n_dot_l * n_dot_l + a2 * dot(cl, cl));
    float q_v = sqrt(n_dot_v * n_dot_v + a2 * dot(cv, cv));
    float vis = 0.5 / (n_dot_v * q_l + n_dot_l * q_v);
    return k_s * D * F * vis;
}
