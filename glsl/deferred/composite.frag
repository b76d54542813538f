#version 330 core
// Notes 01 §8.6.2 step 3, "Generate final image": a screen-sized triangle
// that adds the ambient term to the accumulated light and encodes to sRGB.
#include "common/gbuffer_read.glsl"
// The cascade colours (shadow.cascade_colors) on the deferred paths: the
// composite tints each pixel by the cascade of its G-buffer point, as the
// forward pass tints by the point it lights.
#ifdef CASCADE_TINTS
#include "shadows/cascade_block.glsl"
#endif
#include "common/lighting_output.glsl"
#include "common/image_based_lighting.glsl"
uniform vec3 u_eye;
uniform sampler2D u_light;   // the accumulated light (HDR), unit::LIGHT
uniform bool u_has_light;    // false: the frame has no lights, so no lighting pass ran
uniform vec3 u_ambient;
uniform vec3 u_background;
// The ambient light pass's AO (notes 03, Ambient Light; deferred/ambient_light.rs),
// unit::AMBIENT_OCCLUSION; false: the scene has no [ambient_occlusion].
uniform sampler2D u_ambient_occlusion;
uniform bool u_has_ambient_occlusion;
out vec4 frag_color;

void main() {
    vec2 uv = gbuffer_uv();
    float depth = texture(u_gbuffer_depth, uv).r;
#ifdef WRITE_DEPTH
    // The scene's depth goes to the output too: the passes that draw after
    // the composite (mirrors) test against it.
    gl_FragDepth = depth;
#endif
    if (depth == 1.0) {
        frag_color = output_color(u_background);
        return;
    }
    vec4 albedo = texture(u_gbuffer_albedo, uv);
    vec3 kd = albedo.rgb;
    vec3 ambient = u_ambient * kd;
    // Image-based lighting (render.ibl): the ambient term from the environment.
    // NO_IBL, NO_AMBIENT_OCCLUSION, NO_EMISSION: a variant for a frame
    // without it (src/techniques/deferred/composite.rs), the code left out.
#ifndef NO_IBL
    if (u_has_ibl) {
        Surface s = read_geometry_texel(ivec2(gl_FragCoord.xy));
        ambient = ibl_ambient(u_ambient, normalize(s.N), normalize(u_eye - s.P), kd, s.ks, s.r);
    }
#endif
    ambient *= albedo.a;   // a: the material's occlusion map
#ifndef NO_AMBIENT_OCCLUSION
    if (u_has_ambient_occlusion) {
        ambient *= texture(u_ambient_occlusion, uv).r;
    }
#endif
#ifdef CASCADE_TINTS
    g_cascade_tint = cascade_tint_at(read_geometry_texel(ivec2(gl_FragCoord.xy)).P);
#endif
#ifdef NO_EMISSION
    vec3 emitted = vec3(0.0);
#else
    vec3 emitted = read_emission(uv);
#endif
    frag_color = output_color(ambient + emitted + (u_has_light ? texture(u_light, uv).rgb : vec3(0.0)));
}
