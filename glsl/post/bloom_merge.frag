#version 330 core
// Notes 03, "Blur Pass and Merge Pass": "the merge pass merges the above 4
// blur results and the original image with the weighted factors using the
// Spencer model":
//
//     0.8843 g(x) + 0.1 g(6.2, x) + 0.012 g(24.9, x) + 0.0027 g(81.0, x) + 0.001 g(263, x)
//
// g(x) is the original (sanitised, as the blurs saw it); g(sigma, x) blur i,
// read from its mip level with bilinear filtering (the upsample). A level
// of 2^k pixels a texel holds pixel x's light at (x + 0.5) / 2^k texels:
// each of its texels is the mean of the 2^k pixels from 2^k j on (the
// downsample), also where 2^k does not divide the image's size.
#include "post/finite.glsl"

uniform sampler2D u_image;   // the chain's previous image, one level
uniform sampler2D u_blur0;   // blur i's texture (the same mip texture for
uniform sampler2D u_blur1;   // all four in the notes' scheme)
uniform sampler2D u_blur2;
uniform sampler2D u_blur3;
uniform float u_lod[4];      // blur i's level, counted from its texture's base level
uniform float u_block[4];    // blur i's full-resolution pixels per texel
uniform float u_weight[5];   // the original's weight, then each blur's
uniform bool u_has_blurs;    // false: no level exists (a 1x1 image), g stands in

out vec4 frag_color;

vec4 blur(sampler2D level, float lod, float block, vec4 g) {
    if (!u_has_blurs) {
        return g;
    }
    vec2 size = vec2(textureSize(level, int(lod)));
    return textureLod(level, gl_FragCoord.xy / (block * size), lod);
}

void main() {
    vec4 g = finite(texelFetch(u_image, ivec2(gl_FragCoord.xy), 0));
    vec4 sum = u_weight[0] * g
             + u_weight[1] * blur(u_blur0, u_lod[0], u_block[0], g)
             + u_weight[2] * blur(u_blur1, u_lod[1], u_block[1], g)
             + u_weight[3] * blur(u_blur2, u_lod[2], u_block[2], g)
             + u_weight[4] * blur(u_blur3, u_lod[3], u_block[3], g);
    frag_color = vec4(sum.rgb, g.a);
}
