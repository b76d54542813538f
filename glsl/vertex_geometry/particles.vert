#version 330 core
// Particles (src/techniques/vertex_geometry/particles.rs): one point a
// particle, passed on to the geometry shader.
layout(location = 0) in vec4 a_point;   // position, age / lifetime
out float v_life;

void main() {
    gl_Position = vec4(a_point.xyz, 1.0);
    v_life = a_point.w;
}
