#version 330 core
// Notes 03, "Blur Pass and Merge Pass", step 1 of each blur: the chain's
// image, sanitised, taken down to mip level k. Each level-k texel is the
// mean of the 2^k x 2^k full-resolution pixels under it (an exact box: a
// bilinear tap would average a NaN in before it could be sanitised). A
// block that reaches past the image's edge reads its edge pixels.
#include "post/finite.glsl"

uniform sampler2D u_image;   // the chain's previous image, one level
uniform int u_block;         // 2^k: full-resolution pixels per texel, each way

out vec4 frag_color;

void main() {
    ivec2 last = textureSize(u_image, 0) - 1;
    ivec2 first = ivec2(gl_FragCoord.xy) * u_block;
    vec4 sum = vec4(0.0);
    for (int y = 0; y < u_block; ++y) {
        for (int x = 0; x < u_block; ++x) {
            sum += finite(texelFetch(u_image, min(first + ivec2(x, y), last), 0));
        }
    }
    frag_color = sum / float(u_block * u_block);
}
