#version 330 core
// Object outlines (LearnOpenGL, 4.advanced_opengl "Stencil testing";
// src/techniques/stencil/object_outlines.rs). Step 1 draws the object as it
// is (u_width = 0) to mark the stencil buffer; step 2 draws it again with
// every vertex moved u_width pixels along its normal as the screen sees it,
// so the outline is as wide in pixels at any distance. Its CPU twin is
// `extrude` in object_outlines.rs.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

uniform mat4 u_model;
uniform mat4 u_view_projection;
uniform mat3 u_normal_matrix;
uniform vec2 u_viewport;    // the view's size in pixels
uniform float u_width;      // pixels (0: the object itself)
#include "common/view.glsl"

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    vec4 c = u_view_projection * view_position(world);
    // The normal's direction on screen: d(c.xy / c.w) along the normal,
    // (n.xy c.w - c.xy n.w) / c.w^2, in pixels (x viewport / 2; c.w > 0
    // before clipping, so the direction is the numerator's).
    vec4 n = u_view_projection * vec4(u_normal_matrix * a_normal, 0.0);
    vec2 d = (n.xy * c.w - c.xy * n.w) * u_viewport;
    float len = length(d);
    if (u_width > 0.0 && len > 0.0) {
        // u_width pixels are 2 u_width / viewport in NDC, x c.w in clip space.
        c.xy += (d / len) * (2.0 * u_width / u_viewport) * c.w;
    }
    gl_Position = c;
    write_clip_distances(world);
}
