// The far field (src/techniques/deferred/far_field.rs): each light with a
// radius is split in two by a weight that is 1 up to half its radius and
// falls smoothly to 0 at the radius. Tiled shading shades the near part
// (weight x light) from its cluster lists; the far part ((1 - weight) x
// light), which varies slowly over a surface, is summed by the far-field
// pass once per k x k pixels and interpolated here. The two parts add up to
// the whole light: nothing is cut off.
// Needs common/lighting.glsl, common/shadow.glsl, common/gbuffer_read.glsl
// and common/light_buffer.glsl first.

const float NEAR_INNER = 0.5;   // the near weight is 1 up to this fraction of the radius

uniform sampler2D u_far_diffuse;   // far light, diffuse (not yet x k_d), one texel per sample
uniform sampler2D u_far_specular;  // far light, specular (not yet x k_s)
uniform int u_far_scale;           // k: one sample per k x k pixels
uniform int u_light_count;
uniform float u_far_reach;         // the farthest a sample's surface point may be from the pixel's
uniform vec3 u_eye;
// render.near_radius: the near part ends at this fraction of the radius
// (and is whole up to half of that); tiled shading bins at it.
uniform float u_near_scale;
// common/far_field_sh.glsl: the harmonics' floats 4 to 27 (0 to 3 are in
// u_far_diffuse; u_far_specular keeps the specular light). With far lists
// (u_far_radius > 0) the first four hold the samples' coarse part instead.
uniform sampler2D u_far_sh1;
uniform sampler2D u_far_sh2;
uniform sampler2D u_far_sh3;
uniform sampler2D u_far_sh4;
// render.far_radius = a (src/techniques/deferred/far_lists.rs): 0, no far
// lists; else each light's far part beyond a r (rising to all of it at
// 2 a r) is the coarse part, which a pixel no sample stands for takes from
// a sample's order-1 harmonics; the rest it sums from its cluster's far list.
uniform float u_far_radius;
uniform float u_coarse_reach;      // how far a coarse sample may be from the pixel: a r_min / 2
#ifdef FAR_FIELD_SH
uniform sampler2D u_far_sh5;
uniform sampler2D u_far_sh6;
#endif

float near_weight(float d, float radius) {
    // A light never brighter than the cutoff has radius 0: all far.
    if (radius <= 0.0) return 0.0;
    float outer = u_near_scale * radius;
    return 1.0 - smoothstep(NEAR_INNER * outer, outer, d);
}

// The far part of every light with a radius and no shadow map, at surface s
// seen along V: diffuse and specular apart, not yet multiplied by the material.
void far_light(Surface s, vec3 V, out vec3 diffuse, out vec3 specular) {
    diffuse = vec3(0.0);
    specular = vec3(0.0);
    for (int i = 0; i < u_light_count; ++i) {
        Light light = light_at(i);
        float radius = light.direction_radius.w;
        if (radius < 0.0 || casts_shadow(i)) continue;
        float far = 1.0 - near_weight(distance(s.P, light.position_type.xyz), radius);
        if (far <= 0.0) continue;
        vec3 d, sp;
        surface_light(light, s.P, s.N, V, s.r, d, sp);
        diffuse += far * d;
        specular += far * sp;
    }
}

// The share of a light's far part that is coarse (far_lists.rs): 0 up to
// a r, a smoothstep up to 1 at 2 a r; all of it for a light of radius 0;
// none without far lists.
float coarse_weight(float d, float radius) {
    if (u_far_radius <= 0.0) return 0.0;
    if (radius <= 0.0) return 1.0;
    return smoothstep(u_far_radius * radius, 2.0 * u_far_radius * radius, d);
}

// The diffuse light order-1 coefficients give a surface facing n.
vec3 coarse_irradiance(vec3 c[4], vec3 n) {
    return 0.282095 * c[0] + 0.488603 * (n.y * c[1] + n.z * c[2] + n.x * c[3]);
}

