// Area lights with linearly transformed cosines (Heitz, Dupuy, Hill and
// Neubelt 2016, "Real-Time Polygonal-Light Shading with Linearly
// Transformed Cosines"; the paper's LTC_Evaluate). Included by
// lighting/forward.frag and deferred/ltc_area_lights_deferred.frag (the
// G-buffer paths); src/frame/ltc_area_lights.rs sets the uniforms and
// binds the tables, src/lighting/ltc.rs is the CPU twin.
//
//   diffuse  = k_d L_e FF(identity)                   the exact polygon integral / pi
//   specular = k_s L_e FF(M^-1) (F0 magnitude + (1 - F0) fresnel)
//
// FF(M^-1): the polygon in the frame (T1, T2, N), clipped to the surface's
// horizon, through M^-1 (the table at (sqrt(alpha), sqrt(1 - N.V))),
// clipped to the cosine's horizon, then Lambert's sum of the edges' angles
// on the unit sphere. A Phong material reads the table at GGX's
// alpha = sqrt(2 / (shininess + 2)) (Walter et al. 2007's correspondence)
// with no Fresnel: k_s times the magnitude.
#ifndef LTC_AREA_LIGHTS_GLSL
#define LTC_AREA_LIGHTS_GLSL
#include "common/reflectance.glsl"

#define MAX_AREA_LIGHTS 8
uniform int u_area_light_count;
uniform vec3 u_area_corners[4 * MAX_AREA_LIGHTS];   // (c1 - c0) x (c3 - c0): the lit side
uniform vec3 u_area_radiance[MAX_AREA_LIGHTS];      // L_e, linear RGB
uniform bool u_area_two_sided[MAX_AREA_LIGHTS];
uniform sampler2D u_ltc_1;   // unit::LTC_1: M^-1's m00, m02, m20, m22
uniform sampler2D u_ltc_2;   // unit::LTC_2: magnitude, fresnel, 0, sphere

const float LUT_SIZE = 64.0;
const float LUT_SCALE = (LUT_SIZE - 1.0) / LUT_SIZE;
const float LUT_BIAS = 0.5 / LUT_SIZE;
const float LTC_PI = 3.14159265358979;

// acos(a . b) normalize(a x b).z for unit a, b; the angle from atan, exact
// near 0 and pi where acos loses digits.
float integrate_edge(vec3 a, vec3 b) {
    vec3 c = cross(a, b);
    float s = length(c);
    return s > 0.0 ? c.z * atan(s, dot(a, b)) / s : 0.0;
}

// The polygon p[0..n) clipped to z >= 0 (Sutherland-Hodgman), into q;
// returns its corner count (at most 6 from a quad clipped twice).
int clip_to_horizon(vec3 p[6], int n, out vec3 q[6]) {
    int m = 0;
    for (int i = 0; i < n; ++i) {
        vec3 a = p[i];
        vec3 b = p[i + 1 < n ? i + 1 : 0];
        if (a.z >= 0.0 && m < 6) q[m++] = a;
        if ((a.z >= 0.0) != (b.z >= 0.0) && m < 6) q[m++] = a + (b - a) * (a.z / (a.z - b.z));
    }
    return m;
}

// Lambert's sum over the polygon q[0..n) on the unit sphere: -1/(2 pi)
// sum of the edges' integrals (one-sided lights shine toward a negative sum).
float form_factor(vec3 q[6], int n) {
    float sum = 0.0;
    for (int i = 0; i < n; ++i) {
        sum += integrate_edge(normalize(q[i]), normalize(q[i + 1 < n ? i + 1 : 0]));
    }
    return -sum / (2.0 * LTC_PI);
}

