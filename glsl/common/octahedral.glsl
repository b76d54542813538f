// Octahedral normals (Cigolle et al. 2014, "A Survey of Efficient
// Representations for Independent Unit Vectors", listing 1) in 12 + 12 bits
// over three 8-bit channels: the packed G-buffer's normal
// (render.gbuffer = "octahedral"; src/math/octahedral.rs is the CPU twin).

vec2 oct_sign_not_zero(vec2 v) {
    return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0);
}

// A unit vector to the square [-1, 1]^2: the octahedron's upper half is the
// diamond |u| + |v| <= 1, the lower half folded out into the corners.
vec2 oct_encode(vec3 n) {
    vec2 p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
    return n.z < 0.0 ? (1.0 - abs(p.yx)) * oct_sign_not_zero(p) : p;
}

vec3 oct_decode(vec2 e) {
    vec3 v = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    if (v.z < 0.0) {
        v.xy = (1.0 - abs(v.yx)) * oct_sign_not_zero(v.xy);
    }
    return normalize(v);
}

// Three UNORM8 channels: R, G the high 8 bits of the 12-bit u and v, B their
// low 4 bits (u's in the high nibble). Each value is a whole number / 255,
// which an 8-bit UNORM target stores exactly.
vec3 oct_pack(vec3 n) {
    vec2 q = floor((clamp(oct_encode(n), -1.0, 1.0) * 0.5 + 0.5) * 4095.0 + 0.5);
    vec2 hi = floor(q / 16.0);
    vec2 lo = q - hi * 16.0;
    return vec3(hi, lo.x * 16.0 + lo.y) / 255.0;
}

vec3 oct_unpack(vec3 stored) {
    ivec3 b = ivec3(floor(stored * 255.0 + 0.5));
    vec2 q = vec2((b.x << 4) | (b.z >> 4), (b.y << 4) | (b.z & 15));
    return oct_decode(q / 4095.0 * 2.0 - 1.0);
}
