#version 330 core
// G-buffer pass: write the surface's data, no lighting.
//   0: normal (world, unit) + shininess   RGBA16F
//   1: diffuse albedo                     SRGB8_ALPHA8 (GL_FRAMEBUFFER_SRGB on)
//   2: specular colour                    SRGB8_ALPHA8
//   depth: the depth buffer itself; position is rebuilt from it.
#include "common/normals.glsl"
#include "common/material.glsl"
#include "common/alpha_test.glsl"
in vec3 v_position;
in vec3 v_normal;
#include "common/surface_in.glsl"
#include "common/bump_mapping.glsl"

layout(location = 0) out vec4 g_normal_shininess;
layout(location = 1) out vec4 g_albedo;
layout(location = 2) out vec4 g_specular;

void main() {
    vec2 uv = surface_uv();
    alpha_test(material_alpha(uv));
    // The normal after the normal map (notes 01 §8.4) is what the lights read.
    g_normal_shininess = vec4(bumped_normal(safe_normal(v_normal, v_position), uv), u_shininess);
    g_albedo = vec4(material_diffuse(uv) * surface_color(), 1.0);
    g_specular = vec4(u_specular, 1.0);
}
