#version 330 core
// One triangle that covers the screen (cheaper than a two-triangle quad: no
// diagonal seam to shade twice). u_mvp is the identity for a full-screen pass.
layout(location = 0) in vec3 a_position;
uniform mat4 u_mvp;
void main() {
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
