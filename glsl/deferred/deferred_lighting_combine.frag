#version 330 core
// Light pre-pass, final pass: draw the scene again (gbuffer.vert, depth test
// GL_LEQUAL against the G-buffer's depth) and combine the accumulated light
// with the material, at full precision:  kd (ambient + D) + ks S.
#include "common/material.glsl"
#include "common/alpha_test.glsl"
#include "common/lighting_output.glsl"
in vec3 v_position;
in vec3 v_normal;
#include "common/surface_in.glsl"
uniform sampler2D u_diffuse_light;    // unit::LIGHT
uniform sampler2D u_specular_light;   // unit::SPECULAR_LIGHT
uniform bool u_has_light;             // false: no lights, no light pre-pass ran
uniform vec3 u_ambient;
out vec4 frag_color;

void main() {
    vec2 uv = surface_uv();
    alpha_test(material_alpha(uv));
    vec3 D = vec3(0.0), S = vec3(0.0);
    if (u_has_light) {
        vec2 pixel = gl_FragCoord.xy / textureSize(u_diffuse_light, 0).xy;
        D = texture(u_diffuse_light, pixel).rgb;
        S = texture(u_specular_light, pixel).rgb;
    }
    frag_color = output_color(material_diffuse(uv) * surface_color() * (u_ambient + D) + u_specular * S);
}
