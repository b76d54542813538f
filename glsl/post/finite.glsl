// A neighbourhood pass reads many pixels, so one NaN or infinity in its
// input (a division by zero somewhere upstream) would spread over its
// whole kernel (NaN x 0 and inf x 0 are NaN). The blur, the 3x3 kernel and
// bloom (notes 03, "Blur Pass and Merge Pass") read through finite(): NaN
// becomes 0 (no light), +inf the largest half float (65504: as bright as
// the HDR target holds), and negative light, -inf included, 0. The CPU
// twin is `sanitise` in src/image_compare/bloom_reference.rs.
const float HALF_MAX = 65504.0;

vec4 finite(vec4 c) {
    bvec4 nan = isnan(c);
    // clamp() of a NaN is undefined; those channels are replaced below.
    c = clamp(c, 0.0, HALF_MAX);
    return mix(c, vec4(0.0), nan);
}

vec3 finite(vec3 c) {
    return finite(vec4(c, 0.0)).rgb;
}
