#version 330 core
// Shadow pass, 2D map (notes 01 §8.5, first pass): the scene "rendered from
// the position of the light in the relevant direction"; only depth is kept.
// u_light_view_projection is orthographic for a directional light and
// perspective for a spot light (notes 02).
layout(location = 0) in vec3 a_position;

uniform mat4 u_model;
uniform mat4 u_light_view_projection;

void main() {
    gl_Position = u_light_view_projection * u_model * vec4(a_position, 1.0);
}
