#version 330 core
// Notes 01 §8.6.2 step 3, "Generate final image": a screen-sized triangle
// that adds the ambient term to the accumulated light and encodes to sRGB.
#include "gbuffer_read.glsl"
#include "lighting_output.glsl"
uniform sampler2D u_light;   // unit 4: the accumulated light (HDR)
uniform vec3 u_ambient;
uniform vec3 u_background;
out vec4 frag_color;

void main() {
    vec2 uv = gbuffer_uv();
    float depth = texture(u_gbuffer_depth, uv).r;
    if (depth == 1.0) {
        frag_color = output_color(u_background);
        return;
    }
    vec3 kd = texture(u_gbuffer_albedo, uv).rgb;
    frag_color = output_color(u_ambient * kd + texture(u_light, uv).rgb);
}
