#version 330 core
// A particle: a round spot that fades over its life. Additive: its colour
// times its brightness; alpha test: a disc, discarded outside it.
#include "common/lighting_output.glsl"
uniform vec3 u_color;
uniform bool u_alpha_test;
in vec2 g_corner;
in float g_life;
out vec4 frag_color;

void main() {
    float r2 = dot(g_corner, g_corner);
    if (r2 > 1.0) discard;
    float fade = 1.0 - g_life;
    if (u_alpha_test) {
        frag_color = output_color(u_color * fade);
        return;
    }
    float spot = (1.0 - r2) * fade;
    frag_color = vec4(u_color * spot, 1.0);
}
