//! Linearly transformed cosines on the CPU (Heitz, Dupuy, Hill and Neubelt
//! 2016, "Real-Time Polygonal-Light Shading with Linearly Transformed
//! Cosines", §3-§4 and the paper's shader `LTC_Evaluate`): the f64 twin of
//! glsl/lighting/ltc_area_lights.glsl, for the tests.
//!
//! The specular lobe of a GGX BRDF seen from direction v is fitted by a
//! clamped cosine D_o whose directions are mapped by a 3x3 matrix M:
//! D(w) = D_o(M^-1 w / |M^-1 w|) |det M^-1| / |M^-1 w|^3. Integrating D over
//! a polygon is integrating D_o over the polygon M^-1 P, and that is
//! Lambert's formula (src/lighting/area_light.rs), with no sampling:
//!
//! ```text
//! 1. the frame (T1, T2, N), T1 in the plane of N and V
//! 2. the corners p_i - P into it, clipped to the surface's horizon, then
//!    through M^-1 (the table at (sqrt(alpha), sqrt(1 - N.V)))
//! 3. clipped to the cosine's horizon z >= 0, put on the unit sphere
//! 4. form factor = -1/(2 pi) sum_i acos(u_i . u_i+1) normalize(u_i x u_i+1).z
//! 5. specular = form factor x (F0 magnitude + (1 - F0) fresnel)
//! ```
//!
//! With M^-1 the identity the same steps give the diffuse form factor: the
//! exact irradiance over pi. The tables (src/lighting/ltc_tables/) are the
//! paper's GGX fit, with F = 1 and the Schlick-weighted integral beside
//! it: gloss's D (GGX, alpha = roughness^2 as the fit) and G (Smith,
//! height-correlated) are the fit's; its Fresnel (the exact dielectric
//! formula) is not, so step 5 takes F0 = ((eta - 1) / (eta + 1))^2 through
//! Schlick's form. The error this and the fit leave is measured against
//! `area_light::monte_carlo_specular` in the tests below.
//!
//! The first clip of step 2 is not the paper's: its shader clips once,
//! after M^-1, to the cosine's horizon, and the lobe M maps there reaches a
//! little below the surface, so a light just under the horizon still gave
//! a highlight. Clipping to the surface's horizon first makes a light
//! behind the surface give exactly 0, as gloss's BRDF does.

use super::area_light::QuadLight;
use glam::{DMat3, DVec3};
use std::f64::consts::PI;
use std::sync::OnceLock;

/// The tables' side: 64 x 64 texels.
pub const LTC_SIZE: usize = 64;

static LTC_1_BYTES: &[u8] = include_bytes!("ltc_tables/ltc_1.bin");
static LTC_2_BYTES: &[u8] = include_bytes!("ltc_tables/ltc_2.bin");

fn texels(bytes: &[u8]) -> Vec<[f32; 4]> {
    bytes
        .chunks_exact(16)
        .map(|t| {
            let f = |i: usize| f32::from_le_bytes(t[4 * i..4 * i + 4].try_into().expect("4 bytes"));
            [f(0), f(1), f(2), f(3)]
        })
        .collect()
}

/// The first table: M^-1's four free terms (m00, m02, m20, m22, column and
/// row as GLSL's mat3), texel (a, t) at a + 64 t.
pub fn ltc_1() -> &'static [[f32; 4]] {
    static T: OnceLock<Vec<[f32; 4]>> = OnceLock::new();
    T.get_or_init(|| texels(LTC_1_BYTES))
}

/// The second table: magnitude, Fresnel term, 0, the sphere table (unused).
pub fn ltc_2() -> &'static [[f32; 4]] {
    static T: OnceLock<Vec<[f32; 4]>> = OnceLock::new();
    T.get_or_init(|| texels(LTC_2_BYTES))
}

/// Where the tables are read for a GGX width `alpha` (above 1 read as 1)
/// and N.V: (sqrt(alpha), sqrt(1 - N.V)), each 0..=1 across the texel
/// centres (the shader's uv x 63/64 + 0.5/64).
pub fn table_coords(alpha: f64, n_dot_v: f64) -> (f64, f64) {
    let roughness = alpha.clamp(0.0, 1.0).sqrt();
    (roughness, (1.0 - n_dot_v.clamp(0.0, 1.0)).sqrt())
}

