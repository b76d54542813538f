// Shared lighting: the Phong reflection model of notes 01 §8.3 with the
// Kc/Kl/Kq attenuation of notes 04, Blinn's half vector for the specular term.
//
//   c   = c_a + sum over lights of  att * spot * I * (c_d + c_s)
//   c_d = max(N . L, 0) * k_d
//   c_s = max(N . H, 0)^n * k_s,  H = normalize(L + V)   (the notes' 1/2 (V + L)
//                                 is not unit length; normalise instead)
//   att = 1 / (Kc + Kl d + Kq d^2)      (times a window with render.falloff = "windowed";
//                                        1 - d / Lmax with render.falloff = "linear")
//
// A point or spot light is a sphere of radius LIGHT_RADIUS, not a point
// (src/math/sphere_light.rs says why and cites it): att is taken at
// max(d, LIGHT_RADIUS), and N . L becomes sphere_cosine, which equals it
// wherever the whole sphere is above the surface's horizon.
//
// Every vector is in world space; L points from the surface to the light.
// src/lighting.rs evaluates the same formula on the CPU for the tests.

#include "common/reflectance.glsl"
#include "common/microfacet.glsl"

#define LIGHT_DIRECTIONAL 0
#define LIGHT_POINT 1
#define LIGHT_SPOT 2
// Added to the type when the light's falloff is windowed (render.falloff,
// src/frame/lights.rs WINDOWED): the notes' attenuation times
// (1 - (d / r)^4)^2, clamped, which is 0 from the radius r on (Karis 2013,
// "Real Shading in Unreal Engine 4"). A different model from the notes'.
#define LIGHT_WINDOWED 4
// Added to the type for notes 01 §8.3's linear attenuation (render.falloff
// = "linear", src/frame/lights.rs LINEAR): att = 1 - d / Lmax, 0 from Lmax
// on, with Lmax the volume radius; Kc, Kl, Kq unused.
#define LIGHT_LINEAR 8

// Shaders specialised to the frame (src/frame/variant.rs): a program built
// for a lighting variant defines LIGHTING_VARIANT and which parts the scene
// needs; the #if blocks below leave the others out. Without the defines
// (every program not built as a variant) every part is in: the general model.
#ifndef LIGHTING_VARIANT
#define VARIANT_DIRECTIONAL 1
#define VARIANT_POINT 1
#define VARIANT_SPOT 1
#define VARIANT_WINDOWED 1
#define VARIANT_LINEAR 1
#define VARIANT_SHADOWS 1
#define VARIANT_MICROFACET 1
// common/shadow.glsl: how many 2D and cube maps, which filter loops;
// common/bump_mapping.glsl: normal maps. (VARIANT_GBUFFER_MATERIAL stays
// undefined: common/gbuffer_material.glsl then reads u_gbuffer_material.)
#define VARIANT_SHADOW_2D 4
#define VARIANT_SHADOW_CUBE 4
#define VARIANT_PCF_BOX 1
#define VARIANT_PCF_POISSON 1
#define VARIANT_NORMAL_MAPS 1
#endif

// std140, 64 bytes a light (src/lighting.rs writes this layout).
struct Light {
    vec4 position_type;    // xyz position, w type
    vec4 direction_radius; // xyz unit direction the light shines in, w volume radius (< 0: none)
    vec4 color_cos_outer;  // rgb colour x intensity, w cos(outer angle)
    vec4 atten_cos_inner;  // Kc, Kl, Kq, cos(inner angle)
};

layout(std140) uniform Lights {
    Light u_lights[MAX_LIGHTS];
};

const float LIGHT_RADIUS = 0.01;
const float PI = 3.14159265358979;

// The sphere against the surface's horizon: returns its N . L, cos_theta
// while the whole sphere is up, sin_sigma G(cos_theta / sin_sigma) as it
// sets (the small-angle form, which nothing cancels in), 0 below; and in
// visible the part of it above the horizon (G), which scales the specular.
// sin_sigma 0 (a directional light): N . L and a step.
float sphere_cosine(float cos_theta, float sin_sigma, out float visible) {
    if (cos_theta >= sin_sigma || cos_theta <= -sin_sigma) {
        visible = cos_theta > 0.0 ? 1.0 : 0.0;
        return max(cos_theta, 0.0);
    }
    float t = clamp(cos_theta / sin_sigma, -1.0, 1.0);
    float q = sqrt(1.0 - t * t);
    float g = (t * PI / 2.0 + t * t * q + t * asin(t) + 2.0 / 3.0 * q * q * q) / PI;
    visible = clamp(g, 0.0, 1.0);
    return sin_sigma * visible;
}

