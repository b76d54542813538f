// IEEE binary16 halves packed two to a uint (src/frame/light_halves.rs),
// decoded by hand: GLSL 3.30 has no unpackHalf2x16 (GL 4.2). A half is
// sign (1 bit), exponent (5 bits, bias 15), significand (10 bits):
//   exponent 1-30: (-1)^s 2^(e - 15) (1 + m / 1024), the float with the
//     exponent rebiased by 127 - 15 = 112 and the significand shifted up 13;
//   exponent 0: (-1)^s 2^-14 m / 1024 = m 2^-24 (zero and the subnormals,
//     exact: m < 1024 and a float holds 2^-24 m exactly);
//   exponent 31: infinity (m = 0) or NaN, the float's exponent 255.
// Both halves of a word at once; the sign is set by its bit, so -0 stays -0.
vec2 unpack_half2(uint w) {
    uvec2 h = uvec2(w & 0xffffu, w >> 16);
    uvec2 e = (h >> 10) & 0x1fu;
    uvec2 m = h & 0x3ffu;
    uvec2 normal = ((e + 112u) << 23) | (m << 13);
    uvec2 special = 0x7f800000u | (m << 13);
    vec2 subnormal = vec2(m) * (1.0 / 16777216.0);
    uvec2 bits = uvec2(
        e.x == 0u ? floatBitsToUint(subnormal.x) : (e.x == 31u ? special.x : normal.x),
        e.y == 0u ? floatBitsToUint(subnormal.y) : (e.y == 31u ? special.y : normal.y));
    return uintBitsToFloat(bits | ((h & 0x8000u) << 16));
}

// Four words as eight values: (lo, hi) of x, then of y, ...
vec4 unpack_half4(uint a, uint b) {
    return vec4(unpack_half2(a), unpack_half2(b));
}
