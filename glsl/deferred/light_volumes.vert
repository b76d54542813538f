#version 330 core
// Light volume (notes 04): a simple MVP shader. The mesh is a sphere scaled to
// the light's radius, a cone turned and scaled to a spot light, or the
// full-screen triangle with an identity MVP for a directional light.
layout(location = 0) in vec3 a_position;
uniform mat4 u_mvp;
void main() {
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
