// The far field as spherical harmonics (FAR_FIELD_SH; render.far_field_sh,
// src/techniques/deferred/far_field.rs): each sample stores the far
// lights' incoming light at its surface point as order-2 spherical
// harmonics (nine RGB coefficients, already convolved with the clamped
// cosine: Ramamoorthi and Hanrahan, "An Efficient Representation for
// Irradiance Environment Maps", SIGGRAPH 2001, equations 7 and 8). A pixel
// evaluates them for its own normal, so a sample stands for any surface
// within u_far_reach of it, curved or not. The specular far part stays
// the sample interpolation of common/far_field.glsl.
// Needs common/far_field.glsl first.

// Eight RGBA16F attachments, in this order: the coefficients' floats 0-3
// (u_far_diffuse), the specular far light (u_far_specular, as without
// FAR_FIELD_SH), floats 4-27 (u_far_sh1 to u_far_sh6). Coefficient j's
// channel c is float 3 j + c; float 27 is the sum of the far radiances'
// brightest channels (C below), which decides whether a pixel may use it.
const int SH_ATTACHMENTS = 8;

// The nine real spherical harmonics of band 0 to 2 at unit direction n.
void sh_basis(vec3 n, out float y[9]) {
    y[0] = 0.282095;
    y[1] = 0.488603 * n.y;
    y[2] = 0.488603 * n.z;
    y[3] = 0.488603 * n.x;
    y[4] = 1.092548 * n.x * n.y;
    y[5] = 1.092548 * n.y * n.z;
    y[6] = 0.315392 * (3.0 * n.z * n.z - 1.0);
    y[7] = 1.092548 * n.x * n.z;
    y[8] = 0.546274 * (n.x * n.x - n.y * n.y);
}

// The clamped cosine's band factors (A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4).
float sh_band_factor(int j) {
    return j == 0 ? PI : (j < 4 ? 2.0 * PI / 3.0 : PI / 4.0);
}

// The far light at surface s projected: each light with a radius and no
// shadow map adds its far radiance (its diffuse light on a surface facing
// it) times the basis at its direction, times the band factor. Then band 0
// is moved so that the harmonics give s's own normal its exact diffuse far
// light: a pixel facing the sample's way gets no truncation error, and one
// facing nearly that way little (the error changes by at most half the
// turn of the normal; src/lighting/far_field_sh.rs). `total` gets the sum
// of the radiances' brightest channels (the bound's C), and `specular` the
// far specular light at s seen along V, as far_light sums it.
void far_sh(Surface s, vec3 V, out vec3 c[9], out vec3 specular, out float total) {
    for (int j = 0; j < 9; ++j) c[j] = vec3(0.0);
    specular = vec3(0.0);
    vec3 diffuse = vec3(0.0);
    total = 0.0;
    for (int i = 0; i < u_light_count; ++i) {
        Light light = light_at(i);
        float radius = light.direction_radius.w;
        if (radius < 0.0 || casts_shadow(i)) continue;
        float far = 1.0 - near_weight(distance(s.P, light.position_type.xyz), radius);
        if (far <= 0.0) continue;
        vec3 L;
        float sin_sigma;
        vec3 rad = far * light.color_cos_outer.rgb * light_factor(light, s.P, L, sin_sigma);
        total += max(rad.r, max(rad.g, rad.b));
        float y[9];
        sh_basis(L, y);
        for (int j = 0; j < 9; ++j) c[j] += y[j] * rad;
        vec3 d, sp;
        surface_light(light, s.P, s.N, V, s.r, d, sp);
        diffuse += far * d;
        specular += far * sp;
    }
    for (int j = 0; j < 9; ++j) c[j] *= sh_band_factor(j);
    float y[9];
    sh_basis(s.N, y);
    vec3 at_normal = vec3(0.0);
    for (int j = 0; j < 9; ++j) at_normal += y[j] * c[j];
    c[0] += (diffuse - at_normal) / y[0];
}

