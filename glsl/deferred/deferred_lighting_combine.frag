#version 330 core
// Light pre-pass, final pass: draw the scene again (gbuffer.vert, depth test
// GL_LEQUAL against the G-buffer's depth) and combine the accumulated light
// with the material, at full precision:  kd (ambient + D) + ks S.
#include "common/material.glsl"
#include "common/alpha_test.glsl"
// The cascade colours (shadow.cascade_colors), by the point drawn.
#ifdef CASCADE_TINTS
#include "shadows/cascade_block.glsl"
#endif
#include "common/lighting_output.glsl"
#include "common/normals.glsl"
#include "common/environment.glsl"
#include "common/image_based_lighting.glsl"
in vec3 v_position;
in vec3 v_normal;
#include "common/surface_in.glsl"
#include "common/bump_mapping.glsl"
uniform vec3 u_eye;   // the skybox mirror reflection (notes 03, Implementation), as forward adds it
uniform sampler2D u_diffuse_light;    // unit::LIGHT
uniform sampler2D u_specular_light;   // unit::SPECULAR_LIGHT
uniform bool u_has_light;             // false: no lights, no light pre-pass ran
uniform vec3 u_ambient;
// The ambient light pass's AO (notes 03, Ambient Light; deferred/ambient_light.rs),
// unit::AMBIENT_OCCLUSION; false: the scene has no [ambient_occlusion].
uniform sampler2D u_ambient_occlusion;
uniform bool u_has_ambient_occlusion;
out vec4 frag_color;

void main() {
    vec2 uv = surface_uv();
    // A material that tests nothing is drawn with NO_ALPHA_TEST
    // (src/techniques/deferred/deferred_lighting.rs): no discard in the program.
#ifndef NO_ALPHA_TEST
    alpha_test(material_alpha(uv));
#endif
    vec3 D = vec3(0.0), S = vec3(0.0);
    if (u_has_light) {
        vec2 pixel = gl_FragCoord.xy / textureSize(u_diffuse_light, 0).xy;
        D = texture(u_diffuse_light, pixel).rgb;
        S = texture(u_specular_light, pixel).rgb;
    }
    vec3 ambient = u_ambient * material_occlusion(uv);
    // NO_AMBIENT_OCCLUSION, NO_IBL: a variant for a scene without them
    // (deferred_lighting_combine.rs), whose uniform branches llvmpipe would
    // run all the same.
    float ao = 1.0;
#ifndef NO_AMBIENT_OCCLUSION
    if (u_has_ambient_occlusion) {
        ao = texture(u_ambient_occlusion, gl_FragCoord.xy / textureSize(u_ambient_occlusion, 0).xy).r;
    }
#endif
    ambient *= ao;
    vec3 N = bumped_normal(safe_normal(v_normal, v_position), uv);
    vec3 mirrored = environment_reflection(u_reflectivity, N, normalize(u_eye - v_position));
    vec3 kd = material_diffuse(uv) * surface_color();
    vec3 ks = material_specular() * material_specular_map(uv);
    if (u_pbr && u_has_metal_rough_map) ks = vec3(material_triple(uv).z);
    // Image-based lighting (render.ibl) in place of the constant ambient,
    // occluded alike.
#ifndef NO_IBL
    if (u_has_ibl) {
        ambient = vec3(0.0);
        mirrored += ao * material_occlusion(uv)
            * ibl_ambient(u_ambient, N, normalize(u_eye - v_position), kd, ks, material_reflectance());
    }
#endif
#ifdef CASCADE_TINTS
    g_cascade_tint = cascade_tint_at(v_position);
#endif
    frag_color = output_color(kd * (ambient + D) + ks * S + mirrored + material_emission(uv));
}
