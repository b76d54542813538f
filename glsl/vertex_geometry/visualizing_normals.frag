#version 330 core
// The normals' flat colour.
#include "common/lighting_output.glsl"

uniform vec3 u_color;   // linear RGB

out vec4 frag_color;

void main() {
    frag_color = output_color(u_color);
}
