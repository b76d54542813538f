// Notes 03, "Blur Pass and Merge Pass": what the bloom does to a pixel
// before it blurs it, the same as src/image_compare/bloom_reference.rs:
// NaN becomes 0, +inf the largest finite half float (65504), and anything
// negative 0. One NaN or inf would otherwise spread over the whole blur
// (NaN x 0 and inf x 0 are NaN), and no light is negative.
const float HALF_MAX = 65504.0;

vec4 bloom_sanitise(vec4 v) {
    vec4 finite = mix(v, vec4(0.0), bvec4(isnan(v)));
    finite = mix(finite, vec4(HALF_MAX), bvec4(isinf(finite)));
    // -inf became 65504 above: every negative, -inf included, is 0.
    return mix(finite, vec4(0.0), lessThan(v, vec4(0.0)));
}
