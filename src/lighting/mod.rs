//! The Phong reflection model of notes 01 §8.3 on the CPU: the same formula
//! as glsl/common/lighting.glsl, written once more so that tests can compare
//! rendered pixels with `shade` below. Also the sRGB transfer functions the
//! output uses, and (in `attenuation`) notes 04's attenuation and light-volume
//! radius, and (in `window`) the windowed falloff. `tonemap`: the post chain's tone-mapping and gamma curves.
//! `shadow_reference` is the exact answer shadow mapping approximates
//! (notes 01 §8.5): rays to the light through a BVH (`bvh`, `triangle`).

pub mod ambient_occlusion;
pub mod area_light;
pub mod attenuation;
pub mod bvh;
pub mod far_field_sh;
pub mod image_based_lighting;
pub mod ltc;
pub mod microfacet;
pub mod shadow_reference;
pub mod static_lighting;
pub mod tonemap;
pub mod triangle;
pub mod window;

use crate::math::sphere_light;
use crate::scene::{Falloff, Light, LightKind, Material};
use glam::Vec3;

/// GLSL's smoothstep.
pub fn smoothstep(e0: f32, e1: f32, x: f32) -> f32 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// Attenuation x spot factor, the unit vector to the light, and sin of
/// the light's angular radius (0 for a directional light), as glsl
/// `light_factor`. A point or spot light is a sphere of radius
/// `sphere_light::LIGHT_RADIUS`: attenuated at no less than that distance.
pub fn light_factor(l: &Light, p: Vec3) -> (f32, Vec3, f32) {
    light_factor_with(l, p, None)
}

/// `light_factor` under another falloff model, with the light's volume
/// radius (`frame::lights::model_radius`): the windowed one (`window`), as
/// glsl does for a light whose type has LIGHT_WINDOWED, or notes 01's linear
/// one, 1 - d / Lmax with Lmax the radius (LIGHT_LINEAR). None, or the
/// notes' model: 1 / (Kc + Kl d + Kq d^2).
pub fn light_factor_with(l: &Light, p: Vec3, model: Option<(Falloff, f32)>) -> (f32, Vec3, f32) {
    match l.kind {
        LightKind::Directional => (1.0, -l.direction, 0.0),
        _ => {
            let to = l.position - p;
            let d = to.length();
            let dir = to / d.max(1e-20);
            let r = d.max(sphere_light::LIGHT_RADIUS);
            let mut att = 1.0 / (l.kc + l.kl * r + l.kq * r * r);
            match model {
                Some((Falloff::Windowed, radius)) => att *= window::window(d, radius),
                Some((Falloff::Linear, lmax)) => att = (1.0 - d / lmax).clamp(0.0, 1.0),
                _ => {}
            }
            if l.kind == LightKind::Spot {
                let c = (-dir).dot(l.direction);
                att *= smoothstep(
                    l.outer_angle.to_radians().cos(),
                    l.inner_angle.to_radians().cos(),
                    c,
                );
            }
            (att, dir, sphere_light::sin_sigma(d))
        }
    }
}

/// Diffuse and specular light from one light (before the material), as glsl `phong_light`.
pub fn phong_light(l: &Light, p: Vec3, n: Vec3, v: Vec3, shininess: f32) -> (Vec3, Vec3) {
    phong_light_with(l, p, n, v, shininess, None)
}

/// `phong_light` under another falloff model (`light_factor_with`).
pub fn phong_light_with(
    l: &Light,
    p: Vec3,
    n: Vec3,
    v: Vec3,
    shininess: f32,
    model: Option<(Falloff, f32)>,
) -> (Vec3, Vec3) {
    let (f, dir, sin_sigma) = light_factor_with(l, p, model);
    let i = l.radiance() * f;
    let horizon = sphere_light::sphere_cosine(n.dot(dir), sin_sigma);
    let n_dot_l = horizon.cosine;
    let h = (dir + v).normalize();
    let s = if horizon.visible > 0.0 {
        horizon.visible * n.dot(h).max(0.0).powf(shininess)
    } else {
        0.0
    };
    (i * n_dot_l, i * s)
}

