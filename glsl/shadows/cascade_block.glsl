// The cascades of a directional light's shadow (src/frame/shadows/cascades.rs
// writes the block): which cascade's slice of the camera's depth range holds
// a point, and the cascade colours (shadow.cascade_colors). Included by
// shadows/cascaded_shadow_maps.glsl (the lookup), and by the deferred
// paths' last passes (deferred/composite.frag, the light pre-pass's
// combine) built with CASCADE_TINTS, which tint by the G-buffer's point.
#define MAX_CASCADES 8

// std140, src/frame/shadows/cascades.rs writes this layout.
layout(std140) uniform Cascades {
    mat4 u_cascade_matrix[MAX_CASCADES];  // bias * projection * view of each cascade
    vec4 u_cascade_range[MAX_CASCADES];   // near, far (view depth), texel (world), 0
    vec4 u_cascade_eye;                   // the camera's eye, w: the cascade count
    vec4 u_cascade_forward;               // its unit forward axis, w: the blend band
    vec4 u_cascade_flags;                 // x: tint each cascade (debugging)
};

// The cascade colours: the tint of the last point looked up, which
// output_color (common/lighting_output.glsl) multiplies into the pixel when
// the shader includes this file before that one.
#define CASCADE_TINT 1
vec3 g_cascade_tint = vec3(1.0);

// The tint of cascade k when u_cascade_flags.x is set (else white).
vec3 cascade_tint(int k) {
    const vec3 TINTS[MAX_CASCADES] = vec3[](
        vec3(1.0, 0.45, 0.45), vec3(0.45, 1.0, 0.45), vec3(0.5, 0.6, 1.0), vec3(1.0, 1.0, 0.4),
        vec3(1.0, 0.5, 1.0), vec3(0.4, 1.0, 1.0), vec3(1.0, 0.7, 0.35), vec3(0.75, 0.75, 0.75));
    return u_cascade_flags.x > 0.5 ? TINTS[k] : vec3(1.0);
}

// The cascade whose slice holds view depth z (the last past the far split).
int cascade_of(float z) {
    int count = int(u_cascade_eye.w);
    int k = 0;
    while (k < count - 1 && z > u_cascade_range[k].y) ++k;
    return k;
}

// The view depth of P: along the camera's axis.
float cascade_depth(vec3 P) {
    return dot(P - u_cascade_eye.xyz, u_cascade_forward.xyz);
}

// How far into cascade k's blend band view depth z lies: 1 outside the band
// (k alone), falling to 0 at the split (k + 1 alone).
float cascade_band(int k, float z) {
    float band = u_cascade_forward.w * (u_cascade_range[k].y - u_cascade_range[k].x);
    float to_split = u_cascade_range[k].y - z;
    if (k + 1 < int(u_cascade_eye.w) && band > 0.0 && to_split < band) {
        return clamp(to_split / band, 0.0, 1.0);
    }
    return 1.0;
}

// The tint at P: its cascade's, mixed into the next across the blend band
// as the lookup mixes their shadows. White with no cascades.
vec3 cascade_tint_at(vec3 P) {
    if (int(u_cascade_eye.w) < 1) return vec3(1.0);
    float z = cascade_depth(P);
    int k = cascade_of(z);
    float t = cascade_band(k, z);
    return t < 1.0 ? mix(cascade_tint(k + 1), cascade_tint(k), t) : cascade_tint(k);
}