// far_light's sums (far_diffuse, far_specular) and, in the same loop, the
// coarse part at surface s seen along V: its diffuse light as order-1
// spherical harmonics of the incoming light, convolved with the clamped
// cosine (A_0 = pi, A_1 = 2 pi / 3) and band 0 moved so that s's own
// normal gets its exact diffuse light; its specular light; `total` the sum
// of its radiances' brightest channels (the bound's C).
void far_coarse(Surface s, vec3 V, out vec3 far_diffuse, out vec3 far_specular,
                out vec3 c[4], out vec3 specular, out float total) {
    for (int j = 0; j < 4; ++j) c[j] = vec3(0.0);
    far_diffuse = vec3(0.0);
    far_specular = vec3(0.0);
    specular = vec3(0.0);
    vec3 diffuse = vec3(0.0);
    total = 0.0;
    for (int i = 0; i < u_light_count; ++i) {
        Light light = light_at(i);
        float radius = light.direction_radius.w;
        if (radius < 0.0 || casts_shadow(i)) continue;
        float dist = distance(s.P, light.position_type.xyz);
        float far = 1.0 - near_weight(dist, radius);
        if (far <= 0.0) continue;
        vec3 d, sp;
        surface_light(light, s.P, s.N, V, s.r, d, sp);
        far_diffuse += far * d;
        far_specular += far * sp;
        float v = coarse_weight(dist, radius);
        if (v <= 0.0) continue;   // (v > 0 only beyond a r >= r: all far there)
        vec3 L;
        float sin_sigma;
        vec3 rad = v * light.color_cos_outer.rgb * light_factor(light, s.P, L, sin_sigma);
        total += max(rad.r, max(rad.g, rad.b));
        c[0] += 0.282095 * PI * rad;
        c[1] += 0.488603 * L.y * (2.0 * PI / 3.0) * rad;
        c[2] += 0.488603 * L.z * (2.0 * PI / 3.0) * rad;
        c[3] += 0.488603 * L.x * (2.0 * PI / 3.0) * rad;
        diffuse += v * d;
        specular += v * sp;
    }
    c[0] += (diffuse - coarse_irradiance(c, s.N)) / 0.282095;
}

// The G-buffer texel the far-field pass samples for its texel t (t counted
// from the view's corner): the centre of t's k x k block, inside the view.
ivec2 far_sample_texel(ivec2 t) {
    ivec2 lo = ivec2(u_viewport.xy);
    ivec2 hi = lo + ivec2(u_viewport.zw) - 1;
    return clamp(lo + t * u_far_scale + u_far_scale / 2, lo, hi);
}

// The far-field texture's texel for sample t.
ivec2 far_texel(ivec2 t) {
    return ivec2(u_viewport.xy) / u_far_scale + t;
}

// Whether sample surface o can stand for surface s: on s's tangent plane
// (within 1% of the distance to the eye), within u_far_reach of it, with
// the same shininess (a microfacet pixel's is its lobe's Blinn-Phong
// equivalent, src/scene/material.rs), and its normal within an angle that moves the
// specular lobe by at most 1%: the steepest slope of cos^n is about
// sqrt(n / e) per radian, so 0.01 / sqrt(n / e + 1) radians (0.1 degrees at
// n = 64). On a curved surface that fails for all but the nearest
// neighbours, and the pixel sums its far part itself.
bool same_surface(Surface s, Surface o, float eye_distance) {
    float angle = 0.01 / sqrt(s.shininess / 2.718 + 1.0);
    return o.depth < 1.0
        && abs(dot(s.N, o.P - s.P)) <= 0.01 * eye_distance
        && dot(s.N, o.N) >= 1.0 - 0.5 * angle * angle
        && abs(o.shininess - s.shininess) <= 1e-3 * max(s.shininess, 1.0)
        && distance(o.P, s.P) <= u_far_reach;
}

// The four samples around this pixel, as bilinear filtering takes them:
// the first one's texel t0, and where the pixel lies between them (f).
void far_cell(out ivec2 t0, out vec2 f) {
    vec2 q = (gl_FragCoord.xy - u_viewport.xy) / float(u_far_scale) - 0.5;
    t0 = ivec2(floor(q));
    f = q - vec2(t0);
}

// Sample k (0 to 3) of those four: its texel t, its surface o, and its
// bilinear weight; 0 when it weighs nothing or does not stand for s.
float far_neighbour(int k, ivec2 t0, vec2 f, Surface s, float eye_distance,
                    out ivec2 t, out Surface o) {
    ivec2 grid = (ivec2(u_viewport.zw) + u_far_scale - 1) / u_far_scale;
    ivec2 corner = ivec2(k & 1, k >> 1);
    t = clamp(t0 + corner, ivec2(0), grid - 1);
    float w = (corner.x == 1 ? f.x : 1.0 - f.x) * (corner.y == 1 ? f.y : 1.0 - f.y);
    if (w <= 0.0) return 0.0;
    o = read_geometry_texel(far_sample_texel(t));
    return same_surface(s, o, eye_distance) ? w : 0.0;
}