// The irradiance the coefficients give a surface facing n.
vec3 sh_irradiance(vec3 c[9], vec3 n) {
    float y[9];
    sh_basis(n, y);
    vec3 e = vec3(0.0);
    for (int j = 0; j < 9; ++j) e += y[j] * c[j];
    return max(e, vec3(0.0));
}

// The 27 floats and the specular light in the attachments' order.
void sh_pack(vec3 c[9], vec3 specular, float total, out vec4 att[SH_ATTACHMENTS]) {
    float f[28];
    for (int j = 0; j < 9; ++j) {
        f[3 * j] = c[j].r;
        f[3 * j + 1] = c[j].g;
        f[3 * j + 2] = c[j].b;
    }
    f[27] = total;
    att[0] = vec4(f[0], f[1], f[2], f[3]);
    att[1] = vec4(specular, 1.0);
    for (int k = 1; k < 7; ++k)
        att[k + 1] = vec4(f[4 * k], f[4 * k + 1], f[4 * k + 2], f[4 * k + 3]);
}

void sh_unpack(ivec2 texel, out vec3 c[9]) {
    vec4 v[7];
    v[0] = texelFetch(u_far_diffuse, texel, 0);
    v[1] = texelFetch(u_far_sh1, texel, 0);
    v[2] = texelFetch(u_far_sh2, texel, 0);
    v[3] = texelFetch(u_far_sh3, texel, 0);
    v[4] = texelFetch(u_far_sh4, texel, 0);
    v[5] = texelFetch(u_far_sh5, texel, 0);
    v[6] = texelFetch(u_far_sh6, texel, 0);
    float f[28];
    for (int k = 0; k < 7; ++k) {
        f[4 * k] = v[k].x;
        f[4 * k + 1] = v[k].y;
        f[4 * k + 2] = v[k].z;
        f[4 * k + 3] = v[k].w;
    }
    for (int j = 0; j < 9; ++j) c[j] = vec3(f[3 * j], f[3 * j + 1], f[3 * j + 2]);
}

// How far the truncation may be off at a pixel that uses a sample, in
// linear light, before the pixel sums its far part itself instead: the
// truncation's change is at most min(2/15, |N - N_s| / 2) C k_d.
const float SH_TOLERANCE = 0.5 / 255.0;   // SH_TOLERANCE in src/lighting/far_field_sh.rs

// The sample's C: float 27 (the bound pass keeps it in attachment 0's x).
float far_sh_total(ivec2 t) {
#ifdef FAR_FIELD_BOUND
    return texelFetch(u_far_diffuse, far_texel(t), 0).x;
#else
    return texelFetch(u_far_sh6, far_texel(t), 0).w;
#endif
}

// Whether sample t (surface o) may give pixel s its diffuse far part: its
// point within u_far_reach of the pixel's (any surface), and its normal
// close enough that the truncation stays within SH_TOLERANCE.
bool sh_serves(Surface s, Surface o, ivec2 t) {
    float turn = min(2.0 / 15.0, 0.5 * distance(s.N, o.N));
    float kd = max(s.kd.r, max(s.kd.g, s.kd.b));
    return o.depth < 1.0 && distance(o.P, s.P) <= u_far_reach
        && turn * far_sh_total(t) * kd <= SH_TOLERANCE;
}

// Sample k (0 to 3) of the four around the pixel for the harmonics: its
// texel t, surface o and bilinear weight; 0 when it weighs nothing or does
// not serve.
float far_sh_neighbour(int k, ivec2 t0, vec2 f, Surface s, out ivec2 t, out Surface o) {
    ivec2 grid = (ivec2(u_viewport.zw) + u_far_scale - 1) / u_far_scale;
    ivec2 corner = ivec2(k & 1, k >> 1);
    t = clamp(t0 + corner, ivec2(0), grid - 1);
    float w = (corner.x == 1 ? f.x : 1.0 - f.x) * (corner.y == 1 ? f.y : 1.0 - f.y);
    if (w <= 0.0) return 0.0;
    o = read_geometry_texel(far_sample_texel(t));
    return sh_serves(s, o, t) ? w : 0.0;
}