// The light's irradiance factors at P: returns the direction to the light in
// L, the sine of the light's angular radius in sin_sigma (0: directional),
// and the scalar att * spot factor.
float light_factor(Light light, vec3 P, out vec3 L, out float sin_sigma) {
    int code = int(light.position_type.w);
    int type = code & 3;
    sin_sigma = 0.0;
#if VARIANT_DIRECTIONAL
    if (type == LIGHT_DIRECTIONAL) {
        L = -light.direction_radius.xyz;
        return 1.0;
    }
#endif
#if VARIANT_POINT || VARIANT_SPOT
    vec3 to_light = light.position_type.xyz - P;
    float d = length(to_light);
    L = to_light / max(d, 1e-20);
    float r = max(d, LIGHT_RADIUS);
    sin_sigma = LIGHT_RADIUS / r;
    vec3 k = light.atten_cos_inner.xyz;
    float att = 1.0 / (k.x + k.y * r + k.z * r * r);
#if VARIANT_LINEAR
    if ((code & LIGHT_LINEAR) != 0) {
        att = clamp(1.0 - d / light.direction_radius.w, 0.0, 1.0);
    }
#endif
#if VARIANT_WINDOWED
    if ((code & LIGHT_WINDOWED) != 0) {
        float radius = light.direction_radius.w;
        float x = radius > 0.0 ? d / radius : 1.0;
        float w = clamp(1.0 - x * x * x * x, 0.0, 1.0);
        att *= w * w;
    }
#endif
#if VARIANT_SPOT
    if (type == LIGHT_SPOT) {
        float c = dot(-L, light.direction_radius.xyz);
        float cos_outer = light.color_cos_outer.w;
        float cos_inner = light.atten_cos_inner.w;
        att *= smoothstep(cos_outer, cos_inner, c);
    }
#endif
    return att;
#else
    // Directional lights only (a variant with neither point nor spot).
    L = -light.direction_radius.xyz;
    return 1.0;
#endif
}

// Diffuse and specular light (not yet multiplied by the material) from one light.
void phong_light(Light light, vec3 P, vec3 N, vec3 V, float shininess,
                 out vec3 diffuse, out vec3 specular) {
    vec3 L;
    float sin_sigma;
    float f = light_factor(light, P, L, sin_sigma);
    vec3 I = light.color_cos_outer.rgb * f;
    float visible;
    float n_dot_l = sphere_cosine(dot(N, L), sin_sigma, visible);
    vec3 H = normalize(L + V);
    float s = visible > 0.0 ? visible * pow(max(dot(N, H), 0.0), shininess) : 0.0;
    diffuse = I * n_dot_l;
    specular = I * s;
}

vec3 phong(Light light, vec3 P, vec3 N, vec3 V, vec3 kd, vec3 ks, float shininess) {
    vec3 d, s;
    phong_light(light, P, N, V, shininess, d, s);
    return kd * d + ks * s;
}

// Diffuse and specular light from one light for either reflectance model
// (not yet multiplied by k_d and the specular colour). The microfacet
// specular is pi f_s(L, V, N) (N . L) I with k_s = 1 (common/microfacet.glsl):
// the diffuse term k_d (N . L) I is the Lambertian k_d / pi under an
// irradiance of pi I, so the specular takes the same pi. Over the sphere
// light's horizon both use its N . L.
void surface_light(Light light, vec3 P, vec3 N, vec3 V, Reflectance r,
                   out vec3 diffuse, out vec3 specular) {
#if !VARIANT_MICROFACET
    // No microfacet material in the frame: Phong's lobe alone.
    phong_light(light, P, N, V, r.shininess, diffuse, specular);
#else
    if (!r.microfacet) {
        phong_light(light, P, N, V, r.shininess, diffuse, specular);
        return;
    }
    vec3 L;
    float sin_sigma;
    float f = light_factor(light, P, L, sin_sigma);
    vec3 I = light.color_cos_outer.rgb * f;
    float visible;
    float n_dot_l = sphere_cosine(dot(N, L), sin_sigma, visible);
    diffuse = I * n_dot_l;
    specular = I * (PI * microfacet_brdf(L, V, N, r.alpha, r.eta, 1.0) * n_dot_l);
#endif
}

// The colour one light gives a surface: k_d times its diffuse light plus ks
// (the Phong specular colour, or k_s for a microfacet surface) times its
// specular light.
vec3 surface_shade(Light light, vec3 P, vec3 N, vec3 V, vec3 kd, vec3 ks, Reflectance r) {
    vec3 d, s;
    surface_light(light, P, N, V, r, d, s);
    return kd * d + ks * s;
}
