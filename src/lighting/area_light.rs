//! Area lights, the diffuse half on the CPU (Heitz, Dupuy, Hill and Neubelt
//! 2016, "Real-Time Polygonal-Light Shading with Linearly Transformed
//! Cosines"; LearnOpenGL, guest articles 2022, "Area Lights"): the exact
//! irradiance a polygonal light of uniform radiance gives a point, and the
//! Monte Carlo integral over the light's area that checks it.
//!
//! The diffuse term of LTC shading is the clamped-cosine integral over the
//! polygon, which needs no table: Lambert's formula (1760) sums, over the
//! edges of the polygon as seen from the point, the angle each edge subtends
//! times the cosine between the normal of the plane through that edge and
//! the surface normal:
//!
//! ```text
//! E / L = 1/2 sum_i acos(u_i . u_i+1) (normalize(u_i x u_i+1) . n)
//! ```
//!
//! with u_i the unit vectors from the point to the corners. It holds only
//! for the part of the polygon above the surface's horizon, so the polygon
//! is clipped first by the plane through the point with normal n (the
//! horizon clipping of the paper's ClipQuadToHorizon). A one-sided light
//! seen from behind gives a negative sum: none of its light arrives.
//!
//! `monte_carlo_specular` is the reference for the specular term (gloss's
//! microfacet BRDF integrated over the light); src/lighting/ltc.rs holds the
//! specular term through the LTC tables, and the GPU side is
//! src/techniques/lighting/ltc_area_lights.rs.

use glam::DVec3;

/// A quad light: four corners counter-clockwise as seen from the side it
/// shines toward (one-sided), of uniform radiance.
#[derive(Clone, Copy, Debug)]
pub struct QuadLight {
    pub corners: [DVec3; 4],
}

impl QuadLight {
    /// The unit normal of the side that emits.
    pub fn normal(&self) -> DVec3 {
        let c = &self.corners;
        (c[1] - c[0]).cross(c[3] - c[0]).normalize()
    }

    /// Its area (a parallelogram: corners c0, c1, c1 + c3 - c0, c3).
    pub fn area(&self) -> f64 {
        let c = &self.corners;
        (c[1] - c[0]).cross(c[3] - c[0]).length()
    }

    /// A scene's `[[area_lights]]` entry (src/scene/area_lights.rs) in f64.
    pub fn of(light: &crate::scene::area_lights::AreaLight) -> Self {
        let [w, h] = light.size;
        let d = |v: glam::Vec3| v.as_dvec3();
        QuadLight::rectangle(
            d(light.center),
            d(light.normal),
            d(light.up),
            (f64::from(w), f64::from(h)),
        )
    }

    /// A `width` x `height` rectangle about `center` shining toward
    /// `normal` (unit), its height along `up` (unit, at right angles to
    /// `normal`): corners C - T - B, C + T - B, C + T + B, C - T + B with
    /// B = up height / 2, T = (up x normal) width / 2, so that
    /// (c1 - c0) x (c3 - c0) = T x B points along `normal`.
    pub fn rectangle(center: DVec3, normal: DVec3, up: DVec3, (width, height): (f64, f64)) -> Self {
        let b = up * (0.5 * height);
        let t = up.cross(normal) * (0.5 * width);
        QuadLight {
            corners: [
                center - t - b,
                center + t - b,
                center + t + b,
                center - t + b,
            ],
        }
    }
}

/// The polygon `corners` (relative to the shading point) clipped to the
/// half-space n . x >= 0 (Sutherland-Hodgman against one plane).
pub fn clip_to_horizon(corners: &[DVec3], n: DVec3) -> Vec<DVec3> {
    let mut out = Vec::with_capacity(corners.len() + 1);
    for (i, &a) in corners.iter().enumerate() {
        let b = corners[(i + 1) % corners.len()];
        let (da, db) = (n.dot(a), n.dot(b));
        if da >= 0.0 {
            out.push(a);
        }
        if (da >= 0.0) != (db >= 0.0) {
            out.push(a + (b - a) * (da / (da - db)));
        }
    }
    out
}

/// The irradiance at `p` (surface normal `n`) from `light` of radiance 1:
/// the integral of max(0, n . w) over the solid angle the light covers,
/// by Lambert's formula on the polygon clipped to the horizon. Multiply by
/// the radiance for the irradiance, and by k_d / pi for the diffuse colour.
pub fn polygon_irradiance(p: DVec3, n: DVec3, light: &QuadLight) -> f64 {
    let rel: Vec<DVec3> = light.corners.iter().map(|&c| c - p).collect();
    let poly = clip_to_horizon(&rel, n);
    if poly.len() < 3 {
        return 0.0;
    }
    let mut sum = 0.0;
    for (i, &a) in poly.iter().enumerate() {
        let b = poly[(i + 1) % poly.len()];
        let (ua, ub) = (a.normalize(), b.normalize());
        let theta = ua.dot(ub).clamp(-1.0, 1.0).acos();
        let g = ua.cross(ub);
        let len = g.length();
        if len > 1e-300 {
            sum += theta * (g / len).dot(n);
        }
    }
    // Counter-clockwise as seen from the lit side sums negative with this
    // cross product's order: the light's front faces the point.
    (-0.5 * sum).max(0.0)
}

