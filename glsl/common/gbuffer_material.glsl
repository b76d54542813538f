// Notes 03's material triple in the G-buffer ("Geometry Pass"): gAlpha =
// (alpha, eta, k_s) and gConvert, whose element is 1 where gAlpha's holds
// the reciprocal of a value above 1, so that every stored value is in
// [0, 1]. src/frame/gbuffer.rs makes the attachments (render.gbuffer_encoding);
// src/math/gbuffer_encoding.rs is the CPU twin and measures each format.
//
//   u_gbuffer_material  gAlpha                      gConvert
//   0 (none)            -                           -             every pixel Phong
//   1 (report)          v <= 1: v;  v > 1: 1 / v    (v > 1) per element, w: microfacet
//   2 (plain)           (alpha, eta, k_s), w: microfacet
//
// Decoding the report's scheme takes 1 / max(stored, 1e-3): an alpha of
// 1e3 (the largest) stored in 8 bits as 0 comes back as 1e3, not infinity.
#define GBUFFER_MATERIAL_NONE 0
#define GBUFFER_MATERIAL_REPORT 1
#define GBUFFER_MATERIAL_PLAIN 2

uniform int u_gbuffer_material;
// A lighting variant (src/frame/variant.rs) knows the encoding when it is
// built: a constant, whose branches the compiler drops.
#ifdef VARIANT_GBUFFER_MATERIAL
#define GBUFFER_MATERIAL VARIANT_GBUFFER_MATERIAL
#else
#define GBUFFER_MATERIAL u_gbuffer_material
#endif

// The report's encoding of one value: (stored, convert flag).
vec2 encode_report(float v) {
    return v > 1.0 ? vec2(1.0 / v, 1.0) : vec2(v, 0.0);
}

float decode_report(float stored, float convert) {
    return convert > 0.5 ? 1.0 / max(stored, 1e-3) : stored;
}

// Writing (the geometry pass): gAlpha and gConvert for a surface whose
// triple is t, microfacet or not.
void encode_material(vec3 t, bool microfacet, out vec4 g_alpha, out vec4 g_convert) {
    float m = microfacet ? 1.0 : 0.0;
    if (u_gbuffer_material == GBUFFER_MATERIAL_REPORT) {
        vec2 a = encode_report(t.x);
        vec2 e = encode_report(t.y);
        vec2 k = encode_report(t.z);
        g_alpha = vec4(a.x, e.x, k.x, 0.0);
        g_convert = vec4(a.y, e.y, k.y, m);
    } else {
        g_alpha = vec4(t, m);
        g_convert = vec4(0.0);
    }
}

// Reading (a lighting pass, after common/gbuffer_read.glsl's samplers):
// whether the texel is microfacet, and its triple.
bool decode_material(vec4 g_alpha, vec4 g_convert, out vec3 t) {
    if (GBUFFER_MATERIAL == GBUFFER_MATERIAL_REPORT) {
        t = vec3(decode_report(g_alpha.x, g_convert.x),
                 decode_report(g_alpha.y, g_convert.y),
                 decode_report(g_alpha.z, g_convert.z));
        return g_convert.w > 0.5;
    }
    t = g_alpha.xyz;
    return GBUFFER_MATERIAL == GBUFFER_MATERIAL_PLAIN && g_alpha.w > 0.5;
}
