#version 330 core
// "Clear" with the stencil test on (notes 05): glClear ignores the stencil
// test, so a full-screen triangle writes the clear colour and the far depth
// wherever the stencil test lets it.
uniform vec3 u_clear_color;   // as stored in the target (sRGB-encoded for 8-bit output)

out vec4 frag_color;

void main() {
    frag_color = vec4(u_clear_color, 1.0);
    gl_FragDepth = 1.0;
}
