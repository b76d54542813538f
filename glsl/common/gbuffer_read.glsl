// Reading the G-buffer in a lighting pass (notes 04 "Getting window coordinates
// in shader"): the texture coordinate is the window coordinate divided by the
// G-buffer's size, and the world position is rebuilt from the depth buffer.
// Units: unit::GBUFFER_* in src/frame/uniforms.rs; layout: src/frame/gbuffer.rs.
uniform sampler2D u_gbuffer_normal;     // normal.xyz, shininess (or packed: decode_normal_shininess)
uniform sampler2D u_gbuffer_albedo;     // diffuse albedo (linear)
uniform sampler2D u_gbuffer_specular;   // specular colour (linear; none in the slim G-buffer)
uniform sampler2D u_gbuffer_depth;      // depth: the position is rebuilt from it
uniform sampler2D u_gbuffer_alpha;      // gAlpha, when u_gbuffer_material is not 0
uniform sampler2D u_gbuffer_convert;    // gConvert, for the report's encoding
#include "common/reflectance.glsl"
#include "common/octahedral.glsl"
// The packed G-buffer (render.gbuffer = "octahedral", src/frame/gbuffer.rs):
// the normal attachment is RGBA8, rgb the octahedral normal in 12 + 12 bits,
// a the shininess's index into the scene's table (four a vec4).
uniform bool u_gbuffer_octahedral;
uniform vec4 u_shininess_table[16];
#ifdef VARIANT_GBUFFER_OCTAHEDRAL
#define GBUFFER_OCTAHEDRAL (VARIANT_GBUFFER_OCTAHEDRAL == 1)
#else
#define GBUFFER_OCTAHEDRAL u_gbuffer_octahedral
#endif

// The normal attachment's texel as (unit normal, shininess).
vec4 decode_normal_shininess(vec4 texel) {
    if (GBUFFER_OCTAHEDRAL) {
        int code = int(texel.a * 255.0 + 0.5);
        return vec4(oct_unpack(texel.rgb), u_shininess_table[code >> 2][code & 3]);
    }
    return texel;
}
// The slim G-buffer (render.gbuffer_slim, src/frame/gbuffer_slim.rs): no
// specular attachment, every material's specular colour is one value,
// passed as the full G-buffer would give it back.
uniform bool u_gbuffer_specular_constant;
uniform vec3 u_gbuffer_specular_value;
#ifdef VARIANT_GBUFFER_SPECULAR
#define GBUFFER_SPECULAR_CONSTANT (VARIANT_GBUFFER_SPECULAR == 0)
#else
#define GBUFFER_SPECULAR_CONSTANT u_gbuffer_specular_constant
#endif
#include "common/gbuffer_material.glsl"
uniform mat4 u_inverse_view_projection;
// The view's rectangle in the target (x, y, width, height in pixels): the
// whole target, or a split view's quarter (src/frame/views.rs).
uniform vec4 u_viewport;

struct Surface {
    vec3 P;
    vec3 N;
    float shininess;
    vec3 kd;
    vec3 ks;          // the specular colour, or k_s for a microfacet pixel
    float depth;
    Reflectance r;    // Phong (shininess) or notes 03's microfacet triple
};

// The pixel's reflectance model, from gAlpha and gConvert where the
// G-buffer has them; sets ks to k_s for a microfacet pixel.
void read_reflectance(ivec2 texel, inout Surface s) {
    s.r = Reflectance(false, s.shininess, 1.0, 1.0);
    if (GBUFFER_MATERIAL == GBUFFER_MATERIAL_NONE) {
        return;
    }
    vec4 convert = GBUFFER_MATERIAL == GBUFFER_MATERIAL_REPORT
        ? texelFetch(u_gbuffer_convert, texel, 0) : vec4(0.0);
    vec3 t;
    s.r.microfacet = decode_material(texelFetch(u_gbuffer_alpha, texel, 0), convert, t);
    if (s.r.microfacet) {
        s.r.alpha = t.x;
        s.r.eta = t.y;
        s.ks = vec3(t.z);
    }
}

// The light a pixel emits: a microfacet pixel's gSpecular rgb (its
// specular weight is k_s in gAlpha), none for a Phong pixel.
vec3 read_emission(vec2 uv) {
    if (u_gbuffer_material == GBUFFER_MATERIAL_NONE) {
        return vec3(0.0);
    }
    ivec2 texel = ivec2(uv * vec2(textureSize(u_gbuffer_normal, 0)));
    vec4 convert = u_gbuffer_material == GBUFFER_MATERIAL_REPORT
        ? texelFetch(u_gbuffer_convert, texel, 0) : vec4(0.0);
    vec3 t;
    bool microfacet = decode_material(texelFetch(u_gbuffer_alpha, texel, 0), convert, t);
    return microfacet ? texture(u_gbuffer_specular, uv).rgb : vec3(0.0);
}

vec2 gbuffer_uv() {
    return gl_FragCoord.xy / textureSize(u_gbuffer_normal, 0).xy;
}

// World position from this fragment's window position and depth: NDC =
// (position within the viewport, depth) * 2 - 1, then the inverse
// view-projection and the perspective divide undone. (`uv` is the G-buffer
// texture coordinate, unused here: with a split view the viewport is only
// part of the texture.)
vec3 world_position_at(vec2 window, float depth) {
    vec2 in_viewport = (window - u_viewport.xy) / u_viewport.zw;
    vec4 ndc = vec4(vec3(in_viewport, depth) * 2.0 - 1.0, 1.0);
    vec4 world = u_inverse_view_projection * ndc;
    return world.xyz / world.w;
}

vec3 world_position(vec2 uv, float depth) {
    return world_position_at(gl_FragCoord.xy, depth);
}

// The geometry at G-buffer texel `texel` (a pixel other than this
// fragment's: the far field's samples): depth, position, normal and
// shininess, no material colours.
Surface read_geometry_texel(ivec2 texel) {
    Surface s;
    s.depth = texelFetch(u_gbuffer_depth, texel, 0).r;
    vec4 ns = decode_normal_shininess(texelFetch(u_gbuffer_normal, texel, 0));
    s.N = ns.xyz;
    s.shininess = ns.w;
    s.kd = vec3(0.0);
    s.ks = vec3(0.0);
    s.P = world_position_at(vec2(texel) + 0.5, s.depth);
    read_reflectance(texel, s);
    return s;
}

Surface read_gbuffer(vec2 uv) {
    Surface s;
    s.depth = texture(u_gbuffer_depth, uv).r;
    vec4 ns = decode_normal_shininess(texture(u_gbuffer_normal, uv));
    s.N = ns.xyz;
    s.shininess = ns.w;
    s.kd = texture(u_gbuffer_albedo, uv).rgb;
    s.ks = GBUFFER_SPECULAR_CONSTANT ? u_gbuffer_specular_value
                                     : texture(u_gbuffer_specular, uv).rgb;
    s.P = world_position(uv, s.depth);
    read_reflectance(ivec2(uv * vec2(textureSize(u_gbuffer_normal, 0))), s);
    return s;
}
