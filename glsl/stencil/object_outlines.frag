#version 330 core
// The outline's flat colour (step 2); step 1 writes no colour (glColorMask off).
#include "common/lighting_output.glsl"

uniform vec3 u_color;   // linear RGB

out vec4 frag_color;

void main() {
    frag_color = output_color(u_color);
}
