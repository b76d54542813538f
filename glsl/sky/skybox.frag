#version 330 core
// The skybox pass: the environment cube map along each pixel's view ray.
#include "common/environment.glsl"
#include "common/lighting_output.glsl"
in vec3 v_direction;
out vec4 frag_color;

void main() {
    frag_color = output_color(texture(u_environment, v_direction).rgb);
}