#ifdef TILED_SHADING
// Tiled shading's pass (glsl/deferred/tiled_shading.frag reads u_clusters
// and sets g_cluster, this pixel's cluster, before calling far_field).
uniform int u_far_table;        // 0: no far lists; else the far table's first texel
uniform int u_far_index_base;   // the far lists' light numbers' first texel
int g_cluster = 0;

// The far part less the coarse part of the lights in this pixel's
// cluster's far list: every light whose far part is not all coarse here
// (far_lists.rs bins them at 2 a r), summed exactly.
void far_list_light(Surface s, vec3 V, out vec3 diffuse, out vec3 specular) {
    diffuse = vec3(0.0);
    specular = vec3(0.0);
    int offset = u_far_index_base + int(texelFetch(u_clusters, u_far_table + 2 * g_cluster).r);
    int count = int(texelFetch(u_clusters, u_far_table + 2 * g_cluster + 1).r);
    for (int k = 0; k < count; ++k) {
        int i = int(texelFetch(u_clusters, offset + k).r);
        Light light = light_at(i);
        float radius = light.direction_radius.w;
        float d = distance(s.P, light.position_type.xyz);
        float far = (1.0 - near_weight(d, radius)) * (1.0 - coarse_weight(d, radius));
        if (far <= 0.0) continue;
        vec3 dl, sp;
        surface_light(light, s.P, s.N, V, s.r, dl, sp);
        diffuse += far * dl;
        specular += far * sp;
    }
}

// How far off a sample's coarse part may be, estimated, for a pixel to
// take it (linear light, before the material): 0.5/255
// (RenderSettings::far_coarse_tolerance).
uniform float u_coarse_tolerance;

// The sample whose coarse part a pixel no sample stands for takes: of its
// four within u_coarse_reach, the one with the smallest estimate of the
// bound (far_coarse_bound): C times half the turn of the normal plus the
// move over the shortest coarse distance, 2 u_coarse_reach (G ~ 6 C /
// d_min); false when none is within reach and u_coarse_tolerance.
bool far_coarse_texel(Surface s, ivec2 t0, out ivec2 best, out Surface bo) {
    ivec2 grid = (ivec2(u_viewport.zw) + u_far_scale - 1) / u_far_scale;
    float lowest = u_coarse_tolerance;
    bool found = false;
    for (int k = 0; k < 4; ++k) {
        ivec2 t = clamp(t0 + ivec2(k & 1, k >> 1), ivec2(0), grid - 1);
        Surface o = read_geometry_texel(far_sample_texel(t));
        float d = distance(o.P, s.P);
        float total = texelFetch(u_far_sh4, far_texel(t), 0).a;
        float score = total * (0.5 * length(s.N - o.N) + 3.0 * d / u_coarse_reach);
        if (o.depth < 1.0 && d <= u_coarse_reach && score <= lowest) {
            lowest = score;
            best = t;
            bo = o;
            found = true;
        }
    }
    return found;
}

// That sample's coarse part: its harmonics at this pixel's normal, its
// specular light.
void far_coarse_read(Surface s, ivec2 t, out vec3 diffuse, out vec3 specular) {
    vec4 a = texelFetch(u_far_sh1, far_texel(t), 0);
    vec4 b = texelFetch(u_far_sh2, far_texel(t), 0);
    vec4 c = texelFetch(u_far_sh3, far_texel(t), 0);
    vec3 co[4];
    co[0] = a.rgb;
    co[1] = vec3(a.a, b.rg);
    co[2] = vec3(b.ba, c.r);
    co[3] = c.gba;
    diffuse = max(coarse_irradiance(co, s.N), vec3(0.0));
    specular = texelFetch(u_far_sh4, far_texel(t), 0).rgb;
}
#endif

