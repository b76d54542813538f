#version 330 core
// A 3x3 convolution, a stage of the post chain (notes 01 §9): each pixel
// the weighted sum of its neighbourhood. Rows run from the top, as written
// in the scene file; GL's rows run from the bottom, hence 1 - row.
uniform sampler2D u_image;   // the previous image
uniform float u_kernel[9];   // row by row from the top
out vec4 frag_color;
#include "post/finite.glsl"

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 last = textureSize(u_image, 0) - 1;
    vec3 sum = vec3(0.0);
    for (int row = 0; row < 3; row++) {
        for (int col = 0; col < 3; col++) {
            // Past the edge, the edge pixel repeats (clamp to edge).
            ivec2 q = clamp(p + ivec2(col - 1, 1 - row), ivec2(0), last);
            sum += u_kernel[row * 3 + col] * finite(texelFetch(u_image, q, 0).rgb);
        }
    }
    frag_color = vec4(sum, 1.0);
}
