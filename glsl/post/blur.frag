#version 330 core
// One direction of a separable blur, a stage of the post chain (notes 01
// §9; notes 03 "Blur Pass": a horizontal pass, then a vertical one).
// Taps are one-sided: the centre, then each offset read on both sides.
// Read through a clamp-to-edge sampler: GL_NEAREST for direct taps (whole
// texels), GL_LINEAR for linear taps (a fractional offset reads two texels
// with their two weights).
uniform sampler2D u_image;   // the previous image
uniform vec2 u_direction;    // (1, 0): along the rows; (0, 1): the columns
uniform int u_taps;          // how many of the arrays below are used
uniform float u_offset[128]; // texels from the centre (u_offset[0] = 0)
uniform float u_weight[128]; // each side's weight; all sum to 1
out vec4 frag_color;
#include "post/finite.glsl"

void main() {
    vec2 size = vec2(textureSize(u_image, 0));
    vec2 uv = gl_FragCoord.xy / size;
    vec3 sum = u_weight[0] * finite(texture(u_image, uv).rgb);
    for (int i = 1; i < u_taps; i++) {
        vec2 d = u_offset[i] * u_direction / size;
        sum += u_weight[i] * (finite(texture(u_image, uv + d).rgb) + finite(texture(u_image, uv - d).rgb));
    }
    frag_color = vec4(sum, 1.0);
}