// This pixel's far light times its material: interpolated (bilinearly)
// from those of the four samples around it that stand for its surface,
// their weights renormalised; summed here over every light when none does.
// `eye_distance`: from the eye to s.P.
vec3 far_field(Surface s, vec3 V, float eye_distance) {
    ivec2 t0;
    vec2 f;
    far_cell(t0, f);
    vec3 diffuse = vec3(0.0);
    vec3 specular = vec3(0.0);
    float weight = 0.0;
    for (int k = 0; k < 4; ++k) {
        ivec2 t;
        Surface o;
        float w = far_neighbour(k, t0, f, s, eye_distance, t, o);
        if (w <= 0.0) continue;
        diffuse += w * texelFetch(u_far_diffuse, far_texel(t), 0).rgb;
        specular += w * texelFetch(u_far_specular, far_texel(t), 0).rgb;
        weight += w;
    }
    if (weight > 0.0) {
        diffuse /= weight;
        specular /= weight;
        return s.kd * diffuse + s.ks * specular;
    }
#ifdef TILED_SHADING
    // With far lists: its cluster's far list, and a sample's coarse part.
    ivec2 t;
    Surface o;
    if (u_far_table > 0 && far_coarse_texel(s, t0, t, o)) {
        vec3 cd, cs;
        far_list_light(s, V, diffuse, specular);
        far_coarse_read(s, t, cd, cs);
        return s.kd * (diffuse + cd) + s.ks * (specular + cs);
    }
#endif
    far_light(s, V, diffuse, specular);
    return s.kd * diffuse + s.ks * specular;
}

#ifdef FAR_FIELD_BOUND
// The error bound (docs/deferred/far_field.md derives it). Drawn instead of
// the light when `gloss bench` asks (render.far_field_bound): the far-field
// pass then writes each sample's bound terms into its two targets, and
// tiled shading writes each pixel's bound.
//
// A pixel takes its far part as a convex combination, weights w_k, of
// samples at x_k on its own plane. Taylor about the pixel x: for each part
// f, |sum w_k f(x_k) - f(x)| <= G |sum w_k (x_k - x)| + H/2 sum w_k |x_k - x|^2,
// G and H bounds on |grad f| and |hessian f| over the ball of radius rho
// around each sample that holds every pixel taking it. On a plane, a light
// at height h above it adds diffuse c h S(d) att(d) / d and specular
// c S(d) att(d) cos^n(theta_H) (S: the smoothstep of 1 - near_weight). With
// a = the light's inner radius and d >= d_min = max(a, d_s - rho, h) over
// the ball, the envelopes |att'| <= 2 att / d, |att''| <= 10 att / d^2,
// |S'| <= 3 / d, |S''| <= 24 / d^2 (S changes only where d >= a), and for
// the lobe |d cos^n / d theta| <= sqrt(n), |d^2 cos^n / d theta^2| <= n,
// |grad theta_H| <= T1 = (1/d + 1/e) / m, |hessian theta_H| <= T2 =
// (3/d^2 + 3/e^2) / m + 2 T1^2 (m: |L + V| less how far L and V turn over
// the ball, e: the eye's distance less rho) give
//   diffuse:  G_d = c 6 att / d,  H_d = c 64 att / d^2
//   specular: G_s = c att (5 / d + S sqrt(n) T1),
//             H_s = c att (46 / d^2 + 10 sqrt(n) T1 / d + S (n T1^2 + sqrt(n) T2))
// (att at d_min, S at d_s + rho). A sample stores (H_d, G_d, H_s, G_s) and
// (M, straddle, 0, 0): M the largest of its far values (for their RGBA16F
// rounding), straddle 1 when a light lies within its own radius of the
// plane, where N . L is not smooth.
// RGBA16F holds at most 65504: a sum past it is no bound.
const float TERM_LIMIT = 6e4;

void far_bound_terms(Surface s, vec3 V, vec3 diffuse, vec3 specular, float rho,
                     out vec4 terms, out vec4 extra) {
    float e = max(distance(u_eye, s.P) - rho, 1e-6);
    terms = vec4(0.0);
    extra = vec4(0.0);
    extra.x = max(diffuse.r, max(diffuse.g, diffuse.b)) + max(specular.r, max(specular.g, specular.b));
    float n = s.shininess;
    float rn = sqrt(n);
    for (int i = 0; i < u_light_count; ++i) {
        Light light = light_at(i);
        float radius = light.direction_radius.w;
        if (radius < 0.0 || casts_shadow(i)) continue;
        vec3 p = light.position_type.xyz;
        float h = dot(s.N, p - s.P);
        if (h < -LIGHT_RADIUS) continue;   // below the plane: 0 all over it
        if (h <= LIGHT_RADIUS) {
            extra.y = 1.0;
            continue;
        }
        float d_s = distance(p, s.P);
        float a = NEAR_INNER * u_near_scale * radius;
        if (d_s + rho <= a) continue;      // inside the near part all over the ball
        float d = max(max(a, d_s - rho), h);
        vec3 k = light.atten_cos_inner.xyz;
        float att = 1.0 / (k.x + k.y * d + k.z * d * d);
        float S = 1.0 - near_weight(d_s + rho, radius);
        vec3 rgb = light.color_cos_outer.rgb;
        float c = max(rgb.r, max(rgb.g, rgb.b)) * att;
        vec3 L = normalize(p - s.P);
        float m = max(length(L + V) - rho / d - rho / e, 1e-4);
        float t1 = (1.0 / d + 1.0 / e) / m;
        float t2 = (3.0 / (d * d) + 3.0 / (e * e)) / m + 2.0 * t1 * t1;
        terms.x += c * 64.0 / (d * d);
        terms.y += c * 6.0 / d;
        terms.z += c * (46.0 / (d * d) + 10.0 * rn * t1 / d + S * (n * t1 * t1 + rn * t2));
        terms.w += c * (5.0 / d + S * rn * t1);
    }
    terms = min(terms, vec4(TERM_LIMIT));
}