// The diffuse far light at the pixel: the harmonics of the samples that
// serve it, each evaluated at its normal, weighted bilinearly and
// renormalised; found false when none serves.
vec3 far_sh_diffuse(Surface s, out bool found) {
    ivec2 t0;
    vec2 f;
    far_cell(t0, f);
    vec3 diffuse = vec3(0.0);
    float weight = 0.0;
    for (int k = 0; k < 4; ++k) {
        ivec2 t;
        Surface o;
        float w = far_sh_neighbour(k, t0, f, s, t, o);
        if (w <= 0.0) continue;
        vec3 c[9];
        sh_unpack(far_texel(t), c);
        diffuse += w * sh_irradiance(c, s.N);
        weight += w;
    }
    found = weight > 0.0;
    return found ? diffuse / weight : vec3(0.0);
}

// The specular far light interpolated as common/far_field.glsl does
// (samples on this pixel's surface), read from the array's last layer;
// found false when no sample stands for the surface.
vec3 far_sh_specular(Surface s, float eye_distance, out bool found) {
    ivec2 t0;
    vec2 f;
    far_cell(t0, f);
    vec3 specular = vec3(0.0);
    float weight = 0.0;
    for (int k = 0; k < 4; ++k) {
        ivec2 t;
        Surface o;
        float w = far_neighbour(k, t0, f, s, eye_distance, t, o);
        if (w <= 0.0) continue;
        specular += w * texelFetch(u_far_specular, far_texel(t), 0).rgb;
        weight += w;
    }
    found = weight > 0.0;
    return found ? specular / weight : vec3(0.0);
}

// The specular far part of every light, summed here (no sample on this
// surface: a curved one, or an edge).
vec3 far_specular_light(Surface s, vec3 V) {
    vec3 specular = vec3(0.0);
    for (int i = 0; i < u_light_count; ++i) {
        Light light = light_at(i);
        float radius = light.direction_radius.w;
        if (radius < 0.0 || casts_shadow(i)) continue;
        float far = 1.0 - near_weight(distance(s.P, light.position_type.xyz), radius);
        if (far <= 0.0) continue;
        vec3 d, sp;
        surface_light(light, s.P, s.N, V, s.r, d, sp);
        specular += far * sp;
    }
    return specular;
}

// This pixel's far light times its material: the diffuse part from the
// harmonics of the samples around it, at its own normal, the specular part
// interpolated on its surface; either summed here when no sample serves.
vec3 far_field_sh(Surface s, vec3 V, float eye_distance) {
    bool diffuse_found;
    vec3 diffuse = far_sh_diffuse(s, diffuse_found);
    if (!diffuse_found) {
        vec3 d, sp;
        far_light(s, V, d, sp);
        return s.kd * d + s.ks * sp;
    }
    bool specular_found;
    vec3 specular = far_sh_specular(s, eye_distance, specular_found);
    // A surface with no specular colour (a matte one) needs none.
    if (!specular_found && max(s.ks.r, max(s.ks.g, s.ks.b)) > 0.0)
        specular = far_specular_light(s, V);
    return s.kd * diffuse + s.ks * specular;
}

