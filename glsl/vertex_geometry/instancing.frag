#version 330 core
// A rock's colour: Lambert from one directional light, plus the ambient term.
#include "common/lighting_output.glsl"
in vec3 v_normal;

uniform vec3 u_color;      // linear RGB
uniform vec3 u_ambient;
uniform vec3 u_to_light;   // unit, towards the light
uniform vec3 u_radiance;

out vec4 frag_color;

void main() {
    vec3 n = normalize(v_normal);
    vec3 c = u_color * (u_ambient + u_radiance * max(dot(n, u_to_light), 0.0));
    frag_color = output_color(c);
}
