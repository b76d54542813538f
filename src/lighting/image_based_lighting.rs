//! Image-based lighting on the CPU (Karis 2013, "Real Shading in Unreal
//! Engine 4", Image-Based Lighting), for gloss's microfacet material (notes
//! 03's (alpha, eta, k_s), src/lighting/microfacet.rs) and its Lambertian
//! k_d: the twins of the GPU's precompute (src/techniques/sky/image_based_lighting.rs,
//! glsl/sky/) and the Monte Carlo references the tests hold them to.
//!
//! The light a surface receives from an environment L(l) is
//!
//!   L_o(v) = k_d E(n) / pi + k_s integral of L(l) f_s(l, v, n) (n.l) dl.
//!
//! - Diffuse: E(n) / pi, the cosine-weighted mean radiance about n, stored in
//!   a small cube map by convolving the whole environment (`irradiance_convolution`).
//! - Specular, Karis's split sum: the integral is taken as the product of
//!   the prefiltered radiance (`prefilter_env_map`: the environment averaged
//!   over GGX's lobe with n = v = r, weighted by n.l) and the BRDF's
//!   directional albedo with Schlick's Fresnel split into a scale and a bias
//!   of F0 (`integrate_brdf`: F0 A + B). gloss's Fresnel is the exact
//!   dielectric one; the table uses Schlick's with F0 = ((eta - 1) / (eta + 1))^2,
//!   and `split_sum` against `full_ibl` measures what both steps cost.
//!
//! gloss's alpha is GGX's alpha_g itself (Karis samples with roughness^2);
//! the maps are indexed by sqrt(alpha) (Karis's roughness), alpha clamped to
//! [ALPHA_MIN, 1].

use super::microfacet::{self, clamp_alpha};
use crate::math::cube_map::{CubeImage, direction};
use glam::DVec3;
use std::f64::consts::PI;

/// The irradiance cube map's side (the diffuse term varies slowly).
pub const IRRADIANCE_SIZE: i32 = 32;
/// The environment's mip level face side the convolution sums over.
pub const IRRADIANCE_SOURCE: i32 = 16;
/// The prefiltered cube map's side at level 0 (the roughest level, 5, has 4).
pub const PREFILTERED_SIZE: i32 = 128;
/// Its mip levels, one roughness each: level k holds sqrt(alpha) = k / (levels - 1).
pub const PREFILTERED_LEVELS: i32 = 6;
/// GGX samples per texel of the prefiltered levels past the first.
pub const PREFILTER_SAMPLES: u32 = 512;
/// The split-sum table's side (n.v across, sqrt(alpha) up).
pub const BRDF_SIZE: i32 = 64;
/// GGX samples per texel of the table.
pub const BRDF_SAMPLES: u32 = 1024;

/// The alpha a prefiltered level holds.
pub fn level_alpha(level: i32) -> f64 {
    let r = f64::from(level) / f64::from(PREFILTERED_LEVELS - 1);
    r * r
}

/// Hammersley point i of n (Karis's Hammersley, the radical inverse base 2).
pub fn hammersley(i: u32, n: u32) -> (f64, f64) {
    (
        f64::from(i) / f64::from(n),
        f64::from(i.reverse_bits()) / 4_294_967_296.0,
    )
}

/// Karis's ImportanceSampleGGX: a half vector about `n` distributed as
/// D(h) (n.h), with gloss's GGX (alpha_g = alpha).
pub fn importance_sample_ggx((u, v): (f64, f64), alpha: f64, n: DVec3) -> DVec3 {
    let a = clamp_alpha(alpha);
    let phi = 2.0 * PI * u;
    let cos_theta = ((1.0 - v) / (1.0 + (a * a - 1.0) * v)).sqrt();
    let sin_theta = (1.0 - cos_theta * cos_theta).max(0.0).sqrt();
    let h = DVec3::new(sin_theta * phi.cos(), sin_theta * phi.sin(), cos_theta);
    let up = if n.z.abs() < 0.999 {
        DVec3::Z
    } else {
        DVec3::X
    };
    let tx = up.cross(n).normalize();
    let ty = n.cross(tx);
    tx * h.x + ty * h.y + n * h.z
}

/// A small deterministic generator (SplitMix64) for the references' random
/// points, independent of the Hammersley points the GPU takes.
pub struct SplitMix(pub u64);