// LTC_Evaluate for area light `light` at P, the diffuse form factor
// (M^-1 the identity) in x and the specular one (through Minv) in y: the
// frame and the first clip are shared.
vec2 ltc_evaluate(vec3 N, vec3 V, vec3 P, mat3 Minv, int light, bool two_sided) {
    // 1. The frame: T1 in the plane of N and V (any tangent at V = N).
    vec3 t = V - N * dot(V, N);
    vec3 T1 = length(t) > 1e-6 ? normalize(t)
            : normalize(abs(N.x) < 0.9 ? cross(N, vec3(1.0, 0.0, 0.0)) : cross(N, vec3(0.0, 1.0, 0.0)));
    vec3 T2 = cross(N, T1);
    mat3 frame = transpose(mat3(T1, T2, N));
    // 2. The corners into it, clipped to the surface's horizon.
    vec3 p[6];
    for (int i = 0; i < 4; ++i) p[i] = frame * (u_area_corners[4 * light + i] - P);
    vec3 q[6];
    int n = clip_to_horizon(p, 4, q);
    if (n < 3) return vec2(0.0);
    // The diffuse term: 4. Lambert's sum, M^-1 the identity.
    float diffuse = form_factor(q, n);
    // The specular term: through M^-1, 3. clipped to the cosine's horizon, 4.
    for (int i = 0; i < n; ++i) p[i] = Minv * q[i];
    int m = clip_to_horizon(p, n, q);
    float specular = m < 3 ? 0.0 : form_factor(q, m);
    vec2 ff = vec2(diffuse, specular);
    return two_sided ? abs(ff) : max(ff, vec2(0.0));
}

// Steps 1 and 5's table reads for a surface: M^-1 and the specular
// term's scale (the BRDF's magnitude and Fresnel).
void ltc_lookup(vec3 N, vec3 V, Reflectance r, out mat3 Minv, out float scale) {
    float alpha = r.microfacet ? r.alpha : sqrt(2.0 / (r.shininess + 2.0));
    vec2 uv = vec2(sqrt(clamp(alpha, 0.0, 1.0)), sqrt(1.0 - clamp(dot(N, V), 0.0, 1.0)));
    uv = uv * LUT_SCALE + LUT_BIAS;
    vec4 t1 = texture(u_ltc_1, uv);
    vec4 t2 = texture(u_ltc_2, uv);
    Minv = mat3(vec3(t1.x, 0.0, t1.y), vec3(0.0, 1.0, 0.0), vec3(t1.z, 0.0, t1.w));
    // 5. The BRDF's magnitude and Fresnel: Schlick's form with F0 from eta.
    float f = (r.eta - 1.0) / (r.eta + 1.0);
    scale = r.microfacet ? f * f * t2.x + (1.0 - f * f) * t2.y : t2.x;
}

// The light every area light gives the surface at P (normal N, toward the eye V).
vec3 ltc_area_lights(vec3 P, vec3 N, vec3 V, vec3 kd, vec3 ks, Reflectance r) {
    if (u_area_light_count == 0) return vec3(0.0);
    mat3 Minv;
    float scale;
    ltc_lookup(N, V, r, Minv, scale);
    vec3 c = vec3(0.0);
    for (int i = 0; i < u_area_light_count; ++i) {
        vec2 ff = ltc_evaluate(N, V, P, Minv, i, u_area_two_sided[i]);
        c += u_area_radiance[i] * (kd * ff.x + ks * (ff.y * scale));
    }
    return c;
}

// The same light without the material, for the light pre-pass
// (deferred/ltc_area_lights_deferred.rs): diffuse D and specular S, the
// surface's light being kd D + ks S.
void ltc_area_light_parts(vec3 P, vec3 N, vec3 V, Reflectance r, out vec3 D, out vec3 S) {
    D = vec3(0.0);
    S = vec3(0.0);
    if (u_area_light_count == 0) return;
    mat3 Minv;
    float scale;
    ltc_lookup(N, V, r, Minv, scale);
    for (int i = 0; i < u_area_light_count; ++i) {
        vec2 ff = ltc_evaluate(N, V, P, Minv, i, u_area_two_sided[i]);
        D += u_area_radiance[i] * ff.x;
        S += u_area_radiance[i] * (ff.y * scale);
    }
}
#endif