/// A table read as GL_LINEAR reads it at the coordinates (x, y) in 0..=1
/// across the texel centres.
pub fn bilinear(table: &[[f32; 4]], (x, y): (f64, f64)) -> [f64; 4] {
    let last = (LTC_SIZE - 1) as f64;
    let (fx, fy) = (x.clamp(0.0, 1.0) * last, y.clamp(0.0, 1.0) * last);
    let (x0, y0) = (fx.floor() as usize, fy.floor() as usize);
    let (x1, y1) = ((x0 + 1).min(LTC_SIZE - 1), (y0 + 1).min(LTC_SIZE - 1));
    let (sx, sy) = (fx - x0 as f64, fy - y0 as f64);
    let at = |x: usize, y: usize, c: usize| f64::from(table[x + LTC_SIZE * y][c]);
    std::array::from_fn(|c| {
        let top = at(x0, y0, c) * (1.0 - sx) + at(x1, y0, c) * sx;
        let bottom = at(x0, y1, c) * (1.0 - sx) + at(x1, y1, c) * sx;
        top * (1.0 - sy) + bottom * sy
    })
}

/// M^-1 as the shader builds it from the first table's texel.
pub fn inverse_matrix(t1: [f64; 4]) -> DMat3 {
    DMat3::from_cols(
        DVec3::new(t1[0], 0.0, t1[1]),
        DVec3::Y,
        DVec3::new(t1[2], 0.0, t1[3]),
    )
}

/// The clamped-cosine form factor of `light` seen from `p` (normal `n`,
/// toward the eye `v`) after the directions go through `minv` in the frame
/// (T1, T2, N): steps 1 to 4. One-sided: 0 from behind; two-sided: either
/// face.
pub fn ltc_evaluate(
    p: DVec3,
    n: DVec3,
    v: DVec3,
    minv: DMat3,
    light: &QuadLight,
    two_sided: bool,
) -> f64 {
    // 1. The frame: T1 in the plane of N and V (any tangent at V = N).
    let t = v - n * v.dot(n);
    let t1 = if t.length() > 1e-6 {
        t.normalize()
    } else {
        n.any_orthonormal_vector()
    };
    let t2 = n.cross(t1);
    // 2. Corners into it, clipped to the surface's horizon (gloss's
    // addition: the cosine lobe M^-1 maps to reaches below the horizon,
    // where the BRDF is 0), then through M^-1.
    let frame = DMat3::from_cols(t1, t2, n).transpose();
    let corners: Vec<DVec3> = light.corners.iter().map(|&c| frame * (c - p)).collect();
    let above = super::area_light::clip_to_horizon(&corners, DVec3::Z);
    let transformed: Vec<DVec3> = above.iter().map(|&c| minv * c).collect();
    // 3. Clipped to the cosine's horizon z >= 0.
    let poly = super::area_light::clip_to_horizon(&transformed, DVec3::Z);
    if poly.len() < 3 {
        return 0.0;
    }
    // 4. Lambert's sum on the unit sphere.
    let mut sum = 0.0;
    for (i, &a) in poly.iter().enumerate() {
        let b = poly[(i + 1) % poly.len()];
        sum += edge(a.normalize(), b.normalize());
    }
    let ff = -sum / (2.0 * PI);
    if two_sided { ff.abs() } else { ff.max(0.0) }
}

/// acos(a . b) normalize(a x b).z for unit a, b, with the angle from atan2
/// (exact near 0 and pi, where acos loses digits).
pub fn edge(a: DVec3, b: DVec3) -> f64 {
    let c = a.cross(b);
    let s = c.length();
    if s > 0.0 {
        c.z * s.atan2(a.dot(b)) / s
    } else {
        0.0
    }
}

/// F0 of a dielectric of index eta: ((eta - 1) / (eta + 1))^2.
pub fn f0(eta: f64) -> f64 {
    let r = (eta - 1.0) / (eta + 1.0);
    r * r
}

/// The specular light at `p` from `light` of radiance 1 for gloss's
/// microfacet material (alpha, eta) with k_s = 1 by LTC: steps 1 to 5. The
/// quantity `area_light::monte_carlo_specular` integrates.
pub fn ltc_specular(
    p: DVec3,
    n: DVec3,
    v: DVec3,
    light: &QuadLight,
    (alpha, eta): (f64, f64),
    two_sided: bool,
) -> f64 {
    let uv = table_coords(alpha, n.dot(v));
    let (t1, t2) = (bilinear(ltc_1(), uv), bilinear(ltc_2(), uv));
    let ff = ltc_evaluate(p, n, v, inverse_matrix(t1), light, two_sided);
    let f0 = f0(eta);
    ff * (f0 * t2[0] + (1.0 - f0) * t2[1])
}

/// The diffuse form factor (irradiance / pi for radiance 1): the same steps
/// with M^-1 the identity. One-sided it is `area_light::polygon_irradiance`
/// / pi.
pub fn diffuse_form_factor(p: DVec3, n: DVec3, light: &QuadLight, two_sided: bool) -> f64 {
    // Any eye: the identity lobe is symmetric about N.
    ltc_evaluate(p, n, n, DMat3::IDENTITY, light, two_sided)
}

#[cfg(test)]
mod tests;
