// The last step of every path: write linear colour, or sRGB-encode it for an
// 8-bit image (u_output_srgb).
uniform bool u_output_srgb;

// Exact sRGB encoding (IEC 61966-2-1), applied once at the end of the frame.
vec3 srgb_encode(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    vec3 lo = c * 12.92;
    vec3 hi = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
    return mix(lo, hi, step(vec3(0.0031308), c));
}

vec4 output_color(vec3 c) {
#ifdef CASCADE_TINT
    c *= g_cascade_tint;   // the cascade colours (shadows/cascaded_shadow_maps.glsl)
#endif
#ifdef HARDWARE_SRGB
    // GL encodes: an SRGB8_ALPHA8 output with GL_FRAMEBUFFER_SRGB on (the
    // composite, src/frame/plan.rs hardware_srgb); it clamps to [0, 1] too.
    return vec4(c, 1.0);
#else
    return vec4(u_output_srgb ? srgb_encode(c) : c, 1.0);
#endif
}
