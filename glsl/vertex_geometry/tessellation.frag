#version 400 core
// Tessellation, step 4: the terrain lit by every light of the Lights block
// (Phong, common/lighting.glsl), no shadows.
#include "common/lighting.glsl"
#include "common/lighting_output.glsl"
uniform vec3 u_eye;
uniform vec3 u_ambient;
uniform vec3 u_color;
uniform int u_light_count;
in vec3 v_world;
in vec3 v_normal;
out vec4 frag_color;

void main() {
    vec3 N = normalize(v_normal);
    vec3 V = normalize(u_eye - v_world);
    vec3 c = u_ambient * u_color;
    for (int i = 0; i < u_light_count; ++i)
        c += phong(u_lights[i], v_world, N, V, u_color, vec3(0.1), 16.0);
    frag_color = output_color(c);
}
