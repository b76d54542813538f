//! The Cook-Torrance microfacet specular BRDF (Cook and Torrance 1982) in
//! f64: the CPU reference for the material triple (alpha, eta, k_s) that the
//! geometry pass writes into gAlpha (notes 03, Geometry Pass).
//! glsl/common/microfacet.glsl is its GPU twin (every lighting pass uses it
//! through `surface_light` in glsl/common/lighting.glsl), and
//! [`brdf_f32`] takes that file's steps in f32, for a GPU test to compare with.
//!
//! ```text
//! f_s(l, v, n) = k_s D(h) F(v.h) G(l, v) / (4 (n.l)(n.v)),   h = (l + v) / |l + v|
//!
//! D(h)    = alpha^2 / (pi ((n.h)^2 alpha^2 + |n x h|^2)^2)
//!         = 1 / (pi alpha^2 cos^4 theta_h (1 + tan^2 theta_h / alpha^2)^2)
//! F(c)    = 1/2 ((g - c) / (g + c))^2 (1 + ((c g - s^2) / (c g + s^2))^2),
//!           c = v.h, s^2 = 1 - c^2, g^2 = eta^2 - s^2   (g^2 <= 0: F = 1)
//! G(l, v) = 1 / (1 + Lambda(l) + Lambda(v)),
//!           Lambda(w) = (sqrt(1 + alpha^2 tan^2 theta_w) - 1) / 2
//! ```
//!
//! * D is GGX (Walter et al. 2007, eq. 33), Trowbridge and Reitz's (1975)
//!   distribution. `alpha` is its width alpha_g, used as it is, not squared
//!   (it is not Burley's perceptual roughness r, with alpha = r^2): the
//!   microfacet slopes spread as alpha, and alpha = 1 makes D the constant
//!   1/pi. Notes 03 stores alpha > 1 as 1/alpha (with gConvert.x = 1), so
//!   a channel in [1e-3, 1] carries alpha over 1e-3..1e3; alpha is clamped
//!   to [`ALPHA_MIN`], [`ALPHA_MAX`] (0 becomes the near-mirror 1e-3).
//! * F is the exact unpolarised Fresnel reflectance of a dielectric (the
//!   Fresnel equations in the form of Cook and Torrance 1982 and Walter et al.
//!   2007, eq. 22, whose second ratio (c (g + c) - 1) / (c (g - c) + 1) is
//!   written above with c^2 - 1 = -s^2, so that F(1) is ((eta - 1) /
//!   (eta + 1))^2 to the bit). eta = 1 is no interface: F = 0. eta < 1 gives
//!   total internal reflection past the critical angle. eta is clamped to
//!   [`ETA_MIN`], [`ETA_MAX`]. [`fresnel_schlick`] is Schlick's (1994) fit.
//! * G is Smith's height-correlated masking-shadowing (Heitz 2014, eq. 99)
//!   with GGX's Lambda (Heitz 2014, eq. 72). [`brdf`] folds it with the
//!   denominator, so that nothing divides by n.l:
//!   `G / (4 (n.l)(n.v)) = 1 / (2 (n.v q(l) + n.l q(v)))`, q(w) =
//!   `sqrt((n.w)^2 + alpha^2 |n x w|^2)`. Sines come from cross products, not
//!   `1 - cos^2`, which cancels near the normal.
//!
//! Below the horizon (n.l <= 0 or n.v <= 0) the BRDF is 0; above it the
//! cosines are floored at [`COS_MIN`], so f_s stays finite (and f32-safe) at
//! grazing angles. l, v and n are unit vectors (not checked).

use glam::{DVec3, Vec3};
use std::f64::consts::PI;

/// The smallest alpha: a near-mirror whose D peaks at 1 / (pi 1e-6) = 3.2e5.
pub const ALPHA_MIN: f64 = 1e-3;
/// The largest alpha, notes 03's 1 / 1e-3.
pub const ALPHA_MAX: f64 = 1e3;
/// The smallest index of refraction.
pub const ETA_MIN: f64 = 1e-3;
/// The largest index of refraction (F(normal) = 0.996).
pub const ETA_MAX: f64 = 1e3;
/// The floor on n.l and n.v above the horizon.
pub const COS_MIN: f64 = 1e-8;

