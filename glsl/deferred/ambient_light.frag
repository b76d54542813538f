#version 330 core
// The ambient light pass (notes 03, "Ambient Light"): screen-space ambient
// occlusion (SSAO). For this pixel's surface point P (normal N), u_samples
// directions of the hemisphere above it (cosine-weighted, the kernel of
// src/lighting/ambient_occlusion.rs, turned about N by this pixel's entry
// of the 4x4 rotation tile); along each, points at r/4, r/2, 3r/4 and r
// (r = u_radius). A direction is occluded when one of its points lies
// inside the geometry as the depth buffer sees it (`inside`). The AO is the
// fraction of open directions: the estimate of
//   AO(P) = 1/pi ∫ V_r(P, w) (N . w) dw
// (visibility within r, cosine-weighted), written to an R16F target.
// Depth, positions and normals come only through gbuffer_read.glsl.
#include "common/gbuffer_read.glsl"
uniform mat4 u_view_projection;          // the inverse of u_inverse_view_projection
uniform vec4 u_kernel[MAX_AO_SAMPLES];   // unit directions (xyz), z along N
uniform int u_samples;
uniform float u_radius;
uniform float u_bias;
uniform sampler2D u_rotations;   // the 4x4 tile: (cos, sin) * 0.5 + 0.5, unit::AMBIENT_OCCLUSION
out float ao_out;

// Points along each direction: the last at r, so that V_r is tested to r.
const int STEPS = 4;

// An orthonormal frame (t, b, n) for the unit normal n (Duff et al. 2017);
// the CPU twin is `tangent_frame` in src/lighting/ambient_occlusion.rs.
void tangent_frame(vec3 n, out vec3 t, out vec3 b) {
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float c = n.x * n.y * a;
    t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
    b = vec3(c, s + n.y * n.y * a, -n.y);
}

// Whether the world point S lies inside the geometry according to the
// depth buffer: project S into the view, read the surface Q (normal N_Q)
// the G-buffer shows at that pixel, and call S inside when it lies more
// than u_bias behind Q's tangent plane. The tangent plane, not the depth
// alone: on a plane seen at a grazing angle the depth changes fast across
// a pixel, but a point above the plane is above it wherever in the pixel
// it falls, so an open plane stays exactly unoccluded.
// Range check: Q must be within r of S. A surface far in front of S (an
// object before a distant background) says nothing about whether S is
// inside something: without the check it would darken a halo around it.
// Off the view, or over the background, nothing is known: open.
bool inside(vec3 S) {
    vec4 clip = u_view_projection * vec4(S, 1.0);
    if (clip.w <= 0.0) {
        return false;
    }
    vec2 ndc = clip.xy / clip.w;
    if (any(greaterThan(abs(ndc), vec2(1.0)))) {
        return false;
    }
    ivec2 last = ivec2(u_viewport.xy + u_viewport.zw) - 1;
    ivec2 texel = min(ivec2(u_viewport.xy + (ndc * 0.5 + 0.5) * u_viewport.zw), last);
    Surface q = read_geometry_texel(texel);
    if (q.depth == 1.0) {
        return false;
    }
    float behind = -dot(S - q.P, normalize(q.N));
    return behind > u_bias && distance(S, q.P) < u_radius;
}

void main() {
    Surface s = read_geometry_texel(ivec2(gl_FragCoord.xy));
    if (s.depth == 1.0) {
        ao_out = 1.0;   // background: the composite shows the background colour
        return;
    }
    vec3 N = normalize(s.N);
    vec3 t, b;
    tangent_frame(N, t, b);
    // This pixel's turn about N, from the tile repeated over the screen.
    vec2 turn = normalize(texelFetch(u_rotations, ivec2(gl_FragCoord.xy) & 3, 0).xy * 2.0 - 1.0);
    vec3 T = turn.x * t + turn.y * b;
    vec3 B = -turn.y * t + turn.x * b;
    int open = 0;
    for (int i = 0; i < u_samples; ++i) {
        vec3 k = u_kernel[i].xyz;
        vec3 w = T * k.x + B * k.y + N * k.z;
        bool hit = false;
        for (int j = 1; j <= STEPS && !hit; ++j) {
            hit = inside(s.P + (u_radius * float(j) / float(STEPS)) * w);
        }
        if (!hit) {
            ++open;
        }
    }
    ao_out = float(open) / float(u_samples);
}
