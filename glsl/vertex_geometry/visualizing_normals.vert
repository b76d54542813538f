#version 330 core
// Visualizing normal vectors (LearnOpenGL, 4.advanced_opengl "Geometry
// Shader"; src/techniques/vertex_geometry/visualizing_normals.rs): each
// vertex in world space, with its world normal, for the geometry shader.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

uniform mat4 u_model;
uniform mat3 u_normal_matrix;

out vec3 v_world;
out vec3 v_normal;

void main() {
    v_world = (u_model * vec4(a_position, 1.0)).xyz;
    v_normal = normalize(u_normal_matrix * a_normal);
}
