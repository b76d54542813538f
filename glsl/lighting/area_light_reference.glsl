// The area lights' reference (docs/lighting/ltc_area_lights.md, "The
// reference"): the integral that lighting/ltc_area_lights.glsl approximates,
// taken by quadrature with gloss's own BRDF, slow on purpose. It exists so
// that `gloss bench` can measure LTC's error per pixel. Included by
// lighting/forward.frag after common/lighting.glsl (microfacet_brdf,
// fresnel_dielectric) and lighting/ltc_area_lights.glsl (the lights'
// uniforms, the second LTC table); render.area_light_reference picks it,
// render.area_light_points is N (src/frame/ltc_area_lights.rs sets both).
//
// Each point x of a light is a small light of solid angle
// dw = cos_l dA / r^2 (r = |x - P|, cos_l the cosine at the light), a
// point light of intensity I = L_e dw / pi as common/lighting.glsl's
// surface_light shades one (the diffuse term k_d I (N . w) is the
// Lambertian k_d / pi under the irradiance L_e (N . w) dw):
//
//   diffuse  = (1/pi) sum (N . w) dw
//   specular = sum f_s(w, V) (N . w) dw           microfacet: microfacet_brdf, exact Fresnel
//            = (1/pi) sum max(N . H, 0)^n dw      Phong: phong_light's Blinn lobe
//
// 1. The rectangle clipped to the surface's horizon (the plane through P
//    with normal N, Sutherland-Hodgman), as LTC clips it: a light behind the
//    surface gives exactly 0, and no point straddles the horizon.
// 2. The polygon (at most 5 corners) cut into a fan of triangles; each
//    triangle cut into N x N equal triangles (N the knob), the integrand
//    taken at their centroids and weighted by their area (the midpoint rule:
//    error O(1 / N^2); 2 N^2 points for a rectangle wholly above the horizon).
//
// table_fresnel (mode 2) takes F = 1 at every point and multiplies by the
// table's F0 magnitude + (1 - F0) fresnel over its magnitude: the one
// Schlick-average Fresnel that LTC's step 5 puts on the whole lobe. LTC
// against it is the fit's error alone; it against exact, the Fresnel's.
#ifndef AREA_LIGHT_REFERENCE_GLSL
#define AREA_LIGHT_REFERENCE_GLSL
#include "common/reflectance.glsl"
#include "lighting/ltc_area_lights.glsl"

uniform int u_area_light_reference;   // 0: LTC (this file idle), 1: exact, 2: table_fresnel
uniform int u_area_light_points;      // N: N x N points per triangle

const float REFERENCE_PI = 3.14159265358979;

// 1. The corners c[0..4) clipped to dot(N, x - P) >= 0, into q; returns
// the corner count (a quad cut by one plane keeps at most 5).
int reference_clip(vec3 c[4], vec3 P, vec3 N, out vec3 q[5]) {
    int m = 0;
    for (int i = 0; i < 4; ++i) {
        vec3 a = c[i];
        vec3 b = c[(i + 1) % 4];
        float da = dot(N, a - P);
        float db = dot(N, b - P);
        if (da >= 0.0 && m < 5) q[m++] = a;
        if ((da >= 0.0) != (db >= 0.0) && m < 5) q[m++] = a + (b - a) * (da / (da - db));
    }
    return m;
}

// The integrand at the light's point x: (N . w, the specular lobe) times
// cos_l / r^2 (dw / dA). n_l: the light's lit side (the side P is on when
// two-sided); table: the F = 1 lobe (table_fresnel) or gloss's Fresnel.
vec2 reference_point(vec3 x, vec3 P, vec3 N, vec3 V, vec3 n_l, Reflectance r, bool table) {
    vec3 d = x - P;
    float r2 = dot(d, d);
    vec3 w = d * inversesqrt(r2);
    float cos_l = max(-dot(n_l, w), 0.0);
    float cos_n = max(dot(N, w), 0.0);
    float lobe;
    if (r.microfacet) {
        lobe = microfacet_brdf(w, V, N, r.alpha, r.eta, 1.0) * cos_n;
        if (table && lobe > 0.0) lobe /= fresnel_dielectric(0.5 * length(w + V), r.eta);
    } else {
        lobe = cos_n > 0.0 ? pow(max(dot(N, normalize(w + V)), 0.0), r.shininess) / REFERENCE_PI : 0.0;
    }
    return vec2(cos_n / REFERENCE_PI, lobe) * (cos_l / r2);
}

// 2. The triangle (a, b, c) cut into n x n: the centroids of the cells
// a + u (b - a) + v (c - a), u, v on the grid of step 1/n, u + v <= 1,
// each cell of the triangle's area / n^2.
vec2 reference_triangle(vec3 a, vec3 b, vec3 c, int n, vec3 P, vec3 N, vec3 V, vec3 n_l,
                        Reflectance r, bool table) {
    vec3 e1 = b - a;
    vec3 e2 = c - a;
    float h = 1.0 / float(n);
    vec2 sum = vec2(0.0);
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n - i; ++j) {
            // The cell (i, j) pointing up, and the one pointing down beside it.
            sum += reference_point(a + e1 * ((float(i) + 1.0 / 3.0) * h) + e2 * ((float(j) + 1.0 / 3.0) * h),
                                   P, N, V, n_l, r, table);
            if (j < n - i - 1) {
                sum += reference_point(a + e1 * ((float(i) + 2.0 / 3.0) * h) + e2 * ((float(j) + 2.0 / 3.0) * h),
                                       P, N, V, n_l, r, table);
            }
        }
    }
    return sum * (0.5 * length(cross(e1, e2)) * h * h);
}

// The light every area light gives the surface at P, by quadrature; the
// same arguments as ltc_area_lights.
vec3 area_light_reference(vec3 P, vec3 N, vec3 V, vec3 kd, vec3 ks, Reflectance r) {
    bool table = u_area_light_reference == 2 && r.microfacet;
    float fresnel = 1.0;
    if (table) {
        // The LTC table's Schlick average, read where ltc_area_lights reads it.
        vec2 uv = vec2(sqrt(clamp(r.alpha, 0.0, 1.0)), sqrt(1.0 - clamp(dot(N, V), 0.0, 1.0)));
        vec4 t2 = texture(u_ltc_2, uv * LUT_SCALE + LUT_BIAS);
        float f = (r.eta - 1.0) / (r.eta + 1.0);
        fresnel = (f * f * t2.x + (1.0 - f * f) * t2.y) / t2.x;
    }
    int n = max(u_area_light_points, 1);
    vec3 c = vec3(0.0);
    for (int i = 0; i < u_area_light_count; ++i) {
        vec3 corners[4];
        for (int k = 0; k < 4; ++k) corners[k] = u_area_corners[4 * i + k];
        vec3 n_l = normalize(cross(corners[1] - corners[0], corners[3] - corners[0]));
        // From behind: nothing one-sided; two-sided, the other face.
        if (dot(P - corners[0], n_l) < 0.0) {
            if (!u_area_two_sided[i]) continue;
            n_l = -n_l;
        }
        vec3 q[5];
        int m = reference_clip(corners, P, N, q);
        vec2 sum = vec2(0.0);
        for (int k = 1; k + 1 < m; ++k) {
            sum += reference_triangle(q[0], q[k], q[k + 1], n, P, N, V, n_l, r, table);
        }
        c += u_area_radiance[i] * (kd * sum.x + ks * (sum.y * fresnel));
    }
    return c;
}
#endif
