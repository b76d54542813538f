#version 330 core
// The skybox pass (notes 03, Implementation): one full-screen triangle at
// z = w. After the perspective divide its depth is 1, the far plane; with
// glDepthFunc(GL_LEQUAL) it is drawn only where no geometry wrote a nearer
// depth. Drawn first (render.sky_first) the depth test is off and it covers
// every pixel.
layout(location = 0) in vec3 a_position;   // the triangle, in NDC
// Of this view (a planar mirror's reflection included).
uniform mat4 u_inverse_view_projection;
out vec3 v_direction;

void main() {
    gl_Position = vec4(a_position.xy, 1.0, 1.0);   // z = w
    // The world ray through this corner: from its near-plane point to its
    // far-plane point; the cube map is looked up along it.
    vec4 near = u_inverse_view_projection * vec4(a_position.xy, -1.0, 1.0);
    vec4 far = u_inverse_view_projection * vec4(a_position.xy, 1.0, 1.0);
    v_direction = far.xyz / far.w - near.xyz / near.w;
}
