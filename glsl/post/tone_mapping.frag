#version 330 core
// Tone mapping, a stage of the post chain (notes 01 §9): HDR light to 0..1.
// The CPU twin of each curve is src/lighting/tonemap.rs.
uniform sampler2D u_image;   // the previous image (HDR, linear)
uniform int u_operator;      // 0 clamp, 1 Reinhard, 2 exposure, 3 ACES fit
uniform float u_exposure;    // the light is scaled by this first
out vec4 frag_color;

vec3 tonemap(vec3 x) {
    if (u_operator == 1) {
        return x / (1.0 + x);                  // Reinhard
    } else if (u_operator == 2) {
        return 1.0 - exp(-x);                  // exposure curve
    } else if (u_operator == 3) {
        // Narkowicz's fit of the ACES filmic curve.
        return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
    }
    return min(x, 1.0);                        // clamp
}

void main() {
    vec3 c = texelFetch(u_image, ivec2(gl_FragCoord.xy), 0).rgb;
    frag_color = vec4(tonemap(u_exposure * max(c, 0.0)), 1.0);
}
