#version 330 core
// Particles as quads built on the CPU (expand = "cpu"): the comparison for
// the geometry shader. Each vertex already sits at its quad's corner.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec2 a_corner;
layout(location = 2) in float a_life;
uniform mat4 u_view_projection;
out vec2 g_corner;
out float g_life;

void main() {
    g_corner = a_corner;
    g_life = a_life;
    gl_Position = u_view_projection * vec4(a_position, 1.0);
}
