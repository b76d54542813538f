// Texture coordinates into a fragment shader (common/texcoord.glsl wrote
// them): perspective-correct, or affine with render.uv_interpolation =
// "affine" (notes 01 §5.1).
in vec2 v_uv;
noperspective in vec2 v_uv_affine;
uniform bool u_affine_uv;

vec2 surface_uv() {
    return u_affine_uv ? v_uv_affine : v_uv;
}
