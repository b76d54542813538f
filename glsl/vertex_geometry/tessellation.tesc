#version 400 core
// Tessellation, step 2: the control shader sets how finely the tessellator
// divides each patch. "Inner level controls tessellation inside the area,
// outer level controls tessellation outside the area" (notes 01 §3.1).
//
// With u_shared_edges, each edge's outer level comes from the distance of
// the edge's own middle to the eye: the two patches that share an edge
// compute the same level from the same point, as the notes require. Without
// it, one level per patch from its centre: neighbours split their shared
// edge differently, and the terrain cracks.
layout(vertices = 4) out;
uniform vec3 u_eye;
uniform vec2 u_levels;      // far, near
uniform vec2 u_distances;   // near, far
uniform bool u_shared_edges;

float level_at(vec3 p) {
    float t = clamp((distance(p, u_eye) - u_distances.x) / (u_distances.y - u_distances.x), 0.0, 1.0);
    return mix(u_levels.y, u_levels.x, t);
}

void main() {
    gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
    if (gl_InvocationID != 0) return;
    // Corners: 0 (u0, v0), 1 (u1, v0), 2 (u1, v1), 3 (u0, v1). The quad
    // domain's outer levels: [0] the edge u = 0, [1] v = 0, [2] u = 1, [3] v = 1.
    vec3 p0 = gl_in[0].gl_Position.xyz;
    vec3 p1 = gl_in[1].gl_Position.xyz;
    vec3 p2 = gl_in[2].gl_Position.xyz;
    vec3 p3 = gl_in[3].gl_Position.xyz;
    vec4 outer;
    if (u_shared_edges) {
        outer = vec4(level_at(0.5 * (p0 + p3)), level_at(0.5 * (p0 + p1)),
                     level_at(0.5 * (p1 + p2)), level_at(0.5 * (p3 + p2)));
    } else {
        outer = vec4(level_at(0.25 * (p0 + p1 + p2 + p3)));
    }
    gl_TessLevelOuter[0] = outer.x;
    gl_TessLevelOuter[1] = outer.y;
    gl_TessLevelOuter[2] = outer.z;
    gl_TessLevelOuter[3] = outer.w;
    gl_TessLevelInner[0] = max(outer.y, outer.w);
    gl_TessLevelInner[1] = max(outer.x, outer.z);
}
