#version 330 core
// Billboards (notes 05, "Alpha Test and Billboards"): the sprite's colour,
// simply lit, with its alpha for blending; in the alpha-test mode a fragment
// with alpha < 0.5 is discarded and writes neither colour nor depth.
#include "common/alpha_test.glsl"
#include "common/lighting_output.glsl"

in vec2 v_uv;
uniform sampler2D u_sprites;   // the sprite sheet, sRGB: sampling returns linear
uniform vec3 u_light;          // ambient + directional lights on an up-facing normal
out vec4 frag_color;

void main() {
    vec4 texel = texture(u_sprites, v_uv);
    alpha_test(texel.a);
    frag_color = vec4(output_color(texel.rgb * u_light).rgb, texel.a);
}
