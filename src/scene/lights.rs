//! The lights of a scene file: the `[[lights]]` list, each checked, then
//! the lights a `[light_grid]` generates; and the attenuation check every
//! light's Kc, Kl, Kq pass (notes 04's model).

use super::checks::{finite, non_negative};
use super::file::SceneFile;
use super::light_grid::generate_lights;
use super::shadows::{MAX_SHADOW_CUBES, MAX_SHADOW_MAPS_2D};
use super::{Light, LightKind};
use anyhow::{Result, anyhow, bail};
use glam::Vec3;

/// Lights: the `[[lights]]` list, then the generated `[light_grid]` ones.
pub(super) fn lights(f: &SceneFile) -> Result<Vec<Light>> {
    let mut lights = Vec::new();
    for (i, l) in f.lights.iter().enumerate() {
        let key = |k: &str| format!("lights[{i}].{k}");
        non_negative(&key("color"), &l.color)?;
        non_negative(&key("intensity"), &[l.intensity])?;
        let [kc, kl, kq] = l.attenuation;
        validate_attenuation(kc, kl, kq).map_err(|e| anyhow!("{}: {e}", key("attenuation")))?;
        let kind = match l.kind.as_str() {
            "directional" => LightKind::Directional,
            "point" => LightKind::Point,
            "spot" => LightKind::Spot,
            other => bail!(
                "{}: expected directional, point or spot, found \"{other}\"",
                key("type")
            ),
        };
        let position = match (kind, l.position) {
            (LightKind::Directional, _) => Vec3::ZERO,
            (_, Some(p)) => {
                finite(&key("position"), &p)?;
                Vec3::from(p)
            }
            (_, None) => bail!("{}: required for a {} light", key("position"), l.kind),
        };
        let direction = match (kind, l.direction) {
            (LightKind::Point, _) => Vec3::NEG_Y,
            (_, Some(d)) => {
                finite(&key("direction"), &d)?;
                let d = Vec3::from(d);
                if d.length() < 1e-6 {
                    bail!("{}: must not be zero", key("direction"));
                }
                d.normalize()
            }
            (_, None) => bail!("{}: required for a {} light", key("direction"), l.kind),
        };
        if kind == LightKind::Spot
            && !(l.inner_angle >= 0.0 && l.inner_angle <= l.outer_angle && l.outer_angle < 89.0)
        {
            bail!(
                "{}: expected 0 <= inner_angle <= outer_angle < 89 degrees, found {} and {}",
                key("inner_angle/outer_angle"),
                l.inner_angle,
                l.outer_angle
            );
        }
        if let Some(r) = l.range
            && !(r.is_finite() && r > 0.0 && r <= 1e6)
        {
            bail!(
                "{}: expected a distance in (0, 1e6], found {r}",
                key("range")
            );
        }
        let light = Light {
            range: l.range,
            kind,
            position,
            direction,
            color: Vec3::from(l.color),
            intensity: l.intensity,
            kc,
            kl,
            kq,
            inner_angle: l.inner_angle,
            outer_angle: l.outer_angle,
            shadow: super::shadows::shadow(
                &key("shadow"),
                l.shadow.as_ref(),
                kind == LightKind::Point,
            )?,
        };
        check_brightness(&light, &format!("lights[{i}]"))?;
        lights.push(light);
    }
    let casting = |point: bool| {
        let same = |l: &&Light| (l.kind == LightKind::Point) == point;
        lights
            .iter()
            .filter(|l| l.shadow.is_some())
            .filter(same)
            .count()
    };
    let (flat, cube) = (casting(false), casting(true));
    if flat > MAX_SHADOW_MAPS_2D || cube > MAX_SHADOW_CUBES {
        bail!(
            "lights: {flat} directional or spot and {cube} point lights cast shadows; at most {MAX_SHADOW_MAPS_2D} and {MAX_SHADOW_CUBES} may (one texture unit each)"
        );
    }
    // Cascaded shadow maps (docs/shadows/cascaded_shadow_maps.md): one
    // directional light's map, on one texture unit of its own.
    let cascaded = |l: &&Light| l.shadow.is_some_and(|s| s.cascades > 1);
    for (i, l) in lights.iter().enumerate().filter(|(_, l)| cascaded(l)) {
        if l.kind != LightKind::Directional {
            bail!(
                "lights[{i}].shadow.cascades: only a directional light's map is split into cascades, found a {} light",
                format!("{:?}", l.kind).to_lowercase()
            );
        }
    }
    let n = lights.iter().filter(cascaded).count();
    if n > 1 {
        bail!(
            "lights: {n} directional lights have shadow.cascades > 1; at most one may (the cascades take one texture unit)"
        );
    }
    if let Some(g) = &f.light_grid {
        super::light_grid::check(g)?;
        lights.extend(generate_lights(g));
    }
    Ok(lights)
}

/// The brightest a light may be at its own surface: the most a half float
/// holds. The HDR, light-accumulation and post targets are RGBA16F; a light
/// past it would write inf there.
pub const MAX_BRIGHTNESS: f64 = 65504.0;

/// Refuse a light brighter than `MAX_BRIGHTNESS` at its surface (a point
/// or spot light is a sphere of radius `LIGHT_RADIUS`, so even Kc = 0 has
/// a brightest point), or whose colour x intensity overflows.
fn check_brightness(l: &Light, key: &str) -> Result<()> {
    let i = f64::from(l.color.max_element()) * f64::from(l.intensity);
    let r = f64::from(crate::math::sphere_light::LIGHT_RADIUS);
    let (kc, kl, kq) = (f64::from(l.kc), f64::from(l.kl), f64::from(l.kq));
    let peak = match l.kind {
        LightKind::Directional => i,
        _ => i / (kc + kl * r + kq * r * r),
    };
    if peak.is_nan() || peak > MAX_BRIGHTNESS {
        let at = match l.kind {
            LightKind::Directional => String::new(),
            _ => format!(
                " at its surface (a sphere of radius {r}): I_max / (Kc + Kl r + Kq r^2) = \
                 {i:e} / ({kc:e} + {kl:e} x {r} + {kq:e} x {r}^2)"
            ),
        };
        bail!(
            "{key}: the light is {peak:.3e}{at}, more than {MAX_BRIGHTNESS}, the most the \
             RGBA16F light targets hold: lower its intensity or colour, or raise its attenuation"
        );
    }
    Ok(())
}

/// Checks attenuation coefficients as the scene loader must before any light
/// uses them: every coefficient finite and non-negative, and not all zero
/// (which would make the attenuation infinite everywhere).
pub fn validate_attenuation(kc: f32, kl: f32, kq: f32) -> Result<(), String> {
    for (name, v) in [
        ("Kc (constant)", kc),
        ("Kl (linear)", kl),
        ("Kq (quadratic)", kq),
    ] {
        if !v.is_finite() {
            return Err(format!(
                "attenuation coefficient {name} must be a finite number, got {v}"
            ));
        }
        if v < 0.0 {
            return Err(format!(
                "attenuation coefficient {name} must be >= 0, got {v}"
            ));
        }
    }
    if kc == 0.0 && kl == 0.0 && kq == 0.0 {
        return Err(
            "attenuation coefficients Kc, Kl and Kq are all 0: the light would be infinitely bright"
                .to_string(),
        );
    }
    Ok(())
}
