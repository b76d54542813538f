#version 330 core
// The demo's pass inspector: one render target's attachment drawn over the
// window, made visible. u_mode picks how:
//   0 colour as stored (the output's sRGB bytes, or a linear colour encoded)
//   1 normal: n * 0.5 + 0.5                2 shininess: alpha / 256
//   3 HDR light: exposure x value, encoded  4 depth, linearised near..far
//   5 a count (volumes over a pixel) as a heat map, u_scale the hottest
//   6 one channel (R) in grey: 0 black, 1 white
// u_level picks the mip level (0: the image itself), stretched over the view.
#include "common/lighting_output.glsl"
uniform sampler2D u_texture;
uniform float u_level;
uniform int u_mode;
uniform bool u_encode;      // mode 0: the texture holds linear colour
uniform float u_exposure;
uniform float u_scale;
uniform float u_near;
uniform float u_far;
uniform bool u_orthographic; // depth is then linear already
uniform vec2 u_viewport;    // the size drawn into, in pixels
out vec4 frag_color;

// Black, then blue, green, yellow, red as t goes from 0 to 1.
vec3 heat(float t) {
    t = clamp(t, 0.0, 1.0);
    return clamp(vec3(4.0 * t - 2.0, 2.0 - abs(4.0 * t - 2.0), 2.0 - 4.0 * t), 0.0, 1.0)
        * min(1.0, 8.0 * t);
}

void main() {
    vec4 t = textureLod(u_texture, gl_FragCoord.xy / u_viewport, u_level);
    vec3 c;
    if (u_mode == 0) {
        c = u_encode ? srgb_encode(t.rgb) : t.rgb;
    } else if (u_mode == 1) {
        c = t.xyz * 0.5 + 0.5;
    } else if (u_mode == 2) {
        c = vec3(t.a / 256.0);
    } else if (u_mode == 3) {
        c = srgb_encode(t.rgb * u_exposure);
    } else if (u_mode == 5) {
        c = heat(t.r / u_scale);
    } else if (u_mode == 6) {
        c = vec3(clamp(t.r, 0.0, 1.0));
    } else {
        // Window depth d in [0, 1] back to eye distance, then to [0, 1] over near..far.
        float z = t.r * 2.0 - 1.0;
        float dist = u_orthographic
            ? u_near + t.r * (u_far - u_near)
            : 2.0 * u_near * u_far / (u_far + u_near - z * (u_far - u_near));
        c = vec3(t.r == 1.0 ? 1.0 : (dist - u_near) / (u_far - u_near));
    }
    frag_color = vec4(c, 1.0);
}
