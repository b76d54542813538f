#version 330 core
// Notes 03, "Blur Pass and Merge Pass": "a horizon blur pass and a vertical
// blur pass", one of the two, on one mip level. The kernel is
// src/math/gaussian.rs's, one side of it (the centre first), as
// (offset in texels, weight) pairs:
// - direct taps: one texel each, at whole offsets (texelFetch);
// - linear taps: a pair of texels each, at the offset between them where
//   bilinear filtering weighs them as the kernel does (textureLod).
// Both clamp to the edge: texelFetch by clamping the texel, textureLod by
// the texture's GL_CLAMP_TO_EDGE (a pair past the edge reads the edge texel
// twice, as the direct taps do).

// Two taps a vec4: (offset, weight, offset, weight). 1024 vec4 are the
// 16 KB every GL 3.3 uniform block may hold.
layout(std140) uniform BloomTaps {
    vec4 u_taps[1024];
};

uniform sampler2D u_image;   // the texture whose level is blurred
uniform int u_lod;           // that level, counted from the texture's base level
uniform int u_tap_count;     // taps on one side, the centre's included
uniform bool u_linear;       // linear taps (else direct)
uniform vec2 u_direction;    // (1, 0) horizontal, (0, 1) vertical

out vec4 frag_color;

vec2 tap(int i) {
    vec4 pair = u_taps[i / 2];
    return (i % 2 == 0) ? pair.xy : pair.zw;
}

vec4 fetch_direct(ivec2 texel, ivec2 last) {
    return texelFetch(u_image, clamp(texel, ivec2(0), last), u_lod);
}

void main() {
    ivec2 size = textureSize(u_image, u_lod);
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec4 sum = tap(0).y * texelFetch(u_image, texel, u_lod);
    float lod = float(u_lod);
    if (u_linear) {
        vec2 centre = gl_FragCoord.xy;    // a texel centre, in texels
        for (int i = 1; i < u_tap_count; ++i) {
            vec2 t = tap(i);
            sum += t.y * (textureLod(u_image, (centre + t.x * u_direction) / vec2(size), lod)
                        + textureLod(u_image, (centre - t.x * u_direction) / vec2(size), lod));
        }
    } else {
        ivec2 last = size - 1;
        ivec2 dir = ivec2(u_direction);
        for (int i = 1; i < u_tap_count; ++i) {
            vec2 t = tap(i);
            ivec2 step = int(t.x) * dir;
            sum += t.y * (fetch_direct(texel + step, last) + fetch_direct(texel - step, last));
        }
    }
    frag_color = sum;
}
