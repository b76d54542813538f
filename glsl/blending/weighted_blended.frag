#version 330 core
// Weighted blended order-independent transparency, the accumulation pass
// (McGuire and Bavoil 2013, §3-4): every transparent fragment adds its
// premultiplied colour times a weight w(z, alpha) to `accum.rgb`, and
// multiplies `accum.a` (the revealage, cleared to 1) by (1 - alpha); its
// weight alpha * w goes to `weight.r`. The blend does the sums in any order:
// glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA).
#include "blending/transparent_surface.glsl"

// The opaque world's depth (the world target's): what lies behind it is hidden.
uniform sampler2D u_opaque_depth;

layout(location = 0) out vec4 accum;
layout(location = 1) out vec4 weight;

// The paper's equation (7): w(z, alpha) = alpha * clamp(10 / (1e-5 +
// (|z|/5)^2 + (|z|/200)^6), 1e-2, 3e3), z the view-space depth.
float paper_weight(float z, float alpha) {
    float d = 10.0 / (1e-5 + pow(z / 5.0, 2.0) + pow(z / 200.0, 6.0));
    return alpha * clamp(d, 1e-2, 3e3);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    if (gl_FragCoord.z >= texelFetch(u_opaque_depth, p, 0).r) discard;
    vec4 c = transparent_color();
    // 1 / gl_FragCoord.w is the clip w, the view-space distance |z|.
    float w = paper_weight(1.0 / gl_FragCoord.w, c.a);
    accum = vec4(c.rgb * w, c.a);
    weight = vec4(w, 0.0, 0.0, 0.0);
}