/// alpha clamped to [`ALPHA_MIN`], [`ALPHA_MAX`].
pub fn clamp_alpha(alpha: f64) -> f64 {
    alpha.clamp(ALPHA_MIN, ALPHA_MAX)
}

/// |a x b|^2: the squared sine between unit vectors, exact near 0.
fn sin2(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length_squared()
}

/// GGX from cos theta_h and sin^2 theta_h, alpha already clamped.
fn d_ggx_cs(cos_h: f64, sin2_h: f64, alpha: f64) -> f64 {
    if cos_h <= 0.0 {
        return 0.0;
    }
    let a2 = alpha * alpha;
    let d = a2 * cos_h * cos_h + sin2_h;
    a2 / (PI * d * d)
}

/// The GGX normal distribution D(h) about the normal n (Walter et al. 2007):
/// microfacet area per unit solid angle of normals, so that the integral of
/// D(h) (n.h) over the hemisphere is 1. 0 for n.h <= 0.
pub fn d_ggx(n: DVec3, h: DVec3, alpha: f64) -> f64 {
    d_ggx_cs(n.dot(h), sin2(n, h), clamp_alpha(alpha))
}

/// The exact unpolarised Fresnel reflectance of a dielectric with relative
/// index of refraction eta, at cos_i = cosine of the angle of incidence on
/// the microfacet (its sign is ignored). 1 under total internal reflection.
pub fn fresnel_dielectric(cos_i: f64, eta: f64) -> f64 {
    let eta = eta.clamp(ETA_MIN, ETA_MAX);
    if eta == 1.0 {
        return 0.0;
    }
    let c = cos_i.abs().min(1.0);
    let s2 = 1.0 - c * c;
    let g2 = eta * eta - s2;
    if g2 <= 0.0 {
        return 1.0;
    }
    let g = g2.sqrt();
    let a = (g - c) / (g + c);
    let b = (c * g - s2) / (c * g + s2);
    0.5 * a * a * (1.0 + b * b)
}

/// Schlick's (1994) approximation F0 + (1 - F0) (1 - c)^5 with
/// F0 = ((eta - 1) / (eta + 1))^2, for comparison with [`fresnel_dielectric`].
pub fn fresnel_schlick(cos_i: f64, eta: f64) -> f64 {
    let eta = eta.clamp(ETA_MIN, ETA_MAX);
    let r = (eta - 1.0) / (eta + 1.0);
    let f0 = r * r;
    f0 + (1.0 - f0) * (1.0 - cos_i.abs().min(1.0)).powi(5)
}

/// Smith's Lambda for GGX (Heitz 2014, eq. 72) at cos and sin^2 of theta_w,
/// as alpha^2 tan^2 / (2 (1 + sqrt(1 + alpha^2 tan^2))), which does not
/// cancel for small alpha tan.
fn lambda(cos_w: f64, sin2_w: f64, alpha: f64) -> f64 {
    let c = cos_w.max(COS_MIN);
    let a2t2 = alpha * alpha * sin2_w / (c * c);
    a2t2 / (2.0 * (1.0 + (1.0 + a2t2).sqrt()))
}

/// Smith's height-correlated masking-shadowing G(l, v) for GGX (Heitz 2014,
/// eq. 99): 1 / (1 + Lambda(l) + Lambda(v)); 0 below the horizon.
pub fn g_smith(l: DVec3, v: DVec3, n: DVec3, alpha: f64) -> f64 {
    let (nl, nv) = (n.dot(l), n.dot(v));
    if nl <= 0.0 || nv <= 0.0 {
        return 0.0;
    }
    let alpha = clamp_alpha(alpha);
    1.0 / (1.0 + (lambda(nl, sin2(n, l), alpha) + lambda(nv, sin2(n, v), alpha)))
}

