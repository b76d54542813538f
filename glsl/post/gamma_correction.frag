#version 330 core
// The gamma correction pass (notes 03, "Gamma Correction Pass"): the last
// step of the post chain, into the output.
uniform sampler2D u_image;   // the previous image (linear, 0..1 after tone mapping)
uniform float u_gamma;       // 2.2 unless the scene says otherwise
uniform bool u_encode;       // false: GL_FRAMEBUFFER_SRGB encodes, or the output is linear
out vec4 frag_color;

void main() {
    vec3 c = clamp(texelFetch(u_image, ivec2(gl_FragCoord.xy), 0).rgb, 0.0, 1.0);
    frag_color = vec4(u_encode ? pow(c, vec3(1.0 / u_gamma)) : c, 1.0);
}
