#version 330 core
// Exploding objects (LearnOpenGL, 4.advanced_opengl "Geometry Shader"):
// each triangle moved along its face normal by
// magnitude x (sin(time) + 1) / 2, then projected; the fragment shader is
// forward's (lighting/forward.frag), so it reads the outputs forward.vert
// would write. With magnitude 0 every output equals forward.vert's.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in vec3 g_position[];
in vec3 g_normal[];
in vec2 g_uv[];
in vec3 g_color[];
in vec4 g_tangent[];

uniform mat4 u_view_projection;
uniform float u_time;        // the scene's time, seconds
uniform float u_magnitude;   // world units
uniform float u_mirror;      // -1 when the model matrix flips handedness
// The view drawn for: a mirror's clip plane, or a curved mirror's
// reflection of each vertex (common/view.glsl).
#include "common/view.glsl"

// What forward.frag reads (common/surface.glsl, common/tangent.glsl).
out vec3 v_position;
out vec3 v_normal;
out vec2 v_uv;
out vec3 v_color;
noperspective out vec2 v_uv_affine;
noperspective out vec3 v_color_affine;
out vec4 v_tangent;

// The lesson's GetNormal, in world space: counter-clockwise front faces
// give the outward normal (notes 01 §3.4). A degenerate triangle has none
// and stays where it is.
vec3 get_normal() {
    vec3 a = g_position[1] - g_position[0];
    vec3 b = g_position[2] - g_position[0];
    vec3 n = u_mirror * cross(a, b);
    float len = length(n);
    return len > 0.0 ? n / len : vec3(0.0);
}

// The lesson's explode: the position moved along the normal.
vec3 explode(vec3 position, vec3 normal) {
    vec3 direction = normal * ((sin(u_time) + 1.0) / 2.0) * u_magnitude;
    return position + direction;
}

void main() {
    vec3 normal = get_normal();
    for (int k = 0; k < 3; ++k) {
        vec4 world = vec4(explode(g_position[k], normal), 1.0);
        v_position = world.xyz;
        v_normal = g_normal[k];
        v_uv = g_uv[k];
        v_uv_affine = g_uv[k];
        v_color = g_color[k];
        v_color_affine = g_color[k];
        v_tangent = g_tangent[k];
        gl_Position = u_view_projection * view_position(world);
        write_clip_distances(world);
        EmitVertex();
    }
    EndPrimitive();
}
