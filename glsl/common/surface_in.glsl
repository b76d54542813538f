// The interpolated texture coordinates and vertex colour in a fragment
// shader (common/surface.glsl wrote them): perspective-correct, or affine
// with render.interpolation = "affine" (notes 01 §4.1, §5.1).
in vec2 v_uv;
in vec3 v_color;
noperspective in vec2 v_uv_affine;
noperspective in vec3 v_color_affine;
uniform bool u_affine;

vec2 surface_uv() {
    return u_affine ? v_uv_affine : v_uv;
}

vec3 surface_color() {
    return u_affine ? v_color_affine : v_color;
}