/// The same integral by Monte Carlo over the light's area: `strata` x
/// `strata` jittered samples x on the quad, each adding
/// max(0, n . w) max(0, -n_l . w) / r^2 dA. Returns the estimate and its
/// standard error (of independent samples: jittering only lowers the
/// true error).
pub fn monte_carlo_irradiance(
    p: DVec3,
    n: DVec3,
    light: &QuadLight,
    strata: u32,
    seed: u64,
) -> (f64, f64) {
    jittered_over_quad(p, light, strata, seed, |w, r2, cos_l| {
        n.dot(w).max(0.0) * cos_l / r2
    })
}

/// The specular light at `p` (normal `n`, toward the eye `v`) from `light`
/// of radiance 1 for gloss's microfacet material (notes 03; the shaders'
/// pi f_s (N . L) of a point light becomes the integral of f_s (n . w) over
/// the light): the same jittered samples over the light's area. The
/// reference an LTC fit of this BRDF is to be measured against. Returns the
/// estimate and its standard error.
pub fn monte_carlo_specular(
    p: DVec3,
    n: DVec3,
    v: DVec3,
    light: &QuadLight,
    (alpha, eta): (f64, f64),
    strata: u32,
    seed: u64,
) -> (f64, f64) {
    jittered_over_quad(p, light, strata, seed, |w, r2, cos_l| {
        let cos = n.dot(w);
        if cos > 0.0 {
            let f_s = super::microfacet::brdf(w, v, n, alpha, eta, 1.0);
            f_s * cos * cos_l / r2
        } else {
            0.0
        }
    })
}

/// Any integrand over the light: the integral of `f(w)` dw over the solid
/// angle `light` covers from `p` (w the unit direction to a point of it,
/// the light's lit side toward `p`), by the same jittered samples over its
/// area. The reference for the GPU's quadrature of gloss's BRDF
/// (glsl/lighting/area_light_reference.glsl) with any lobe: Phong's, or the
/// microfacet BRDF with another Fresnel. Returns the estimate and its
/// standard error.
pub fn monte_carlo_solid_angle(
    p: DVec3,
    light: &QuadLight,
    strata: u32,
    seed: u64,
    f: impl Fn(DVec3) -> f64,
) -> (f64, f64) {
    jittered_over_quad(p, light, strata, seed, |w, r2, cos_l| {
        if cos_l > 0.0 { f(w) * cos_l / r2 } else { 0.0 }
    })
}

