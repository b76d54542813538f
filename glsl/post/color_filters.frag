#version 330 core
// Per-pixel colour filters, stages of the post chain (notes 01 §9).
uniform sampler2D u_image;   // the previous image
uniform int u_mode;          // 0 grayscale (Rec. 709 luminance), 1 invert
out vec4 frag_color;

void main() {
    vec3 c = texelFetch(u_image, ivec2(gl_FragCoord.xy), 0).rgb;
    if (u_mode == 0) {
        c = vec3(dot(c, vec3(0.2126, 0.7152, 0.0722)));
    } else {
        c = 1.0 - clamp(c, 0.0, 1.0);
    }
    frag_color = vec4(c, 1.0);
}
