#version 330 core
// Shadow pass, 2D map: no colour. "The map is the depth buffer" (notes 01
// §8.5): the rasteriser writes each fragment's depth, glPolygonOffset's
// slope-scaled bias included. An alpha-tested caster (a leaf on a quad)
// runs its material's alpha test first: what the test discards casts no
// shadow, so a leaf casts a leaf. DEPTH_ONLY (opaque casters): empty.
#ifndef DEPTH_ONLY
#include "shadows/shadow_alpha.glsl"
in vec2 v_uv;
#endif

void main() {
#ifndef DEPTH_ONLY
    shadow_alpha_test(v_uv);
#endif
}
