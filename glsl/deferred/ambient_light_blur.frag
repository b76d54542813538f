#version 330 core
// The ambient light pass's blur (notes 03, "Ambient Light"): the AO
// averaged over the 4x4 pixels around this one, the size of the rotation
// tile, so that every average holds each of the tile's 16 turns once and
// the tile's pattern is gone. Depth-aware: a neighbour counts only when
// its surface lies within r/4 of this pixel's tangent plane, so that the
// AO of an object does not bleed onto a background far behind it (nor the
// background's onto it). Neighbours outside the view are left out.
#include "common/gbuffer_read.glsl"
uniform sampler2D u_ambient_occlusion;   // the AO to blur, unit::AMBIENT_OCCLUSION
uniform float u_radius;
out float ao_out;

void main() {
    ivec2 c = ivec2(gl_FragCoord.xy);
    Surface s = read_geometry_texel(c);
    if (s.depth == 1.0) {
        ao_out = 1.0;
        return;
    }
    vec3 N = normalize(s.N);
    ivec2 lo = ivec2(u_viewport.xy);
    ivec2 hi = ivec2(u_viewport.xy + u_viewport.zw) - 1;
    float sum = 0.0;
    float count = 0.0;
    for (int y = -2; y < 2; ++y) {
        for (int x = -2; x < 2; ++x) {
            ivec2 p = c + ivec2(x, y);
            if (any(lessThan(p, lo)) || any(greaterThan(p, hi))) {
                continue;
            }
            Surface q = read_geometry_texel(p);
            if (q.depth == 1.0 || abs(dot(q.P - s.P, N)) > 0.25 * u_radius) {
                continue;
            }
            sum += texelFetch(u_ambient_occlusion, p, 0).r;
            count += 1.0;
        }
    }
    // The pixel itself always counts: count >= 1.
    ao_out = sum / count;
}
