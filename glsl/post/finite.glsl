// A neighbourhood pass reads many pixels, so one NaN or infinity in its
// input (a division by zero somewhere upstream) would spread over its
// whole kernel. Read through finite(): NaN becomes 0 (no light), +inf the
// largest half float (65504: as bright as the HDR target holds), and
// negative light 0.
vec3 finite(vec3 c) {
    bvec3 nan = isnan(c);
    c = min(max(c, 0.0), 65504.0);
    return vec3(nan.x ? 0.0 : c.x, nan.y ? 0.0 : c.y, nan.z ? 0.0 : c.z);
}
