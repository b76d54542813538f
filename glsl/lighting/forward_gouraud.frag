#version 330 core
// Gouraud shading: the light was computed per vertex; only the material is per fragment.
#include "common/lighting_output.glsl"
#include "common/material.glsl"
#include "common/alpha_test.glsl"
in vec3 v_diffuse_light;
in vec3 v_specular_light;
#include "common/surface_in.glsl"
uniform vec3 u_ambient;
out vec4 frag_color;

void main() {
    vec2 uv = surface_uv();
    alpha_test(material_alpha(uv));
    vec3 kd = material_diffuse(uv) * surface_color();
    vec3 c = kd * (u_ambient + v_diffuse_light) + material_specular() * material_specular_map(uv) * v_specular_light;
    frag_color = output_color(c);
}