/// f_s with any Fresnel term of c = v.h (the white furnace uses F = 1).
/// Every step is symmetric in l and v, so f_s(l, v) == f_s(v, l) exactly.
fn specular(l: DVec3, v: DVec3, n: DVec3, alpha: f64, k_s: f64, f: impl Fn(f64) -> f64) -> f64 {
    let (nl, nv) = (n.dot(l), n.dot(v));
    if nl <= 0.0 || nv <= 0.0 {
        return 0.0;
    }
    let s = l + v;
    let len = s.length();
    if len <= 0.0 {
        return 0.0; // l = -v: no half vector
    }
    let h = s / len;
    let alpha = clamp_alpha(alpha);
    let d = d_ggx_cs(n.dot(h), sin2(n, h), alpha);
    // v.h = l.h = |l + v| / 2 for unit l and v, symmetric in the two.
    let fresnel = f(0.5 * len);
    let (nl, nv) = (nl.max(COS_MIN), nv.max(COS_MIN));
    let a2 = alpha * alpha;
    let q_l = (nl * nl + a2 * sin2(n, l)).sqrt();
    let q_v = (nv * nv + a2 * sin2(n, v)).sqrt();
    let vis = 0.5 / (nv * q_l + nl * q_v);
    k_s * d * fresnel * vis
}

/// The Cook-Torrance BRDF f_s(l, v, n) with GGX roughness alpha, index of
/// refraction eta and specular weight k_s (notes 03's triple). l points to
/// the light and v to the eye, both from the surface.
pub fn brdf(l: DVec3, v: DVec3, n: DVec3, alpha: f64, eta: f64, k_s: f64) -> f64 {
    specular(l, v, n, alpha, k_s, |c| fresnel_dielectric(c, eta))
}

/// [`brdf`] evaluated in f32 with exactly the steps of
/// glsl/common/microfacet.glsl's `microfacet_brdf` (IEEE f32 here; the GPU's
/// division and sqrt may differ by a few ulp).
pub fn brdf_f32(l: Vec3, v: Vec3, n: Vec3, alpha: f32, eta: f32, k_s: f32) -> f32 {
    let (nl, nv) = (n.dot(l), n.dot(v));
    if nl <= 0.0 || nv <= 0.0 {
        return 0.0;
    }
    let s = l + v;
    let len = s.length();
    if len <= 0.0 {
        return 0.0;
    }
    let h = s / len;
    let alpha = alpha.clamp(ALPHA_MIN as f32, ALPHA_MAX as f32);
    let a2 = alpha * alpha;
    let (cos_h, ch) = (n.dot(h), n.cross(h));
    let d = if cos_h <= 0.0 {
        0.0
    } else {
        let dd = a2 * cos_h * cos_h + ch.dot(ch);
        a2 / (std::f32::consts::PI * dd * dd)
    };
    let fresnel = fresnel_dielectric_f32(0.5 * len, eta);
    let (nl, nv) = (nl.max(COS_MIN as f32), nv.max(COS_MIN as f32));
    let (cl, cv) = (n.cross(l), n.cross(v));
    let q_l = (nl * nl + a2 * cl.dot(cl)).sqrt();
    let q_v = (nv * nv + a2 * cv.dot(cv)).sqrt();
    let vis = 0.5 / (nv * q_l + nl * q_v);
    k_s * d * fresnel * vis
}

/// [`fresnel_dielectric`] in f32, as the GLSL's `fresnel_dielectric`.
pub fn fresnel_dielectric_f32(cos_i: f32, eta: f32) -> f32 {
    let eta = eta.clamp(ETA_MIN as f32, ETA_MAX as f32);
    if eta == 1.0 {
        return 0.0;
    }
    let c = cos_i.abs().min(1.0);
    let s2 = 1.0 - c * c;
    let g2 = eta * eta - s2;
    if g2 <= 0.0 {
        return 1.0;
    }
    let g = g2.sqrt();
    let a = (g - c) / (g + c);
    let b = (c * g - s2) / (c * g + s2);
    0.5 * a * a * (1.0 + b * b)
}

