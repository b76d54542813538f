#version 330 core
// Shadow pass, cube map in one pass: each triangle is sent to all six faces
// of the layered framebuffer, gl_Layer choosing the face (+x, -x, +y, -y,
// +z, -z) and u_face_view_projection[face] projecting it there.
layout(triangles) in;
layout(triangle_strip, max_vertices = 18) out;

uniform mat4 u_face_view_projection[6];

in vec3 v_world[];
out vec3 g_world;
#ifndef DEPTH_ONLY
in vec2 v_uv[];
out vec2 g_uv;
#endif

void main() {
    for (int face = 0; face < 6; ++face) {
        for (int i = 0; i < 3; ++i) {
            gl_Layer = face;
            g_world = v_world[i];
#ifndef DEPTH_ONLY
            g_uv = v_uv[i];
#endif
            gl_Position = u_face_view_projection[face] * vec4(v_world[i], 1.0);
            EmitVertex();
        }
        EndPrimitive();
    }
}
