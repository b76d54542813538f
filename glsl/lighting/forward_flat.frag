#version 330 core
// Flat shading: the geometry shader already lit the whole triangle.
#include "common/lighting_output.glsl"
flat in vec3 f_color;
out vec4 frag_color;
void main() {
    frag_color = output_color(f_color);
}
