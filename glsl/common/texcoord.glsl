// Texture coordinates out of a vertex shader (notes 01 §5): the material's
// transform uv x scale + offset, then two copies of the result. v_uv is
// interpolated perspective-correctly (divided by w, interpolated, multiplied
// back: what notes 01 §5.1 calls the "affine transform"); v_uv_affine
// linearly across the screen, which is what bends a tilted texture.
// common/texcoord_in.glsl picks one in the fragment shader.
uniform vec4 u_uv_transform;   // scale.xy, offset.zw

out vec2 v_uv;
noperspective out vec2 v_uv_affine;

vec2 texcoord(vec2 uv) {
    return uv * u_uv_transform.xy + u_uv_transform.zw;
}

void write_texcoord(vec2 uv) {
    v_uv = texcoord(uv);
    v_uv_affine = v_uv;
}
