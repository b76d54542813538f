#version 330 core
// Instancing (LearnOpenGL, 4.advanced_opengl "Instancing"; src/techniques/
// vertex_geometry/instancing.rs). Built twice: with INSTANCED each rock's
// model matrix is an instanced array, a mat4 attribute in locations 5-8
// (four vec4 columns, glVertexAttribDivisor(loc, 1): one per instance, not
// per vertex; locations 3 and 4 are the meshes' tangents and colours);
// without it, a uniform set before each rock's draw.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
#ifdef INSTANCED
layout(location = 5) in mat4 a_model;
#else
uniform mat4 u_model;
#endif

uniform mat4 u_view_projection;
#include "common/view.glsl"

out vec3 v_normal;

void main() {
#ifdef INSTANCED
    mat4 model = a_model;
#else
    mat4 model = u_model;
#endif
    vec4 world = model * vec4(a_position, 1.0);
    // A rock is turned and scaled alike on every axis: mat3(model) keeps
    // its normals' directions.
    v_normal = mat3(model) * a_normal;
    gl_Position = u_view_projection * view_position(world);
    write_clip_distances(world);
}