impl SplitMix {
    pub fn next_f64(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A unit vector about `n` from local (x, y, z), z along n.
fn about(n: DVec3, local: DVec3) -> DVec3 {
    let up = if n.z.abs() < 0.999 {
        DVec3::Z
    } else {
        DVec3::X
    };
    let tx = up.cross(n).normalize();
    let ty = n.cross(tx);
    tx * local.x + ty * local.y + n * local.z
}

/// Monte Carlo reference of E(n) / pi: `samples` random cosine-distributed
/// directions about n, the mean of the radiance along them.
pub fn irradiance_mc(env: &dyn Fn(DVec3) -> DVec3, n: DVec3, samples: u32, seed: u64) -> DVec3 {
    let mut rng = SplitMix(seed);
    let mut sum = DVec3::ZERO;
    for _ in 0..samples {
        let (u, v) = (rng.next_f64(), rng.next_f64());
        let r = v.sqrt();
        let phi = 2.0 * PI * u;
        let l = DVec3::new(r * phi.cos(), r * phi.sin(), (1.0 - v).max(0.0).sqrt());
        sum += env(about(n, l));
    }
    sum / f64::from(samples)
}

/// The solid angle of the part of a cube face between (x0, y0) and
/// (x1, y1) in [-1, 1]^2, from the area element's integral
/// atan(x y / sqrt(x^2 + y^2 + 1)).
pub fn face_solid_angle(x0: f64, y0: f64, x1: f64, y1: f64) -> f64 {
    let f = |x: f64, y: f64| (x * y).atan2((x * x + y * y + 1.0).sqrt());
    f(x0, y0) - f(x0, y1) - f(x1, y0) + f(x1, y1)
}

/// The GPU's diffuse convolution (glsl/sky/irradiance_map.frag): every
/// texel of `source` weighted by its solid angle and max(n.l, 0), divided
/// by the sum of the weights (pi in the limit), so a uniform environment
/// gives itself exactly.
pub fn irradiance_convolution(source: &CubeImage, n: DVec3) -> DVec3 {
    let size = source.size as f64;
    let (mut sum, mut weight) = (DVec3::ZERO, 0.0);
    for face in 0..6 {
        for j in 0..source.size {
            for i in 0..source.size {
                let (s, t) = ((i as f64 + 0.5) / size, (j as f64 + 0.5) / size);
                let l = direction(face, s, t).normalize();
                let c = n.dot(l);
                if c <= 0.0 {
                    continue;
                }
                let (x0, y0) = (2.0 * i as f64 / size - 1.0, 2.0 * j as f64 / size - 1.0);
                let w = c * face_solid_angle(x0, y0, x0 + 2.0 / size, y0 + 2.0 / size);
                let texel = source.texel(face, i, j);
                sum += w * DVec3::new(texel[0].into(), texel[1].into(), texel[2].into());
                weight += w;
            }
        }
    }
    sum / weight
}

/// Karis's PrefilterEnvMap with n = v = r: `samples` GGX half vectors
/// (Hammersley), the radiance along each reflected l weighted by n.l. The
/// GPU takes the same points and reads a blurrier mip level where the
/// sample density is low (`lod`); here `env` is read as it is.
pub fn prefilter_env_map(
    env: &dyn Fn(DVec3) -> DVec3,
    r: DVec3,
    alpha: f64,
    samples: u32,
) -> DVec3 {
    let (n, v) = (r, r);
    let (mut sum, mut weight) = (DVec3::ZERO, 0.0);
    for i in 0..samples {
        let h = importance_sample_ggx(hammersley(i, samples), alpha, n);
        let l = 2.0 * v.dot(h) * h - v;
        let nl = n.dot(l);
        if nl > 0.0 {
            sum += env(l) * nl;
            weight += nl;
        }
    }
    if weight > 0.0 { sum / weight } else { env(r) }
}

/// Monte Carlo reference of what `prefilter_env_map` estimates:
/// integral of L(l) D(h) (n.l) dl / integral of D(h) (n.l) dl with
/// n = v = r, from `samples` random GGX half vectors (the D's cancel in the
/// ratio with their density).
pub fn prefiltered_mc(
    env: &dyn Fn(DVec3) -> DVec3,
    r: DVec3,
    alpha: f64,
    samples: u32,
    seed: u64,
) -> DVec3 {
    let mut rng = SplitMix(seed);
    let (mut sum, mut weight) = (DVec3::ZERO, 0.0);
    for _ in 0..samples {
        let h = importance_sample_ggx((rng.next_f64(), rng.next_f64()), alpha, r);
        let l = 2.0 * r.dot(h) * h - r;
        let nl = r.dot(l);
        if nl > 0.0 {
            sum += env(l) * nl;
            weight += nl;
        }
    }
    sum / weight
}

/// The mip level the GPU reads a sample of density `pdf` from (Colbert and
/// Krivanek 2007, "GPU-Based Importance Sampling"): half the log2 of the
/// sample's solid angle over a level-0 texel's, plus one.
pub fn lod(pdf: f64, samples: u32, source_size: f64) -> f64 {
    let omega_s = 1.0 / (f64::from(samples) * pdf);
    let omega_p = 4.0 * PI / (6.0 * source_size * source_size);
    (0.5 * (omega_s / omega_p).log2() + 1.0).max(0.0)
}

/// Karis's IntegrateBRDF with gloss's Smith G: the scale A and bias B of F0
/// in the specular directional albedo, F0 A + B, with Schlick's Fresnel
/// F0 + (1 - F0)(1 - v.h)^5. `samples` GGX half vectors (Hammersley).
pub fn integrate_brdf(n_dot_v: f64, alpha: f64, samples: u32) -> (f64, f64) {
    let nv = n_dot_v.clamp(microfacet::COS_MIN, 1.0);
    let v = DVec3::new((1.0 - nv * nv).sqrt(), 0.0, nv);
    let n = DVec3::Z;
    let (mut a, mut b) = (0.0, 0.0);
    for i in 0..samples {
        let h = importance_sample_ggx(hammersley(i, samples), alpha, n);
        let vh = v.dot(h);
        let l = 2.0 * vh * h - v;
        if l.z > 0.0 && vh > 0.0 {
            let g = microfacet::g_smith(l, v, n, alpha);
            let g_vis = g * vh / (h.z * nv);
            let fc = (1.0 - vh).powi(5);
            a += (1.0 - fc) * g_vis;
            b += fc * g_vis;
        }
    }
    (a / f64::from(samples), b / f64::from(samples))
}

/// The table's reference: A and B as integrals of gloss's own f_s (F
/// replaced by 1 - (1 - v.h)^5 and (1 - v.h)^5), by the deterministic
/// quadrature `microfacet::albedo_with` (error below 1e-11 at 256 nodes).
pub fn brdf_table_reference(n_dot_v: f64, alpha: f64) -> (f64, f64) {
    let nv = n_dot_v.clamp(1e-6, 1.0);
    let v = DVec3::new((1.0 - nv * nv).sqrt(), 0.0, nv);
    let a = microfacet::albedo_with(v, alpha, 1.0, 256, |c| 1.0 - (1.0 - c).powi(5));
    let b = microfacet::albedo_with(v, alpha, 1.0, 256, |c| (1.0 - c).powi(5));
    (a, b)
}

/// F0 of a dielectric of index eta (Schlick's F at normal incidence).
pub fn f0(eta: f64) -> f64 {
    let r = (eta - 1.0) / (eta + 1.0);
    r * r
}

/// The split-sum specular, as glsl/common/image_based_lighting.glsl takes
/// it: prefiltered(r) x k_s (F0 A + B), the two factors given.
pub fn split_sum(prefiltered: DVec3, (a, b): (f64, f64), eta: f64, k_s: f64) -> DVec3 {
    prefiltered * k_s * (f0(eta) * a + b)
}

/// Monte Carlo reference of the whole specular integral, k_s times the
/// integral of L(l) f_s(l, v, n) (n.l) dl with gloss's exact f_s: random GGX
/// half vectors, each l weighted by f_s (n.l) / pdf(l), pdf(l) = D (n.h) / (4 v.h).
/// The material is notes 03's triple (alpha, eta, k_s).
pub fn full_ibl(
    env: &dyn Fn(DVec3) -> DVec3,
    (n, v): (DVec3, DVec3),
    (alpha, eta, k_s): (f64, f64, f64),
    samples: u32,
    seed: u64,
) -> DVec3 {
    let mut rng = SplitMix(seed);
    let mut sum = DVec3::ZERO;
    for _ in 0..samples {
        let h = importance_sample_ggx((rng.next_f64(), rng.next_f64()), alpha, n);
        let vh = v.dot(h);
        let l = 2.0 * vh * h - v;
        if n.dot(l) <= 0.0 || vh <= 0.0 {
            continue;
        }
        let pdf = microfacet::d_ggx(n, h, alpha) * n.dot(h) / (4.0 * vh);
        let f = microfacet::brdf(l, v, n, alpha, eta, k_s);
        sum += env(l) * (f * n.dot(l) / pdf);
    }
    sum / f64::from(samples)
}

/// A cube image as an environment: bilinear, seamless (what the GPU reads at level 0).
pub fn cube_environment(image: &CubeImage) -> impl Fn(DVec3) -> DVec3 + '_ {
    move |d| {
        let c = image.sample(d, true);
        DVec3::new(c[0], c[1], c[2])
    }
}

/// `image` box-filtered down to faces of `size` (what glGenerateMipmap
/// makes of it, each texel the mean of the texels it covers).
pub fn downsample(image: &CubeImage, size: usize) -> CubeImage {
    let k = (image.size / size.max(1)).max(1);
    let faces = std::array::from_fn(|f| {
        let mut out = Vec::with_capacity(size * size);
        for j in 0..size {
            for i in 0..size {
                let mut s = [0f32; 4];
                for dj in 0..k {
                    for di in 0..k {
                        let t = image.texel(f, i * k + di, j * k + dj);
                        for c in 0..4 {
                            s[c] += t[c];
                        }
                    }
                }
                out.push(s.map(|c| c / (k * k) as f32));
            }
        }
        out
    });
    CubeImage { size, faces }
}

#[cfg(test)]
mod tests;
