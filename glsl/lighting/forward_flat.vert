#version 330 core
// Flat shading (notes 01 §8.2): the vertex shader only moves vertices to
// world space; the geometry shader lights each triangle once.
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
layout(location = 4) in vec3 a_color;
uniform mat4 u_model;
uniform vec4 u_uv_transform;   // the material's scale.xy, offset.zw (notes 01 §5)
out vec3 g_position;
out vec2 g_uv;
out vec3 g_color;
void main() {
    g_position = (u_model * vec4(a_position, 1.0)).xyz;
    g_uv = a_uv * u_uv_transform.xy + u_uv_transform.zw;
    g_color = a_color;
}