/// Tanh-sinh nodes (Takahasi and Mori 1974) on [0, b]: 2 floor(count / 2) + 1
/// (at least 3) pairs (x, weight), the trapezoid rule in t on
/// x = b / (1 + e^(-pi sinh t)), t in [-3, 3]. The nodes crowd both ends,
/// down to 2e-14 b from them, so a
/// peak of any width at an end (D at theta_h = 0 for small alpha, at pi/2
/// for large alpha) is resolved, and the error falls exponentially with
/// `count` for an integrand analytic inside the interval.
fn tanh_sinh(b: f64, count: usize) -> impl Iterator<Item = (f64, f64)> {
    let m = (count.max(3) / 2) as i64;
    let step = 3.0 / m as f64;
    (-m..=m).map(move |k| {
        let t = k as f64 * step;
        let u = 0.5 * PI * t.sinh();
        let x = b / (1.0 + (-2.0 * u).exp());
        let cosh_u = u.cosh();
        // dx/dt = b (pi / 2) cosh t / (2 cosh^2 u)
        (x, step * b * 0.25 * PI * t.cosh() / (cosh_u * cosh_u))
    })
}

/// The directional albedo E(v) = integral over the hemisphere of
/// f_s(l, v) cos theta_l dl: the fraction of light from v that single
/// scattering reflects (at most k_s). v is in the shading frame (n = +z).
///
/// Deterministic quadrature over the half vector h, with dl = 4 (v.h) dh and
/// v turned into the xz plane (D is isotropic). The azimuth phi_h runs over
/// [0, pi/2] and its mirror [pi/2, pi], doubled by the symmetry about v's
/// plane; theta_h runs from 0 to l's horizon: with v at theta_v,
/// n.l = R cos(2 theta_h - gamma), gamma = atan2(sin theta_v cos phi_h,
/// cos theta_v), so l is up for theta_h < theta_max = gamma / 2 + pi / 4.
/// Both are `tanh_sinh` rules, `samples` nodes in theta_h and as many in
/// phi_h. Cutting at the horizon keeps the integrand smooth inside, and the
/// crowding at the ends resolves D's peak at theta_h = 0 and, for grazing
/// v, theta_max's swing near phi_h = pi/2. At 256 samples the error is
/// below 1e-11 (the tests compare with 1024).
pub fn directional_albedo(v: DVec3, alpha: f64, eta: f64, k_s: f64, samples: usize) -> f64 {
    albedo_with(v, alpha, k_s, samples, |c| fresnel_dielectric(c, eta))
}

/// [`directional_albedo`] with any Fresnel term of v.h (image-based
/// lighting's split-sum table integrates F = 1 - (1 - v.h)^5 and (1 - v.h)^5).
pub fn albedo_with(
    v: DVec3,
    alpha: f64,
    k_s: f64,
    samples: usize,
    f: impl Fn(f64) -> f64 + Copy,
) -> f64 {
    let v = v.normalize_or_zero();
    if v.z <= 0.0 {
        return 0.0;
    }
    let v = DVec3::new(v.x.hypot(v.y), 0.0, v.z);
    let n = DVec3::Z;
    let mut sum = 0.0;
    for (x, w_x) in tanh_sinh(0.5 * PI, samples / 2) {
        for phi in [x, PI - x] {
            let (sin_phi, cos_phi) = phi.sin_cos();
            let gamma = (v.x * cos_phi).atan2(v.z);
            let theta_max = 0.5 * gamma + 0.25 * PI;
            for (theta, w) in tanh_sinh(theta_max, samples) {
                let (s, c) = theta.sin_cos();
                let h = DVec3::new(s * cos_phi, s * sin_phi, c);
                let vh = v.dot(h);
                let l = 2.0 * vh * h - v;
                let fs = specular(l, v, n, alpha, k_s, f);
                sum += fs * l.z * 4.0 * vh * s * w * 2.0 * w_x;
            }
        }
    }
    sum
}

#[cfg(test)]
mod tests;