/// The colour of a surface point: ambient + the sum over lights (linear RGB).
pub fn shade(
    lights: &[Light],
    ambient: Vec3,
    m: &Material,
    kd: Vec3,
    p: Vec3,
    n: Vec3,
    eye: Vec3,
) -> Vec3 {
    let v = (eye - p).normalize();
    let mut c = ambient * kd;
    for l in lights {
        let (d, s) = phong_light(l, p, n, v, m.shininess);
        c += kd * d + m.specular * s;
    }
    c
}

/// sRGB encode one linear channel (clamped), exactly as glsl `srgb_encode`.
pub fn srgb_encode(c: f32) -> f32 {
    let c = c.clamp(0.0, 1.0);
    if c < 0.003_130_8 {
        c * 12.92
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    }
}

/// sRGB decode one channel.
pub fn srgb_decode(c: f32) -> f32 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_round_trip_and_known_values() {
        assert_eq!(srgb_encode(0.0), 0.0);
        assert!((srgb_encode(1.0) - 1.0).abs() < 1e-6);
        assert!((srgb_encode(0.5) * 255.0 - 187.5).abs() < 0.6);
        for i in 0..=100 {
            let x = i as f32 / 100.0;
            assert!((srgb_decode(srgb_encode(x)) - x).abs() < 1e-5);
        }
    }

    fn light(kind: LightKind, position: Vec3, direction: Vec3) -> Light {
        Light {
            kind,
            position,
            direction,
            color: Vec3::new(1.0, 0.5, 0.25),
            intensity: 2.0,
            kc: 1.0,
            kl: 0.09,
            kq: 0.032,
            inner_angle: 20.0,
            outer_angle: 30.0,
            shadow: None,
            range: None,
        }
    }

    #[test]
    fn a_point_lights_factor_is_the_notes_attenuation() {
        // Notes 04: 1 / (Kc + Kl d + Kq d^2): by hand at d = 2, and against
        // src/lighting/attenuation.rs (the formula the light volumes are
        // sized by) at other distances.
        let l = light(LightKind::Point, Vec3::new(0.0, 2.0, 0.0), Vec3::NEG_Y);
        let (f, dir, _) = light_factor_with(&l, Vec3::ZERO, None);
        assert!((f - 1.0 / (1.0 + 0.18 + 0.128)).abs() < 1e-6, "{f}");
        assert!((dir - Vec3::Y).length() < 1e-6, "{dir}");
        for d in [0.5f32, 3.0, 7.25, 20.0] {
            let (f, _, _) = light_factor_with(&l, Vec3::new(0.0, 2.0 - d, 0.0), None);
            let want = attenuation::attenuation(l.kc, l.kl, l.kq, d);
            assert!(
                (f - want).abs() <= 1e-6 * want,
                "d = {d}: {f} against {want}"
            );
        }
    }

    #[test]
    fn blinn_phong_worked_by_hand() {
        // A sun 45 degrees up, the eye straight above the point: the halfway
        // vector lies 22.5 degrees from the normal, so the specular light is
        // the radiance times cos(22.5)^s, the diffuse light the radiance
        // times cos 45.
        let l = light(
            LightKind::Directional,
            Vec3::ZERO,
            Vec3::new(-1.0, -1.0, 0.0).normalize(),
        );
        let (d, s) = phong_light_with(&l, Vec3::ZERO, Vec3::Y, Vec3::Y, 8.0, None);
        let r = l.radiance();
        let c45 = std::f32::consts::FRAC_1_SQRT_2;
        let c22 = (std::f32::consts::PI / 8.0).cos();
        assert!((d - r * c45).abs().max_element() < 1e-5, "{d}");
        assert!((s - r * c22.powi(8)).abs().max_element() < 1e-5, "{s}");
    }
}
