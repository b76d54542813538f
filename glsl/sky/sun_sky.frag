#version 330 core
// The sun-sky pass: the Preetham sky (common/preetham.glsl, the twin of
// src/math/preetham.rs) in the direction of each pixel's ray.
#include "common/preetham.glsl"
#include "common/lighting_output.glsl"
in vec3 v_direction;
uniform float u_sky_intensity;
out vec4 frag_color;

void main() {
    frag_color = output_color(u_sky_intensity * preetham_sky(normalize(v_direction)));
}
