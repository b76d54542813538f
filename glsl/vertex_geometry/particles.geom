#version 330 core
// Notes 01 §3.2: the geometry shader "takes single primitive as input and
// outputs zero or more new primitives": a point in, a camera-facing quad
// out (a strip of 4 vertices), its corners along the view's right and up.
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;
uniform mat4 u_view_projection;   // of the view (reflected, in a mirror)
uniform mat4 u_view;
uniform float u_size;
in float v_life[];
out vec2 g_corner;
out float g_life;

void main() {
    vec3 right = vec3(u_view[0][0], u_view[1][0], u_view[2][0]) * (0.5 * u_size);
    vec3 up = vec3(u_view[0][1], u_view[1][1], u_view[2][1]) * (0.5 * u_size);
    vec3 c = gl_in[0].gl_Position.xyz;
    vec2 corners[4] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));
    for (int k = 0; k < 4; ++k) {
        g_corner = corners[k];
        g_life = v_life[0];
        gl_Position = u_view_projection * vec4(c + right * corners[k].x + up * corners[k].y, 1.0);
        EmitVertex();
    }
    EndPrimitive();
}
