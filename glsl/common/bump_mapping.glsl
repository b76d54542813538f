// Bump (normal) mapping (notes 01 §8.4): the normal map holds tangent-space
// normals as (n + 1) / 2, loaded as linear data. The TBN matrix, whose
// columns are the tangent T, the bitangent B = cross(N, T) (times the
// handedness) and the normal N, takes them to world space: N_w = TBN . n.
in vec4 v_tangent;
uniform bool u_has_normal_map;
uniform sampler2D u_normal_map;   // unit::NORMAL_MAP
uniform vec4 u_uv_transform;      // the material's uv scale.xy, offset.zw
uniform float u_normal_scale;     // the map's strength: its x and y are scaled (1: as stored)

vec3 bumped_normal(vec3 N, vec2 uv) {
#ifdef VARIANT_NORMAL_MAPS
#if !VARIANT_NORMAL_MAPS
    return N;   // a lighting variant whose frame has no normal map (src/frame/variant.rs)
#endif
#endif
    if (!u_has_normal_map) return N;
    // The interpolated tangent, made perpendicular to N again (Gram-Schmidt).
    vec3 T = v_tangent.xyz - N * dot(N, v_tangent.xyz);
    float len = length(T);
    if (!(len > 1e-12)) return N;   // no frame here: keep the normal
    T /= len;
    vec3 B = cross(N, T) * v_tangent.w;
    // A uv transform that flips an axis flips that axis of the frame.
    T *= u_uv_transform.x < 0.0 ? -1.0 : 1.0;
    B *= u_uv_transform.y < 0.0 ? -1.0 : 1.0;
    mat3 TBN = mat3(T, B, N);   // columns: [Tx Bx Nx; Ty By Ny; Tz Bz Nz]
    vec3 n = texture(u_normal_map, uv).xyz * 2.0 - 1.0;
    n.xy *= u_normal_scale;
    vec3 w = TBN * n;
    float wl = length(w);
    return wl > 1e-12 ? w / wl : N;
}
