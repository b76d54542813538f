#version 330 core
// A transparent object (notes 01 §4.5): lit like a forward fragment (the same
// Phong code, glsl/common/lighting.glsl), written with alpha = the material's
// opacity; glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA) mixes it with
// what lies behind: C = C_source * alpha + C_dest * (1 - alpha).
#include "blending/transparent_surface.glsl"

out vec4 frag_color;

void main() {
    frag_color = transparent_color();
}
