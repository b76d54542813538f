//! `[sky]`: the Preetham sun-sky of notes 03, Sun Sky (src/math/preetham.rs),
//! drawn behind the world by the sun-sky pass (src/techniques/sky/sun_sky.rs).
//!
//! ```toml
//! [sky]
//! sun = [0.3, 0.25, -1.0]   # the direction to the sun (y up; any length)
//! turbidity = 3.0           # 2 (clear) ..= 10 (hazy)
//! intensity = 1.0           # a factor on the model's radiance (1.0 = 10 kcd/m^2)
//! sun_disc = 0.5            # the sun's own disc: its irradiance, 0 (none) ..= 2
//! ```
//!
//! Preetham's model is the sky without the sun. `sun_disc` adds the sun as a
//! disc 0.53 degrees across, bright enough that the bloom of notes 03 ("Blur
//! Pass and Merge Pass", "Blurred Sun-sky") spreads it: its radiance is the
//! irradiance `sun_disc` over the disc's solid angle (about 6.8e-5 sr, so
//! 1 gives 14,700), in the colour of the sky around the sun.

use crate::math::preetham::Sky;
use anyhow::{Result, anyhow, bail};
use glam::Vec3;
use serde::Deserialize;

#[derive(Deserialize, Debug, Clone)]
#[serde(deny_unknown_fields)]
pub struct SkyFile {
    pub sun: [f32; 3],
    #[serde(default = "three")]
    pub turbidity: f32,
    #[serde(default = "one")]
    pub intensity: f32,
    #[serde(default)]
    pub sun_disc: f32,
}

fn three() -> f32 {
    3.0
}
fn one() -> f32 {
    1.0
}

/// The scene's sky, checked.
#[derive(Clone, Debug, PartialEq)]
pub struct SkySettings {
    /// The unit direction to the sun.
    pub sun: Vec3,
    pub turbidity: f32,
    pub intensity: f32,
    /// The sun disc's irradiance (0: no disc).
    pub sun_disc: f32,
}

/// The sun's angular radius, 0.2666 degrees, in radians.
pub const SUN_ANGULAR_RADIUS: f64 = 0.004_653;

/// The most `sun_disc` may be: its radiance, up to 1.5 times the
/// luminance in a red channel at a low sun, stays well inside a half
/// float's 65504 (the sky's target is RGBA16F).
pub const MAX_SUN_DISC: f32 = 2.0;

impl SkySettings {
    /// The sun disc's linear sRGB radiance: `sun_disc` / Omega, Omega =
    /// 2 pi (1 - cos r), in the colour the sky has toward the sun scaled to
    /// luminance 1. Zero without a disc, or with the sun wholly below the
    /// horizon.
    pub fn sun_disc_radiance(&self) -> Vec3 {
        let sun = self.sun.as_dvec3();
        if self.sun_disc == 0.0 || sun.y < -SUN_ANGULAR_RADIUS {
            return Vec3::ZERO;
        }
        let omega = std::f64::consts::TAU * (1.0 - SUN_ANGULAR_RADIUS.cos());
        let [r, g, b] = self.model().radiance_rgb(sun);
        let luminance = 0.2126 * r + 0.7152 * g + 0.0722 * b;
        let colour = glam::DVec3::new(r, g, b) / luminance.max(1e-12);
        (colour * f64::from(self.sun_disc) / omega).as_vec3()
    }

    /// The model for this sky (the checks in `sky` make this succeed).
    pub fn model(&self) -> Sky {
        Sky::new(self.sun.as_dvec3(), f64::from(self.turbidity))
            .expect("the sky was checked when the scene loaded")
    }
}

/// Check `[sky]`.
pub(super) fn sky(f: &Option<SkyFile>) -> Result<Option<SkySettings>> {
    let Some(s) = f else { return Ok(None) };
    if !(s.intensity.is_finite() && (0.0..=1e4).contains(&s.intensity)) {
        bail!(
            "sky.intensity: expected a number in 0..=10000, found {}",
            s.intensity
        );
    }
    if !(s.sun_disc.is_finite() && (0.0..=MAX_SUN_DISC).contains(&s.sun_disc)) {
        bail!(
            "sky.sun_disc: expected an irradiance in 0..={MAX_SUN_DISC} (the disc's radiance \
             must fit a half float), found {}",
            s.sun_disc
        );
    }
    let sun = Vec3::from(s.sun).as_dvec3();
    let model = Sky::new(sun, f64::from(s.turbidity)).map_err(|e| {
        let key = if e.contains("turbidity") {
            "sky.turbidity"
        } else {
            "sky.sun"
        };
        anyhow!("{key}: {e}")
    })?;
    Ok(Some(SkySettings {
        sun: model.sun.as_vec3(),
        turbidity: s.turbidity,
        intensity: s.intensity,
        sun_disc: s.sun_disc,
    }))
}
