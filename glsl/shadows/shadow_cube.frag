#version 330 core
// Shadow pass, cube map: store the distance to the light over `far`, the
// same number whichever face holds the point (no seams between faces), and
// as precise near the far end as near the light (docs/shadows.md). Writing
// gl_FragDepth bypasses glPolygonOffset, so the slope-scaled bias is added
// here, as glPolygonOffset would: slope_bias x the depth's largest slope
// across a pixel.
#ifdef LAYERED
in vec3 g_world;
#define WORLD g_world
#else
in vec3 v_world;
#define WORLD v_world
#endif

uniform vec3 u_light_position;
uniform float u_far;
uniform float u_slope_bias;

void main() {
    float d = length(WORLD - u_light_position) / u_far;
    float slope = max(abs(dFdx(d)), abs(dFdy(d)));
    gl_FragDepth = d + u_slope_bias * slope;
}
