#version 330 core
// Exploding objects (LearnOpenGL, 4.advanced_opengl "Geometry Shader";
// src/techniques/vertex_geometry/exploding_objects.rs): what forward.vert
// computes per vertex, in world space, handed to the geometry shader, which
// moves the triangle and projects it (exploding_objects.geom).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_tangent;
layout(location = 4) in vec3 a_color;

uniform mat4 u_model;
uniform mat3 u_normal_matrix;
uniform vec4 u_uv_transform;   // the material's scale.xy, offset.zw (notes 01 §5)
uniform float u_tangent_sign;  // sign(det(mat3(u_model)))

out vec3 g_position;
out vec3 g_normal;
out vec2 g_uv;
out vec3 g_color;
out vec4 g_tangent;

void main() {
    g_position = (u_model * vec4(a_position, 1.0)).xyz;
    g_normal = u_normal_matrix * a_normal;
    g_uv = a_uv * u_uv_transform.xy + u_uv_transform.zw;
    g_color = a_color;
    g_tangent = vec4(mat3(u_model) * a_tangent.xyz, a_tangent.w * u_tangent_sign);
}
