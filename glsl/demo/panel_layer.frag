#version 330 core
// The panel, painted by egui into a texture of its own (premultiplied
// alpha), laid over the frame with glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA).
uniform sampler2D u_layer;
out vec4 frag_color;

void main() {
    frag_color = texelFetch(u_layer, ivec2(gl_FragCoord.xy), 0);
}
