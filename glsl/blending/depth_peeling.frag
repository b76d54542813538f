#version 330 core
// Depth peeling, one layer (Everitt 2001, "Interactive Order-Independent
// Transparency"): of the transparent fragments in front of the opaque world
// and behind the previous layer's, the depth test keeps the nearest. Its
// colour (premultiplied) and its exact depth are written; the next layer
// peels what lies behind that depth.
#include "blending/transparent_surface.glsl"

uniform sampler2D u_opaque_depth;    // the world target's depth
uniform sampler2D u_previous_depth;  // the previous layer's depth (R32F)
uniform bool u_first_layer;

layout(location = 0) out vec4 layer_color;
layout(location = 1) out vec4 layer_depth;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float z = gl_FragCoord.z;
    // The opaque world hides it (GL_LESS against the opaque depth).
    if (z >= texelFetch(u_opaque_depth, p, 0).r) discard;
    // Peeled already: at or in front of the previous layer (Everitt's
    // second depth test, GL_GREATER against the previous layer's depth).
    if (!u_first_layer && z <= texelFetch(u_previous_depth, p, 0).r) discard;
    vec4 c = transparent_color();
    layer_color = vec4(c.rgb * c.a, c.a);
    layer_depth = vec4(z, 0.0, 0.0, 0.0);
}
