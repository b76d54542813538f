#version 330 core
// G-buffer pass: write the surface's data, no lighting.
//   0: normal (world, unit) + shininess   RGBA16F; OCTAHEDRAL_NORMALS: RGBA8,
//      rgb the octahedral normal (common/octahedral.glsl), a the shininess's
//      index into the scene's table (u_shininess_code, src/frame/gbuffer.rs)
//   1: diffuse albedo, ambient occlusion  SRGB8_ALPHA8 (GL_FRAMEBUFFER_SRGB on)
//   2: specular colour (a microfacet pixel: its emission), reflectivity  SRGB8_ALPHA8
//   depth: the depth buffer itself; position is rebuilt from it.
//   3: gAlpha, 4: gConvert: notes 03's microfacet triple (common/gbuffer_material.glsl),
//      when the scene has a microfacet material; at 1 and 2 in the light
//      pre-pass's thin G-buffer (THIN_GBUFFER), which drops albedo and specular.
#include "common/normals.glsl"
#include "common/material.glsl"
#include "common/alpha_test.glsl"
#include "common/gbuffer_material.glsl"
#include "common/octahedral.glsl"
uniform float u_shininess_code;
in vec3 v_position;
in vec3 v_normal;
#include "common/surface_in.glsl"
#include "common/bump_mapping.glsl"

layout(location = 0) out vec4 g_normal_shininess;
#ifdef THIN_GBUFFER
layout(location = 1) out vec4 g_alpha;
layout(location = 2) out vec4 g_convert;
layout(location = 3) out vec4 g_albedo;     // no attachment: dropped
layout(location = 4) out vec4 g_specular;   // no attachment: dropped
#else
layout(location = 1) out vec4 g_albedo;
layout(location = 2) out vec4 g_specular;
layout(location = 3) out vec4 g_alpha;
layout(location = 4) out vec4 g_convert;
#endif

void main() {
    vec2 uv = surface_uv();
    // A material that tests nothing is drawn with NO_ALPHA_TEST
    // (src/techniques/deferred/gbuffer.rs): no discard in the program.
#ifndef NO_ALPHA_TEST
    alpha_test(material_alpha(uv));
#endif
    // The normal after the normal map (notes 01 §8.4) is what the lights read.
    vec3 N = bumped_normal(safe_normal(v_normal, v_position), uv);
#ifdef OCTAHEDRAL_NORMALS
    g_normal_shininess = vec4(oct_pack(N), u_shininess_code / 255.0);
#else
    g_normal_shininess = vec4(N, u_shininess);
#endif
    // Alpha: what the ambient term is multiplied by (glTF's occlusion).
    g_albedo = vec4(material_diffuse(uv) * surface_color(), material_occlusion(uv));
    // A microfacet pixel's specular weight is k_s in gAlpha: its rgb holds
    // the emitted light instead (glTF's emissive; the composite adds it).
    vec3 specular = u_microfacet ? material_emission(uv) : u_specular * material_specular_map(uv);
    g_specular = vec4(specular, u_reflectivity);
    vec3 triple = material_triple(uv);
    encode_material(triple, u_microfacet, g_alpha, g_convert);
}
