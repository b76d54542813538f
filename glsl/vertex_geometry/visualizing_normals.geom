#version 330 core
// One line per vertex of each triangle, from the vertex along its normal,
// u_length long (world units): 3 lines, 6 vertices a triangle. g_world is
// the line's end in world space (transform feedback captures it in tests).
layout(triangles) in;
layout(line_strip, max_vertices = 6) out;

in vec3 v_world[];
in vec3 v_normal[];

uniform mat4 u_view_projection;
uniform float u_length;

out vec3 g_world;

void emit(vec3 p) {
    g_world = p;
    gl_Position = u_view_projection * vec4(p, 1.0);
    EmitVertex();
}

void main() {
    for (int i = 0; i < 3; i++) {
        emit(v_world[i]);
        emit(v_world[i] + v_normal[i] * u_length);
        EndPrimitive();
    }
}
