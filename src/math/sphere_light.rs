//! What a light at distance 0 means: every point and spot light is a small
//! sphere of radius [`LIGHT_RADIUS`], not a point (Lagarde and de Rousiers,
//! "Moving Frostbite to Physically Based Rendering", SIGGRAPH 2014: §4.1.1
//! "Punctual lights" gives a light a 1 cm minimum size, §4.7.2 the sphere's
//! illuminance with its horizon, after Snyder, "Area Light Sources for
//! Real-Time Graphics", 1996). glsl/common/lighting.glsl does the same.
//!
//! Two things change, and only near the light or at its horizon:
//!
//! - the attenuation is taken at `max(d, LIGHT_RADIUS)`: inside the sphere
//!   the light is as bright as on its surface, so `Kc = 0` is never singular;
//! - N.L becomes [`sphere_cosine`]: the sphere's light that falls on the
//!   surface, which goes smoothly from 0 to cos(theta) as the sphere rises
//!   over the surface's horizon, and the specular term is scaled by the
//!   part of the sphere above it ([`Horizon::visible`]).
//!
//! Why: a point light's N.L jumps from 0 to its slope at the horizon. For a
//! light lying on a surface (N.L = 0 exactly), a position off by one depth
//! step (the deferred paths rebuild it from a 24-bit depth) becomes light x
//! 1 / (Kl d): bright noise. The sphere's cosine has a slope of 1/2 there
//! and a value of about r / (4.7 d), so the same step is a relative error
//! of about 2.4 x step / r.
//!
//! Snyder's exact formula subtracts terms of size sin(sigma) to leave one
//! of size sin^3(sigma): in f32, with a GPU's acos and atan, it gives 0 or
//! three times the answer 2 m from a 1 cm light. Here the sphere is taken in
//! its small-angle limit (a flat disc of angular radius sigma), in which
//! nothing cancels: with t = cos(theta) / sin(sigma) in [-1, 1],
//!
//! ```text
//! G(t) = (t pi/2 + t^2 sqrt(1 - t^2) + t asin(t) + 2/3 (1 - t^2)^(3/2)) / pi
//! E / (pi sin^2 sigma) = sin(sigma) G(t)
//! ```
//!
//! It differs from the exact sphere by under 0.08 sin^3(sigma) (6e-5 at ten
//! radii; the tests check it). Anywhere the whole sphere is above the
//! horizon the result is the point light's exactly: cos(theta).

/// The radius of every point and spot light, in scene units (Frostbite's
/// 1 cm, for scenes in metres).
pub const LIGHT_RADIUS: f32 = 0.01;

/// sin of the angular radius of the light's sphere seen from distance `d`
/// (1 inside the sphere).
pub fn sin_sigma(d: f32) -> f32 {
    LIGHT_RADIUS / d.max(LIGHT_RADIUS)
}

/// A sphere light against a surface's horizon.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Horizon {
    /// The sphere's illuminance over that of a point at its centre straight
    /// overhead: N.L for the diffuse term.
    pub cosine: f32,
    /// The part of the sphere above the horizon, 0..=1: scales the
    /// specular term (1 while the whole sphere is up, 0 once it has set).
    pub visible: f32,
}