// The farthest surface point, from sample t's (surface o), of the pixels
// that take their far part from t: those within 1.5 k + 1 pixels of its
// texel that find it on their surface (same_surface, as far_field tests).
float far_support_radius(ivec2 t, Surface o) {
    ivec2 c = far_sample_texel(t);
    ivec2 lo = ivec2(u_viewport.xy);
    ivec2 hi = lo + ivec2(u_viewport.zw) - 1;
    int n = u_far_scale + u_far_scale / 2 + 1;
    float r = 0.0;
    for (int dy = -n; dy <= n; ++dy) {
        for (int dx = -n; dx <= n; ++dx) {
            Surface s = read_geometry_texel(clamp(c + ivec2(dx, dy), lo, hi));
            if (s.depth < 1.0 && same_surface(s, o, distance(u_eye, s.P)))
                r = max(r, distance(s.P, o.P));
        }
    }
    return r;
}

// The bound's terms of sample t: (H_d, G_d, H_s, G_s) and (M, straddle).
void far_bound_fetch(ivec2 t, out vec4 terms, out vec4 extra) {
#ifdef FAR_FIELD_SH
    terms = texelFetch(u_far_sh1, far_texel(t), 0);
    extra = texelFetch(u_far_sh2, far_texel(t), 0);
#else
    terms = texelFetch(u_far_diffuse, far_texel(t), 0);
    extra = texelFetch(u_far_specular, far_texel(t), 0);
#endif
}

// The samples this pixel interpolates (as far_field takes them): the
// worst of their terms, the weighted offset |sum w_k (x_k - x)| and
// spread sum w_k |x_k - x|^2; false when it takes none.
bool far_bound_samples(Surface s, float eye_distance, out vec4 worst, out vec4 extra,
                       out float off, out float spread2) {
    ivec2 t0;
    vec2 f;
    far_cell(t0, f);
    float weight = 0.0;
    vec3 centre = vec3(0.0);    // sum of w_k (x_k - x)
    spread2 = 0.0;              // sum of w_k |x_k - x|^2
    worst = vec4(0.0);
    extra = vec4(0.0);
    off = 0.0;
    for (int k = 0; k < 4; ++k) {
        ivec2 t;
        Surface o;
        float w = far_neighbour(k, t0, f, s, eye_distance, t, o);
        if (w <= 0.0) continue;
        vec3 dx = o.P - s.P;
        weight += w;
        centre += w * dx;
        spread2 += w * dot(dx, dx);
        vec4 terms;
        vec4 more;
        far_bound_fetch(t, terms, more);
        worst = max(worst, terms);
        extra = max(extra, more);
    }
    if (weight == 0.0) return false;
    off = length(centre) / weight;
    spread2 /= weight;
    return true;
}

// Whether the terms give no bound: a light straddles the plane or a term
// overflowed (a sample at the pixel itself, k = 1, needs no smoothness).
bool far_bound_unbounded(vec4 worst, vec4 extra, float spread2) {
    return spread2 > 0.0 && (extra.y > 0.0 || any(greaterThanEqual(worst, vec4(TERM_LIMIT))));
}