#ifdef FAR_FIELD_BOUND
// The bound (docs/deferred/far_field.md, "spherical harmonics"): a pixel at x
// takes its diffuse far part from the sample at x_s, |x - x_s| <= rho
// (u_far_reach). Per light of brightest far radiance c (at distance d):
//   - order-2 truncation of the clamped cosine, g(N . L) c with g(x) =
//     3/32 + x/2 + 15/32 x^2 - max(x, 0) (Ramamoorthi and Hanrahan's A_l),
//     less its value at the sample's normal N_s (band 0 is moved to make
//     that exact): |g(N . L) - g(N_s . L)| c <= min(2/15, |N - N_s| / 2) c,
//     g taking values in [-1/24 ... 3/32] and changing by at most 1/2 per
//     unit of N . L (src/lighting/far_field_sh.rs);
//   - moving from x_s to x: |grad (c(d) max(N . L, 0))| <= 6 c att(d) / d
//     with c = I att S, |att'| <= 2 att / d, |S'| <= 3 / d, |grad N . L| <=
//     1 / d, all at d_min = max(inner radius, d_s - rho);
//   - the light's sphere against the horizon: at most 0.25 sin_sigma c.
// A sample stores, in attachment 0, (C, G, M, horizon terms), M the largest
// coefficient (RGBA16F rounding); G is TERM_LIMIT (no bound) when a spot
// light is in the far part (its cone is not in G). Attachments 2 and 3 (u_far_sh1,
// u_far_sh2) hold the specular interpolation's terms (far_bound_terms).
void far_sh_bound_terms(Surface s, float total, vec3 c[9], out vec4 terms) {
    float rho = u_far_reach;
    terms = vec4(0.0);
    for (int j = 0; j < 9; ++j) terms.z = max(terms.z, max(abs(c[j].r), max(abs(c[j].g), abs(c[j].b))));
    for (int i = 0; i < u_light_count; ++i) {
        Light light = light_at(i);
        float radius = light.direction_radius.w;
        if (radius < 0.0 || casts_shadow(i)) continue;
        vec3 p = light.position_type.xyz;
        float d_s = distance(p, s.P);
        float a = NEAR_INNER * u_near_scale * radius;
        if (d_s + rho <= a) continue;      // near only, all over the ball
        if ((int(light.position_type.w) & 3) == LIGHT_SPOT) terms.y = TERM_LIMIT;
        float d = max(a, d_s - rho);
        vec3 k = light.atten_cos_inner.xyz;
        float att = 1.0 / (k.x + k.y * d + k.z * d * d);
        vec3 rgb = light.color_cos_outer.rgb;
        float ci = max(rgb.r, max(rgb.g, rgb.b)) * att;
        terms.y += ci * 6.0 / d;
        terms.w += ci * 0.5 * LIGHT_RADIUS / d;   // at the pixel and at the sample
    }
    terms.x = total;
    terms = min(terms, vec4(TERM_LIMIT));
}

// This pixel's bound on |far part as drawn - far part|, linear light: the
// weighted sum over the samples that serve it of each one's truncation and
// move terms, its rounding, and the specular part's bound.
float far_field_sh_bound(Surface s, float eye_distance) {
    ivec2 t0;
    vec2 f;
    far_cell(t0, f);
    float diffuse = 0.0;
    float weight = 0.0;
    for (int k = 0; k < 4; ++k) {
        ivec2 t;
        Surface o;
        float w = far_sh_neighbour(k, t0, f, s, t, o);
        if (w <= 0.0) continue;
        vec4 terms = texelFetch(u_far_diffuse, far_texel(t), 0);
        if (any(greaterThanEqual(terms, vec4(TERM_LIMIT)))) return 1e30;
        float turn = min(2.0 / 15.0, 0.5 * distance(s.N, o.N));
        // 9 coefficients, each within 2^-11 of itself, times |Y_j| <= 1.1.
        diffuse += w * (terms.x * turn + terms.y * distance(o.P, s.P) + terms.w
                        + 9.0 * 1.1 * terms.z * exp2(-11.0));
        weight += w;
    }
    if (weight == 0.0) return 0.0;     // summed here, exactly
    float kd = max(s.kd.r, max(s.kd.g, s.kd.b));
    return kd * diffuse / weight + far_sh_specular_bound(s, eye_distance);
}
#endif