/// `cos_theta` (clamped at 0) while the whole sphere is above the horizon,
/// less as it sets, 0 once it is below; `sin_sigma` 0 is a point (or a
/// directional light): N.L and a step. The same operations as glsl
/// `sphere_cosine`.
pub fn sphere_cosine(cos_theta: f32, sin_sigma: f32) -> Horizon {
    if cos_theta >= sin_sigma || cos_theta <= -sin_sigma {
        let up = cos_theta > 0.0;
        return Horizon {
            cosine: cos_theta.max(0.0),
            visible: if up { 1.0 } else { 0.0 },
        };
    }
    let t = (cos_theta / sin_sigma).clamp(-1.0, 1.0);
    let q = (1.0 - t * t).sqrt();
    let pi = std::f32::consts::PI;
    let g = (t * pi / 2.0 + t * t * q + t * t.asin() + 2.0 / 3.0 * q * q * q) / pi;
    let g = g.clamp(0.0, 1.0);
    Horizon {
        cosine: sin_sigma * g,
        visible: g,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Snyder's exact sphere, in f64 (Frostbite's illuminanceSphereOrDisk
    /// over pi sin^2 sigma).
    fn exact(c: f64, ss: f64) -> f64 {
        if c * c > ss {
            return c.max(0.0);
        }
        let st = (1.0 - c * c).sqrt();
        let x = (1.0 / ss - 1.0).sqrt();
        let y = (-x * c / st).clamp(-1.0, 1.0);
        let s = st * (1.0 - y * y).sqrt();
        ((c * y.acos() - x * s) * ss + s.atan2(x)).max(0.0) / (std::f64::consts::PI * ss)
    }

    #[test]
    fn the_sphere_is_a_point_above_its_horizon_and_dark_below() {
        for d in [0.02f32, 0.1, 1.0, 5.0] {
            let s = sin_sigma(d);
            for c in [1.0, 0.5, s * 1.01, s] {
                let h = sphere_cosine(c, s);
                assert_eq!((h.cosine, h.visible), (c, 1.0), "d {d} cos {c}");
            }
            for c in [-s, -s * 1.01, -1.0] {
                assert_eq!(sphere_cosine(c, s).cosine, 0.0);
                assert_eq!(sphere_cosine(c, s).visible, 0.0);
            }
        }
        // A point (and a directional light): N.L and a step.
        assert_eq!(sphere_cosine(0.3, 0.0).cosine, 0.3);
        assert_eq!(sphere_cosine(1e-9, 0.0).visible, 1.0);
        assert_eq!(sphere_cosine(0.0, 0.0).visible, 0.0);
    }

    #[test]
    fn it_sets_smoothly_and_is_the_exact_sphere_far_from_it() {
        for d in [0.012f32, 0.02, 0.05, 0.1, 1.0, 9.0] {
            let s = sin_sigma(d);
            let mut last = 0.0f32;
            for i in 0..=1000 {
                let c = -s + 2.0 * s * i as f32 / 1000.0;
                let h = sphere_cosine(c, s);
                // Monotonic; continuous: the slope is at most 1.
                assert!(h.cosine + 1e-7 >= last, "d {d}: falls at cos {c}");
                assert!(
                    h.cosine - last <= 2.0 * s / 1000.0 + 1e-6,
                    "d {d}: jumps at {c}"
                );
                assert!((0.0..=1.0).contains(&h.visible));
                let want = exact(f64::from(c), f64::from(s * s));
                // Beyond two radii (sin sigma <= 1/2): the small-angle form
                // is the exact sphere to 0.08 sin^3 sigma. Nearer it is an
                // approximation (where the light is 10^3 times brighter
                // than anywhere it is seen from afar).
                let bound = 0.08 * f64::from(s).powi(3) + 2e-7;
                let err = (f64::from(h.cosine) - want).abs();
                assert!(
                    s > 0.5 || err <= bound,
                    "d {d} cos {c}: {} vs exact {want}",
                    h.cosine
                );
                last = h.cosine;
            }
        }
    }

    #[test]
    fn a_light_on_the_surface_lights_it_by_about_r_over_4_7_d() {
        // cos theta = 0: the sphere half set, 2 sin(sigma) / (3 pi) = r / (4.71 d).
        for d in [0.05f32, 0.1, 0.5, 2.0] {
            let h = sphere_cosine(0.0, sin_sigma(d));
            let want = 2.0 * LIGHT_RADIUS / (3.0 * std::f32::consts::PI * d);
            assert!(
                (h.cosine - want).abs() <= 1e-6 * want,
                "d {d}: {} vs {want}",
                h.cosine
            );
            assert!((h.visible - 2.0 / (3.0 * std::f32::consts::PI)).abs() < 1e-6);
        }
        // Inside the sphere sin(sigma) is 1: a surface through it is lit.
        assert_eq!(sin_sigma(0.0), 1.0);
        assert!(sphere_cosine(0.0, sin_sigma(0.0)).cosine > 0.2);
    }
}
