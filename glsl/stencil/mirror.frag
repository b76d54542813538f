#version 330 core
// The mirror's colour: the background while its region is marked (a mirror
// that reflects nothing shows the clear colour), then its tint x reflectance
// x roughening texture, which the blend multiplies the reflection by.
#include "common/lighting_output.glsl"
in vec2 v_uv;

uniform vec3 u_color;            // linear RGB
uniform bool u_has_roughness;
uniform sampler2D u_roughness;   // linear greyscale

out vec4 frag_color;

void main() {
    float rough = u_has_roughness ? texture(u_roughness, v_uv).r : 1.0;
    frag_color = output_color(u_color * rough);
}
