// The Phong material of the object being drawn.
uniform vec3 u_diffuse;
uniform vec3 u_specular;
uniform float u_shininess;
uniform bool u_has_diffuse_texture;
uniform sampler2D u_diffuse_texture;   // sRGB texture: sampling returns linear

vec3 material_diffuse(vec2 uv) {
    return u_has_diffuse_texture ? u_diffuse * texture(u_diffuse_texture, uv).rgb : u_diffuse;
}

// The texture's alpha, what the alpha test reads (1 without a texture).
float material_alpha(vec2 uv) {
    return u_has_diffuse_texture ? texture(u_diffuse_texture, uv).a : 1.0;
}
