#version 330 core
// Light pre-pass, final pass: draw the scene again (gbuffer.vert, depth test
// GL_LEQUAL against the G-buffer's depth) and combine the accumulated light
// with the material, at full precision:  kd (ambient + D) + ks S.
#include "material.glsl"
#include "lighting_output.glsl"
in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
uniform sampler2D u_diffuse_light;    // unit 4
uniform sampler2D u_specular_light;   // unit 5
uniform vec3 u_ambient;
out vec4 frag_color;

void main() {
    vec2 uv = gl_FragCoord.xy / textureSize(u_diffuse_light, 0).xy;
    vec3 D = texture(u_diffuse_light, uv).rgb;
    vec3 S = texture(u_specular_light, uv).rgb;
    frag_color = output_color(material_diffuse(v_uv) * (u_ambient + D) + u_specular * S);
}
