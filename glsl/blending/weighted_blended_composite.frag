#version 330 core
// Weighted blended OIT, the composite (McGuire and Bavoil 2013, §4): the
// weighted average colour sum(C alpha w) / sum(alpha w), over the opaque
// image with coverage 1 - revealage:
// glBlendFunc(GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA) with alpha = revealage.
uniform sampler2D u_accum;
uniform sampler2D u_weight;
out vec4 frag_color;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 accum = texelFetch(u_accum, p, 0);
    float revealage = accum.a;
    // No transparent fragment here: leave the opaque image as it is.
    if (revealage == 1.0) discard;
    float weights = texelFetch(u_weight, p, 0).r;
    frag_color = vec4(accum.rgb / max(weights, 1e-5), revealage);
}