/// The mean and standard error of `f(w, r^2, max(0, -n_l . w)) area` at
/// `strata` x `strata` jittered points over `light` seen from `p` (w the
/// unit direction to the point, r its distance): the one estimator both
/// Monte Carlo references use.
fn jittered_over_quad(
    p: DVec3,
    light: &QuadLight,
    strata: u32,
    seed: u64,
    f: impl Fn(DVec3, f64, f64) -> f64,
) -> (f64, f64) {
    let mut rng = crate::math::lcg::Lcg(seed);
    let c = &light.corners;
    let (e1, e2) = (c[1] - c[0], c[3] - c[0]);
    let (nl, area) = (light.normal(), light.area());
    let count = f64::from(strata) * f64::from(strata);
    let (mut sum, mut sum2) = (0.0, 0.0);
    for i in 0..strata {
        for j in 0..strata {
            let s = (f64::from(i) + f64::from(rng.next())) / f64::from(strata);
            let t = (f64::from(j) + f64::from(rng.next())) / f64::from(strata);
            let d = c[0] + e1 * s + e2 * t - p;
            let r2 = d.length_squared();
            let w = d / r2.sqrt();
            let x = f(w, r2, (-nl.dot(w)).max(0.0)) * area;
            sum += x;
            sum2 += x * x;
        }
    }
    let mean = sum / count;
    let var = (sum2 / count - mean * mean).max(0.0);
    (mean, (var / count).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// A square of half-size `a` at height `h` above the origin, facing down.
    fn ceiling(a: f64, h: f64) -> QuadLight {
        // (c1 - c0) x (c3 - c0) = (0, 2a, 0) x (2a, 0, 0) points down: it shines down.
        let q = |x: f64, y: f64| DVec3::new(x, y, h);
        QuadLight {
            corners: [q(-a, -a), q(-a, a), q(a, a), q(a, -a)],
        }
    }

    /// The form factor of a point to a parallel a x b rectangle with one
    /// corner straight above it at height h (the textbook closed form),
    /// times pi: the irradiance from radiance 1.
    fn corner_rectangle(a: f64, b: f64, h: f64) -> f64 {
        let (x, y) = (a / h, b / h);
        let (sx, sy) = ((1.0 + x * x).sqrt(), (1.0 + y * y).sqrt());
        0.5 * (x / sx * (y / sx).atan() + y / sy * (x / sy).atan())
    }

    #[test]
    fn a_ceiling_square_gives_the_closed_form() {
        let light = ceiling(0.5, 1.0);
        assert!((light.normal() - DVec3::NEG_Z).length() < 1e-12);
        let e = polygon_irradiance(DVec3::ZERO, DVec3::Z, &light);
        let want = 4.0 * corner_rectangle(0.5, 0.5, 1.0);
        assert!((e - want).abs() < 1e-12, "{e} against {want}");
        // An infinite ceiling gives pi (the whole hemisphere).
        let big = polygon_irradiance(DVec3::ZERO, DVec3::Z, &ceiling(1e6, 1.0));
        assert!((big - PI).abs() < 1e-5, "{big}");
    }

    #[test]
    fn lambert_agrees_with_monte_carlo_in_front_across_and_behind_the_horizon() {
        let light = ceiling(0.5, 1.0);
        // Shading points and normals: facing the light, tilted, the light
        // partly below the horizon (clipping), grazing, entirely behind,
        // and the point behind the one-sided light.
        let cases = [
            (DVec3::ZERO, DVec3::Z, "facing"),
            (
                DVec3::new(0.3, -0.2, 0.0),
                DVec3::new(0.4, 0.1, 1.0).normalize(),
                "tilted",
            ),
            (
                DVec3::new(0.0, 0.0, 0.5),
                DVec3::X,
                "half behind the horizon",
            ),
            (
                DVec3::new(0.2, 0.0, 0.6),
                DVec3::new(1.0, 0.0, 0.3).normalize(),
                "mostly behind",
            ),
            (DVec3::new(2.0, 0.0, 0.98), DVec3::Z, "grazing"),
            (
                DVec3::new(0.0, 0.0, 0.5),
                DVec3::NEG_Z,
                "behind the surface",
            ),
            (DVec3::new(0.0, 0.0, 2.0), DVec3::NEG_Z, "behind the light"),
        ];
        for (p, n, what) in cases {
            let exact = polygon_irradiance(p, n, &light);
            let (mc, se) = monte_carlo_irradiance(p, n, &light, 400, 7);
            assert!(
                (exact - mc).abs() <= 4.0 * se + 1e-9,
                "{what}: Lambert {exact}, Monte Carlo {mc} +- {se}"
            );
            if what.starts_with("behind") {
                assert_eq!(exact, 0.0, "{what}");
            } else {
                assert!(exact > 1e-6, "{what}: {exact}");
            }
        }
    }

    #[test]
    fn a_small_light_far_away_gives_the_point_lights_specular() {
        // A 0.02 x 0.02 light 1 above: its solid angle is 4e-4 / 1, so the
        // integral is f_s (n . w) times that (a point light of intensity
        // radiance x area), to a few parts in 1e4.
        let light = ceiling(0.01, 1.0);
        let (p, n) = (DVec3::ZERO, DVec3::Z);
        let v = DVec3::new(0.3, 0.0, 1.0).normalize();
        let (spec, se) = monte_carlo_specular(p, n, v, &light, (0.3, 1.5), 32, 3);
        let point = super::super::microfacet::brdf(DVec3::Z, v, n, 0.3, 1.5, 1.0) * 4e-4;
        assert!(
            (spec - point).abs() < 1e-3 * point + 4.0 * se,
            "{spec} {point}"
        );
        // And below the horizon nothing.
        let (none, _) = monte_carlo_specular(p, DVec3::NEG_Z, v, &light, (0.3, 1.5), 8, 3);
        assert_eq!(none, 0.0);
    }

    #[test]
    fn without_horizon_clipping_the_formula_counts_light_from_below() {
        // The light straddles the horizon of a wall at x = 0 facing +x: the
        // unclipped sum weighs the part behind by a negative cosine.
        let light = ceiling(0.5, 1.0);
        let (p, n) = (DVec3::new(0.0, 0.0, 0.5), DVec3::X);
        let rel: Vec<DVec3> = light.corners.iter().map(|&c| c - p).collect();
        let mut unclipped = 0.0;
        for i in 0..4 {
            let (a, b) = (rel[i].normalize(), rel[(i + 1) % 4].normalize());
            unclipped += a.dot(b).acos() * a.cross(b).normalize().dot(n);
        }
        let unclipped = (-0.5 * unclipped).max(0.0);
        let (mc, se) = monte_carlo_irradiance(p, n, &light, 400, 7);
        assert!((unclipped - mc).abs() > 20.0 * se, "{unclipped} {mc}");
        assert!((polygon_irradiance(p, n, &light) - mc).abs() <= 4.0 * se);
    }
}
