// What a vertex shader passes on about the surface for the fragment shader
// to interpolate (notes 01 §4.1, §5): the texture coordinates, after the
// material's transform uv x scale + offset, and the vertex colour (white
// where the mesh has none). Each goes out twice: v_uv and v_color are
// interpolated perspective-correctly (divided by w, interpolated,
// multiplied back: what notes 01 §5.1 calls the "affine transform");
// v_uv_affine and v_color_affine linearly across the screen
// (`noperspective`), which is what bends a tilted texture.
// common/surface_in.glsl picks one pair in the fragment shader.
layout(location = 4) in vec3 a_color;
uniform vec4 u_uv_transform;   // scale.xy, offset.zw

out vec2 v_uv;
out vec3 v_color;
noperspective out vec2 v_uv_affine;
noperspective out vec3 v_color_affine;

vec2 texcoord(vec2 uv) {
    return uv * u_uv_transform.xy + u_uv_transform.zw;
}

void write_surface(vec2 uv) {
    v_uv = texcoord(uv);
    v_uv_affine = v_uv;
    v_color = a_color;
    v_color_affine = a_color;
}
