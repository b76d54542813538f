#version 330 core
// Depth peeling, blending a layer (premultiplied colour, alpha) as it is
// read: UNDER the layers before it into the accumulation target
// (glBlendFunc(GL_ONE_MINUS_DST_ALPHA, GL_ONE)), and at the end the
// accumulated layers OVER the opaque image
// (glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA)). The same shader both times.
uniform sampler2D u_layer;
out vec4 frag_color;

void main() {
    frag_color = texelFetch(u_layer, ivec2(gl_FragCoord.xy), 0);
}
