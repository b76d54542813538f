#version 330 core
// An area light seen: its radiance L_e from the side it shines toward
// (both sides when two-sided), black from behind a one-sided light.
#include "common/lighting_output.glsl"

uniform vec3 u_radiance;
uniform bool u_two_sided;

out vec4 frag_color;

void main() {
    // The lit side winds counter-clockwise: (c1 - c0) x (c3 - c0) is its normal.
    bool lit = gl_FrontFacing || u_two_sided;
    frag_color = output_color(lit ? u_radiance : vec3(0.0));
}
