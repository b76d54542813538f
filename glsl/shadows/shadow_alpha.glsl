// The caster's alpha test in the shadow pass (notes 05, "Alpha Test", applied
// to notes 01 §8.5): the same test, on the same alpha (the diffuse
// texture's, glsl/common/material.glsl), as the passes that draw the object,
// so the shadow has the shape the eye sees. u_alpha_test is ALPHA_ALWAYS
// (0) for an opaque caster: nothing is sampled or discarded.
#include "common/alpha_test.glsl"
uniform bool u_has_diffuse_texture;
uniform sampler2D u_diffuse_texture;   // unit::DIFFUSE_TEXTURE

void shadow_alpha_test(vec2 uv) {
    if (u_alpha_test == ALPHA_ALWAYS) return;
    alpha_test(u_has_diffuse_texture ? texture(u_diffuse_texture, uv).a : 1.0);
}