// The coarse part's bound terms at sample s (far_lists.rs; the derivation
// is in docs/deferred/far_field.md, "Far lists"): over the ball of radius
// rho = u_coarse_reach around s, with d_min = max(a r, d_s - rho) and c =
// the light's brightest channel times att(d_min):
//   x: C = sum of the coarse radiances at s (the harmonics' truncation);
//   y: G = sum 6 c / d_min (the coarse diffuse light's gradient);
//   z: S = sum c (the coarse specular light, which the pixel takes as is);
//   w: sum c LIGHT_RADIUS / d_min (the light's sphere against the horizon).
// A spot light in the coarse part gives no bound (its cone is not in G).
vec4 far_coarse_bound_terms(Surface s) {
    vec4 t = vec4(0.0);
    float rho = u_coarse_reach;
    for (int i = 0; i < u_light_count; ++i) {
        Light light = light_at(i);
        float radius = light.direction_radius.w;
        if (radius < 0.0 || casts_shadow(i)) continue;
        vec3 p = light.position_type.xyz;
        float d_s = distance(p, s.P);
        float a = u_far_radius * radius;
        if (radius > 0.0 && d_s + rho <= a) continue;   // no coarse part over the ball
        if ((int(light.position_type.w) & 3) == LIGHT_SPOT) return vec4(TERM_LIMIT);
        float d = max(max(a, d_s - rho), LIGHT_RADIUS);
        vec3 k = light.atten_cos_inner.xyz;
        vec3 rgb = light.color_cos_outer.rgb;
        float c = max(rgb.r, max(rgb.g, rgb.b)) / (k.x + k.y * d + k.z * d * d);
        vec3 L;
        float sin_sigma;
        vec3 rad = coarse_weight(d_s, radius) * rgb * light_factor(light, s.P, L, sin_sigma);
        t.x += max(rad.r, max(rad.g, rad.b));
        t.y += 6.0 * c / d;
        t.z += c;
        t.w += c * LIGHT_RADIUS / d;
    }
    return min(t, vec4(TERM_LIMIT));
}

// The coarse part's bound at a pixel no sample stands for (far lists):
// the harmonics' truncation, which changes by at most half the turn of the
// normal from the sample's (where band 0 makes them exact), C min(1/2,
// |N - N_s| / 2); the move from the sample, G |x - x_s|; the spheres, 2 x
// 0.25 sin sigma c; the specular part taken as is, S; the RGBA16F rounding.
// 0 where the pixel sums its far part itself.
float far_coarse_bound(Surface s) {
#ifdef TILED_SHADING
    ivec2 t0;
    vec2 f;
    far_cell(t0, f);
    ivec2 t;
    Surface o;
    if (u_far_table > 0 && far_coarse_texel(s, t0, t, o)) {
        vec4 c = texelFetch(u_far_sh1, far_texel(t), 0);
        if (any(greaterThanEqual(c, vec4(TERM_LIMIT)))) return 1e30;
#if VARIANT_MICROFACET
        if (s.r.microfacet) return 1e30;   // its lobe is not bounded by 1
#endif
        float kd = max(s.kd.r, max(s.kd.g, s.kd.b));
        float ks = max(s.ks.r, max(s.ks.g, s.ks.b));
        float turn = min(0.5, 0.5 * length(s.N - o.N));
        return kd * (c.x * turn + c.y * distance(o.P, s.P) + 0.5 * c.w)
            + ks * c.z + max(kd, ks) * (c.x + c.z) * exp2(-9.0);
    }
#endif
    return 0.0;
}

// This pixel's bound on |far part interpolated - far part|, in linear
// light: from the worst of its samples' terms, its own material and the
// weighted distances to the samples. 0 where it sums its own far part;
// 1e30 where a light straddles the plane or a term overflowed.
float far_field_bound(Surface s, float eye_distance) {
    vec4 worst, extra;
    float off, spread2;
    if (!far_bound_samples(s, eye_distance, worst, extra, off, spread2)) return far_coarse_bound(s);
    if (far_bound_unbounded(worst, extra, spread2)) return 1e30;
    float kd = max(s.kd.r, max(s.kd.g, s.kd.b));
    float ks = max(s.ks.r, max(s.ks.g, s.ks.b));
    return kd * (worst.y * off + 0.5 * worst.x * spread2)
        + ks * (worst.w * off + 0.5 * worst.z * spread2)
        + max(kd, ks) * extra.x * exp2(-11.0);
}

// The specular half of far_field_bound (the harmonics' far field
// interpolates only the specular part this way).
float far_sh_specular_bound(Surface s, float eye_distance) {
    vec4 worst, extra;
    float off, spread2;
    if (!far_bound_samples(s, eye_distance, worst, extra, off, spread2)) return 0.0;
    if (far_bound_unbounded(worst, extra, spread2)) return 1e30;
    float ks = max(s.ks.r, max(s.ks.g, s.ks.b));
    return ks * (worst.w * off + 0.5 * worst.z * spread2 + extra.x * exp2(-11.0));
}
#endif
