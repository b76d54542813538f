#version 330 core
// Shadow pass, cube map: store the distance to the light over `far`, the
// same number whichever face holds the point (no seams between faces), and
// as precise near the far end as near the light (docs/shadows.md). Writing
// gl_FragDepth bypasses glPolygonOffset, so the slope-scaled bias is added
// here, as glPolygonOffset would: slope_bias x the depth's largest slope
// across a pixel.
// DEPTH_ONLY (opaque casters, src/techniques/shadows/casters.rs): the
// distance alone, without the alpha test.
#ifndef DEPTH_ONLY
#include "shadows/shadow_alpha.glsl"
#endif
#ifdef LAYERED
in vec3 g_world;
#define WORLD g_world
#define UV g_uv
#else
in vec3 v_world;
#define WORLD v_world
#define UV v_uv
#endif
#ifndef DEPTH_ONLY
#ifdef LAYERED
in vec2 g_uv;
#else
in vec2 v_uv;
#endif
#endif

uniform vec3 u_light_position;
uniform float u_far;
uniform float u_slope_bias;

void main() {
    // A leaf casts a leaf: the caster's alpha test first.
#ifndef DEPTH_ONLY
    shadow_alpha_test(UV);
#endif
    float d = length(WORLD - u_light_position) / u_far;
    float slope = max(abs(dFdx(d)), abs(dFdy(d)));
    gl_FragDepth = d + u_slope_bias * slope;
}
